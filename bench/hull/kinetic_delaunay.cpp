// Fig. 2.3's kinetic Delaunay baseline (header: guarantees). The one CGAL translation unit of it.
#include "kinetic_delaunay.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <utility>

#include "exact/error.hpp"
#include "poly/polynomial.hpp"

namespace kmr::bench {

namespace {

// Exact predicates on the exact integer coordinates (CGAL's lazy exact kernel: interval filter,
// cached per point; 4x faster here than Filtered_kernel<Simple_cartesian<Gmpz>>).
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Cb = CGAL::Delaunay_triangulation_cell_base_3<K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Delaunay = CGAL::Delaunay_triangulation_3<K, Tds>;
using exact::Dyadic;
using exact::Integer;
using poly::Polynomial;

// (−1)^(inversions): the sign of the permutation that sorts v (distinct entries).
template <std::size_t N>
int parity(const std::array<int, N>& v) {
  int s = 1;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j)
      if (v[i] > v[j]) s = -s;
  return s;
}

template <std::size_t N>
std::array<int, N> sorted(std::array<int, N> v) {
  std::sort(v.begin(), v.end());
  return v;
}

// The positions at the dyadic time t, all scaled by one power of two (Delaunay and orientation are
// invariant under a common positive scale): Σ c_i·m^i·2^(s·(D − i)) for t = m·2^−s, D the largest degree.
std::vector<std::array<Integer, 3>> scaled_positions(const std::vector<hull::MovingPoint>& pts, const Dyadic& t) {
  int degree = 0;
  for (const auto& p : pts)
    for (int k = 0; k < 3; ++k) degree = std::max(degree, p[k].degree());
  const Integer m = t.exponent() >= 0 ? t.floor() : t.mantissa();
  const long long s = t.exponent() >= 0 ? 0 : -t.exponent();
  std::vector<std::array<Integer, 3>> out(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const auto& c = pts[i][k].coefficients();
      auto coefficient = [&](int j) { return j < static_cast<int>(c.size()) ? c[static_cast<std::size_t>(j)] : Integer(0); };
      Integer acc = coefficient(degree);
      for (int j = degree - 1; j >= 0; --j) acc = acc * m + (coefficient(j) << static_cast<unsigned>(s * (degree - j)));
      out[i][k] = acc;
    }
  return out;
}

K::FT to_ft(const Integer& x) { return K::FT(K::FT::Exact_type(mpz_class(x.backend().data()))); }

// CGAL's Delaunay triangulation of the points at t, as cells and certificate keys (header).
KineticDelaunay::Snapshot snapshot_at(const std::vector<hull::MovingPoint>& pts, const Dyadic& t) {
  KineticDelaunay::Snapshot snap;
  const auto pos = scaled_positions(pts, t);
  std::vector<std::pair<K::Point_3, int>> input;
  input.reserve(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    input.emplace_back(K::Point_3(to_ft(pos[i][0]), to_ft(pos[i][1]), to_ft(pos[i][2])), static_cast<int>(i));
  Delaunay dt(input.begin(), input.end());
  if (dt.dimension() < 3 || dt.number_of_vertices() != pts.size()) return snap;  // degenerate at t
  snap.complete = true;
  auto id = [&](Delaunay::Vertex_handle v) { return v->info(); };
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    snap.cells.push_back(sorted(std::array<int, 4>{id(c->vertex(0)), id(c->vertex(1)), id(c->vertex(2)), id(c->vertex(3))}));
  std::sort(snap.cells.begin(), snap.cells.end());
  std::vector<Delaunay::Vertex_handle> hull;
  dt.adjacent_vertices(dt.infinite_vertex(), std::back_inserter(hull));
  for (auto v : hull) snap.hull_vertices.push_back(id(v));
  std::sort(snap.hull_vertices.begin(), snap.hull_vertices.end());
  // The four vertices of a finite cell in CGAL's (positive) order.
  auto vertices = [&](Delaunay::Cell_handle c) {
    return std::array<int, 4>{id(c->vertex(0)), id(c->vertex(1)), id(c->vertex(2)), id(c->vertex(3))};
  };
  for (auto f = dt.all_facets_begin(); f != dt.all_facets_end(); ++f) {
    Delaunay::Cell_handle c = f->first, n = c->neighbor(f->second);
    int i = f->second;
    if (dt.is_infinite(c) && !dt.is_infinite(n)) std::swap(c, n), i = c->index(n);
    const int j = n->index(c);
    if (!dt.is_infinite(c) && !dt.is_infinite(n)) {
      // Sphere test: the apex w of n outside the sphere of c. Q = −side(c, w) = −parity·side(sorted).
      const auto cv = vertices(c);
      const int w = id(n->vertex(j));
      std::array<int, 5> tuple{cv[0], cv[1], cv[2], cv[3], w};
      std::array<int, 3> facet{};
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != i) facet[static_cast<std::size_t>(m++)] = cv[static_cast<std::size_t>(k)];
      facet = sorted(facet);
      auto apex = sorted(std::array<int, 2>{cv[static_cast<std::size_t>(i)], w});
      snap.keys.push_back({0, facet[0], facet[1], facet[2], apex[0], apex[1], -parity(tuple)});
    } else if (!dt.is_infinite(c)) {
      // Hull face of the finite cell c: orientation(c) > 0 (= parity·orientation(sorted)).
      const auto cv = vertices(c);
      std::array<int, 3> facet{};
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != i) facet[static_cast<std::size_t>(m++)] = cv[static_cast<std::size_t>(k)];
      facet = sorted(facet);
      snap.keys.push_back({1, facet[0], facet[1], facet[2], cv[static_cast<std::size_t>(i)], -1, parity(cv)});
    } else {
      // Hull edge ab: c = ∞abx, n = ∞abe (both infinite). e must lie on the inner side of the plane
      // of the hull face abx, the side of the apex d of the finite cell under that face.
      const int inf = c->index(dt.infinite_vertex());
      std::array<int, 2> edge{};
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != i && k != inf) edge[static_cast<std::size_t>(m++)] = id(c->vertex(k));
      const int x = id(c->vertex(i)), e = id(n->vertex(j));
      Delaunay::Cell_handle under = c->neighbor(inf);
      const int d = id(under->vertex(under->index(c)));
      // sign(orientation(a, b, x, d)) = parity(a, b, x, d)·parity(under's order) (under is positive).
      const int s = parity(std::array<int, 4>{edge[0], edge[1], x, d}) * parity(vertices(under));
      const int sigma = s * parity(std::array<int, 4>{edge[0], edge[1], x, e});
      auto apex = sorted(std::array<int, 2>{x, e});
      auto ab = sorted(edge);
      snap.keys.push_back({2, ab[0], ab[1], -1, apex[0], apex[1], sigma});
    }
  }
  std::sort(snap.keys.begin(), snap.keys.end());
  KMR_CHECK(std::adjacent_find(snap.keys.begin(), snap.keys.end()) == snap.keys.end(), "duplicate certificate key");
  return snap;
}

