#include "sac/runtime.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <new>

#include "sac/asan.hpp"

namespace kmr::sac {

// ---- memory: size-classed free lists (8-byte classes) over chunks that grow geometrically -------
namespace {
// Chunks of pools that ended, kept (up to kCacheBytes) for the next pool of the same thread: a
// runtime built and dropped again and again (the audit's kinetic hulls, best of 5) takes warm pages
// instead of faulting in fresh ones (chunks of 128 KiB and more come from mmap and go back to the
// system when freed; issue 9, spec/sac.md "Warm memory"). Plain thread-locals, readable at any
// time; the holder frees the kept chunks when the thread exits.
// Under AddressSanitizer nothing is kept: a dead runtime's chunks are freed, so a stale pointer into
// them is reported rather than reading the next runtime's nodes.
#ifdef KMR_ASAN
constexpr std::size_t kCacheBytes = 0;
#else
constexpr std::size_t kCacheBytes = std::size_t{64} << 20;
#endif
struct KeptChunks {
  struct Chunk {
    void* p;
    std::size_t bytes;
  };
  std::vector<Chunk> chunks;
  std::size_t bytes = 0;
  KeptChunks();
  ~KeptChunks();
};
// The holder's state, trivially destructible so it is readable at any time: 0 not built yet, 1 alive,
// 2 destroyed (a pool used from a later thread-exit or static destructor goes to the system).
thread_local int kept_state = 0;
thread_local KeptChunks kept;
KeptChunks::KeptChunks() { kept_state = 1; }
KeptChunks::~KeptChunks() {
  kept_state = 2;
  for (const Chunk& c : chunks) std::free(c.p);
}

void* take_chunk(std::size_t bytes) {
  if (kept_state == 2 || kCacheBytes == 0) return std::aligned_alloc(4096, bytes);
  KeptChunks& k = kept;  // (constructs this thread's holder at its first use)
  for (std::size_t i = k.chunks.size(); i-- > 0;)
    if (k.chunks[i].bytes == bytes) {
      void* p = k.chunks[i].p;
      k.chunks.erase(k.chunks.begin() + static_cast<std::ptrdiff_t>(i));
      k.bytes -= bytes;
      return p;
    }
  return std::aligned_alloc(4096, bytes);
}
void give_chunk(void* p, std::size_t bytes) {
  if (kept_state == 1 && kept.bytes + bytes <= kCacheBytes) {
    kept.chunks.push_back({p, bytes});
    kept.bytes += bytes;
  } else {
    std::free(p);
  }
}
}  // namespace

void* NodePool::refill(std::size_t bytes) {
  std::size_t size = next_chunk_;
  if (next_chunk_ < kMaxChunk) next_chunk_ *= 2;
  // (Transparent huge pages (MADV_HUGEPAGE) and MAP_POPULATE were measured on map at 10^6: neither
  // cut the system time, huge pages doubled it.)
  void* c = take_chunk(size);
  if (!c) throw std::bad_alloc();
  chunks_.push_back({c, size});
  // The rest of the old chunk goes to the free lists, so no byte is lost.
  for (std::size_t k = kClasses - 1; k > 0 && left_ >= 8; --k)
    while (left_ >= k * 8) {
      *static_cast<void**>(static_cast<void*>(cur_)) = free_[k];
      free_[k] = cur_;
      cur_ += k * 8;
      left_ -= k * 8;
    }
  cur_ = static_cast<char*>(c);
  left_ = size;
  return alloc(bytes);
}

NodePool::~NodePool() {
  for (const auto& [c, bytes] : chunks_) give_chunk(c, bytes);
}

Runtime::Runtime() : buckets_(1024, nullptr) {}

Runtime::~Runtime() {
  for (Stamp* s = om_.base()->next; s;) {
    Stamp* nx = s->next;
    Node* n = static_cast<Node*>(s);
    if (n->kind == Kind::Alloc) {
      if (ModBase* m = static_cast<AllocNode*>(n)->mod) m->descriptor().destroy(m);
    }
    if (n->kind == Kind::MemoStart) {
      if (ModBase* m = static_cast<MemoNode*>(n)->owned()) m->descriptor().destroy(m);
    }
    if (n->kind == Kind::MemoRead) {
      if (ModBase* m = static_cast<MemoReadNode*>(static_cast<ReadNode*>(n))->dest) m->descriptor().destroy(m);
    }
    destroy_node(n);
    s = nx;
  }
  for (ModBase* m : dead_) m->descriptor().destroy(m);
  for (ModBase* m : inputs_) m->descriptor().destroy(m);
}

namespace {
template <class T>
void* destroy_as(Node* n) {  // T has a virtual destructor; its object starts at the returned address
  auto* x = static_cast<T*>(n);
  x->~T();
  return x;
}
}  // namespace

void* Runtime::destroy_node(Node* n) {
  switch (n->kind) {
    case Kind::ReadStart:
    case Kind::MemoRead:
      return destroy_as<ReadNode>(n);
    case Kind::MemoStart: {
      auto* m = static_cast<MemoNode*>(n);
      m->type().destroy(m);
      return m;
    }
    case Kind::IWrite:
      return destroy_as<IWriteNode>(n);
    case Kind::Hook:
      return destroy_as<HookNode>(n);
    case Kind::Alloc:
    case Kind::Write:
    case Kind::End:
      break;  // trivially destructible, Node at offset 0
  }
  static_assert(std::is_trivially_destructible_v<AllocNode> && std::is_trivially_destructible_v<WriteNode> &&
                std::is_trivially_destructible_v<EndNode>);
  return n;
}

void Runtime::free_node(Node* n) {
  std::size_t b = n->bytes;
  void* p = destroy_node(n);
  raw_free(p, b);
  --live_nodes_;
}

void Runtime::free_mod(ModBase* m) {
  unindex_all(m);  // keys naming a freed modifiable can never match again (no address reuse)
  const ModType& t = m->descriptor();
  std::size_t b = t.bytes;
  if (!m->input) --live_owned_;
  t.destroy(m);
  raw_free(m, b);
}

// ---- modifiable types: a registry of static descriptors, indexed by 16 bits -------------------
namespace detail {
namespace {
std::mutex mod_types_mutex;
std::atomic<std::uint32_t> mod_types_count{1};  // index 0 is never given out
}  // namespace
const ModType* mod_types[std::size_t{1} << 16] = {};
std::uint16_t register_mod_type(const ModType* t) {
  std::lock_guard<std::mutex> lock(mod_types_mutex);
  std::uint32_t i = mod_types_count.load();
  KMR_CHECK(i < (std::uint32_t{1} << 16), "sac: more than 65535 modifiable types");
  mod_types[i] = t;
  mod_types_count.store(i + 1);
  return static_cast<std::uint16_t>(i);
}
}  // namespace detail

// ---- errors -----------------------------------------------------------------------------------
void Runtime::fail(const std::string& what) { throw ContractError("sac: " + what); }

void Runtime::fail_written_twice(const ModBase* m) {
  fail("modifiable " + hex(m->name) + " written twice in one execution");
}

void Runtime::outside(const char* op) const {
  if (running_) fail(std::string(op) + " during a run or change propagation");
}

void Runtime::inside_failed(const char* op) const {
  if (in_undo_) fail(std::string(op) + " inside an undo hook");
  fail(std::string(op) + " outside a run (trace operations need rt.run or propagate)");
}

std::string Runtime::hex(std::uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

void Runtime::check_readable(const ModBase* m) const {
  if (m->dead) fail("read of a discarded modifiable " + hex(m->name));
  if (m->input || m->external) return;
  // The writer at now_ is the operation just performed (a read right after its write).
  if (!m->written || !m->writer || (m->writer != now_ && !OrderList::before(m->writer, now_)))
    fail("read of modifiable " + hex(m->name) + " before it was written in this execution");
}

// A writer inside (now, finger) belongs to the trace being replaced. A writer at or after the
// finger is a later write of the previous execution: the write moves earlier (CEAL accepts it); a
// consistent program removes the later write before propagation ends (checked in propagate()).
bool Runtime::check_writable(const ModBase* m) const {
  if (m->input) fail("write to input modifiable " + hex(m->name) + " inside a run (use change outside runs)");
  if (m->external) fail("write to traceable " + hex(m->name) + " inside a run (its owner sets it with change)");
  if (m->dead) fail("write to a discarded modifiable " + hex(m->name));
  if (!m->writer || in_window(m->writer)) return false;
  // (An inline write is its memo_read node's, at or before now: a second write.)
  if (finger_ && !OrderList::before(m->writer, finger_) && !m->inline_write) return true;
  fail("modifiable " + hex(m->name) + " written twice in one execution");
}

// ---- readers and the queue of affected reads --------------------------------------------------
// The head of the reader list r is on: its modifiable's, or (an IMod read) its version's.
static ReadNode** reader_head(ReadNode* r) {
  return r->flag ? &static_cast<IReadNode*>(r)->ver->readers : &r->mod->readers;
}

void Runtime::link_reader(ReadNode* r, ReadNode** head) {
  r->rprev = nullptr;
  r->rnext = *head;
  if (*head) (*head)->rprev = r;
  *head = r;
}

void Runtime::unlink_reader(ReadNode* r) {
  if (r->rprev) r->rprev->rnext = r->rnext;
  else *reader_head(r) = r->rnext;
  if (r->rnext) r->rnext->rprev = r->rprev;
  r->rprev = r->rnext = nullptr;
}

void Runtime::requeue(ReadNode* readers) {
  for (ReadNode* r = readers; r; r = r->rnext)
    if (r->heap < 0) heap_push(r);
}

void Runtime::dirty(ModBase* m) {
  for (ReadNode* r = m->readers; r; r = r->rnext) {
    if (r->heap >= 0) continue;
    if (running_ && !OrderList::before(now_, r))
      fail("write to modifiable " + hex(m->name) +
           " affects a read earlier in the trace: the program is not consistent");
    heap_push(r);
  }
}

void Runtime::heap_up(std::size_t i) {
  ReadNode* x = heap_[i];
  while (i > 0) {
    std::size_t p = (i - 1) / 2;
    if (!OrderList::before(x, heap_[p])) break;
    heap_[i] = heap_[p];
    heap_[i]->heap = static_cast<std::int32_t>(i);
    i = p;
  }
  heap_[i] = x;
  x->heap = static_cast<std::int32_t>(i);
}

void Runtime::heap_down(std::size_t i) {
  ReadNode* x = heap_[i];
  std::size_t n = heap_.size();
  for (;;) {
    std::size_t c = 2 * i + 1;
    if (c >= n) break;
    if (c + 1 < n && OrderList::before(heap_[c + 1], heap_[c])) ++c;
    if (!OrderList::before(heap_[c], x)) break;
    heap_[i] = heap_[c];
    heap_[i]->heap = static_cast<std::int32_t>(i);
    i = c;
  }
  heap_[i] = x;
  x->heap = static_cast<std::int32_t>(i);
}

void Runtime::heap_push(ReadNode* r) {
  heap_.push_back(r);
  heap_up(heap_.size() - 1);
}

ReadNode* Runtime::heap_pop() {
  ReadNode* top = heap_[0];
  heap_erase(top);
  return top;
}

void Runtime::heap_erase(ReadNode* r) {
  std::size_t i = static_cast<std::size_t>(r->heap);
  ReadNode* last = heap_.back();
  heap_.pop_back();
  r->heap = -1;
  if (last != r) {
    heap_[i] = last;
    last->heap = static_cast<std::int32_t>(i);
    heap_up(i);
    heap_down(static_cast<std::size_t>(last->heap));
  }
}

// ---- key index --------------------------------------------------------------------------------
void Runtime::index(Node* n, ModBase* anchor) {
  KeyLink* l = key_link(n);
  if (anchor) {
    set_in_table(n, false);
    l->hnext = anchor->keyed;
    if (anchor->keyed) key_link(anchor->keyed)->hpprev = &l->hnext;
    anchor->keyed = n;
    l->hpprev = &anchor->keyed;
    return;
  }
  if (indexed_ + 1 > buckets_.size()) rehash(buckets_.size() * 2);
  Node** b = &buckets_[l->hash & (buckets_.size() - 1)];
  l->hnext = *b;
  if (*b) key_link(*b)->hpprev = &l->hnext;
  *b = n;
  l->hpprev = b;
  set_in_table(n, true);
  ++indexed_;
}

// Moves every table entry into `size` buckets (a power of two): one pass, each node relinked in
// place (chain order is lookup-only: find_alloc/find_memo pick the earliest match by time).
void Runtime::rehash(std::size_t size) {
  std::vector<Node*> old(size, nullptr);
  old.swap(buckets_);
  for (Node* head : old)
    for (Node* k = head; k;) {
      KeyLink* l = key_link(k);
      Node* nx = l->hnext;
      Node** b = &buckets_[l->hash & (size - 1)];
      l->hnext = *b;
      if (*b) key_link(*b)->hpprev = &l->hnext;
      *b = k;
      l->hpprev = b;
      k = nx;
    }
}

void Runtime::reserve_keys(std::size_t n) {
  KMR_CHECK(n <= (std::size_t{1} << 40), "sac: reserve_keys beyond 2^40 keys");
  std::size_t size = buckets_.size();
  while (size < n) size *= 2;
  if (size <= buckets_.size()) return;
  if (indexed_ == 0) buckets_.assign(size, nullptr);  // nothing to move
  else rehash(size);
}

void Runtime::unindex(Node* n) {
  KeyLink* l = key_link(n);
  if (!l->hpprev) return;
  *l->hpprev = l->hnext;
  if (l->hnext) key_link(l->hnext)->hpprev = l->hpprev;
  l->hnext = nullptr;
  l->hpprev = nullptr;
  if (in_table(n)) --indexed_;
}

// ---- change propagation (§1.3.1) --------------------------------------------------------------
void Runtime::rerun(ReadNode* r) {
  ++stats_.reads_reexecuted;
  Scope s(*this, r, r->end);
  MemoReadNode* open = nullptr;
  if (r->kind == Kind::MemoRead) {  // its inline write belongs to the execution being replaced
    open = static_cast<MemoReadNode*>(r);
    if (open->dest && open->dest->inline_write && open->dest->writer) {
      open->dest->writer = nullptr;
      unwritten_.push_back(open->dest);  // checked at the end of propagate(), as for a discarded write
    }
  }
  {
    FreshScope fs(*this, static_cast<const ModBase*>(r->mod), open);
    r->rerun();
  }
  discard(now_, r->end);  // what was not reused inside r's interval
}

void Runtime::first_run(MemoReadNode* m, ModBase* src, ModBase* anchor) {
  m->mod = src;
  link_reader(m, &src->readers);
  {
    FreshScope fs(*this, static_cast<const ModBase*>(src), m);
    m->rerun();
  }
  m->end = append(make_node<EndNode>());
  index(m, anchor);
}

void Runtime::propagate_until(const Stamp* end) {
  while (!heap_.empty() && (!end || OrderList::before(heap_[0], end))) rerun(heap_pop());
}

void Runtime::propagate() {
  outside("propagate");
  unwritten_.clear();
  {
    Scope s(*this, om_.base(), nullptr);
    propagate_until(nullptr);
  }
  if (stale_writes_ != 0)
    fail(std::to_string(stale_writes_) + " write(s) moved earlier but the later write is still in the trace: "
         "the program writes a modifiable twice in one execution");
  // A modifiable whose write re-execution removed must be written again, or be discarded, or have
  // no live reader: else a live read keeps a value no execution wrote (from scratch it would be a
  // read of an unwritten modifiable).
  for (const ModBase* m : unwritten_)
    if (!m->dead && !m->writer && !m->input && !m->external && m->readers)
      fail("modifiable " + hex(m->name) + " lost its write in re-execution but is still read by live trace");
  unwritten_.clear();
  collect_dead();
}

void Runtime::discard(Stamp* from, Stamp* to) {
  for (Stamp* s = from->next; s != to;) {
    Stamp* nx = s->next;
    kill(static_cast<Node*>(s));
    s = nx;
  }
}

void Runtime::kill(Node* n) {
  switch (n->kind) {
    case Kind::ReadStart: {
      auto* r = static_cast<ReadNode*>(n);
      unlink_reader(r);
      if (r->heap >= 0) heap_erase(r);
      break;
    }
    case Kind::MemoRead: {
      auto* r = static_cast<MemoReadNode*>(static_cast<ReadNode*>(n));
      unlink_reader(r);
      if (r->heap >= 0) heap_erase(r);
      unindex(r);
      if (ModBase* d = r->dest) {
        if (d->inline_write) d->writer = nullptr;
        d->dead = true;
        dead_.push_back(d);
      }
      break;
    }
    case Kind::MemoStart: {
      auto* memo = static_cast<MemoNode*>(n);
      unindex(memo);
      if (ModBase* m = memo->owned()) {
        m->dead = true;
        dead_.push_back(m);
      }
      break;
    }
    case Kind::Alloc: {
      auto* a = static_cast<AllocNode*>(n);
      unindex(a);
      if (ModBase* m = a->mod) {
        if (auto release = m->descriptor().release) {  // an owned traceable: its fused undo hook
          in_undo_ = true;
          try {
            release(m);
          } catch (...) {
            in_undo_ = false;
            throw;
          }
          in_undo_ = false;
          ++stats_.hooks_run;
        }
        m->dead = true;
        dead_.push_back(m);
      }
      break;
    }
    case Kind::Write: {
      auto* w = static_cast<WriteNode*>(n);
      if (w->flag) --stale_writes_;
      if (!w->mod->inline_write && w->mod->writer == w) {
        w->mod->writer = nullptr;
        if (finger_) unwritten_.push_back(w->mod);  // in re-execution: checked at the end of propagate()
      }
      break;
    }
    case Kind::IWrite: {
      // The reads of this version see the previous one again.
      auto* w = static_cast<IWriteNode*>(n);
      IVersion* v = &w->version;
      IVersion* p = v->vprev;
      bool same = w->same_as_previous();
      while (ReadNode* r = v->readers) {
        unlink_reader(r);
        static_cast<IReadNode*>(r)->ver = p;
        link_reader(r, &p->readers);
        if (!same && r->heap < 0) heap_push(r);
      }
      p->vnext = v->vnext;
      if (v->vnext) v->vnext->vprev = p;
      else static_cast<IModBase*>(w->mod)->last = p;
      break;
    }
    case Kind::Hook: {
      in_undo_ = true;
      try {
        static_cast<HookNode*>(n)->undo();
      } catch (...) {
        in_undo_ = false;
        throw;
      }
      in_undo_ = false;
      ++stats_.hooks_run;
      break;
    }
    case Kind::End:
      break;
  }
  om_.remove(n);
  free_node(n);
  ++stats_.nodes_discarded;
}

void Runtime::collect_dead() {
  for (ModBase* m : dead_) {
    KMR_CHECK(m->readers == nullptr, "sac: a discarded modifiable " + hex(m->name) + " is still read by live trace");
    KMR_CHECK(m->writer == nullptr, "sac: a discarded modifiable " + hex(m->name) + " is still written by live trace");
    if (m->imperative) {
      auto* im = static_cast<IModBase*>(m);
      KMR_CHECK(im->first.readers == nullptr && im->last == &im->first,
                "sac: a discarded imperative modifiable " + hex(m->name) + " is still read or written by live trace");
    }
    free_mod(m);
  }
  dead_.clear();
}

void Runtime::reset() {
  outside("reset");
  {
    Scope s(*this, om_.base(), nullptr);
    discard(om_.base(), nullptr);
  }
  unwritten_.clear();
  collect_dead();
}

void Runtime::release(ModBase* m) {
  outside("release");
  if (!m->input) fail("release: only input modifiables are released by their owner");
  if (m->readers) fail("release of input " + hex(m->name) + " that live trace still reads (propagate first)");
  inputs_.erase(m);
  free_mod(m);
}

// ---- introspection ----------------------------------------------------------------------------
namespace {
void put_hex(std::string& out, std::uint64_t v) {  // 16 hex digits, no temporaries
  static const char digits[] = "0123456789abcdef";
  char buf[16];
  for (int i = 15; i >= 0; --i, v >>= 4) buf[i] = digits[v & 15];
  out.append(buf, 16);
}
}  // namespace

std::string Runtime::signature() const {
  std::string out;
  out.reserve(live_nodes_ * 24);
  for (const Stamp* s = om_.base()->next; s; s = s->next) {
    const Node* n = static_cast<const Node*>(s);
    switch (n->kind) {
      case Kind::ReadStart:
        out += 'R';
        put_hex(out, static_cast<const ReadNode*>(n)->mod->name);
        break;
      case Kind::End:
        out += ')';
        break;
      case Kind::MemoRead: {  // the tokens of the memo_box call, its read and (inline) the write of its destination
        auto* m = static_cast<const MemoReadNode*>(static_cast<const ReadNode*>(n));
        out += 'M';
        out += m->label->name;
        out += ':';
        put_hex(out, m->hash);
        if (m->dest) {
          out += '=';
          put_hex(out, m->dest->name);
        }
        out += " R";
        put_hex(out, m->mod->name);
        if (m->dest && m->dest->inline_write && m->dest->writer) {
          out += " W";
          put_hex(out, m->dest->name);
          out += '=';
          put_hex(out, m->dest->value_hash());
        }
        break;
      }
      case Kind::MemoStart: {
        auto* m = static_cast<const MemoNode*>(n);
        out += 'M';
        out += m->label->name;
        out += ':';
        put_hex(out, m->hash);
        out += '=';
        put_hex(out, m->result_hash());
        break;
      }
      case Kind::Alloc: {
        auto* a = static_cast<const AllocNode*>(n);
        out += a->tag ? 'A' : 'F';
        put_hex(out, a->hash);
        if (a->mod && a->mod->external) {  // a traceable's value
          out += '=';
          put_hex(out, a->mod->value_hash());
        }
        break;
      }
      case Kind::Write: {
        const ModBase* m = static_cast<const WriteNode*>(n)->mod;
        out += 'W';
        put_hex(out, m->name);
        out += '=';
        put_hex(out, m->value_hash());
        break;
      }
      case Kind::IWrite: {
        auto* w = static_cast<const IWriteNode*>(n);
        out += 'I';
        put_hex(out, w->mod->name);
        out += '=';
        put_hex(out, w->value_hash());
        break;
      }
      case Kind::Hook:
        out += 'H';
        out += static_cast<const HookNode*>(n)->label->name;
        break;
    }
    out += ' ';
  }
  return out;
}

Stats Runtime::stats() const {
  Stats s = stats_;
  s.trace_nodes = live_nodes_;
  s.live_mods = live_owned_;
  s.input_mods = inputs_.size();
  s.bytes = bytes_ + om_.bytes() + buckets_.capacity() * sizeof(void*) + heap_.capacity() * sizeof(void*);
  s.om_relabels = om_.relabels();
  return s;
}

}  // namespace kmr::sac
