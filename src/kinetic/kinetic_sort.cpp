#include "kinetic/kinetic_sort.hpp"

#include <algorithm>
#include <functional>
#include <numeric>

#include "exact/error.hpp"
#include "poly/linear_root.hpp"

namespace kmr::kinetic {

namespace {
constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);

// Puts distinct marked slots in increasing order: a scan of the marks when they are dense in their
// range (large batches), else a sort.
void sort_marked(std::vector<std::size_t>& slots, const std::vector<char>& marked) {
  if (slots.empty()) return;
  auto [lo, hi] = std::minmax_element(slots.begin(), slots.end());
  std::size_t first = *lo, last = *hi;
  if (last - first < 8 * slots.size()) {
    slots.clear();
    for (std::size_t j = first; j <= last; ++j)
      if (marked[j]) slots.push_back(j);
  } else {
    std::sort(slots.begin(), slots.end());
  }
}

}  // namespace

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
  // Differences of coefficients below 2^61 stay below 2^62, within add_linear's fast path.
  machine_ = sim_.options().machine_fast_path && sim_.now_index().has_value() && std::all_of(x_.begin(), x_.end(), [](const Polynomial& p) {
               return p.degree() <= 1 && std::all_of(p.coefficients().begin(), p.coefficients().end(),
                                                     [](const Integer& c) { return exact::bit_length(c) <= 60; });
             });
  if (machine_)
    for (const auto& p : x_)
      linear_.emplace_back(p.degree() >= 0 ? static_cast<std::int64_t>(p[0]) : 0,
                           p.degree() >= 1 ? static_cast<std::int64_t>(p[1]) : 0);
  refresh_now();
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return before(a, b); });
  if (machine_)
    for (std::size_t i : order_) placed_.push_back(linear_[i]);
  is_dirty_.assign(order_.size(), 0);
  is_changed_.assign(order_.size(), 0);
  slot_certificate_.resize(order_.empty() ? 0 : order_.size() - 1);
  for (std::size_t j = 0; j < slot_certificate_.size(); ++j) certify(j);
}

KineticSort::~KineticSort() {
  for (CertificateId id : slot_certificate_) sim_.remove(id);
}

void KineticSort::refresh_now() {
  if (machine_) now_k_ = *sim_.now_index();
}

bool KineticSort::before(std::size_t a, std::size_t b) const {
  if (!machine_) return poly::sign_before(x_[b] - x_[a], sim_.now()) > 0;
  // Sign just before now = kδ of (x0b − x0a) + (vb − va)·t, exactly: 2^b·value fits __int128.
  return poly::linear_sign_before(linear_[b].first - linear_[a].first, linear_[b].second - linear_[a].second,
                                 sim_.lattice_bits(), now_k_) > 0;
}

void KineticSort::certify(std::size_t slot) {
  CertificateId id = machine_ ? sim_.add_linear(placed_[slot + 1].first - placed_[slot].first,
                                               placed_[slot + 1].second - placed_[slot].second)
                              : sim_.add(x_[order_[slot + 1]] - x_[order_[slot]]);
  slot_certificate_[slot] = id;
  if (slot_of_.size() <= id) slot_of_.resize(std::max<std::size_t>(id + 1, slot_of_.size() * 3 / 2), kNoSlot);
  slot_of_[id] = slot;
}

void KineticSort::update(const std::vector<CertificateId>& batch) {
  refresh_now();
  // Insertion-sort repair at the new time. Invariant: outside the batch's slots, adjacent pairs are
  // in order at now() (only a failed certificate can hold an out-of-order pair). From each batch slot
  // not yet covered, points are sunk leftwards into the sorted prefix, moving right while the next
  // slot is a batch slot or out of order; a region ends at a slot that is in order and not in the
  // batch, so everything left of it is sorted and separated from the sorted rest. Each swap removes
  // one inversion (swaps = inversions, as for any adjacent-swap repair); the slots whose pair a swap
  // touches are re-certified in increasing slot order, for a canonical run.
  std::vector<std::size_t> slots, changed;
  slots.reserve(batch.size());
  for (CertificateId id : batch) {
    KMR_CHECK(id < slot_of_.size() && slot_of_[id] != kNoSlot, "a batch names a certificate this sort does not own");
    slots.push_back(slot_of_[id]);
  }
  for (std::size_t j : slots) is_dirty_[j] = 1;  // batch slots
  sort_marked(slots, is_dirty_);
  auto mark_changed = [&](std::size_t j) {
    if (j + 1 < order_.size() && !is_changed_[j]) is_changed_[j] = 1, changed.push_back(j);
  };
  std::size_t covered = 0;  // slots < covered belong to a repaired region
  // out_of_order(k): order_[k] strictly before order_[k−1] just before now().
  const int bits = sim_.lattice_bits();
  const std::int64_t now = now_k_;
  auto out_of_order = [&](std::size_t k) {
    if (!machine_) return before(order_[k], order_[k - 1]);
    const auto &a = placed_[k - 1], &b = placed_[k];
    return poly::linear_sign_before(a.first - b.first, a.second - b.second, bits, now) > 0;  // x_{k−1} − x_k
  };
  for (std::size_t s : slots) {
    mark_changed(s);
    if (s < covered) continue;
    for (std::size_t pos = s + 1; pos < order_.size(); ++pos) {
      for (std::size_t k = pos; k > 0 && out_of_order(k); --k) {
        std::swap(order_[k], order_[k - 1]);
        if (machine_) std::swap(placed_[k], placed_[k - 1]);
        ++swaps_;
        if (k >= 2) mark_changed(k - 2);
        mark_changed(k - 1);
        mark_changed(k);
      }
      covered = pos;
      if (pos + 1 >= order_.size() || (!is_dirty_[pos] && !out_of_order(pos + 1))) break;
    }
  }
  for (std::size_t j : slots) is_dirty_[j] = 0;
  sort_marked(changed, is_changed_);
  for (std::size_t slot : changed) {
    is_changed_[slot] = 0;
    CertificateId old = slot_certificate_[slot];
    slot_of_[old] = kNoSlot;
    sim_.remove(old);
    certify(slot);
  }
}

void KineticSort::run_until(const Dyadic& until) {
  while (auto batch = sim_.next_batch(until)) update(*batch);
}

}  // namespace kmr::kinetic
