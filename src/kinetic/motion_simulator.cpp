#include "kinetic/motion_simulator.hpp"

#include "exact/error.hpp"

namespace kmr::kinetic {

MotionSimulator::MotionSimulator(int lattice_bits, Dyadic horizon) : bits_(lattice_bits), horizon_(std::move(horizon)) {
  if (lattice_bits < 0 || lattice_bits > 62) throw InputError("lattice bits must be in [0, 62]");
  if (horizon_.sign() < 0) throw InputError("the horizon must be >= 0");
}

CertificateId MotionSimulator::add(const Polynomial& p) {
  if (p.is_zero()) throw InputError("identically zero certificate polynomial: its outcome is undefined");
  CertificateId id = next_id_++;
  int outcome = poly::sign_before(p, now_);
  certificates_.emplace(id, Certificate{p, poly::LatticeRootSolver(p, bits_), outcome, std::nullopt});
  schedule(id);
  ++counters_.created;
  return id;
}

void MotionSimulator::remove(CertificateId id) {
  unschedule(id);
  KMR_CHECK(certificates_.erase(id) == 1, "removing an unknown certificate");
  ++counters_.destroyed;
}

const Certificate& MotionSimulator::certificate(CertificateId id) const {
  auto it = certificates_.find(id);
  KMR_CHECK(it != certificates_.end(), "unknown certificate id");
  return it->second;
}

void MotionSimulator::schedule(CertificateId id) {
  Certificate& c = certificates_.at(id);
  // A failure in interval k is processed at (k+1)δ, which must not pass the horizon.
  Dyadic last_end = lattice_point(horizon_.shifted(bits_).floor());  // the last lattice point ≤ horizon
  c.failure = c.solver.next_failure_after(now_, last_end);
  if (c.failure) queue_.emplace(*c.failure, id);
}

void MotionSimulator::unschedule(CertificateId id) {
  auto it = certificates_.find(id);
  KMR_CHECK(it != certificates_.end(), "unknown certificate id");
  if (it->second.failure) queue_.erase({*it->second.failure, id});
  it->second.failure.reset();
}

std::optional<Integer> MotionSimulator::next_failure_interval() const {
  if (queue_.empty()) return std::nullopt;
  return queue_.begin()->first;
}

std::optional<std::vector<CertificateId>> MotionSimulator::next_batch(const Dyadic& until) {
  if (queue_.empty()) return std::nullopt;
  Integer k = queue_.begin()->first;
  if (lattice_point(k + 1) > until) return std::nullopt;
  std::vector<CertificateId> batch;
  while (!queue_.empty() && queue_.begin()->first == k) {
    batch.push_back(queue_.begin()->second);
    queue_.erase(queue_.begin());
  }
  now_ = lattice_point(k + 1);
  for (CertificateId id : batch) {
    Certificate& c = certificates_.at(id);
    c.failure.reset();
    c.outcome = -c.outcome;
    KMR_CHECK(c.outcome == poly::sign_before(c.polynomial, now_), "a popped failure did not change the sign");
    schedule(id);
  }
  auto size = static_cast<long long>(batch.size());
  counters_.events += size;
  counters_.batches += 1;
  counters_.max_batch = std::max(counters_.max_batch, size);
  counters_.batch_sizes[size] += 1;
  return batch;
}

}  // namespace kmr::kinetic
