#pragma once
// A reference KDS for Chapter 4 that repairs by reconstruction: the §4.3 certificates of the current
// mesh (kmesh/certificates.hpp) are advanced lattice interval by lattice interval (δ = 2^−bits);
// when some fail in an interval (one batch), or at a dynamic insertion or deletion, the mesh is
// rebuilt from scratch (Fig. 4.2) at the end of that interval. It is NOT the update of Fig. 4.5
// (change propagation over ranks), which is not implemented; it gives the thesis's certificates,
// their events and batches, and a certified mesh at every time, against which such an update can be
// compared (spec/kmesh.md).
// Guarantees (tests/kmesh/rebuild_simulation_test.cpp):
//  * mesh_at(t) for the current time t is the current mesh moved to t, and every certificate holds at t;
//  * a batch is the set of certificates whose first failure falls in one lattice interval
//    (kδ, (k+1)δ] (failure_batch in kmesh/certificates.hpp), repaired at (k+1)δ: a certificate that
//    fails at its zero (fails_at_zero) vanishing at a lattice time is repaired there, with or without
//    a sign change, also at the horizon of run_until;
//  * collisions of two trajectories at a time in [now, T] are refused by check_collisions.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

#include "kmesh/certificates.hpp"

namespace kmr::kmesh {

struct Batch {
  Dyadic time;             // the rebuild time (end of the failing interval, or the update time)
  std::size_t events = 0;  // failing certificates in the interval (0 for an update)
  std::string what;        // "events", "insert" or "delete"
  std::size_t vertices = 0, steiner_kept = 0, steiner_before = 0;  // |M| after; Steiner positions kept
  std::uint64_t ops = 0;   // kinetic KDS (kmesh/kds.hpp): Fig. 4.5's local operations for the batch
  std::size_t affected = 0, moved = 0;  // satellites taken from the F_ℓ; nuclei relocated
  std::size_t certs_created = 0, certs_destroyed = 0;  // kinetic KDS: certificates built / dropped
};

class RebuildSimulation {
 public:
  RebuildSimulation(std::vector<InputPoint> trajectories, int lattice_bits);
  // Advances to time T (a lattice point ≥ now), processing every batch on the way; `after` is called
  // after each rebuild.
  void run_until(const Dyadic& T, const std::function<void(const Batch&)>& after = {});
  void insert(const InputPoint& p);  // at the current time
  void erase(const InputPoint& p);   // at the current time; InputError if absent
  const Dyadic& now() const { return now_; }
  const Mesh& snapshot() const { return mesh_; }          // built at snapshot_time()
  const Dyadic& snapshot_time() const { return built_at_; }
  Mesh mesh_now() const { return moved_to(mesh_, now_ - built_at_); }
  const std::vector<Certificate>& current_certificates() const { return certs_; }
  const std::vector<Batch>& batches() const { return batches_; }
  std::size_t events() const { return events_; }

 private:
  void rebuild(const std::string& what, std::size_t events);
  std::vector<InputPoint> traj_;
  int bits_;
  Dyadic now_{0}, built_at_{0};
  Mesh mesh_;
  std::vector<Certificate> certs_;
  std::vector<Batch> batches_;
  std::size_t events_ = 0;
};

// The first time in [from, to] at which two of the trajectories coincide, exactly (a rational: str()
// prints "1/3"), with their indices.
using CollisionTime = boost::multiprecision::mpq_rational;
std::optional<std::tuple<CollisionTime, std::size_t, std::size_t>> first_collision(const std::vector<InputPoint>& t,
                                                                                  const Dyadic& from, const Dyadic& to);

}  // namespace kmr::kmesh
