#pragma once
// Independent oracles for thesis Chapter 3 (well-spaced point sets), CGAL-free interface.
//
// Guarantees (every decision below is exact; doubles appear only in reports):
//  * Points are exact dyadics (kmr::exact::Dyadic) or doubles (converted exactly). The domain is
//    Ω = [0,1]^D; points outside Ω, duplicate points and sets of fewer than two points are refused
//    with kmr::InputError.
//  * Delaunay neighbours come from CGAL (Delaunay_triangulation_2/3 over Epeck, dD Delaunay over
//    Epeck_d for D = 4), in a separate translation unit. Everything else is this library's own
//    exact rational arithmetic (GMP mpq), independent of the library under test and of CGAL's
//    Voronoi code: the Voronoi cell of v clipped to Ω is the box Ω cut, one exact half-space at a
//    time, by the bisector of v and each Delaunay neighbour (§3.1.1: Vor_M(v) ⊂ Ω).
//  * ρ is given through ρ² as an exact rational (Rho), so ρ = √2 is exact as well as ρ = 3/2.
//  * judge_well_spaced: v is ρ-well-spaced iff max_{x ∈ Vor(v) ∩ Ω} |vx| ≤ ρ·NN(v) (§3.1.1,
//    Talmor); the maximum of |vx| over a polytope is attained at a vertex, so the comparison
//    R_v² ≤ ρ²·NN(v)² over exact rationals is the exact answer.
//  * judge_size_conforming: c·NN_M(v) ≥ lfs(v) with c = 2ρ/(ρ−1) (Lemma 3.3.3), lfs(v) the distance
//    from v to the second-nearest input point (a point of N at v itself counts as the nearest);
//    decided exactly from ρ², NN² and lfs² (no square root is rounded).
//  * beta_clipped_voronoi_neighbors: u is a β-clipped Voronoi neighbour of v iff the β-clipped
//    cell Vor(v) ∩ B(v, β·NN(v)) contains a point equidistant from v and u (§3.1.1), i.e. the
//    Voronoi face F_u = Vor(v) ∩ bisector(v,u) is nonempty and dist(v, F_u) ≤ β·NN(v) (or < with
//    strict). A face touching the cell in a single point (cocircular inputs) counts. D = 2, 3, 4.
//    Candidates are all sites within 2β·NN(v) of v, gathered by a search of CGAL's Delaunay graph
//    (so sites that touch the cell but are not edges of CGAL's chosen triangulation are found).
//    dist(v, F_u) is exact: in 2D/3D the midpoint of uv, a vertex or an edge point of F_u; in 4D
//    (and on request in 2D/3D) the least of the KKT points, the projections of v onto the affine
//    hulls of the faces of F_u that lie in the cell (see FaceDistance).
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "exact/dyadic.hpp"

namespace kmr::oracle::ws {

template <std::size_t D>
using XPoint = std::array<exact::Dyadic, D>;  // exact point
template <std::size_t D>
using DPoint = std::array<double, D>;  // convenience input, converted exactly

template <std::size_t D>
std::vector<XPoint<D>> to_exact(const std::vector<DPoint<D>>& pts);

// A hex float "[+-]0x<hex>[.<hex>]p[+-]<dec>" read exactly, any number of digits (`kmr wellspaced`
// prints coordinates finer than doubles this way, spec/formats.md); nullopt if text is not one.
// Its own digit loop (shares nothing with the library's writer, VertexPoint::text).
std::optional<exact::Dyadic> parse_hex_exact(const std::string& text);

// ρ given by its square, an exact rational num/den (num, den > 0).
struct Rho {
  exact::Dyadic sq_num{1}, sq_den{1};
  static Rho exactly(const exact::Dyadic& rho) { return {rho * rho, exact::Dyadic(1)}; }
  static Rho sqrt_of(const exact::Dyadic& rho_squared) { return {rho_squared, exact::Dyadic(1)}; }
  static Rho ratio(const exact::Dyadic& p, const exact::Dyadic& q) { return {p * p, q * q}; }
  double approx() const;  // for reports
};

struct WellSpacedReport {
  bool ok = false;                 // every vertex ρ-well-spaced (exact)
  std::size_t vertices = 0;
  std::size_t violations = 0;      // vertices with R_v > ρ·NN(v)
  std::size_t worst_vertex = 0;    // argmax of R_v / NN(v)
  double worst_ratio = 0;          // max_v R_v / NN(v) (rounded, report only)
  std::string worst_ratio_sq;      // the same maximum squared, exact rational text "p/q"
  std::vector<double> ratio;       // R_v / NN(v) per vertex (report only)
};

struct SizeConformingReport {
  bool ok = false;                 // c·NN_M(v) ≥ lfs(v) for every output vertex v (exact)
  std::size_t vertices = 0;
  std::size_t violations = 0;
  std::size_t worst_vertex = 0;    // argmax of lfs(v) / NN_M(v)
  double worst_ratio = 0;          // max_v lfs(v) / NN_M(v) (report only)
  double c = 0;                    // 2ρ/(ρ−1) (report only)
  std::string worst_ratio_sq;      // exact max of lfs²/NN², "p/q"
};

// Options of the β-clipped neighbourhood. The thesis definition (§3.1.1) is the default: Vor(v)
// restricted to Ω, the closed ball of radius β·NN(v). The scan of Fig. 3.6 reaches u when the
// smallest empty ball through v and u has diameter < β·NN(v): pass β/2 and strict = true, and
// clip_to_domain = false (the certificate-ball centres of Fig. 3.6 are not confined to Ω).
// How dist(v, F_u) is computed (all exact; Auto: Edges23 for D = 2, 3, KktFaceVertices for D = 4).
//  Edges23: the midpoint of uv if it lies in the cell, else the nearest vertex or edge point of F_u.
//  KktFaceVertices: the vertices of F_u and the projections of v onto {bisector} ∪ T that lie in
//    the cell, T ⊆ the planes through one vertex of F_u, |T| ≤ D − 2, independent rows.
//  KktAllFacePlanes: the projections onto {bisector} ∪ T, T ⊆ all planes meeting F_u, |T| ≤ D − 1
//    (slow; a self-test of the other two).
enum class FaceDistance { Auto, Edges23, KktFaceVertices, KktAllFacePlanes };
struct BetaOptions {
  bool clip_to_domain = true;
  bool strict = false;
  bool brute_force = false;  // candidates: every other site (self-tests of the oracle)
  FaceDistance face_distance = FaceDistance::Auto;
};

// Per-vertex exact geometry of one point set: Delaunay neighbours (CGAL), NN², clipped cells.
template <std::size_t D>
class CellOracle {
 public:
  explicit CellOracle(std::vector<XPoint<D>> points);  // throws InputError (see above)
  ~CellOracle();
  CellOracle(CellOracle&&) noexcept;
  CellOracle& operator=(CellOracle&&) noexcept;