std::string describe(const std::vector<int>& pts) {
  std::string s;
  for (int p : pts) s += (s.empty() ? "" : " ") + std::to_string(p);
  return s;
}

}  // namespace

std::vector<int> key_points(const KineticDelaunay::Key& k) {
  std::vector<int> p;
  for (int i = 1; i <= 5; ++i)
    if (k[static_cast<std::size_t>(i)] >= 0) p.push_back(k[static_cast<std::size_t>(i)]);
  std::sort(p.begin(), p.end());
  return p;
}

KineticDelaunay::KineticDelaunay(std::vector<hull::MovingPoint> points, kinetic::MotionSimulator& sim)
    : points_(std::move(points)), sim_(sim) {
  hull::refuse_identical_trajectories(points_);
  rebuild();
}

KineticDelaunay::~KineticDelaunay() {
  for (const auto& [key, id] : ids_) sim_.remove(id);
}

Polynomial KineticDelaunay::certificate_polynomial(const Key& k) const {
  const auto p = key_points(k);
  const auto& P = points_;
  Polynomial q = k[0] == 0 ? hull::side_of_sphere_polynomial(P[p[0]], P[p[1]], P[p[2]], P[p[3]], P[p[4]])
                           : hull::orientation_polynomial(P[p[0]], P[p[1]], P[p[2]], P[p[3]]);
  if (q.is_zero())
    throw InputError("points " + describe(p) + (k[0] == 0 ? " stay cospherical" : " stay coplanar") +
                     " for all time (an identically zero Delaunay certificate)");
  return k[6] > 0 ? q : Integer(-1) * q;
}

