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
  List* next = nil_;
  std::vector<List*> cells(values.size());
  for (std::size_t i = values.size(); i-- > 0;) {
    cells[i] = rt.input<Cell>(kIn, ids[i], Cell{false, values[i], next});
    next = cells[i];
  }
  root_ = rt.input<List*>(kRoot, 0, next);
  for (std::size_t i = 0; i < cells.size(); ++i) add(cells[i], i ? cells[i - 1] : nullptr);
}

void ListInput::add(List* cell, List* pred) {
  where_[cell] = pool_.size();
  pool_.push_back(cell);
  prev_[cell] = pred;
}

void ListInput::point(List* pred, List* to) {
  if (!pred) {
    rt_.change(root_, to);
  } else {
    Cell c = rt_.deref(pred);
    c.tail = to;
    rt_.change(pred, c);
  }
  if (to != nil_) prev_[to] = pred;
}

List* ListInput::insert_after(List* pred, std::uint64_t id, long long value) {
  List* next = pred ? rt_.deref(pred).tail : rt_.deref(root_);
  List* cell = rt_.input<Cell>(kIn, id, Cell{false, value, next});
  add(cell, pred);
  point(pred, cell);
  if (next != nil_) prev_[next] = cell;
  return cell;
}

void ListInput::erase(List* cell) {
  auto w = where_.find(cell);
  if (w == where_.end()) throw InputError("ListInput::erase: not a live cell");
  List* pred = prev_.at(cell);
  point(pred, rt_.deref(cell).tail);
  std::size_t i = w->second;
  pool_[i] = pool_.back();
  where_[pool_[i]] = i;
  pool_.pop_back();
  where_.erase(cell);
  prev_.erase(cell);
  released_.push_back(cell);
}

void ListInput::set(List* cell, long long value) {
  Cell c = rt_.deref(cell);
  c.head = value;
  rt_.change(cell, c);
}

List* ListInput::cell_at(std::size_t pos) const {
  if (pos >= pool_.size()) throw InputError("ListInput: no element at position " + std::to_string(pos));
  List* l = rt_.deref(root_);
  for (; pos > 0; --pos) l = rt_.deref(l).tail;
  return l;
}

List* ListInput::random_cell(std::uint64_t r) const {
  if (pool_.empty()) throw InputError("ListInput::random_cell: the list is empty");
  return pool_[r % pool_.size()];
}

void ListInput::insert(std::size_t pos, std::uint64_t id, long long value) {
  if (pos > pool_.size()) throw InputError("ListInput::insert: position " + std::to_string(pos) + " past the end");
  insert_after(pos ? cell_at(pos - 1) : nullptr, id, value);
}

void ListInput::erase(std::size_t pos) { erase(cell_at(pos)); }
void ListInput::set(std::size_t pos, long long value) { set(cell_at(pos), value); }

void ListInput::propagate() {
  rt_.propagate();
  for (List* l : released_) rt_.release(l);
  released_.clear();
}

std::vector<long long> ListInput::values() const { return to_vector(rt_, root_); }

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
