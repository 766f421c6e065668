#pragma once
// The kinetic mesh KDS of §4.3: the certificates of the current mesh (the spanner's four kinds over M
// and over the input alone, ball-empty / ball-not-empty of every conversion decision, the Delaunay
// certificates; kmesh/certificates.hpp) are advanced lattice interval by lattice interval
// (δ = 2^−bits); the certificates failing in one interval form a batch, repaired at the end of the
// interval by the update of Fig. 4.5 (kmesh/update.hpp, Updater::relocate) instead of a rebuild:
// the nuclei of the vertices of the failed certificates leave with their satellites and come back at
// their new positions, the change propagating over the ranks. Dynamic insertions and deletions of
// moving points go through the same Updater at their time. The rebuild KDS
// (kmesh/rebuild_simulation.hpp) is the reference it is compared with.
//
// Guarantees (tests/kmesh/kds_test.cpp, proptests/kmesh/kds_state_prop.cpp):
//  * L4.3.1: after the construction and after every batch and update, every certificate holds at
//    now() (so the mesh is certified until the next batch's interval);
//  * a batch is the set of certificates whose first sign change falls in one lattice interval; a
//    batch of Delaunay certificates only (no spanner or ball certificate) changes no vertex of M;
//  * mesh() passes the brute-force checks of an updated mesh (kmesh/invariants.hpp,
//    check_all_updated: spanner, U1, L4.3.2, L4.2.6, L4.2.9, L4.2.10, Delaunay, 9/2-well-spaced).
// Deviations (spec/kmesh.md): F_ℓ of a kinetic batch is every satellite of the nuclei involved
// (not only the satellites of the failed certificates), so the work per event is O(log Δ) times the
// affected nuclei; the certificates and the Delaunay stage are recomputed globally after a batch
// (O(|M|), counted apart from the local operations of Fig. 4.5).
#include <functional>
#include <optional>
#include <vector>

#include "kmesh/rebuild_simulation.hpp"
#include "kmesh/update.hpp"

namespace kmr::kmesh {

// The first lattice interval k ≥ from/δ, kδ < horizon, in which some certificate changes sign, and
// every certificate whose first sign change after `from` is that interval.
std::optional<std::pair<exact::Integer, std::vector<std::size_t>>> next_batch(const std::vector<Certificate>& certs,
                                                                             int bits, const Dyadic& from,
                                                                             const Dyadic& horizon);

class KineticMesh {
 public:
  KineticMesh(std::vector<InputPoint> trajectories, int lattice_bits);
  // Advances to time T (≥ now), processing every batch on the way; `after` is called after each.
  void run_until(const Dyadic& T, const std::function<void(const Batch&)>& after = {});
  void insert(const InputPoint& p);  // at now(); InputError (nothing changed) for a duplicate
  void erase(const InputPoint& p);   // at now(); InputError if absent or the last point
  const Dyadic& now() const { return upd_.now(); }
  const Mesh& mesh() const { return mesh_; }  // at now()
  const std::vector<Certificate>& current_certificates() const { return certs_; }
  const std::vector<Batch>& batches() const { return batches_; }
  std::size_t events() const { return events_; }
  const UpdateStats& last() const { return upd_.last(); }
  std::vector<InputPoint> trajectories() const { return mesh_.input; }

 private:
  void recertify();
  void refresh(const std::string& what, std::size_t events, std::size_t moved);
  int bits_;
  Updater upd_;
  Mesh mesh_;
  Dyadic mesh_time_{0};  // the time of mesh_'s positions
  std::vector<Certificate> certs_;  // of mesh_ and of S_N (the ρ certificates), polynomials of t − now
  std::size_t mesh_certs_ = 0;      // certs_[0, mesh_certs_) are about mesh_, the rest about S_N
  std::vector<Batch> batches_;
  std::size_t events_ = 0;
};

}  // namespace kmr::kmesh
