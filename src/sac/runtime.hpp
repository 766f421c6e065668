#pragma once
// kmr::sac — a self-adjusting computation runtime in the CEAL / ΔML style (thesis §1.3, App. A.2).
//
// Vocabulary (ΔML → here): `Box` modifiable → Mod<T>, `IBox` → IMod<T> (rt.ialloc / iread /
// iwrite); `Box.get $ m` → rt.read(m, k);
// `put` / `PutMemoTable.mkPut` keyed allocation → rt.alloc<T>(label, keys...); `mfun` memoized
// function → rt.memo<R>(label, key, body); `Box.Meta.new/change/deref` → rt.input / rt.change /
// rt.deref; `Adaptive.Meta.propagate` → rt.propagate(); `mfun` returning a Box → rt.memo_box;
// unkeyed `Box.put` → rt.put / rt.fresh. A traceable value whose changes come from outside (a
// kinetic certificate's outcome) is rt.traceable inside a run (keyed) or an input outside one
// (Traceable<T> does either).
//
// Guarantees (tested in tests/sac and proptests/sac; see spec/sac.md):
//  * Change propagation re-executes affected reads in increasing start time; after propagate() the
//    trace equals, token for token (signature()), the trace of a from-scratch run on the current
//    input, and the live counts (trace nodes, owned modifiables) are equal (§1.3.1, §1.3.2).
//  * A write of a value equal (==) to the current one dirties nothing.
//  * IMod<T> (ΔML IBox) may be written many times in one execution: a read sees the latest write at
//    or before its time (or the initial value from ialloc); inserting or discarding a write re-runs
//    exactly the reads whose visible value changed.
//  * A memoized call is reused only if its interval lies inside the interval being re-executed and
//    after the current time (Acar's rule); the initial run never reuses.
//  * alloc (and traceable) under a key found in the interval being re-executed returns the same
//    modifiable; keys are compared in full (label and key tuple), not by hash; allocation keys are
//    unique within an execution (a repeated key throws ContractError: reusing one modifiable in two
//    roles would corrupt the computation). fresh/put allocate anew each time, any number of times.
//  * A traceable created in a run keeps the value its owner set when it is reused; only the owner
//    changes it (rt.change outside runs).
//  * memo_box(label, key, body): body writes the returned destination, possibly inside reads; the
//    destination is reused exactly when the call is.
//  * memo_read(label, key, src, k) behaves as memo_box (memo_read<void>: as memo) whose body is the
//    one read `read(src, k)`, in one trace node; its closure's own write of the destination is
//    inline and checked at its exact time (a read before it, a second write, a lost write while
//    read are errors as for write nodes).
//  * A write whose modifiable's current write lies after the interval being re-executed moves the
//    write earlier (CEAL); the later write must be gone when propagate() returns (else ContractError).
//  * The signature lists every node with names and digests of written values, memo results and
//    traceables' values (value_hash; extend with an ADL canon_value).
//  * Trace that is not reused is discarded; discarding runs its undo hooks (on_discard) in time
//    order, after the replacement code that precedes them in the re-executed interval (so hooks
//    carry a per-instance HookId); modifiables allocated in discarded trace are freed at the end of
//    propagate().
//  * Misuse throws kmr::ContractError with a message naming it: reading an unwritten modifiable,
//    writing a modifiable twice in one execution, an allocation key used twice in one execution,
//    a modifiable still read after re-execution removed its only write,
//    writing an input inside a run, trace operations outside a run or inside an undo hook,
//    propagate/change/release during a run, releasing an input that still has readers. (A write that
//    would affect an earlier read is also refused; with write-once modifiables it is a defensive
//    check that no test can reach.)
//  * Deterministic: no result or signature depends on pointer values or hash-table order.
// Closures given to read/memo/on_discard are stored and may be re-run: capture by value.
#include <concepts>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <tuple>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

#include "exact/error.hpp"
#include "sac/order.hpp"