void KineticDelaunay::rebuild() {
  const Dyadic now = sim_.now();
  bool any_complete = false;
  for (int j = 1; j <= 200; ++j) {
    const Dyadic t = now - Dyadic::pow2(-sim_.lattice_bits() - j);
    // A cheap necessary condition first: t lies after the last root in the interval of every
    // certificate of the batch just processed (its sign at t is its outcome just before now).
    bool after_batch = true;
    for (kinetic::CertificateId id : last_batch_)
      if (sim_.certificate(id).polynomial.sign_at(t) != sim_.outcome(id)) {
        after_batch = false;
        break;
      }
    if (!after_batch) continue;
    ++counters_.rebuilds;
    if (j > 1) ++counters_.retries;
    Snapshot snap = snapshot_at(points_, t);
    if (!snap.complete) continue;
    any_complete = true;
    // Every certificate must hold just before now; new ones are evaluated, kept ones asked.
    std::map<Key, Polynomial> fresh;
    bool holds = true;
    for (const Key& k : snap.keys) {
      auto it = ids_.find(k);
      int outcome;
      if (it != ids_.end()) {
        outcome = sim_.outcome(it->second);
      } else {
        Polynomial q = certificate_polynomial(k);
        outcome = poly::sign_before(q, now);
        fresh.emplace(k, std::move(q));
      }
      if (outcome <= 0) {
        holds = false;
        break;
      }
    }
    if (!holds) continue;
    std::set<Key> wanted(snap.keys.begin(), snap.keys.end());
    for (auto it = ids_.begin(); it != ids_.end();) {
      if (wanted.count(it->first)) {
        ++it;
        continue;
      }
      sim_.remove(it->second);
      keys_.erase(it->second);
      it = ids_.erase(it);
    }
    for (auto& [k, q] : fresh) {
      const kinetic::CertificateId id = sim_.add(q);
      KMR_CHECK(sim_.outcome(id) > 0, "a new Delaunay certificate does not hold just before now");
      ids_.emplace(k, id);
      keys_.emplace(id, k);
      ++counters_.certificates_created;
    }
    counters_.max_certificates = std::max<long long>(counters_.max_certificates, static_cast<long long>(ids_.size()));
    cells_ = std::move(snap.cells);
    hull_vertices_ = std::move(snap.hull_vertices);
    return;
  }
  if (!any_complete)
    throw InputError("kinetic Delaunay: just before " + now.to_decimal() +
                     " the points are coplanar or two of them coincide (no 3D triangulation of all of them)");
  throw ContractError("kinetic Delaunay: no dyadic time just before " + now.to_decimal() +
                      " gives a triangulation whose certificates all hold");
}

long long KineticDelaunay::update(const std::vector<kinetic::CertificateId>& batch) {
  std::set<std::vector<int>> flips;
  for (kinetic::CertificateId id : batch) {
    auto it = keys_.find(id);
    KMR_CHECK(it != keys_.end(), "a batch certificate that is not the kinetic Delaunay's");
    flips.insert(key_points(it->second));
  }
  counters_.events += static_cast<long long>(batch.size());
  counters_.flips += static_cast<long long>(flips.size());
  ++counters_.batches;
  last_batch_ = batch;
  rebuild();
  last_batch_.clear();
  return static_cast<long long>(flips.size());
}

std::string KineticDelaunay::check_gap(const Dyadic& a, const Dyadic& b) {
  if (!(a < b)) return "";
  for (int j = 1; j <= 8; ++j)
    for (long long k = 1; k < (1LL << j); k += 2) {
      const Dyadic t = a + (b - a) * Dyadic(Integer(k), -j);
      bool degenerate = false;
      for (const auto& [key, id] : ids_)
        if (sim_.certificate(id).polynomial.sign_at(t) == 0) {
          degenerate = true;
          break;
        }
      if (degenerate) continue;
      Snapshot snap = snapshot_at(points_, t);
      if (!snap.complete) continue;
      if (snap.cells == cells_) return "";
      std::vector<Cell> missing, extra;
      std::set_difference(snap.cells.begin(), snap.cells.end(), cells_.begin(), cells_.end(), std::back_inserter(missing));
      std::set_difference(cells_.begin(), cells_.end(), snap.cells.begin(), snap.cells.end(), std::back_inserter(extra));
      return "at t = " + t.to_decimal() + ": CGAL's Delaunay has " + std::to_string(missing.size()) +
             " cells the kept triangulation lacks and lacks " + std::to_string(extra.size()) + " of its cells";
    }
  return "";  // no nondegenerate time found among 255 candidates: nothing to compare
}

}  // namespace kmr::bench
