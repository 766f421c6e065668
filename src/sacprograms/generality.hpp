#pragma once
// Three small list programs in the shapes the Appendix A.2 hull needs from kmr::sac (issue 8 §1),
// each with a static twin; proptests/sac/generality_prop.cpp checks them against the twins and
// against from-scratch runs (signature and live counts) after every edit.
//  * certified_filter (§1 items 1, 2): per input cell the run creates a certificate, a traceable
//    keyed by the cell, registers it with its owner (the simulator's role) and an undo hook that
//    unregisters it; the output keeps the elements whose certificate holds. The owner flips
//    certificates between runs (CertificateOwner::flip) and propagates. Guarantee: after each
//    propagation the owner's registry holds exactly one certificate per input cell, the live one,
//    holding the owner's truth (a certificate re-created under its key survives the discard of its
//    predecessor's hook), and the hooks of one propagation ran in the trace's time order.
//  * next_greater (§1 item 3): out[i] = the first element after position i greater than in[i]
//    (kNoGreater if none), by a destination-passing memoized search (ΔML `mfun search` returning a
//    Box) whose result depends on the reads it makes. Equal elements repeat memo keys in one
//    execution, so a memo reused outside the re-executed interval shows in the trace.
//  * first_positive (§1 item 4): [the first positive element], or [the number of elements] if none,
//    the count written by a second pass after the first: inserting a positive element moves the
//    write of the output earlier than the write it replaces.
#include <cstdint>
#include <map>
#include <vector>

#include "sacprograms/list.hpp"

namespace kmr::sacprograms {

// The name ListInput gives the input cell of element `id` (for twins that key by cell).
std::uint64_t input_cell_name(std::uint64_t id);
// The owner's truth for the certificate of the cell named `name`: its last flip, else a coin.
bool certificate_truth(const std::map<std::uint64_t, bool>& flips, std::uint64_t name);

class CertificateOwner {
 public:
  struct Registration {
    Mod<bool>* cert = nullptr;
    sac::HookId hook = 0;
  };
  explicit CertificateOwner(Runtime& rt) : rt_(&rt) {}
  bool truth(std::uint64_t name) const { return certificate_truth(flips_, name); }
  // Outside runs: flips the truth and, if the certificate is live, changes it (then propagate).
  void flip(std::uint64_t name);
  void set_flips(const std::map<std::uint64_t, bool>& f) { flips_ = f; }
  const std::map<std::uint64_t, bool>& flips() const { return flips_; }
  // Called by the program (inside runs and undo hooks).
  void created(std::uint64_t name, Mod<bool>* cert, sac::HookId hook);
  void discarded(std::uint64_t name, sac::HookId self);
  const std::map<std::uint64_t, Registration>& live() const { return live_; }
  // The hooks run since the last call, in the order they ran.
  std::vector<sac::HookId> take_discards();

 private:
  Runtime* rt_;
  std::map<std::uint64_t, bool> flips_;
  std::map<std::uint64_t, Registration> live_;
  std::vector<sac::HookId> discards_;
};

Root* sa_certified_filter(Runtime& rt, Root* in, CertificateOwner* owner);
std::vector<long long> static_certified_filter(const std::vector<long long>& values,
                                               const std::vector<std::uint64_t>& ids,
                                               const std::map<std::uint64_t, bool>& flips);

constexpr long long kNoGreater = 1'000'000'000;
Root* sa_next_greater(Runtime& rt, Root* in);
std::vector<long long> static_next_greater(const std::vector<long long>& values);

Mod<long long>* sa_first_positive(Runtime& rt, Root* in);
long long static_first_positive(const std::vector<long long>& values);

}  // namespace kmr::sacprograms
