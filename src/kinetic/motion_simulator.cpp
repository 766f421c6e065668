#include "kinetic/motion_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "exact/error.hpp"
#include "poly/linear_root.hpp"

namespace kmr::kinetic {

namespace {

constexpr std::int64_t kMachineLimit = std::int64_t{1} << 62;  // |c| and lattice indices below this

bool fits_machine(const Integer& c) { return exact::bit_length(c) <= 61; }  // |c| < 2^61 ≤ 2^62

// sign_before(p, kδ), exactly: where p(kδ) ≠ 0 it is that sign, decided by the double filter of
// filtered_sign_at (exact fallback inside); at a root, the derivatives decide (exact).
int sign_before_lattice(const Polynomial& p, const poly::DoubleCoefficients& approx, std::int64_t k, int bits) {
  if (approx.usable) {
    if (int s = poly::filtered_sign_at(p, approx, Integer(k), bits); s != 0) return s;
  }
  return poly::sign_before(p, Dyadic(Integer(k), -bits));
}

}  // namespace

MotionSimulator::MotionSimulator(int lattice_bits, Dyadic horizon)
    : MotionSimulator(lattice_bits, std::move(horizon), SimulatorOptions{}) {}

MotionSimulator::MotionSimulator(int lattice_bits, Dyadic horizon, SimulatorOptions options)
    : bits_(lattice_bits), horizon_(std::move(horizon)), options_(options) {
  if (lattice_bits < 0 || lattice_bits > 62) throw InputError("lattice bits must be in [0, 62]");
  if (horizon_.sign() < 0) throw InputError("the horizon must be >= 0");
  // A failure in interval k is processed at (k+1)δ, which must not pass the horizon: k < last.
  last_k_big_ = horizon_.shifted(bits_).floor();
  small_lattice_ = last_k_big_ < Integer(kMachineLimit);
  scale_ = std::ldexp(1.0, bits_);
  if (small_lattice_) last_k_ = static_cast<std::int64_t>(last_k_big_);
}

void MotionSimulator::reserve(std::size_t more) {
  // Geometric, so that reserving again and again (a hull rebuilt at every integrated change) stays
  // amortised O(1) per certificate instead of copying everything each time.
  auto room = [](auto& v, std::size_t need) {
    if (v.capacity() < need) v.reserve(std::max(need, 2 * v.capacity()));
  };
  room(slot_of_id_, slot_of_id_.size() + more);
  if (free_slots_.size() < more) room(records_, records_.size() + (more - free_slots_.size()));
}

MotionSimulator::Record& MotionSimulator::record(CertificateId id) {
  KMR_CHECK(id < slot_of_id_.size() && slot_of_id_[id] != kNoRecord, "unknown certificate id");
  return records_[slot_of_id_[id]];
}
const MotionSimulator::Record& MotionSimulator::record(CertificateId id) const {
  KMR_CHECK(id < slot_of_id_.size() && slot_of_id_[id] != kNoRecord, "unknown certificate id");
  return records_[slot_of_id_[id]];
}

MotionSimulator::Record& MotionSimulator::fresh_record(CertificateId& id) {
  id = next_id_++;
  std::uint32_t slot;
  if (!free_slots_.empty()) {
    slot = free_slots_.back();
    free_slots_.pop_back();
    records_[slot] = Record{};
  } else {
    slot = static_cast<std::uint32_t>(records_.size());
    records_.emplace_back();
  }
  slot_of_id_.push_back(slot);  // ids are sequential: slot_of_id_[id]
  return records_[slot];
}

CertificateId MotionSimulator::add_record(Record r) {
  CertificateId id;
  Record& slot = fresh_record(id);
  slot = std::move(r);
  schedule(slot, id);
  ++counters_.created;
  return id;
}

CertificateId MotionSimulator::add(const Polynomial& p) {
  if (p.is_zero()) throw InputError("identically zero certificate polynomial: its outcome is undefined");
  if (options_.machine_fast_path && small_lattice_ && p.degree() <= 1 &&
      std::all_of(p.coefficients().begin(), p.coefficients().end(), fits_machine))
    return add_linear(static_cast<std::int64_t>(p[0]), p.degree() == 1 ? static_cast<std::int64_t>(p[1]) : 0);
  Record r;
  r.approx = poly::double_coefficients(p);
  int outcome = options_.machine_fast_path && small_lattice_ ? sign_before_lattice(p, r.approx, now_k_, bits_) : poly::sign_before(p, now_);
  r.exact = std::make_unique<Certificate>(Certificate{p, poly::LatticeRootSolver(p, bits_), outcome, std::nullopt});
  r.outcome = outcome;
  ++counters_.exact_certificates;
  return add_record(std::move(r));
}

CertificateId MotionSimulator::add(const poly::MachinePolynomial& p) {
  if (p.is_zero()) throw InputError("identically zero certificate polynomial: its outcome is undefined");
  // Degree ≤ 1 keeps the linear machine path of add(Polynomial); off the machine lattice or without
  // the filter the exact path decides everything anyway.
  if (!(options_.machine_fast_path && options_.failure_filter && small_lattice_) || p.degree() <= 1)
    return add(p.to_polynomial());
  const int outcome = poly::sign_before_lattice(p, now_k_, bits_);
  ++counters_.machine_polynomials;
  // Built in its slot (as add_record, without a Record moved twice: one per certificate).
  CertificateId id;
  Record& r = fresh_record(id);
  r.cubic = true;
  r.mp = p;
  r.outcome = outcome;
  schedule(r, id);
  ++counters_.created;
  return id;
}

Certificate& MotionSimulator::exact_of(Record& r) {
  if (!r.exact) {
    Polynomial p = r.mp.to_polynomial();
    r.approx = poly::double_coefficients(p);
    poly::LatticeRootSolver solver(p, bits_);
    r.exact = std::make_unique<Certificate>(Certificate{std::move(p), std::move(solver), r.outcome, std::nullopt});
    if (r.scheduled) r.exact->failure = Integer(r.failure);
    ++counters_.machine_polynomials_exact;
  }
  return *r.exact;
}

CertificateId MotionSimulator::add_linear(std::int64_t c0, std::int64_t c1) {
  if (c0 == 0 && c1 == 0) throw InputError("identically zero certificate polynomial: its outcome is undefined");
  auto small = [](std::int64_t c) { return c > -kMachineLimit && c < kMachineLimit; };
  if (!options_.machine_fast_path || !small_lattice_ || !small(c0) || !small(c1))
    return add(Polynomial(std::vector<Integer>{Integer(c0), Integer(c1)}));
  Record r;
  r.machine = true;
  r.c0 = c0, r.c1 = c1;
  r.outcome = machine_sign_before(r, now_k_);
  return add_record(std::move(r));
}

void MotionSimulator::remove(CertificateId id) {
  Record& r = record(id);
  if (r.scheduled || r.checkpoint) {
    if (small_lattice_)
      ++stale_entries_;  // its queue entry is skipped when it surfaces
    else
      queue_.erase({r.exact->failure.value(), id});
  }
  r.scheduled = false;
  r.checkpoint = false;
  r.pending = false;
  r.exact.reset();
  free_slots_.push_back(slot_of_id_[id]);
  slot_of_id_[id] = kNoRecord;
  views_.erase(id);
  ++counters_.destroyed;
  if (stale_entries_ > 1024 && stale_entries_ * 2 > static_cast<long long>(lattice_queue_.size())) compact_queue();
}

const Certificate& MotionSimulator::certificate(CertificateId id) const {
  const Record& r = record(id);
  if (r.cubic) {  // a view with the exact polynomial (off the hot path)
    Polynomial p = r.mp.to_polynomial();
    std::optional<Integer> failure = cubic_failure_uncounted(r);
    poly::LatticeRootSolver solver(p, bits_);
    views_.insert_or_assign(id, Certificate{std::move(p), std::move(solver), r.outcome, std::move(failure)});
    return views_.at(id);
  }
  if (!r.machine) return *r.exact;
  // A view built on demand (off the hot path): the same polynomial and solver the exact path uses.
  Polynomial p(std::vector<Integer>{Integer(r.c0), Integer(r.c1)});
  std::optional<Integer> failure;
  if (r.scheduled) failure = Integer(r.failure);
  // A pending record is a popped linear one: its only root lay in the interval just processed, so
  // this finds no later failure (kept general; the k-found side is never taken; viewed in linear_brute_force_test).
  if (r.pending)
    if (auto k = machine_failure_uncounted(r)) failure = Integer(*k);
  poly::LatticeRootSolver solver(p, bits_);
  views_.insert_or_assign(id, Certificate{std::move(p), std::move(solver), r.outcome, std::move(failure)});
  return views_.at(id);
}

int MotionSimulator::outcome(CertificateId id) const { return record(id).outcome; }

std::optional<std::int64_t> MotionSimulator::now_index() const {
  if (!small_lattice_) return std::nullopt;
  return now_k_;
}

int MotionSimulator::machine_sign_before(const Record& r, std::int64_t k) {
  ++counters_.machine_sign_evaluations;
  return poly::linear_sign_before(r.c0, r.c1, bits_, k);
}

std::optional<std::int64_t> MotionSimulator::machine_failure_uncounted(const Record& r) const {
  if (r.c1 == 0) return std::nullopt;
  __int128 k;
  if (auto filtered = poly::linear_root_interval_filtered(r.c0, r.c1, scale_))
    k = *filtered;
  else
    k = poly::linear_root_interval_exact(r.c0, r.c1, bits_);
  if (k < now_k_ || k >= last_k_) return std::nullopt;
  return static_cast<std::int64_t>(k);
}

void MotionSimulator::flush_pending() {
  for (CertificateId id : pending_) {
    if (slot_of_id_[id] == kNoRecord) continue;  // removed meanwhile
    Record& r = records_[slot_of_id_[id]];
    if (!r.pending) continue;  // defensive, never taken: ids are pending once per batch, removal frees the slot
    r.pending = false;
    schedule(r, id);
  }
  pending_.clear();
}

std::optional<std::int64_t> MotionSimulator::machine_failure(const Record& r) {
  if (r.c1 == 0) return std::nullopt;  // a nonzero constant never fails
  // The one root −c0/c1 lies in interval k = floor(−c0·2^b / c1) (poly/linear_root.hpp: the double
  // filter, else exact __int128 division); it is a failure iff now ≤ kδ and k < last.
  __int128 k;
  if (auto filtered = poly::linear_root_interval_filtered(r.c0, r.c1, scale_)) {
    ++counters_.filter_decided;
    k = *filtered;
  } else {
    ++counters_.filter_fallbacks;
    k = poly::linear_root_interval_exact(r.c0, r.c1, bits_);
  }
  if (k < now_k_ || k >= last_k_) return std::nullopt;
  return static_cast<std::int64_t>(k);
}

void MotionSimulator::schedule(Record& r, CertificateId id) {
  r.scheduled = false;
  if (r.machine) {
    if (auto k = machine_failure(r)) {
      r.failure = *k;
      r.scheduled = true;
    }
  } else if (r.cubic) {
    schedule_cubic(r, id, now_k_, false);
    return;  // schedule_cubic pushed the queue entry
  } else {
    Certificate& c = *r.exact;
    bool decided = false;
    if (options_.machine_fast_path && options_.failure_filter && small_lattice_) {
      poly::FailureFilterResult f = poly::filtered_next_failure(c.polynomial, r.approx, bits_, now_k_, last_k_);
      if ((decided = f.decided)) {
        ++counters_.poly_filter_decided;
        c.failure.reset();
        if (f.failure) c.failure = Integer(*f.failure);
      } else {
        ++counters_.poly_filter_fallbacks;
      }
    }
    if (!decided) {
      long long before = c.solver.sturm_queries;
      c.failure = c.solver.next_failure_after(now_, lattice_point(last_k_big_));
      counters_.sturm_queries += c.solver.sturm_queries - before;
    }
    if (c.failure) {
      r.scheduled = true;
      if (small_lattice_)
        r.failure = static_cast<std::int64_t>(*c.failure);
      else
        queue_.emplace(*c.failure, id);
    }
  }
  if (r.scheduled && small_lattice_) {
    lattice_queue_.push(r.failure, id);
  }
}

void MotionSimulator::schedule_cubic(Record& r, CertificateId id, std::int64_t from, bool at_checkpoint) {
  r.scheduled = false;
  r.checkpoint = false;
  if (r.exact) r.exact->failure.reset();
  // One window per certificate (a reached checkpoint searches at once: measured, a second window
  // costs more on long runs than it saves — spec/hull.md "Lazy isolation").
  if (!at_checkpoint) {
    // Descartes: no root in [0, ∞) ⊇ [now, ∞): no failure, nothing to schedule (from ≥ now ≥ 0).
    if (poly::no_failure_from_zero(r.mp)) {
      ++counters_.lazy_no_root;
      return;
    }
    // No root in [from·δ, w·δ]: no failure in [from, w); a checkpoint at w (none at the horizon).
    if (const std::int64_t w = poly::root_free_until(r.mp, bits_, from, last_k_); w > from) {
      ++counters_.lazy_deferred;
      if (w < last_k_) {
        r.checkpoint = true;
        r.failure = w;
        lattice_queue_.push(w, id);
      }
      return;
    }
  }
  poly::FailureFilterResult f = poly::filtered_next_failure(r.mp, bits_, from, last_k_);
  if (!f.decided) {
    ++counters_.poly_filter_fallbacks;
    exact_of(r);
    schedule_exact(r, id);  // from now: the same first failure (none in [now, from))
    return;
  }
  ++counters_.poly_filter_decided;
  if (f.failure) {
    r.failure = *f.failure;
    r.scheduled = true;
    if (r.exact) r.exact->failure = Integer(*f.failure);
    lattice_queue_.push(r.failure, id);
  }
}

std::optional<Integer> MotionSimulator::cubic_failure_uncounted(const Record& r) const {
  if (!r.checkpoint) {
    if (r.scheduled) return Integer(r.failure);
    return std::nullopt;
  }
  poly::LatticeRootSolver solver(r.mp.to_polynomial(), bits_);  // off the hot path: exact
  return solver.next_failure_after(now_, lattice_point(last_k_big_));
}

void MotionSimulator::schedule_exact(Record& r, CertificateId id) {
  Certificate& c = *r.exact;
  long long before = c.solver.sturm_queries;
  c.failure = c.solver.next_failure_after(now_, lattice_point(last_k_big_));
  counters_.sturm_queries += c.solver.sturm_queries - before;
  r.scheduled = false;
  if (c.failure) {
    r.scheduled = true;
    r.failure = static_cast<std::int64_t>(*c.failure);  // cubic records live on a small lattice
    lattice_queue_.push(r.failure, id);
  }
}

bool MotionSimulator::entry_live(const Entry& e) const {
  if (e.id >= slot_of_id_.size() || slot_of_id_[e.id] == kNoRecord) return false;
  const Record& r = records_[slot_of_id_[e.id]];
  return (r.scheduled || r.checkpoint) && r.failure == e.k;  // a record is queued at most once per interval
}

void MotionSimulator::compact_queue() {
  lattice_queue_.compact([&](const Entry& e) { return entry_live(e); });
  stale_entries_ = 0;
}

std::optional<Integer> MotionSimulator::next_failure_interval() const {
  if (!small_lattice_) {
    if (queue_.empty()) return std::nullopt;
    return queue_.begin()->first;
  }
  // The earliest live entry, found without changing the queue (pending records included; a pending
  // linear record's only root was in the interval just processed, so today none of them yields one).
  std::optional<std::int64_t> best;
  for (CertificateId id : pending_)
    if (slot_of_id_[id] != kNoRecord && records_[slot_of_id_[id]].pending)
      if (auto k = machine_failure_uncounted(records_[slot_of_id_[id]]); k && (!best || *k < *best)) best = k;
  // Scheduled failures from the queue; checkpointed cubics' failures computed exactly (a scan of
  // the records: off the hot path).
  if (auto k = lattice_queue_.earliest_unchanged([&](const Entry& e) { return entry_live(e) && !records_[slot_of_id_[e.id]].checkpoint; });
      k && (!best || *k < *best))
    best = k;
  std::optional<Integer> result;
  if (best) result = Integer(*best);
  for (const Record& r : records_)
    if (r.checkpoint)
      if (auto k = cubic_failure_uncounted(r); k && (!result || *k < *result)) result = k;
  return result;
}

std::optional<std::vector<CertificateId>> MotionSimulator::next_batch(const Dyadic& until) {
  std::vector<CertificateId> batch;
  flush_pending();
  if (small_lattice_) {
    auto live = [&](const Entry& e) { return entry_live(e); };
    std::optional<std::int64_t> k;
    for (;;) {
      k = lattice_queue_.earliest(live);
      if (!k) return std::nullopt;
      // (k+1)δ > until ⇔ k + 1 > floor(until·2^b): compared as Integers once per interval. A
      // checkpoint's failure is ≥ k, so none lies before until either.
      if (Integer(*k) + 1 > until.shifted(bits_).floor()) return std::nullopt;
      // Pop interval k; the checkpoints among it look for their failure from k on (pushing it, or
      // a later checkpoint); those failing in k itself are popped by the next round.
      for (;;) {
        std::vector<CertificateId> popped;
        lattice_queue_.pop_interval(*k, live, popped);
        bool resolved = false;
        for (CertificateId id : popped) {
          Record& r = record(id);
          if (!r.checkpoint) {
            batch.push_back(id);
            continue;
          }
          ++counters_.lazy_checkpoints_reached;
          resolved = true;
          schedule_cubic(r, id, *k, true);
        }
        if (!resolved) break;
      }
      if (!batch.empty()) break;  // else: only checkpoints were at k
    }
    std::sort(batch.begin(), batch.end());
    now_k_ = *k + 1;
    lattice_queue_.advance(now_k_);
    now_ = lattice_point(Integer(now_k_));
  } else {
    if (queue_.empty()) return std::nullopt;
    Integer k = queue_.begin()->first;
    if (lattice_point(k + 1) > until) return std::nullopt;
    while (!queue_.empty() && queue_.begin()->first == k) {
      batch.push_back(queue_.begin()->second);
      queue_.erase(queue_.begin());
    }
    now_ = lattice_point(k + 1);
  }
  for (CertificateId id : batch) {
    Record& r = record(id);
    r.scheduled = false;
    r.outcome = -r.outcome;
    if (r.machine) {
      KMR_CHECK(r.outcome == machine_sign_before(r, now_k_), "a popped failure did not change the sign");
      r.pending = true;
      pending_.push_back(id);
      continue;
    } else if (r.cubic) {
      if (r.exact) {
        r.exact->failure.reset();
        r.exact->outcome = r.outcome;
      }
      KMR_CHECK(r.outcome == poly::sign_before_lattice(r.mp, now_k_, bits_), "a popped failure did not change the sign");
    } else {
      r.exact->failure.reset();
      r.exact->outcome = r.outcome;
      KMR_CHECK(r.outcome == (options_.machine_fast_path && small_lattice_ ? sign_before_lattice(r.exact->polynomial, r.approx, now_k_, bits_)
                                             : poly::sign_before(r.exact->polynomial, now_)),
                "a popped failure did not change the sign");
    }
    schedule(r, id);
  }
  auto size = static_cast<long long>(batch.size());
  counters_.events += size;
  counters_.batches += 1;
  counters_.max_batch = std::max(counters_.max_batch, size);
  counters_.batch_sizes[size] += 1;
  return batch;
}

}  // namespace kmr::kinetic