namespace kmr::sac {

// ---- canonical keys -------------------------------------------------------------------------
constexpr std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
  std::uint64_t z = h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::uint64_t fnv(const char* s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (; *s; ++s) h = (h ^ static_cast<unsigned char>(*s)) * 1099511628211ULL;
  return h;
}

// A function or allocation label (ΔML: the name of an mfun / put table).
struct Label {
  const char* name;
  std::uint64_t hash;
  constexpr explicit Label(const char* n) : name(n), hash(fnv(n)) {}
};

struct ModBase;
template <class T>
struct Mod;

// canon_key(x): a 64-bit name of x that is the same in every run (modifiables by their allocation
// names, never by address). Extend for your own types with an overload found by ADL.
template <class T>
  requires std::is_integral_v<T> || std::is_enum_v<T>
constexpr std::uint64_t canon_key(T x) {
  return static_cast<std::uint64_t>(x);
}
std::uint64_t canon_key(const ModBase* m);
template <class A, class B>
std::uint64_t canon_key(const std::pair<A, B>& p) {
  return mix(canon_key(p.first), canon_key(p.second));
}
template <class... A>
std::uint64_t canon_key(const std::tuple<A...>& t) {
  std::uint64_t h = 0x5ac;
  std::apply([&h](const auto&... x) { ((h = mix(h, canon_key(x))), ...); }, t);
  return h;
}

// The name of a keyed allocation (alloc, ialloc, traceable, owned) under (label, keys...): its
// modifiable's `name` and its key-index hash. Public so that an owner can index its own records
// by the same hash instead of hashing the key again (the kinetic hull's certificates, issue 9).
template <class... K>
std::uint64_t alloc_name(const Label& label, const K&... keys) {
  std::uint64_t h = label.hash;
  ((h = mix(h, canon_key(keys))), ...);
  return h;
}

// value_hash(x): a 64-bit digest of a written value or memo result for the signature (§1.3.1
// from-scratch comparison: a stale value under an unchanged name must show). Canonical like
// canon_key (modifiables by name); extend with an ADL overload `std::uint64_t canon_value(const T&)`.
template <class T>
std::uint64_t value_hash(const T& x);
namespace detail {
template <class T>
concept HasCanonValue = requires(const T& x) {
  { canon_value(x) } -> std::convertible_to<std::uint64_t>;
};
}  // namespace detail
template <class T>
std::uint64_t value_hash(const T& x) {
  if constexpr (detail::HasCanonValue<T>) {
    return canon_value(x);
  } else if constexpr (std::is_same_v<T, bool>) {
    return x ? 0xb1 : 0xb0;
  } else if constexpr (std::is_integral_v<T> || std::is_enum_v<T>) {
    return mix(0x1a, static_cast<std::uint64_t>(x));
  } else if constexpr (std::is_floating_point_v<T>) {
    double d = x == 0 ? 0.0 : static_cast<double>(x);  // -0 == 0
    std::uint64_t b;
    std::memcpy(&b, &d, sizeof b);
    return mix(0xf1, b);
  } else if constexpr (std::is_pointer_v<T> && std::is_convertible_v<T, const ModBase*>) {
    return canon_key(static_cast<const ModBase*>(x));
  } else if constexpr (requires { std::tuple_size<T>::value; }) {
    std::uint64_t h = 0x7a;
    std::apply([&h](const auto&... e) { ((h = mix(h, value_hash(e))), ...); }, x);
    return h;
  } else {
    static_assert(sizeof(T) == 0, "sac: define std::uint64_t canon_value(const T&) for this value type");
    return 0;
  }
}

// The anchor of a key: its first modifiable, on whose list the memo/alloc node is indexed (the
// modifiable was just touched, so lookups stay in cache); keys without one use a hash table.
template <class T>
ModBase* anchor_one(const T& x) {
  if constexpr (std::is_convertible_v<const T&, const ModBase*>)
    return const_cast<ModBase*>(static_cast<const ModBase*>(x));
  else
    return nullptr;
}
template <class T>
ModBase* anchor_of(const T& x) {
  return anchor_one(x);
}
template <class... A>
ModBase* anchor_of(const std::tuple<A...>& t) {
  return std::apply([](const auto&... x) {
    ModBase* a = nullptr;
    ((a = a ? a : anchor_one(x)), ...);
    return a;
  }, t);
}

// ---- trace nodes ------------------------------------------------------------------------------
enum class Kind : std::uint8_t { ReadStart, End, MemoStart, Alloc, Write, IWrite, Hook, MemoRead };

// Node = Stamp with kind, flag and size in the Stamp's tail padding (32 bytes), not polymorphic:
// only nodes that hold a closure or a typed key/value (read, memo, iwrite, hook) carry a vtable
// pointer (placed before their Node part); Runtime::destroy_node dispatches on kind.
struct Node : Stamp {
  Kind kind;
  // KeyedNode: in the runtime's hash table (else on its anchor's list); WriteNode: superseded by an
  // earlier write (§1 item 4); ReadNode: a read of an IMod (an IReadNode).
  bool flag = false;
  std::uint16_t bytes = 0;    // allocation size (make_node checks that it fits)
  explicit Node(Kind k) : kind(k) {}
};

struct EndNode : Node {
  EndNode() : Node(Kind::End) {}
};

struct IVersion;

struct ReadNode : Node {
  ModBase* mod = nullptr;
  ReadNode* rprev = nullptr;
  ReadNode* rnext = nullptr;
  Node* end = nullptr;
  std::int32_t heap = -1;  // index in the queue of affected reads, −1 if not queued
  bool in_table = false;   // a MemoReadNode whose key is in the runtime's hash table (Node::flag is the IRead flag)
  explicit ReadNode(Kind k = Kind::ReadStart) : Node(k) {}
  virtual ~ReadNode() = default;
  virtual void rerun() = 0;
};

struct IReadNode : ReadNode {  // a read of an IMod (flag set): on the reader list of the version it sees
  IVersion* ver = nullptr;
};

// The key-index entry of a memo, alloc or memo-read node (lookup only; see Runtime::index).
struct KeyLink {
  std::uint64_t hash = 0;
  const void* tag = nullptr;  // identifies the key/value types; null: a fresh allocation (never indexed)
  Node* hnext = nullptr;
  Node** hpprev = nullptr;
};

struct KeyedNode : Node, KeyLink {  // memo and alloc nodes, indexed by key hash
  using Node::Node;
};

struct MemoNode;
// The static descriptor of a memo node's key and result types; its address is the node's tag (no
// vtable pointer in memo nodes, issue 8 §2).
struct MemoType {
  std::uint64_t (*result_hash)(const MemoNode*);
  ModBase* (*owned)(const MemoNode*);  // a memo_box destination, freed with this node's trace
  void (*destroy)(MemoNode*);
};

struct MemoNode : KeyedNode {  // MemoImpl holds the key and result
  static constexpr Kind kKind = Kind::MemoStart;
  const Label* label = nullptr;
  Node* end = nullptr;
  MemoNode() : KeyedNode(Kind::MemoStart) {}
  const MemoType& type() const { return *static_cast<const MemoType*>(tag); }
  std::uint64_t result_hash() const { return type().result_hash(this); }
  ModBase* owned() const { return type().owned(this); }
};

// A memo_box call whose body is one read (Runtime::memo_read; issue 8 §2, CEAL's one node per basic
// block): the call, its destination, the read and the destination's write share one node, one
// stamp and one end. It is a read (reader lists, the queue, rerun) with a key-index entry; the
// write of `dest` by its own closure is recorded inline (dest->inline_write; dest->writer is the
// stamp the write follows, a top-level node of this interval, so it lives as long as this execution).
struct MemoReadNode : ReadNode, KeyLink {
  static constexpr Kind kKind = Kind::MemoRead;
  const Label* label = nullptr;
  ModBase* dest = nullptr;  // the memo_box destination, freed with this node's trace (null: memo_read<void>)
  MemoReadNode() : ReadNode(Kind::MemoRead) {}
};

struct AllocNode : KeyedNode {
  ModBase* mod = nullptr;  // null once the modifiable was reused by a later alloc
  AllocNode() : KeyedNode(Kind::Alloc) {}
};

struct WriteNode : Node {
  ModBase* mod = nullptr;
  WriteNode() : Node(Kind::Write) {}
};

// A version of an imperative modifiable (ΔML IBox): its initial value, or the value of one write.
// Versions are kept in time order; a read sees the latest version written before it.
struct IVersion {
  IVersion* vprev = nullptr;
  IVersion* vnext = nullptr;
  ReadNode* readers = nullptr;  // the live reads that see this version
  const Stamp* time = nullptr;  // the write's time; null for the initial value
  const void* value = nullptr;
};

struct IWriteNode : Node {
  ModBase* mod = nullptr;
  IVersion version;
  IWriteNode() : Node(Kind::IWrite) {}
  virtual ~IWriteNode() = default;
  virtual bool same_as_previous() const = 0;
  virtual std::uint64_t value_hash() const = 0;
};

using HookId = std::uint64_t;  // per-instance identity of an undo hook (a serial, never reused)

struct HookNode : Node {
  const Label* label = nullptr;
  HookId id = 0;
  HookNode() : Node(Kind::Hook) {}
  virtual ~HookNode() = default;
  virtual void undo() = 0;
};

// The static descriptor of a modifiable's type (its size, value digest and destructor), found by
// a 16-bit index stored in the modifiable: modifiables carry no vtable pointer (issue 8 §2).
struct ModType {
  std::uint64_t (*value_hash)(const ModBase*);
  void (*destroy)(ModBase*);
  std::uint32_t bytes;
  void (*release)(ModBase*) = nullptr;  // an owned traceable's release (OwnedMod), else null
};
namespace detail {
std::uint16_t register_mod_type(const ModType* t);  // thread-safe; ContractError past 65 535 types
extern const ModType* mod_types[std::size_t{1} << 16];  // written once per type, before its first use
inline const ModType* mod_type(std::uint16_t id) { return mod_types[id]; }
template <class M>
struct ModTypeOf {
  static std::uint64_t hash(const ModBase* m) { return static_cast<const M*>(m)->value_digest(); }
  static void destroy(ModBase* m) { static_cast<M*>(m)->~M(); }
  static void release(ModBase* m) {
    if constexpr (requires { M::kOwned; }) {
      auto* o = static_cast<M*>(m);
      if (o->release) o->release(o->owner, o);
    }
  }
  static constexpr ModType desc{&hash, &destroy, sizeof(M), requires { M::kOwned; } ? &release : nullptr};
  static std::uint16_t id() {
    static const std::uint16_t i = register_mod_type(&desc);
    return i;
  }
};
}  // namespace detail

// A modifiable: 40 bytes before its value (name, reader list, writer, key-index head, flags, type).
struct ModBase {
  std::uint64_t name = 0;       // canonical: allocation key, or the input's name
  ReadNode* readers = nullptr;  // intrusive list of live reads
  Node* writer = nullptr;       // the write of the current execution: its WriteNode, or (inline_write) the stamp it follows
  Node* keyed = nullptr;        // memo/alloc nodes whose key's first modifiable is this one
  bool input = false;
  bool written = false;
  bool dead = false;
  bool imperative = false;      // an IMod
  bool external = false;        // a traceable allocated in a run: set by its owner between runs
  bool inline_write = false;    // a memo_read destination written by its node's closure (no WriteNode)
  std::uint16_t type = 0;       // index of its ModType (set by the runtime at allocation)
  const ModType& descriptor() const { return *detail::mod_type(type); }
  std::uint64_t value_hash() const { return descriptor().value_hash(this); }  // of the current value (signature)
};

template <class T>
struct Mod : ModBase {
  T value{};
  std::uint64_t value_digest() const { return sac::value_hash(value); }
};
template <class T>
using Box = Mod<T>;  // ΔML's name

// An imperative modifiable (ΔML IBox): written any number of times in one execution; a read sees
// the latest write before it in the trace (or the initial value given at allocation).
struct IModBase : ModBase {
  IVersion first;           // the initial value's version
  IVersion* last = &first;  // the latest version in time
  IModBase() { imperative = true; }
};
template <class T>
struct IMod : IModBase {
  T initial{};
  IMod() { first.value = &initial; }
  std::uint64_t value_digest() const { return sac::value_hash(initial); }
};
template <class T>
using IBox = IMod<T>;

// An owned traceable (rt.owned): a traceable value whose owner keeps its record P in the
// modifiable and is told, by release(owner, m), when the trace node that allocated it is
// discarded while still holding it (not when a re-execution reuses it under its key). This is an
// undo hook fused into the allocation node: the same time order (release runs where the node
// is), one trace node and one stamp instead of two, and nothing to look up on reuse.
template <class T, class P>
struct OwnedMod : Mod<T> {
  static constexpr bool kOwned = true;
  P payload{};
  void (*release)(void* owner, OwnedMod* self) = nullptr;
  void* owner = nullptr;
};

inline std::uint64_t canon_key(const ModBase* m) { return m ? m->name : 0x6e696cULL; }

static_assert(sizeof(Node) == 32, "sac: Node should reuse the Stamp's tail padding");
static_assert(sizeof(ModBase) == 40 && sizeof(Mod<long long>) == 48, "sac: a modifiable carries no vtable pointer");
static_assert(sizeof(ReadNode) == 80 && sizeof(MemoNode) == 80 && sizeof(MemoReadNode) == 128 && sizeof(AllocNode) == 72 && sizeof(WriteNode) == 40 &&
              sizeof(EndNode) == 32);

// ---- statistics -------------------------------------------------------------------------------
struct Stats {
  std::uint64_t trace_nodes = 0;    // live trace nodes (reads, ends, memos, allocs, writes, hooks)
  std::uint64_t live_mods = 0;      // live modifiables allocated by the computation
  std::uint64_t input_mods = 0;     // live input modifiables
  std::uint64_t bytes = 0;          // bytes in use: nodes + closures + modifiables + OM groups + index
  std::uint64_t reads_reexecuted = 0;
  std::uint64_t memo_hits = 0;
  std::uint64_t memo_misses = 0;
  std::uint64_t allocs_reused = 0;  // keyed allocations that returned an existing modifiable
  std::uint64_t nodes_discarded = 0;
  std::uint64_t hooks_run = 0;
  std::uint64_t writes_moved_earlier = 0;  // writes that superseded a later write (§1 item 4)
  std::uint64_t fresh_allocs = 0;          // unkeyed allocations (never reused)
  std::uint64_t om_relabels = 0;
};

// ---- memory -----------------------------------------------------------------------------------
// Size-classed free lists with 8-byte classes (nodes and modifiables need no more alignment: make_node
// and make_mod check it), carved from chunks that grow from 64 KiB to 32 MiB (small runtimes stay
// small). Blocks of 1 KiB and more use operator new.
class NodePool {
 public:
  static constexpr std::size_t kClasses = 128;
  NodePool() = default;
  NodePool(const NodePool&) = delete;
  NodePool& operator=(const NodePool&) = delete;
  ~NodePool();
  static std::size_t rounded(std::size_t bytes) { return (bytes + 7) / 8 * 8; }
  void* alloc(std::size_t bytes) {
    std::size_t c = (bytes + 7) / 8;
    if (c >= kClasses) return ::operator new(bytes);
    if (void* p = free_[c]) {
      free_[c] = *static_cast<void**>(p);
      return p;
    }
    std::size_t b = c * 8;
    if (left_ < b) return refill(bytes);
    void* p = cur_;
    cur_ += b;
    left_ -= b;
    return p;
  }
  void free(void* p, std::size_t bytes) {
    std::size_t c = (bytes + 7) / 8;
    if (c >= kClasses) {
      ::operator delete(p);
      return;
    }
    *static_cast<void**>(p) = free_[c];
    free_[c] = p;
  }

