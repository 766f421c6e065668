#pragma once
// ListSession: one self-adjusting list program on its own runtime with an editable input, plus the
// comparisons the verification doctrine asks for (design.md: "change propagation is judged against
// from-scratch runs"). Guarantees:
//  * snapshot() reads output, trace signature and live counts without changing anything;
//  * from_scratch(program, values, ids) runs the program on a fresh runtime over an input with the
//    same element ids, so its snapshot is the one an updated session must equal;
//  * static_output() runs the static twin on the current input values.
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sacprograms/programs.hpp"

namespace kmr::sacprograms {

struct Snapshot {
  std::vector<long long> output;
  std::string signature;
  std::uint64_t trace_nodes = 0;
  std::uint64_t live_mods = 0;
  std::uint64_t bytes = 0;
};

class ListSession {
 public:
  ListSession(const ListProgram& program, const std::vector<long long>& values, std::vector<std::uint64_t> ids = {});
  void insert(std::size_t pos, long long value);  // a fresh id
  void erase(std::size_t pos);
  void set(std::size_t pos, long long value);
  void propagate() { input_->propagate(); }
  // One random edit: insert (always when empty), erase or set, at a uniform position.
  void random_edit(std::mt19937_64& rng, const std::function<long long()>& value);
  Snapshot snapshot(bool with_signature = true) const;
  std::vector<long long> values() const { return input_->values(); }
  const std::vector<std::uint64_t>& ids() const { return ids_; }
  std::vector<long long> static_output() const;
  Runtime& runtime() { return *rt_; }
  const ListProgram& program() const { return *program_; }

 private:
  const ListProgram* program_;
  std::unique_ptr<Runtime> rt_;
  std::unique_ptr<ListInput> input_;
  std::function<std::vector<long long>()> reader_;
  std::vector<std::uint64_t> ids_;
  std::uint64_t next_id_ = 1;
};

Snapshot from_scratch(const ListProgram& program, const std::vector<long long>& values,
                      const std::vector<std::uint64_t>& ids, bool with_signature = true);

}  // namespace kmr::sacprograms
