#include "kinetic/kinetic_sort.hpp"

#include <algorithm>
#include <numeric>
#include <set>

#include "exact/error.hpp"

namespace kmr::kinetic {

KineticSort::KineticSort(std::vector<Polynomial> positions, MotionSimulator& simulator)
    : x_(std::move(positions)), sim_(simulator), order_(x_.size()) {
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  // Refuse identical trajectories first (canonical: by coefficients, then index).
  std::vector<std::size_t> by_coefficients = order_;
  std::sort(by_coefficients.begin(), by_coefficients.end(), [&](std::size_t a, std::size_t b) {
    const auto &ca = x_[a].coefficients(), &cb = x_[b].coefficients();
    if (ca != cb) return std::lexicographical_compare(ca.begin(), ca.end(), cb.begin(), cb.end());
    return a < b;
  });
  for (std::size_t i = 1; i < by_coefficients.size(); ++i)
    if (x_[by_coefficients[i - 1]] == x_[by_coefficients[i]])
      throw InputError("points " + std::to_string(by_coefficients[i - 1]) + " and " +
                       std::to_string(by_coefficients[i]) + " have identical trajectories; their order is undefined");
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return before(a, b); });
  slot_certificate_.resize(order_.empty() ? 0 : order_.size() - 1);
  for (std::size_t j = 0; j < slot_certificate_.size(); ++j) certify(j);
}

KineticSort::~KineticSort() {
  for (CertificateId id : slot_certificate_) sim_.remove(id);
}

bool KineticSort::before(std::size_t a, std::size_t b) const { return poly::sign_before(x_[b] - x_[a], sim_.now()) > 0; }

void KineticSort::certify(std::size_t slot) {
  CertificateId id = sim_.add(x_[order_[slot + 1]] - x_[order_[slot]]);
  slot_certificate_[slot] = id;
  slot_of_[id] = slot;
}

void KineticSort::update(const std::vector<CertificateId>& batch) {
  // Bubble repair at the new time: every out-of-order adjacent pair is swapped, and its neighbours
  // are re-examined, until the slots touched by the batch are in order (each swap removes one
  // inversion, so this ends). Slots are visited smallest first, for a canonical run.
  std::set<std::size_t> dirty, changed;
  for (CertificateId id : batch) {
    std::size_t slot = slot_of_.at(id);
    dirty.insert(slot);
    changed.insert(slot);
  }
  while (!dirty.empty()) {
    std::size_t j = *dirty.begin();
    dirty.erase(dirty.begin());
    if (!before(order_[j + 1], order_[j])) continue;
    std::swap(order_[j], order_[j + 1]);
    ++swaps_;
    changed.insert(j);
    if (j > 0) dirty.insert(j - 1), changed.insert(j - 1);
    if (j + 2 < order_.size()) dirty.insert(j + 1), changed.insert(j + 1);
  }
  for (std::size_t slot : changed) {
    CertificateId old = slot_certificate_[slot];
    slot_of_.erase(old);
    sim_.remove(old);
    certify(slot);
  }
}

void KineticSort::run_until(const Dyadic& until) {
  while (auto batch = sim_.next_batch(until)) update(*batch);
}

}  // namespace kmr::kinetic