 private:
  static constexpr std::size_t kMaxChunk = std::size_t{32} << 20;
  void* refill(std::size_t bytes);
  void* free_[kClasses] = {};
  char* cur_ = nullptr;
  std::size_t left_ = 0;
  std::size_t next_chunk_ = std::size_t{64} << 10;
  std::vector<std::pair<void*, std::size_t>> chunks_;  // (start, bytes): kept chunks are matched by size
};

// ---- the runtime ------------------------------------------------------------------------------
class Runtime {
 public:
  Runtime();
  ~Runtime();
  Runtime(const Runtime&) = delete;
  Runtime& operator=(const Runtime&) = delete;

  // Meta operations (outside runs): the owner's side of inputs and traceable values.
  template <class T>
  Mod<T>* input(const Label& label, std::uint64_t id, T value) {
    outside("input");
    auto* m = make_mod<Mod<T>>();
    m->name = mix(label.hash, id);
    m->input = true;
    m->written = true;
    m->value = std::move(value);
    inputs_.insert(m);
    return m;
  }
  // change(m, v): m is an input, or a traceable the computation allocated (rt.traceable).
  template <class T>
  void change(Mod<T>* m, T value) {
    outside("change");
    if (!m->input && !m->external)
      fail("change: only inputs and traceables are changed from outside a run");
    if (m->value == value) return;
    m->value = std::move(value);
    dirty(m);
  }
  void release(ModBase* m);  // frees an input that no live read depends on
  template <class T>
  const T& deref(const Mod<T>* m) const {
    if (!m->written) fail("deref of an unwritten modifiable");
    return m->value;
  }

