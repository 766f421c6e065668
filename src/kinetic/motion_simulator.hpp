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
//  * The machine fast path changes no decision, only its cost (spec/kinetic.md): a certificate of
//    degree ≤ 1 with coefficients |c| < 2^62 on a lattice whose horizon index is < 2^62 is kept as
//    two int64 coefficients. Its signs at lattice points are exact in __int128; its failure
//    interval floor(−c0·2^b / c1) comes from the double filter of poly/linear_root.hpp (exact
//    whenever it answers: fl(q) ∉ ℤ, |fl(q)| < 2^52) or else from an exact __int128 floor division.
//    Everything else takes the exact path (Polynomial + LatticeRootSolver), whose failure interval
//    is first asked of the double filter of poly/failure_filter.hpp (on a machine lattice; it
//    answers what next_failure_after answers, or nothing, and then Sturm decides); their signs
//    just before lattice points go through filtered_sign_at first (exact fallback).
//    The queue is lattice_queue.hpp (buckets for the next 1024 lattice intervals, a heap beyond,
//    lazy deletion); no GMP number is allocated per event on the fast path.
//  * Lazy isolation (machine cubics, issue 8/9) changes no decision either: a cubic with no root in
//    [0, ∞) (Descartes' rule on its exact coefficients) is never scheduled; one proved root-free on
//    [now, w] (poly::root_free_until: |p(now)| above a majorant of its change, w a power-of-two
//    window guessed from the exponents, capped at the horizon) gets a checkpoint entry at w instead
//    of its failure interval. next_batch resolves every checkpoint at the earliest interval k
//    before popping k (its failure is then searched from k on by the filter), so each batch
//    is exactly the set of certificates whose first failure is k; certificate() and
//    next_failure_interval() report the exact failure of a checkpointed record.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include "kinetic/lattice_queue.hpp"
#include "poly/failure_filter.hpp"
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
  // Root-solver work (spec/kinetic.md): failure intervals decided by the double filter, by the
  // exact __int128 fallback, and certificates on the exact (GMP, Sturm) path with their Sturm
  // queries; sign evaluations at lattice points on the machine path (outcomes and checks).
  long long filter_decided = 0, filter_fallbacks = 0, exact_certificates = 0;
  long long sturm_queries = 0, machine_sign_evaluations = 0;
  // Exact-path certificates (degree ≥ 2, or big coefficients) whose failure interval the double
  // filter of poly/failure_filter.hpp decided, or left to the Sturm path.
  long long poly_filter_decided = 0, poly_filter_fallbacks = 0;
  // Certificates added in machine form (add(MachinePolynomial)), and those of them that needed
  // their exact Polynomial (a filter fallback or a certificate() view).
  long long machine_polynomials = 0, machine_polynomials_exact = 0;
  // Lazy isolation of machine cubics (issue 8/9): failure intervals settled without the filter's
  // search — no root in [0, ∞) by Descartes' rule (never scheduled), or no root up to a checkpoint
  // (a queue entry that re-examines the certificate when the simulation reaches it) — and the
  // checkpoints reached.
  long long lazy_no_root = 0, lazy_deferred = 0, lazy_checkpoints_reached = 0;
};

struct SimulatorOptions {
  bool machine_fast_path = true;  // false: every certificate on the exact path (for comparisons)
  // With machine_fast_path, on a machine lattice: exact-path certificates try the double filter
  // for their failure interval (poly/failure_filter.hpp; the same decision as Sturm) first.
  bool failure_filter = true;
};

class MotionSimulator {
 public:
  // δ = 2^−lattice_bits; failures are scheduled only in intervals [kδ, (k+1)δ) with (k+1)δ ≤ horizon.
  MotionSimulator(int lattice_bits, Dyadic horizon);
  MotionSimulator(int lattice_bits, Dyadic horizon, SimulatorOptions options);

  int lattice_bits() const { return bits_; }
  const Dyadic& now() const { return now_; }
  const Dyadic& horizon() const { return horizon_; }
  const SimulatorOptions& options() const { return options_; }
  Dyadic lattice_point(const Integer& k) const { return Dyadic(k, -bits_); }

