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
#include <cstddef>
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

  std::vector<Polynomial> x_;
  MotionSimulator& sim_;
  std::vector<std::size_t> order_;
  std::vector<CertificateId> slot_certificate_;     // slot j certifies order_[j] < order_[j+1]
  std::unordered_map<CertificateId, std::size_t> slot_of_;  // lookup only
  long long swaps_ = 0;
};

}  // namespace kmr::kinetic