  // The initial run: f's trace is appended to the trace. Returns f's result.
  template <class F>
  auto run(F&& f) {
    outside("run");
    Scope s(*this, om_.last(), nullptr);
    return f();
  }
  // Change propagation (§1.3.1): re-executes affected reads in time order.
  void propagate();

  // Trace operations (inside runs).
  template <class T, class F>
  void read(Mod<T>* m, F&& k) {
    inside("read");
    check_readable(m);
    using R = ReadImpl<T, std::decay_t<F>>;
    R* r = make_node<R>(std::forward<F>(k));
    append(r);
    r->mod = m;
    link_reader(r, &m->readers);
    {
      FreshScope fs(*this, static_cast<const ModBase*>(m));
      r->k(static_cast<const T&>(m->value));
    }
    r->end = append(make_node<EndNode>());
  }
  template <class T>
  void write(Mod<T>* m, T value) {
    inside("write");
    Node* w;
    if (open_ && m == open_->dest) {  // memo_read's destination, written by its own closure (never for memo_read<void>)
      // Recorded inline: the writer is the stamp the write follows (now), so reads are checked
      // against the write's exact time. A writer outside the window is this execution's.
      if (m->writer && !in_window(m->writer)) fail_written_twice(m);
      m->inline_write = true;
      w = static_cast<Node*>(now_);
    } else {
      if (check_writable(m)) {  // the write moved earlier: the later one must go before propagate ends
        m->writer->flag = true;
        ++stale_writes_;
        ++stats_.writes_moved_earlier;
      }
      m->inline_write = false;
      auto* wn = make_node<WriteNode>();
      append(wn);
      wn->mod = m;
      w = wn;
    }
    bool changed = !m->written || !(m->value == value);
    m->writer = w;
    if (changed) {
      m->value = std::move(value);
      m->written = true;
      dirty(m);
    }
  }
  // Imperative modifiables (ΔML IBox): ialloc is keyed like alloc and sets the initial value.
  template <class T, class... K>
  IMod<T>* ialloc(const Label& label, T initial, const K&... keys) {
    IMod<T>* m = alloc_impl<IMod<T>>(label, nullptr, keys...);
    if (!(m->initial == initial)) {
      m->initial = std::move(initial);
      requeue(m->first.readers);
    }
    return m;
  }
  template <class T, class F>
  void iread(IMod<T>* m, F&& k) {
    inside("iread");
    if (m->dead) fail("iread of a discarded modifiable");
    IVersion* v = m->last;
    while (v->time && OrderList::before(now_, v->time)) v = v->vprev;  // latest write at or before now
    using R = IReadImpl<T, std::decay_t<F>>;
    R* r = make_node<R>(std::forward<F>(k));
    append(r);
    r->mod = m;
    r->ver = v;
    r->flag = true;
    link_reader(r, &v->readers);
    {
      FreshScope fs(*this, static_cast<const ModBase*>(m));
      r->k(*static_cast<const T*>(v->value));
    }
    r->end = append(make_node<EndNode>());
  }
  template <class T>
  void iwrite(IMod<T>* m, T value) {
    inside("iwrite");
    if (m->dead) fail("iwrite to a discarded modifiable");
    auto* w = make_node<IWriteImpl<T>>(std::move(value));
    append(w);
    w->mod = m;
    IVersion* v = &w->version;
    v->time = w;
    v->value = &w->value;
    IVersion* p = m->last;
    while (p->time && !OrderList::before(p->time, w)) p = p->vprev;
    v->vprev = p;
    v->vnext = p->vnext;
    if (p->vnext) p->vnext->vprev = v;
    else m->last = v;
    p->vnext = v;
    // The reads of p after this write now see it.
    bool same = w->same_as_previous();
    for (ReadNode* r = p->readers; r;) {
      ReadNode* nx = r->rnext;
      if (OrderList::before(w, r)) {
        unlink_reader(r);
        static_cast<IReadNode*>(r)->ver = v;
        link_reader(r, &v->readers);
        if (!same && r->heap < 0) heap_push(r);
      }
      r = nx;
    }
  }