  std::size_t size() const;
  const std::vector<std::uint32_t>& delaunay_neighbors(std::size_t v) const;  // sorted
  std::uint32_t nearest_neighbor(std::size_t v) const;   // smallest index among the nearest
  std::string nn_squared(std::size_t v) const;           // exact "p/q"
  std::string far_squared(std::size_t v) const;          // R_v², exact "p/q"
  // ρ-well-spacedness of one vertex (exact).
  bool well_spaced(std::size_t v, const Rho& rho) const;
  // β-clipped Voronoi neighbours of v (sorted indices). D = 2, 3, 4.
  std::vector<std::uint32_t> beta_neighbors(std::size_t v, const exact::Dyadic& beta,
                                            BetaOptions opt = {}) const;
  // Same with β given by β² = num/den (e.g. β = √2).
  std::vector<std::uint32_t> beta_neighbors_sq(std::size_t v, const exact::Dyadic& beta_sq_num,
                                               const exact::Dyadic& beta_sq_den,
                                               BetaOptions opt = {}) const;
  // Exact dist(v, F_u)² ("p/q") for every candidate u (|uv| ≤ 2β·NN(v)) whose face F_u is
  // nonempty, sorted by u; for self-tests of the face distance methods.
  std::vector<std::pair<std::uint32_t, std::string>> face_distances_squared(
      std::size_t v, const exact::Dyadic& beta, BetaOptions opt = {}) const;
  // R_v² computed by clipping with ALL other points' bisectors (O(n) per vertex): an oracle for
  // the oracle, independent of CGAL; for small sets in self-tests.
  std::string far_squared_brute_force(std::size_t v) const;

  struct Impl;
  const Impl& impl() const { return *impl_; }  // for the judges in ws_oracle.cpp

 private:
  std::unique_ptr<Impl> impl_;
};

template <std::size_t D>
WellSpacedReport judge_well_spaced(const std::vector<XPoint<D>>& points, const Rho& rho);

// Lemma 3.3.3: output ⊇ input is required (checked; refused with InputError otherwise).
template <std::size_t D>
SizeConformingReport judge_size_conforming(const std::vector<XPoint<D>>& output,
                                           const std::vector<XPoint<D>>& input, const Rho& rho);

// lfs(x)² with respect to `input` for each query (exact "p/q"); input needs ≥ 2 points.
template <std::size_t D>
std::vector<std::string> lfs_squared(const std::vector<XPoint<D>>& input,
                                     const std::vector<XPoint<D>>& queries);

// Named forms asked for by the issue.
inline WellSpacedReport judge_well_spaced_2d(const std::vector<XPoint<2>>& p, const Rho& r) {
  return judge_well_spaced<2>(p, r);
}
inline WellSpacedReport judge_well_spaced_3d(const std::vector<XPoint<3>>& p, const Rho& r) {
  return judge_well_spaced<3>(p, r);
}
std::vector<std::uint32_t> beta_clipped_voronoi_neighbors_oracle_2d(
    const std::vector<XPoint<2>>& points, std::size_t v, const exact::Dyadic& beta,
    BetaOptions opt = {});
std::vector<std::uint32_t> beta_clipped_voronoi_neighbors_oracle_3d(
    const std::vector<XPoint<3>>& points, std::size_t v, const exact::Dyadic& beta,
    BetaOptions opt = {});
std::vector<std::uint32_t> beta_clipped_voronoi_neighbors_oracle_4d(
    const std::vector<XPoint<4>>& points, std::size_t v, const exact::Dyadic& beta,
    BetaOptions opt = {});

// Raw CGAL Delaunay adjacency (sorted neighbour lists; input must be duplicate-free).
// D = 2, 3: Delaunay_triangulation_2/3<Epeck>; D = 4: Delaunay_triangulation<Epeck_d<4>> (always
// built: CMake refuses to configure the oracles without Eigen3).
template <std::size_t D>
std::vector<std::vector<std::uint32_t>> cgal_delaunay_adjacency(const std::vector<XPoint<D>>& pts);

// For each query, the index of a nearest site (CGAL nearest_vertex, exact predicates). D = 2, 3.
template <std::size_t D>
std::vector<std::uint32_t> cgal_nearest_site(const std::vector<XPoint<D>>& sites,
                                             const std::vector<XPoint<D>>& queries);

}  // namespace kmr::oracle::ws
