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
//  * a batch is the set of certificates whose first failure falls in one lattice interval
//    (kδ, (k+1)δ], repaired at (k+1)δ (failure_batch in kmesh/certificates.hpp: a strict certificate
//    vanishing at (k+1)δ is violated there, so it is in that batch, also when it only touches 0
//    there, and so is a triangle flat at (k+1)δ; a cocircular in-circle one is not); a batch of Delaunay
//    certificates only (no spanner or ball certificate) changes no vertex of M;
//  * mesh() passes the brute-force checks of an updated mesh (kmesh/invariants.hpp,
//    check_all_updated: spanner, U1, L4.3.2, L4.2.6, L4.2.9, L4.2.10, Delaunay, 9/2-well-spaced,
//    the rigid boundary);
//  * incremental certificates: a certificate is kept under a canonical name (kind, rank, and its
//    vertices: an input vertex by its trajectory, a Steiner vertex by its nucleus's trajectory, rank
//    and ray — never an id of mesh() nor of the Updater), with its polynomial of absolute time and
//    its isolated first failure; after a change only certificates under new names are built and
//    root-isolated, and those whose names are gone are dropped. The kept set equals the from-scratch
//    recomputation (certificates(mesh()) and S_N's) after every batch and update, except that a
//    ball-not-empty certificate keeps its witness while it stays a vertex of rank ≤ ℓ in the ball
//    (the recomputation takes the nearest vertex at now) — tested in kds_test.cpp.
// Deviations (spec/kmesh.md): F_ℓ of a kinetic batch is every satellite of the nuclei involved
// (not only the satellites of the failed certificates), so the work per event is O(log Δ) times the
// affected nuclei; the Delaunay stage is local (the vertices of the failed Delaunay certificates are
// reported to the Updater, whose voronoi_repair recomputes their stars and their neighbours'); the
// renumbering and the enumeration of the certificates' names are still global after a batch
// (O(|M|), integer work; counted apart from the local operations of Fig. 4.5); building
// polynomials and isolating roots is done for new names only.
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <vector>

#include "kmesh/invariants.hpp"
#include "kmesh/rebuild_simulation.hpp"
#include "kmesh/update.hpp"

namespace kmr::kmesh {

class KineticMesh {
 public:
  KineticMesh(std::vector<InputPoint> trajectories, int lattice_bits);
  // Advances to time T (≥ now), processing every batch on the way; `after` is called after each.
  // A batch is repaired at the end (k+1)δ of its interval and holds the certificates failing in
  // (kδ, (k+1)δ] (failure_batch: one failing at its zero, fails_at_zero, is violated at (k+1)δ if it vanishes there), so at a lattice
  // T every certificate holds at now() = T, also one failing exactly at T. T off the lattice: the
  // batch of the interval holding T is repaired at that interval's end, so now() ends after T (by
  // less than δ); with no batch there, now() = T (the CLI takes lattice times only).
  void run_until(const Dyadic& T, const std::function<void(const Batch&)>& after = {});
  void insert(const InputPoint& p);  // at now(); InputError (nothing changed) for a duplicate
  void erase(const InputPoint& p);   // at now(); InputError if absent or the last point
  const Dyadic& now() const { return upd_.now(); }
  const Mesh& mesh() const { return mesh_; }  // at now()
  // The kept certificates as polynomials of t − now, a and b the ids of mesh() (S_N's: input ids).
  std::vector<Certificate> current_certificates() const;
  // The same set recomputed from scratch (certificates(mesh()) and S_N's): the reference the
  // incremental maintenance is tested against.
  std::vector<Certificate> recomputed_certificates() const;
  std::size_t certificates_created() const { return created_; }    // by the last refresh
  std::size_t certificates_destroyed() const { return destroyed_; }
  std::size_t certificates_kept() const { return certs_.size(); }   // of M and of S_N, now
  const std::vector<Batch>& batches() const { return batches_; }
  std::size_t events() const { return events_; }
  const UpdateStats& last() const { return upd_.last(); }
  std::vector<InputPoint> trajectories() const { return mesh_.input; }

 private:
  // A certificate kept between batches (§4.3, incremental): its polynomial in absolute time t (its
  // vertices keep their motion, so it never changes while the certificate lives), the canonical
  // vertices of its two ends, and its first failure as far as isolated.
  struct Kept {
    Certificate cert;              // value: polynomial of absolute time; a, b: unused
    int end_a, end_b;              // canonical vertices (interned) of the ends named by Certificate
    bool input_spanner;            // a certificate of S_N (ends are input vertices)
    std::optional<exact::Integer> fail;  // first failing lattice interval (absolute index) ≥ searched
    Dyadic searched_from, searched_to;   // if !fail: no failure in [searched_from, searched_to)
  };
  // (kind, rank, canonical vertices…): the certificate's identity, independent of ids and history.
  using Key = std::tuple<int, Rank, int, int, int, int>;
  void recertify();
  void refresh(const std::string& what, std::size_t events, std::size_t moved);
  int intern(const InputPoint& p, Rank rank, int ray);
  // The first failing lattice interval of a kept certificate at or after now (relative to now),
  // before horizon T; isolates its roots only when the cached answer does not cover [now, T).
  void unqueue(const Key& key, const Kept& k);
  void isolate(const Key& key, Kept& k, const Dyadic& T);  // from now, far ahead; queues it
  std::optional<std::pair<exact::Integer, std::vector<const std::pair<const Key, Kept>*>>> next_failures(
      const Dyadic& T);
  int bits_;
  Updater upd_;
  Mesh mesh_, sn_mesh_;
  Dyadic mesh_time_{0};  // the time of mesh_'s positions
  std::map<Key, Kept> certs_;  // the certificates of mesh_ and of S_N
  // The event queue: kept certificates by first failure (absolute lattice index), and those with no
  // failure isolated yet by the end of the window searched (a new one: searched_to = its creation).
  std::set<std::pair<exact::Integer, Key>> queue_;
  std::set<std::pair<Dyadic, Key>> pending_;
  std::map<std::tuple<exact::Integer, exact::Integer, exact::Integer, exact::Integer, Rank, int>, int> interned_;
  std::vector<int> cv_, cv_sn_;        // mesh_ id / sn_mesh_ id → canonical vertex
  std::vector<int> mesh_id_of_;        // canonical vertex → mesh_ id (−1: not in M now)
  std::map<std::tuple<int, int, Rank>, int> witness_;  // satellite (nucleus, ray, rank) → witness
  std::vector<Batch> batches_;
  std::size_t events_ = 0;
  std::size_t created_ = 0, destroyed_ = 0;
};

// `kmr kmesh --check` (§4.3, incremental): every kept certificate holds now (L4.3.1), and the kept set
// (current_certificates) equals the recomputation from scratch on the current mesh
// (recomputed_certificates) as multisets of names: kind, rank, strictness, ends (unordered for the
// symmetric kinds, ball-empty included: |s v| named by its two vertices and the rank) and the
// polynomial up to a positive factor (which tells a Delaunay in-circle's apexes apart). A
// ball-not-empty certificate is named by its satellite (nucleus, ray, rank) only: its witness may
// differ (above), must hold now and must be eligible: an input vertex or a Steiner vertex of
// rank ≤ the satellite's. One violation per kind whose names differ, with the counts and
// a first example.
CheckResult check_kept_certificates(const KineticMesh& k);

}  // namespace kmr::kmesh
