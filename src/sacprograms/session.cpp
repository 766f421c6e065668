#include "sacprograms/session.hpp"

#include <algorithm>

namespace kmr::sacprograms {

ListSession::ListSession(const ListProgram& program, const std::vector<long long>& values, std::vector<std::uint64_t> ids)
    : program_(&program), rt_(std::make_unique<Runtime>()), ids_(std::move(ids)) {
  if (ids_.empty())
    for (std::size_t i = 0; i < values.size(); ++i) ids_.push_back(i + 1);
  KMR_CHECK(ids_.size() == values.size(), "ListSession: one id per value");
  for (auto id : ids_) next_id_ = std::max(next_id_, id + 1);
  input_ = std::make_unique<ListInput>(*rt_, values, ids_);
  reader_ = program.build(*rt_, input_->root());
}

void ListSession::insert(std::size_t pos, long long value) {
  input_->insert(pos, next_id_, value);
  ids_.insert(ids_.begin() + static_cast<std::ptrdiff_t>(pos), next_id_++);
}

void ListSession::erase(std::size_t pos) {
  input_->erase(pos);
  ids_.erase(ids_.begin() + static_cast<std::ptrdiff_t>(pos));
}

void ListSession::set(std::size_t pos, long long value) { input_->set(pos, value); }

void ListSession::random_edit(std::mt19937_64& rng, const std::function<long long()>& value) {
  std::size_t n = input_->size();
  int kind = n == 0 ? 0 : static_cast<int>(rng() % 3);
  if (kind == 0) insert(rng() % (n + 1), value());
  else if (kind == 1) erase(rng() % n);
  else set(rng() % n, value());
}

Snapshot ListSession::snapshot(bool with_signature) const {
  Snapshot s;
  s.output = reader_();
  if (with_signature) s.signature = rt_->signature();
  auto st = rt_->stats();
  s.trace_nodes = st.trace_nodes;
  s.live_mods = st.live_mods;
  s.bytes = st.bytes;
  return s;
}

std::vector<long long> ListSession::static_output() const {
  SArena arena;
  return program_->twin(to_slist(arena, values()), arena, nullptr);
}

Snapshot from_scratch(const ListProgram& program, const std::vector<long long>& values,
                      const std::vector<std::uint64_t>& ids, bool with_signature) {
  ListSession s(program, values, ids);
  return s.snapshot(with_signature);
}

}  // namespace kmr::sacprograms
