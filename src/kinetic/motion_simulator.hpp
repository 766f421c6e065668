#pragma once
// The robust motion simulator of §2.1: time advances on the lattice {kδ}, δ = 2^−b, and all
// certificate failures inside one lattice interval are processed together as one batch.
//
// Guarantees:
//  * A certificate's outcome at lattice time t is sign_before(p, t) (§2.1 degeneracy rule: a
//    certificate that vanishes at t takes the sign just before t). Outcomes are ±1, never 0.
//  * The queue holds nonempty lattice intervals only. next_batch pops *every* certificate whose
//    scheduled failure is the earliest interval k, flips their outcomes, advances now() to (k+1)δ,
//    and reschedules them from there; the batch lists their ids in increasing order.
//  * Every popped event is real: the certificate's sign just before kδ differs from the sign just
//    before (k+1)δ. No failure before the horizon is skipped, none after it is reported.
//  * add() refuses an identically-zero certificate polynomial with an InputError.
//  * Results do not depend on anything but the certificates added and their order of addition
//    (ids are assigned sequentially; ties in the queue are broken by id).
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include "poly/sturm.hpp"

namespace kmr::kinetic {

using exact::Dyadic;
using exact::Integer;
using poly::Polynomial;

using CertificateId = std::uint64_t;

struct Certificate {
  Polynomial polynomial;
  poly::LatticeRootSolver solver;
  int outcome;                      // ±1: the sign just before now()
  std::optional<Integer> failure;   // the scheduled failure interval k, if before the horizon
};

struct SimulatorCounters {
  long long events = 0;        // certificate failures processed
  long long batches = 0;       // lattice intervals processed
  long long max_batch = 0;
  long long created = 0, destroyed = 0;
  std::map<long long, long long> batch_sizes;  // size → number of batches of that size
  long long live() const { return created - destroyed; }
};

class MotionSimulator {
 public:
  // δ = 2^−lattice_bits; failures are scheduled only in intervals [kδ, (k+1)δ) with (k+1)δ ≤ horizon.
  MotionSimulator(int lattice_bits, Dyadic horizon);

  int lattice_bits() const { return bits_; }
  const Dyadic& now() const { return now_; }
  const Dyadic& horizon() const { return horizon_; }
  Dyadic lattice_point(const Integer& k) const { return Dyadic(k, -bits_); }

  CertificateId add(const Polynomial& p);
  void remove(CertificateId id);
  const Certificate& certificate(CertificateId id) const;
  int outcome(CertificateId id) const { return certificate(id).outcome; }

  // The next batch with (k+1)δ ≤ until, or nothing (now() unchanged) if there is none.
  std::optional<std::vector<CertificateId>> next_batch(const Dyadic& until);
  // The earliest scheduled failure interval, if any.
  std::optional<Integer> next_failure_interval() const;

  const SimulatorCounters& counters() const { return counters_; }

 private:
  void schedule(CertificateId id);
  void unschedule(CertificateId id);

  int bits_;
  Dyadic horizon_;
  Dyadic now_{0};
  CertificateId next_id_ = 0;
  std::unordered_map<CertificateId, Certificate> certificates_;  // lookup only; never iterated
  std::set<std::pair<Integer, CertificateId>> queue_;            // (failure interval, id)
  SimulatorCounters counters_;
};

}  // namespace kmr::kinetic