  template <class T, class... K>
  Mod<T>* alloc(const Label& label, const K&... keys) {
    Mod<T>* m = alloc_impl<Mod<T>>(label, nullptr, keys...);
    if (m->external) fail(std::string("allocation ") + label.name + ": key of a traceable reused by a plain allocation");
    return m;
  }
  // A traceable value created by the computation (§1 item 1; a kinetic certificate): keyed like
  // alloc (the same key inside the re-executed interval returns the same traceable, with the value
  // its owner last set); `initial` is its value when it is new. Read with rt.read; only its owner
  // changes it, with rt.change outside runs, then rt.propagate(). It is freed with its trace (the
  // owner learns of that from an undo hook registered next to it).
  template <class T, class... K>
  Mod<T>* traceable(const Label& label, T initial, const K&... keys) {
    bool reused = false;
    Mod<T>* m = alloc_impl<Mod<T>>(label, &reused, keys...);
    if (reused && !m->external) fail(std::string("traceable ") + label.name + ": key reused by a plain allocation");
    if (!reused) {
      m->external = true;
      m->written = true;
      m->value = std::move(initial);
    }
    return m;
  }
  // An owned traceable (OwnedMod; a kinetic certificate): keyed like traceable. When the key is new
  // in this execution's window, init(m) sets m->value and m->payload (the modifiable is then
  // written); when it is reused, m keeps its value and payload and init is not called.
  // release(owner, m) runs, as an undo hook would (in_undo: no trace operations), when the
  // allocation node holding m is discarded; not on ~Runtime, and not for a node whose modifiable
  // was taken over by a reusing allocation.
  template <class T, class P, class Init, class... K>
  OwnedMod<T, P>* owned(const Label& label, void* owner, void (*release)(void*, OwnedMod<T, P>*), Init&& init,
                        const K&... keys) {
    bool reused = false;
    auto* m = alloc_impl<OwnedMod<T, P>>(label, &reused, keys...);
    if (!reused) {
      m->external = true;
      init(*m);
      m->written = true;
      m->owner = owner;
      m->release = release;
    }
    return m;
  }
  // A fresh (unkeyed) allocation (ΔML Box.put's box; CEAL's modref()): any number per execution,
  // never reused by re-execution. Named canonically by (label, enclosing read or memo call, ordinal
  // among that scope's fresh allocations), so signatures of updated and from-scratch runs agree.
  template <class T>
  Mod<T>* fresh(const Label& label) {
    return fresh_impl<Mod<T>>(label);
  }
  template <class M>
  M* fresh_impl(const Label& label) {
    inside("fresh");
    auto* m = make_mod<M>();
    m->name = mix(mix(label.hash, scope_read_ ? read_scope(scope_read_) : scope_), fresh_ordinal_++);
    ++live_owned_;
    ++stats_.fresh_allocs;
    AllocNode* a = make_node<AllocNode>();
    append(a);
    a->hash = m->name;  // tag stays null: a fresh allocation, never indexed
    a->mod = m;
    return m;
  }
  template <class T>
  Mod<T>* put(const Label& label, T value) {  // ΔML `Box.put $ v`: fresh, then written
    Mod<T>* m = fresh<T>(label);
    write(m, std::move(value));
    return m;
  }
  template <class M, class... K>
  M* alloc_impl(const Label& label, bool* reused, const K&... keys) {
    inside("alloc");
    using A = AllocImpl<std::tuple<std::decay_t<K>...>>;
    static_assert(std::is_trivially_destructible_v<A>, "sac: allocation keys must be trivially destructible");
    const std::uint64_t h = alloc_name(label, keys...);
    ModBase* anchor = nullptr;
    ((anchor = anchor ? anchor : anchor_one(keys)), ...);
    std::tuple<std::decay_t<K>...> key(keys...);
    if (taken<M, A>(label, h, key, anchor))
      fail(std::string("allocation key ") + label.name + ":" + hex(h) + " used twice in one execution");
    M* m = nullptr;
    if (finger_) {
      if (A* a = find_alloc<M, A>(label, h, key, anchor)) {
        m = static_cast<M*>(a->mod);
        a->mod = nullptr;
        unindex(a);
        ++stats_.allocs_reused;
        if (reused) *reused = true;
      }
    }
    if (!m) {
      m = make_mod<M>();
      m->name = h;
      ++live_owned_;
    }
    A* a = make_node<A>(&label, std::move(key));
    append(a);
    a->hash = h;
    a->tag = tag<std::pair<M, A>>();
    a->mod = m;
    index(a, anchor);
    return m;
  }
  template <class R, class Key, class F>
  R memo(const Label& label, const Key& key, F&& body) {
    return memo_impl<MemoImpl<Key, R>, R>(label, key, [&body](MemoImpl<Key, R>*) { return body(); });
  }
  // memo with the node in hand: body(node) computes the result (memo_box allocates its
  // destination into the node before running the user's body).
  template <class M, class R, class Key, class F>
  R memo_impl(const Label& label, const Key& key, F&& body) {
    inside("memo");
    std::uint64_t h = mix(label.hash, canon_key(key));
    ModBase* anchor = anchor_of(key);
    if (finger_) {
      if (M* m = find_memo<M>(h, label, key, anchor)) {
        ++stats_.memo_hits;
        discard(now_, m);
        propagate_until(m->end);
        now_ = m->end;
        return m->result;
      }
    }
    ++stats_.memo_misses;
    M* m = make_node<M>(key);
    append(m);
    m->hash = h;
    m->label = &label;
    R result = [&] {
      FreshScope fs(*this, h);
      return body(m);
    }();
    // A body whose last trace operation was a read or memo call ends where that interval ends: the
    // memo shares its end stamp (no node of the body can follow it, and whatever discards the
    // shared stamp discards this memo too, as intervals nest).
    Node* last = static_cast<Node*>(now_);
    m->end = last->kind == Kind::End ? last : append(make_node<EndNode>());
    m->result = result;
    index(m, anchor);
    return result;
  }
  // Destination-passing memo (ΔML `mfun` returning a Box; CEAL's destination modrefs): a memoized
  // call whose result depends on reads. body(dest) writes the destination, possibly inside reads;
  // the call returns dest, a fresh allocation at the start of the call's interval, so it is reused
  // exactly when the call is. Re-executing a read inside body rewrites dest, so readers of dest see
  // results that depend on reads. (A keyed destination would add no reuse: a key found in the
  // interval being re-executed comes with its memo call, which is then reused; and keying it would
  // make two calls with one key in one execution collide, or make the choice between them depend
  // on history, which the from-scratch comparison catches.)
  // The destination lives in the memo node (one node and one stamp for call and allocation, as
  // CEAL fuses them): it is named by the call's key and freed with the call's trace.
  template <class T, class Key, class F>
  Mod<T>* memo_box(const Label& label, const Key& key, F&& body) {
    using M = MemoImpl<Key, Mod<T>*, true>;
    return memo_impl<M, Mod<T>*>(label, key, [this, &body](M* node) {
      auto* dest = make_mod<Mod<T>>();
      dest->name = mix(node->hash, 0xde57);
      ++live_owned_;
      node->result = dest;
      body(dest);
      return dest;
    });
  }
  // memo_read(label, key, src, k): memo_box whose body is one read of src (ΔML `mfun f l = Box.get l
  // (fn c => ...)`, map's loop), the same as
  //   memo_box<T>(label, key, [=](Mod<T>* d) { read(src, [=](const U& v) { k(v, d); }); })
  // but in one trace node: call, destination, read and the destination's write by k share one
  // stamp and one end (issue 8 §2). k(v, dest) is re-run when src changes; it writes dest at most
  // once directly (a write of dest inside a nested read or memo call is an ordinary write).
  // memo_read<void>(label, key, src, k): the same for `memo<Unit>(label, key, [=]{ read(src, k); ...})`
  // (a memoized call whose body is one read, with no destination): k(v) only.
  template <class T, class Key, class U, class F>
  std::conditional_t<std::is_void_v<T>, void, Mod<T>*> memo_read(const Label& label, const Key& key, Mod<U>* src,
                                                                   F&& k) {
    inside("memo");
    using M = MemoReadImpl<Key, T, U, std::decay_t<F>>;
    std::uint64_t h = mix(label.hash, canon_key(key));
    ModBase* anchor = anchor_of(key);
    if (finger_) {
      if (M* m = reuse_memo<M>(h, label, key, anchor)) {
        if constexpr (!std::is_void_v<T>) return static_cast<Mod<T>*>(m->dest);
        else return;
      }
    }
    ++stats_.memo_misses;
    check_readable(src);
    M* m = make_node<M>(key, std::forward<F>(k));
    append(m);
    m->hash = h;
    m->label = &label;
    if constexpr (!std::is_void_v<T>) {
      auto* dest = make_mod<Mod<T>>();
      dest->name = mix(h, 0xde57);  // as memo_box names it
      ++live_owned_;
      m->dest = dest;
    }
    first_run(m, src, anchor);
    if constexpr (!std::is_void_v<T>) return static_cast<Mod<T>*>(m->dest);
  }
  // Undo hook: f runs when this point of the trace is discarded (not on ~Runtime). f may take its
  // own HookId: the identity of this registration, distinct from every other hook's, so an owner
  // that registers by name can tell a discarded registration from its replacement (spec/sac.md,
  // "Undo hooks": discarded trace's hooks run after the replacing code of the same interval).
  template <class F>
  HookId on_discard(const Label& label, F&& f) {
    inside("on_discard");
    auto* h = make_node<HookImpl<std::decay_t<F>>>(std::forward<F>(f));
    h->label = &label;
    h->id = ++hook_serial_;
    append(h);
    return h->id;
  }

