#pragma once
// Kinetic sorting of points moving on a line: the first kinetic structure on the motion simulator.
// Certificates are the comparisons of adjacent points (x_right − x_left > 0).
//
// Guarantees:
//  * At every lattice time t the simulator reaches, order() lists the points sorted by position
//    just before t (equivalently: by position at t, ties broken by the order just before t).
//  * update() repairs a whole batch of simultaneous failures, including several points crossing at
//    one place at one time and points that pass several neighbours within one lattice interval:
//    certificates created already-violated are repaired in the same batch (they are not events).
//  * Identical trajectories are refused with an InputError naming both points: their order would
//    be undefined, and their certificate identically zero.
//  * Linear trajectories with |coefficients| < 2^61 on a simulator with a machine lattice are
//    compared in exact __int128 arithmetic and certified with MotionSimulator::add_linear (no
//    Polynomial per event); the order, swaps and certificate ids are the same as on the exact path.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "kinetic/motion_simulator.hpp"

namespace kmr::kinetic {

class KineticSort {
 public:
  KineticSort(std::vector<Polynomial> positions, MotionSimulator& simulator);
  ~KineticSort();
  KineticSort(const KineticSort&) = delete;
  KineticSort& operator=(const KineticSort&) = delete;

  const std::vector<std::size_t>& order() const { return order_; }
  void update(const std::vector<CertificateId>& batch);
  // Runs the simulation up to `until` (a time the lattice reaches), updating after each batch.
  void run_until(const Dyadic& until);
  long long swaps() const { return swaps_; }

 private:
  bool before(std::size_t a, std::size_t b) const;  // a strictly before b just before now()
  void certify(std::size_t slot);                   // certificate for positions (slot, slot+1)
  void refresh_now();                               // caches the simulator's lattice index of now()

  std::vector<Polynomial> x_;
  MotionSimulator& sim_;
  std::vector<std::size_t> order_;
  std::vector<CertificateId> slot_certificate_;     // slot j certifies order_[j] < order_[j+1]
  std::vector<std::size_t> slot_of_;                // certificate id → slot (kNoSlot if not ours)
  // The fast path: x_[i] = x0 + v·t as int64 (x0, v), when every trajectory allows it.
  std::vector<std::pair<std::int64_t, std::int64_t>> linear_;
  std::vector<std::pair<std::int64_t, std::int64_t>> placed_;  // placed_[j] = linear_[order_[j]]
  bool machine_ = false;
  std::int64_t now_k_ = 0;
  // Scratch of update(), kept to avoid allocations: marks of dirty and changed slots.
  std::vector<char> is_dirty_, is_changed_;
  long long swaps_ = 0;
};

}  // namespace kmr::kinetic
