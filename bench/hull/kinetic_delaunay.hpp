#pragma once
// Fig. 2.3's baseline: a kinetic 3D Delaunay triangulation of moving points, certified on kmr's
// lattice MotionSimulator (§2.1), CGAL's Delaunay_triangulation_3 rebuilt after every batch. (The
// thesis used CGAL 3.3's Kinetic package, which CGAL no longer ships.) CGAL stays in the .cpp.
//
// Guarantees:
//  * Certificates: one per facet of the triangulation with the infinite vertex ∞, the Delaunay test
//    with ∞ as a vertex (as a kinetic Delaunay KDS keeps them):
//      - finite|finite facet (cells abcd and abce): e outside the sphere of abcd, the polynomial
//        −side_of_sphere_polynomial(cell, e) (degree ≤ 5 for linear motion);
//      - finite|infinite facet (hull face abc of the finite cell abcx): orientation(abcx) > 0, so
//        that x never crosses a hull face unseen (degree ≤ 3);
//      - infinite|infinite facet (hull edge ab between hull faces abc and abe): e on the inner side
//        of the plane abc, i.e. the hull is locally convex at ab (degree ≤ 3).
//    Each is stored normalised (> 0 iff it holds) and keyed by (kind, points, sign): a key that
//    survives a rebuild keeps its simulator certificate, so only changed facets get new ones.
//  * After construction and after every update(batch), cells() is the Delaunay triangulation of the
//    points just before now() (the limit of dyadic times inside the lattice interval ending at now,
//    the convention of the kinetic hull): CGAL (exact filtered predicates on the exact integer
//    positions) rebuilds it at t = now − δ·2^−j for the smallest j ≥ 1 at which every certificate of
//    the rebuilt triangulation holds just before now — which proves it is that triangulation (all
//    facets locally Delaunay, hull locally convex, no hull face crossed). InputError when the
//    points are coplanar or two coincide at every tried time; ContractError otherwise.
//  * events = certificate failures (the simulator's count); flips = per batch, the number of
//    distinct point sets among the failed certificates (the facets of one cospherical 5-set, or the
//    hull edges of one coplanar 4-set, fail together and a flip-based KDS processes one event).
//    Flips in cascade inside one lattice interval, whose certificates are born and die in it, are
//    not seen: both counts are lower bounds on a flip-by-flip KDS's events.
//  * check_gap(a, b) rebuilds CGAL's triangulation at a time strictly inside (a, b) at which no kept
//    certificate vanishes and compares it with cells(): the independent check that no change between
//    two batches was missed (a dropped certificate shows here).
//  * Deterministic: keys and cells in sorted containers; CGAL's triangulation of points in general
//    position is unique.
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "hull/moving_points.hpp"
#include "kinetic/motion_simulator.hpp"

namespace kmr::bench {

struct KineticDelaunayCounters {
  long long events = 0, flips = 0, batches = 0;
  long long rebuilds = 0;   // CGAL triangulations built (retries included)
  long long retries = 0;    // rebuilds at j > 1 (a time nearer now: a certificate did not hold at the earlier one)
  long long certificates_created = 0;
  long long max_certificates = 0;
};

class KineticDelaunay {
 public:
  using Cell = std::array<int, 4>;  // sorted point indices
  // Key: {kind, shared points (sorted, −1 padded to 3), apexes (sorted, −1 padded to 2), sign}.
  using Key = std::array<int, 7>;

  // Builds the triangulation just before sim.now() and registers its certificates on `sim`.
  KineticDelaunay(std::vector<hull::MovingPoint> points, kinetic::MotionSimulator& sim);
  ~KineticDelaunay();
  KineticDelaunay(const KineticDelaunay&) = delete;
  KineticDelaunay& operator=(const KineticDelaunay&) = delete;

  // After sim.next_batch returned `batch`: counts it and rebuilds. Returns the batch's flips.
  long long update(const std::vector<kinetic::CertificateId>& batch);
  // "" when the kept triangulation equals CGAL's at a dyadic time strictly inside (a, b) (a < b);
  // otherwise what differs. Skipped ("") when a == b.
  std::string check_gap(const exact::Dyadic& a, const exact::Dyadic& b);

  const std::vector<Cell>& cells() const { return cells_; }
  std::size_t live_certificates() const { return ids_.size(); }
  const KineticDelaunayCounters& counters() const { return counters_; }
  // The hull vertices of the triangulation (vertices of the hull faces), increasing.
  std::vector<int> hull_vertices() const { return hull_vertices_; }

  // One triangulation as combinatorics: finite cells and the certificate keys of its facets.
  struct Snapshot {
    std::vector<Cell> cells;
    std::vector<int> hull_vertices;
    std::vector<Key> keys;  // sorted
    bool complete = false;  // false: the points at t were degenerate for CGAL (fewer than n vertices or dimension < 3)
  };

 private:
  poly::Polynomial certificate_polynomial(const Key& k) const;
  void rebuild();

  std::vector<hull::MovingPoint> points_;
  kinetic::MotionSimulator& sim_;
  std::vector<Cell> cells_;
  std::vector<int> hull_vertices_;
  std::map<Key, kinetic::CertificateId> ids_;
  std::map<kinetic::CertificateId, Key> keys_;
  std::vector<kinetic::CertificateId> last_batch_;  // during update's rebuild
  KineticDelaunayCounters counters_;
};

// The point set of a certificate key (5 points for a sphere test, 4 for an orientation test).
std::vector<int> key_points(const KineticDelaunay::Key& k);

}  // namespace kmr::bench
