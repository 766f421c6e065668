#include "sacprograms/list.hpp"

namespace kmr::sacprograms {

namespace {
constexpr Label kRoot{"in.root"};
constexpr Label kIn{"in.cell"};
constexpr Label kNil{"in.nil"};
}  // namespace

std::vector<long long> to_vector(const Runtime& rt, const List* l) {
  std::vector<long long> out;
  for (;;) {
    const Cell& c = rt.deref(l);
    if (c.nil) break;
    out.push_back(c.head);
    l = c.tail;
  }
  return out;
}

std::vector<long long> to_vector(const Runtime& rt, const Root* r) { return to_vector(rt, rt.deref(r)); }

ListInput::ListInput(Runtime& rt, const std::vector<long long>& values, const std::vector<std::uint64_t>& ids)
    : rt_(rt) {
  KMR_CHECK(values.size() == ids.size(), "ListInput: one id per value");
  nil_ = rt.input<Cell>(kNil, 0, Cell{});
  cells_.resize(values.size());
  List* next = nil_;
  for (std::size_t i = values.size(); i-- > 0;) {
    cells_[i] = rt.input<Cell>(kIn, ids[i], Cell{false, values[i], next});
    next = cells_[i];
  }
  root_ = rt.input<List*>(kRoot, 0, next);
}

void ListInput::point(std::size_t pos, List* to) {
  if (pos == 0) {
    rt_.change(root_, to);
  } else {
    Cell c = rt_.deref(cells_[pos - 1]);
    c.tail = to;
    rt_.change(cells_[pos - 1], c);
  }
}

void ListInput::insert(std::size_t pos, std::uint64_t id, long long value) {
  if (pos > cells_.size()) throw InputError("ListInput::insert: position " + std::to_string(pos) + " past the end");
  List* next = pos < cells_.size() ? cells_[pos] : nil_;
  List* cell = rt_.input<Cell>(kIn, id, Cell{false, value, next});
  point(pos, cell);
  cells_.insert(cells_.begin() + static_cast<std::ptrdiff_t>(pos), cell);
}

void ListInput::erase(std::size_t pos) {
  if (pos >= cells_.size()) throw InputError("ListInput::erase: no element at position " + std::to_string(pos));
  List* next = pos + 1 < cells_.size() ? cells_[pos + 1] : nil_;
  point(pos, next);
  released_.push_back(cells_[pos]);
  cells_.erase(cells_.begin() + static_cast<std::ptrdiff_t>(pos));
}

void ListInput::set(std::size_t pos, long long value) {
  if (pos >= cells_.size()) throw InputError("ListInput::set: no element at position " + std::to_string(pos));
  Cell c = rt_.deref(cells_[pos]);
  c.head = value;
  rt_.change(cells_[pos], c);
}

void ListInput::propagate() {
  rt_.propagate();
  for (List* l : released_) rt_.release(l);
  released_.clear();
}

std::vector<long long> ListInput::values() const {
  std::vector<long long> v;
  v.reserve(cells_.size());
  for (const List* l : cells_) v.push_back(rt_.deref(l).head);
  return v;
}

namespace {
constexpr std::size_t kBlock = 1 << 16;
}

SArena::~SArena() {
  for (SCell* b : blocks_) delete[] b;
}

SCell* SArena::cell(long long h, SCell* t) {
  if (blocks_.empty() || used_ == kBlock) {
    blocks_.push_back(new SCell[kBlock]);
    used_ = 0;
  }
  SCell* c = &blocks_.back()[used_++];
  c->head = h;
  c->tail = t;
  return c;
}

SCell* to_slist(SArena& arena, const std::vector<long long>& v) {
  SCell* l = nullptr;
  for (std::size_t i = v.size(); i-- > 0;) l = arena.cell(v[i], l);
  return l;
}

std::vector<long long> to_vector(const SCell* l) {
  std::vector<long long> out;
  for (; l; l = l->tail) out.push_back(l->head);
  return out;
}

}  // namespace kmr::sacprograms