  // Introspection.
  std::string signature() const;  // canonical trace: one token per node, in time order
  Stats stats() const;
  bool running() const { return running_; }
  std::size_t queued() const { return heap_.size(); }
  const OrderList& order() const { return om_; }
  void reset();  // discards the whole trace (undo hooks run); inputs stay
  // Room in the key index for n keys without an anchor (allocations and memo calls keyed by plain
  // values): the table takes its size for n at once instead of doubling (and rehashing) on the
  // way. Lookup only: changes no result, signature or count (issue 9, the kinetic hull's start).
  void reserve_keys(std::size_t n);

 private:
  template <class T, class F>
  struct ReadImpl : ReadNode {
    F k;
    template <class G>
    explicit ReadImpl(G&& g) : k(std::forward<G>(g)) {}
    void rerun() override { k(static_cast<const T&>(static_cast<Mod<T>*>(mod)->value)); }
  };
  template <class Key, class R, bool Owns = false>
  struct MemoImpl : MemoNode {  // Owns: result is a destination this node allocated (memo_box)
    Key key;
    R result{};
    explicit MemoImpl(const Key& k) : key(k) { tag = &desc; }
    static std::uint64_t hash_of(const MemoNode* n) { return sac::value_hash(static_cast<const MemoImpl*>(n)->result); }
    static ModBase* owned_by(const MemoNode* n) {
      if constexpr (Owns) return static_cast<const MemoImpl*>(n)->result;
      else return nullptr;
    }
    static void destroy(MemoNode* n) { static_cast<MemoImpl*>(n)->~MemoImpl(); }
    static constexpr MemoType desc{&hash_of, &owned_by, &destroy};
  };
  template <class Keys>
  struct AllocImpl : AllocNode {  // the full key, compared on reuse (not only its hash)
    const Label* label;
    Keys keys;
    AllocImpl(const Label* l, Keys k) : label(l), keys(std::move(k)) {}
  };
  template <class Key, class T, class U, class F>
  struct MemoReadImpl : MemoReadNode {
    Key key;
    F k;
    static constexpr char desc = 0;  // its address is the tag
    template <class G>
    MemoReadImpl(const Key& key_, G&& g) : key(key_), k(std::forward<G>(g)) { tag = &desc; }
    void rerun() override {
      const U& v = static_cast<Mod<U>*>(mod)->value;
      if constexpr (std::is_void_v<T>) k(v);
      else k(v, static_cast<Mod<T>*>(dest));
    }
  };
  template <class T, class F>
  struct IReadImpl : IReadNode {
    F k;
    template <class G>
    explicit IReadImpl(G&& g) : k(std::forward<G>(g)) {}
    void rerun() override { k(*static_cast<const T*>(ver->value)); }
  };
  template <class T>
  struct IWriteImpl : IWriteNode {
    T value;
    explicit IWriteImpl(T v) : value(std::move(v)) {}
    bool same_as_previous() const override { return *static_cast<const T*>(version.vprev->value) == value; }
    std::uint64_t value_hash() const override { return sac::value_hash(value); }
  };
  template <class F>
  struct HookImpl : HookNode {
    F f;
    template <class G>
    explicit HookImpl(G&& g) : f(std::forward<G>(g)) {}
    void undo() override {
      if constexpr (std::is_invocable_v<F&, HookId>) f(id);
      else f();
    }
  };
  struct Scope {  // saves and restores (running, now, finger)
    Runtime& rt;
    bool running;
    Stamp* now;
    Stamp* finger;
    Scope(Runtime& r, Stamp* n, Stamp* f) : rt(r), running(r.running_), now(r.now_), finger(r.finger_) {
      rt.running_ = true;
      rt.now_ = n;
      rt.finger_ = f;
    }
    ~Scope() {
      rt.running_ = running;
      rt.now_ = now;
      rt.finger_ = finger;
    }
  };
  // Names fresh allocations by their enclosing read or memo call; sets open_. A read's scope name
  // read_scope(m) is computed only if a fresh allocation asks for it (scope_read_ holds m): most
  // reads allocate nothing fresh, and the mix per read was ≈ 1.5 % of the kinetic hull's initial
  // run (issue 9). The names are the same either way.
  struct FreshScope {
    Runtime& rt;
    std::uint64_t scope;
    const ModBase* scope_read;
    std::uint32_t ordinal;
    MemoReadNode* open;
    FreshScope(Runtime& r, std::uint64_t s, MemoReadNode* o = nullptr) : FreshScope(r, o) { rt.scope_ = s; }
    FreshScope(Runtime& r, const ModBase* read, MemoReadNode* o = nullptr) : FreshScope(r, o) { rt.scope_read_ = read; }
    ~FreshScope() {
      rt.scope_ = scope;
      rt.scope_read_ = scope_read;
      rt.fresh_ordinal_ = ordinal;
      rt.open_ = open;
    }