  CertificateId add(const Polynomial& p);
  // A certificate of degree ≤ 3 in machine form (the kinetic hull's cubics): on a machine lattice
  // with the failure filter on, kept without GMP (the exact Polynomial and its Sturm solver are
  // built only if the double filter leaves a query undecided); otherwise add(p.to_polynomial()).
  // Either way every outcome and failure interval is the one add(p.to_polynomial()) would give.
  CertificateId add(const poly::MachinePolynomial& p);
  // The certificate c0 + c1·t, without building a Polynomial (the fast path when it applies).
  CertificateId add_linear(std::int64_t c0, std::int64_t c1);
  void remove(CertificateId id);
  // Room for `more` further certificates (no record moves while they are added); changes nothing else.
  void reserve(std::size_t more);
  // A view of the certificate; the reference is valid until the next call on the simulator.
  const Certificate& certificate(CertificateId id) const;
  int outcome(CertificateId id) const;
  // The lattice index of now() when the fast path's lattice applies (horizon index < 2^62).
  std::optional<std::int64_t> now_index() const;

  // The next batch with (k+1)δ ≤ until, or nothing (now() unchanged) if there is none.
  std::optional<std::vector<CertificateId>> next_batch(const Dyadic& until);
  // The earliest scheduled failure interval, if any.
  std::optional<Integer> next_failure_interval() const;

  const SimulatorCounters& counters() const { return counters_; }

 private:
  // One certificate. Machine records hold c0 + c1·t; cubic records hold a MachinePolynomial (and
  // the exact Certificate once needed); the others hold the exact Certificate.
  struct Record {
    std::int64_t c0 = 0, c1 = 0;
    std::int64_t failure = 0;          // the scheduled interval, when scheduled and the lattice is small
    bool machine = false, scheduled = false;
    bool cubic = false;                // a MachinePolynomial record (small lattice only)
    poly::MachinePolynomial mp;
    bool pending = false;              // popped machine record whose rescheduling is deferred
    bool checkpoint = false;           // a cubic record whose queue entry at `failure` is a checkpoint:
                                       // no failure before it (proved), none looked for after it
    int outcome = 0;
    std::unique_ptr<Certificate> exact;
    poly::DoubleCoefficients approx;  // of exact->polynomial, for the failure filter
  };
  using Entry = LatticeQueue::Entry;  // stale once its record is gone or rescheduled
  static constexpr std::uint32_t kNoRecord = 0xffffffffu;

  CertificateId add_record(Record r);
  Record& fresh_record(CertificateId& id);  // a default record under the next id (its slot reused or new)
  Record& record(CertificateId id);
  const Record& record(CertificateId id) const;
  void schedule(Record& r, CertificateId id);
  void schedule_exact(Record& r, CertificateId id);  // the exact record's failure interval
  // A cubic record's first failure interval ≥ from (no failure in [now, from) is known), or (not
  // at a checkpoint) a checkpoint before which it has none.
  void schedule_cubic(Record& r, CertificateId id, std::int64_t from, bool at_checkpoint);
  std::optional<Integer> cubic_failure_uncounted(const Record& r) const;  // its failure, exactly
  Certificate& exact_of(Record& r);                  // a cubic record's exact Certificate, built once
  int machine_sign_before(const Record& r, std::int64_t k);  // exact sign just before kδ
  std::optional<std::int64_t> machine_failure(const Record& r);     // interval in [now, last), counted
  std::optional<std::int64_t> machine_failure_uncounted(const Record& r) const;
  void flush_pending();  // schedules the popped machine records not removed since
  bool entry_live(const Entry& e) const;
  void compact_queue();

  int bits_;
  Dyadic horizon_;
  Dyadic now_{0};
  SimulatorOptions options_;
  bool small_lattice_ = false;        // last_k_ < 2^62: int64 lattice indices and the heap queue
  std::int64_t now_k_ = 0, last_k_ = 0;
  double scale_ = 1;                  // 2^bits, for the double filter
  Integer last_k_big_;                // the last lattice index ≤ horizon
  CertificateId next_id_ = 0;
  std::vector<std::uint32_t> slot_of_id_;  // id → index into records_, or kNoRecord
  std::vector<Record> records_;
  std::vector<std::uint32_t> free_slots_;
  LatticeQueue lattice_queue_;              // (failure interval, id); lazy deletion
  long long stale_entries_ = 0;              // an upper bound: entries of records removed since compaction
  // Popped machine records are rescheduled lazily (most are removed by their structure's update
  // right away): before the next batch, or computed on demand by certificate() and
  // next_failure_interval(), which reports the same answers as eager rescheduling.
  std::vector<CertificateId> pending_;
  std::set<std::pair<Integer, CertificateId>> queue_;  // (failure interval, id), huge lattices only
  mutable std::unordered_map<CertificateId, Certificate> views_;  // certificate() of machine records
  SimulatorCounters counters_;
};

}  // namespace kmr::kinetic