   private:
    FreshScope(Runtime& r, MemoReadNode* o)
        : rt(r), scope(r.scope_), scope_read(r.scope_read_), ordinal(r.fresh_ordinal_), open(r.open_) {
      rt.scope_read_ = nullptr;
      rt.fresh_ordinal_ = 0;
      rt.open_ = o;
    }
  };
  static std::uint64_t read_scope(const ModBase* m) { return mix(m->name, 0x52ead); }
  template <class T>
  static const void* tag() {
    static const char t = 0;
    return &t;
  }

  [[noreturn]] static void fail(const std::string& what);
  void outside(const char* op) const;
  void inside(const char* op) const {
    if (!running_ || in_undo_) inside_failed(op);
  }
  [[noreturn]] void inside_failed(const char* op) const;
  static std::string hex(std::uint64_t v);
  void check_readable(const ModBase* m) const;
  bool check_writable(const ModBase* m) const;  // true: m's write moves earlier than its current one
  bool in_window(const Stamp* s) const {  // strictly inside (now, finger)
    return finger_ && OrderList::before(now_, s) && OrderList::before(s, finger_);
  }

  void* raw_alloc(std::size_t bytes) {
    bytes_ += NodePool::rounded(bytes);
    return pool_.alloc(bytes);
  }
  void raw_free(void* p, std::size_t bytes) {
    bytes_ -= NodePool::rounded(bytes);
    pool_.free(p, bytes);
  }
  template <class N, class... A>
  N* make_node(A&&... a) {
    static_assert(alignof(N) <= 8, "sac: trace nodes (closures, keys, results) need at most 8-byte alignment");
    static_assert(sizeof(N) <= 0xffff, "sac: a trace node (closure, key, result) must be smaller than 64 KiB");
    void* p = raw_alloc(sizeof(N));
    N* n = new (p) N(std::forward<A>(a)...);
    n->bytes = static_cast<std::uint16_t>(sizeof(N));
    ++live_nodes_;
    return n;
  }
  template <class M>
  M* make_mod() {
    static_assert(alignof(M) <= 8, "sac: modifiable values need at most 8-byte alignment");
    void* p = raw_alloc(sizeof(M));
    auto* m = new (p) M();
    m->type = detail::ModTypeOf<M>::id();
    return m;
  }
  void free_node(Node* n);
  static void* destroy_node(Node* n);  // runs the destructor of n's type; returns its allocation
  void free_mod(ModBase* m);
  Node* append(Node* n) {
    om_.insert_after(now_, n);
    now_ = n;
    return n;
  }
  void link_reader(ReadNode* r, ReadNode** head);
  void requeue(ReadNode* readers);  // queues every read of a list (no consistency check)
  void unlink_reader(ReadNode* r);
  void dirty(ModBase* m);  // queues the live reads of m

  // queue of affected reads, ordered by start time
  void heap_push(ReadNode* r);
  ReadNode* heap_pop();
  void heap_erase(ReadNode* r);
  void heap_up(std::size_t i);
  void heap_down(std::size_t i);

  // key index for memo and alloc nodes (lookup only; results never depend on its order)
  static KeyLink* key_link(Node* n) {
    if (n->kind == Kind::MemoRead) return static_cast<MemoReadNode*>(static_cast<ReadNode*>(n));
    return static_cast<KeyedNode*>(n);
  }
  static const KeyLink* key_link(const Node* n) { return key_link(const_cast<Node*>(n)); }
  static void set_in_table(Node* n, bool v) {
    if (n->kind == Kind::MemoRead) static_cast<ReadNode*>(n)->in_table = v;
    else n->flag = v;
  }
  static bool in_table(const Node* n) {
    return n->kind == Kind::MemoRead ? static_cast<const ReadNode*>(n)->in_table : n->flag;
  }
  void index(Node* n, ModBase* anchor);
  void rehash(std::size_t size);  // the table's entries into `size` buckets (a power of two)
  void unindex(Node* n);
  void unindex_all(ModBase* m) {
    while (m->keyed) unindex(m->keyed);
  }
  Node* chain(std::uint64_t h, const ModBase* anchor) const {
    return anchor ? anchor->keyed : buckets_[h & (buckets_.size() - 1)];
  }
  template <class M, class A>
  static bool same_key(const Node* n, std::uint64_t h, const Label& label, const decltype(A::keys)& key) {
    if (n->kind != Kind::Alloc) return false;
    if (static_cast<const A*>(n)->hash != h || static_cast<const A*>(n)->tag != tag<std::pair<M, A>>()) return false;
    auto* a = static_cast<const A*>(n);
    return a->mod && (a->label == &label || std::strcmp(a->label->name, label.name) == 0) && a->keys == key;
  }
  // The live allocation with this full key inside (now, finger), earliest first.
  template <class M, class A>
  A* find_alloc(const Label& label, std::uint64_t h, const decltype(A::keys)& key, const ModBase* anchor) const {
    A* best = nullptr;
    for (Node* n = chain(h, anchor); n; n = key_link(n)->hnext) {
      if (!same_key<M, A>(n, h, label, key) || !in_window(n)) continue;
      if (!best || OrderList::before(n, best)) best = static_cast<A*>(n);
    }
    return best;
  }
  // A live allocation with the same full key at or before the current time belongs to this
  // execution too.
  template <class M, class A>
  bool taken(const Label& label, std::uint64_t h, const decltype(A::keys)& key, const ModBase* anchor) const {
    for (Node* n = chain(h, anchor); n; n = key_link(n)->hnext)
      if (same_key<M, A>(n, h, label, key) && (OrderList::before(n, now_) || n == now_)) return true;
    return false;
  }
  template <class M, class Key>
  M* find_memo(std::uint64_t h, const Label& label, const Key& key, const ModBase* anchor) const {
    M* best = nullptr;
    for (Node* n = chain(h, anchor); n; n = key_link(n)->hnext) {  // memo and memo-read nodes (M::kKind)
      if (n->kind != M::kKind || key_link(n)->hash != h || key_link(n)->tag != &M::desc) continue;
      auto* m = static_cast<M*>(n);
      if ((m->label != &label && std::strcmp(m->label->name, label.name) != 0) || !(m->key == key)) continue;
      if (!in_window(m) || !OrderList::before(m->end, finger_)) continue;
      if (!best || OrderList::before(m, best)) best = m;
    }
    return best;
  }

  // The memo (or memo-read) node to reuse, with the trace before it discarded and the affected reads
  // inside it propagated; null if none. Out of line: re-execution only (keeps the recursive path's
  // native frames small).
  template <class M, class Key>
  [[gnu::noinline]] M* reuse_memo(std::uint64_t h, const Label& label, const Key& key, const ModBase* anchor) {
    M* m = find_memo<M>(h, label, key, anchor);
    if (!m) return nullptr;
    ++stats_.memo_hits;
    discard(now_, m);
    propagate_until(m->end);
    now_ = m->end;
    return m;
  }
  [[noreturn, gnu::noinline, gnu::cold]] static void fail_written_twice(const ModBase* m);
  // A new memo-read node's first execution: registers the read, runs its closure, ends and indexes
  // it. Out of line and not a template, so that each level of a program's recursion through
  // memo_read adds one small fixed frame (native stack is touched memory too).
  void first_run(MemoReadNode* m, ModBase* src, ModBase* anchor);

  void rerun(ReadNode* r);
  void propagate_until(const Stamp* end);  // processes queued reads that start before end
  void discard(Stamp* from, Stamp* to);    // kills every node strictly between
  void kill(Node* n);
  void collect_dead();

  OrderList om_;
  Stamp* now_ = nullptr;
  Stamp* finger_ = nullptr;
  bool running_ = false;
  bool in_undo_ = false;
  std::uint64_t scope_ = 0;          // the enclosing read or memo call (fresh allocation names)
  const ModBase* scope_read_ = nullptr;  // the enclosing read's modifiable (its scope is read_scope of it), or null: scope_
  std::uint32_t fresh_ordinal_ = 0;  // fresh allocations so far in that scope
  std::uint64_t stale_writes_ = 0;   // live writes superseded by an earlier write
  HookId hook_serial_ = 0;
  MemoReadNode* open_ = nullptr;     // the memo_read node whose closure runs innermost (inline writes of its dest)
  std::vector<ModBase*> unwritten_;   // modifiables whose writer was discarded in this propagation
  std::vector<ReadNode*> heap_;
  std::vector<Node*> buckets_;
  std::size_t indexed_ = 0;
  std::vector<ModBase*> dead_;
  std::unordered_set<ModBase*> inputs_;  // lookup and freeing only
  std::uint64_t live_nodes_ = 0;
  std::uint64_t live_owned_ = 0;
  std::uint64_t bytes_ = 0;
  Stats stats_;
  NodePool pool_;  // frees the chunks after ~Runtime's body has run the node destructors
};

// A traceable value (§1.3.3): the computation reads it like a modifiable; its owner (e.g. the
// kinetic simulator for a certificate's outcome) sets it outside runs and then propagates.
template <class T>
class Traceable {
 public:
  // Outside a run: an input named (label, id). Inside a run: rt.traceable(label, value, id), keyed
  // and reused on re-execution like alloc (§1 item 1).
  Traceable(Runtime& rt, const Label& label, std::uint64_t id, T value)
      : rt_(&rt),
        mod_(rt.running() ? rt.traceable<T>(label, std::move(value), id) : rt.input<T>(label, id, std::move(value))) {}
  explicit Traceable(Runtime& rt, Mod<T>* m) : rt_(&rt), mod_(m) {}
  Mod<T>* mod() const { return mod_; }
  const T& get() const { return rt_->deref(mod_); }
  void set(T value) { rt_->change(mod_, std::move(value)); }

 private:
  Runtime* rt_;
  Mod<T>* mod_;
};

}  // namespace kmr::sac
