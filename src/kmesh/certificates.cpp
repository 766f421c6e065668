#include "kmesh/certificates.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "exact/error.hpp"
#include "geometry/predicates.hpp"
#include "poly/sturm.hpp"

namespace kmr::kmesh {
namespace {

// Polynomials of time with dyadic coefficients (positions of moving dyadic points), only for
// building certificate polynomials with the geometry templates; converted to integer polynomials
// by a positive power-of-two factor, which keeps every sign.
struct DPoly {
  std::vector<Dyadic> c;
  DPoly() = default;
  DPoly(Dyadic a) : c{std::move(a)} {}  // NOLINT
  DPoly(Dyadic a, Dyadic b) : c{std::move(a), std::move(b)} {}
  friend DPoly operator+(const DPoly& x, const DPoly& y) {
    DPoly r;
    r.c.resize(std::max(x.c.size(), y.c.size()), Dyadic(0));
    for (std::size_t i = 0; i < x.c.size(); ++i) r.c[i] += x.c[i];
    for (std::size_t i = 0; i < y.c.size(); ++i) r.c[i] += y.c[i];
    return r;
  }
  DPoly operator-() const {
    DPoly r = *this;
    for (auto& v : r.c) v = -v;
    return r;
  }
  friend DPoly operator-(const DPoly& x, const DPoly& y) { return x + (-y); }
  friend DPoly operator*(const DPoly& x, const DPoly& y) {
    DPoly r;
    if (x.c.empty() || y.c.empty()) return r;
    r.c.assign(x.c.size() + y.c.size() - 1, Dyadic(0));
    for (std::size_t i = 0; i < x.c.size(); ++i)
      for (std::size_t j = 0; j < y.c.size(); ++j) r.c[i + j] += x.c[i] * y.c[j];
    return r;
  }
};

poly::Polynomial to_poly(const DPoly& p) {
  std::int64_t e = 0;
  for (auto& v : p.c)
    if (!v.is_zero()) e = std::min(e, v.exponent());
  std::vector<exact::Integer> out;
  for (auto& v : p.c) {
    Dyadic w = v.shifted(-e);
    KMR_CHECK(w.is_integer(), "certificate: scaling to integers failed");
    out.push_back(w.is_zero() ? exact::Integer(0) : exact::Integer(w.mantissa() << static_cast<unsigned>(w.exponent())));
  }
  return poly::Polynomial(out);
}

using MPoint = geometry::Point<2, DPoly>;

}  // namespace

const char* kind_name(Certificate::Kind k) {
  static const char* n[] = {"parent-child", "separation", "edge", "potential-neighbour", "ball-not-empty", "ball-empty", "delaunay"};
  return n[k];
}

std::vector<std::array<exact::Integer, 2>> vertex_velocities(const Mesh& m) {
  std::vector<std::array<exact::Integer, 2>> v(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    const InputPoint& p = m.input[m.info[i].nucleus];
    v[i] = {p.vx * kScale, p.vy * kScale};
  }
  return v;
}

int nearest_witness(const Mesh& m, const Considered& c, const Point2& s0) {
  const Spanner& S = m.spanner;
  int w = -1;  // the nearest earlier vertex in the ball, found by brute force
  for (int x = 0; x < c.existing; ++x)
    if (within(s0, S.position(x), 1, c.rank - 2) &&
        (w < 0 || geometry::compare_squared_distance<2, Dyadic>(s0, S.position(x), S.position(w)) < 0))
      w = x;
  return w;
}

// Integer work over the spanner's lists (sorted by id): no per-vertex set is built; `mark` stamps the
// vertices already listed (the cousins of one (x, ℓ), the earlier neighbours of one satellite).
std::vector<CertificateSpec> certificate_specs(const Mesh& m, const WitnessChoice& witness) {
  const Spanner& S = m.spanner;
  const int N = static_cast<int>(m.size());
  std::vector<CertificateSpec> out;
  std::vector<std::size_t> mark(N, 0);
  std::size_t stamp = 0;
  std::vector<int> cousins;
  static const std::vector<int> kNone;
  std::vector<Rank> ranks;
  for (int x = 0; x < N; ++x) {
    if (x != S.root()) out.push_back({Certificate::ParentChild, x, S.parent(x), S.top(x) + 1, false});
    for (auto& [l, list] : S.all_neighbors(x))
      for (int y : list)
        if (y > x) {
          out.push_back({Certificate::Separation, x, y, l, true});
          out.push_back({Certificate::Edge, x, y, l, false});
        }
    // Potential neighbours at rank l: cousins (x's rank-(l+1) representative r, its (l+1)-neighbours,
    // and their children at l) that are not l-neighbours. Kids of r alone are all l-neighbours
    // (within 2·2^(l+1) of r), so a rank needs r to have (l+1)-neighbours: r = x for l < top(x) (the
    // ranks l − 1 below x's lists, also where x has no list at l: gaps, and the rank below λ_x), r =
    // parent(x) for l = top(x).
    ranks.clear();
    for (auto& [l, list] : S.all_neighbors(x))
      if (!list.empty() && l <= S.top(x)) ranks.push_back(l - 1);
    if (S.top(x) < S.top_rank()) ranks.push_back(S.top(x));
    for (Rank l : ranks) {
      if (l >= S.top_rank()) continue;
      auto own = S.all_neighbors(x).find(l);
      const std::vector<int>& list = own == S.all_neighbors(x).end() ? kNone : own->second;
      int r = S.rep(x, l + 1);
      ++stamp;
      cousins.clear();
      auto add = [&](int y) {
        if (y > x && mark[y] != stamp) mark[y] = stamp, cousins.push_back(y);
      };
      add(r);
      for (int y : S.kids(r, l)) add(y);
      for (int z : S.neighbors(r, l + 1)) {
        add(z);
        for (int y : S.kids(z, l)) add(y);
      }
      std::sort(cousins.begin(), cousins.end());
      for (int y : cousins)
        if (!std::binary_search(list.begin(), list.end(), y) && S.top(y) >= l)
          out.push_back({Certificate::Potential, x, y, l, true});
    }
  }
  // Conversion decisions (§4.3).
  for (std::size_t i = 0; i < m.considered.size(); ++i) {
    const Considered& c = m.considered[i];
    if (!c.converted) {
      Point2 s0 = satellite_position(S.position(c.nucleus), c.ray, c.rank);
      int w = witness ? witness(i, s0) : nearest_witness(m, c, s0);
      KMR_CHECK(w >= 0, "certificates: a satellite not converted has no vertex in its ball");
      out.push_back({Certificate::BallNotEmpty, c.nucleus, w, c.rank, false, c.nucleus, c.ray});
    } else {
      ++stamp;
      for (Rank l = c.rank - 6; l <= c.rank - 1; ++l)
        for (int v : S.neighbors(c.vertex, l))
          if (v < c.vertex && mark[v] != stamp) {
            mark[v] = stamp;
            out.push_back({Certificate::BallEmpty, c.vertex, v, c.rank, true, c.nucleus, c.ray});
          }
    }
  }
  // Delaunay: every triangle stays counter-clockwise, and every interior edge locally Delaunay.
  for (auto& t : m.triangles) out.push_back({Certificate::Delaunay, t[0], t[1], 0, true, t[2], -1});
  std::map<std::pair<int, int>, int> apex;
  for (auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) apex[{t[i], t[(i + 1) % 3]}] = t[(i + 2) % 3];
  for (auto& [e, c] : apex) {
    if (e.first > e.second) continue;
    auto it = apex.find({e.second, e.first});
    if (it == apex.end()) continue;
    out.push_back({Certificate::Delaunay, e.first, e.second, 0, true, c, it->second});
  }
  return out;
}

namespace {

// The moving point of each vertex of m (position at τ = at, its nucleus's velocity), built once.
class MovingPoints {
 public:
  MovingPoints(const Mesh& m, const Dyadic& at) : m_(m), at_(at), cache_(m.size()) {}
  const MPoint& operator()(int i) {
    if (!cache_[i]) {
      const InputPoint& p = m_.input[m_.info[i].nucleus];
      Dyadic v[2] = {Dyadic(p.vx * kScale), Dyadic(p.vy * kScale)};
      const Point2& x = m_.spanner.position(i);
      MPoint q;
      for (int k = 0; k < 2; ++k) q[k] = at_.is_zero() ? DPoly(x[k], v[k]) : DPoly(x[k] - v[k] * at_, v[k]);
      cache_[i] = std::move(q);
    }
    return *cache_[i];
  }

 private:
  const Mesh& m_;
  Dyadic at_;
  std::vector<std::optional<MPoint>> cache_;
};

Certificate build_one(const CertificateSpec& sp, MovingPoints& mp) {
  auto d2 = [&](const MPoint& a, const MPoint& q) { return geometry::squared_distance<2, DPoly>(a, q); };
  auto satellite = [&]() {
    MPoint s = mp(sp.c);
    const Point2 off = satellite_offset(sp.d, sp.rank);
    for (int k = 0; k < 2; ++k) s[k] = s[k] + DPoly(off[k]);
    return s;
  };
  Certificate out{sp.kind, sp.a, sp.b, sp.rank, sp.strict, {}};
  if (sp.kind == Certificate::BallNotEmpty) out.ray = sp.d;
  switch (sp.kind) {
    case Certificate::ParentChild:  // |x parent|² ≤ (2^(top+1))²
      out.value = to_poly(-(d2(mp(sp.a), mp(sp.b)) - DPoly(threshold2(1, sp.rank))));
      break;
    case Certificate::Separation:
      out.value = to_poly(d2(mp(sp.a), mp(sp.b)) - DPoly(threshold2(1, sp.rank)));
      break;
    case Certificate::Edge:
      out.value = to_poly(-(d2(mp(sp.a), mp(sp.b)) - DPoly(threshold2(kC, sp.rank))));
      break;
    case Certificate::Potential:
      out.value = to_poly(d2(mp(sp.a), mp(sp.b)) - DPoly(threshold2(kC, sp.rank)));
      break;
    case Certificate::BallNotEmpty:
      out.value = to_poly(DPoly(threshold2(1, sp.rank - 2)) - d2(satellite(), mp(sp.b)));
      break;
    case Certificate::BallEmpty:
      out.value = to_poly(d2(satellite(), mp(sp.b)) - DPoly(threshold2(1, sp.rank - 2)));
      break;
    case Certificate::Delaunay:
      out.ccw = sp.d < 0;
      if (out.ccw)
        out.value = to_poly(geometry::orientation_value<DPoly>(mp(sp.a), mp(sp.b), mp(sp.c)));
      else
        out.value = to_poly(-geometry::side_of_oriented_circle_value<DPoly>(mp(sp.a), mp(sp.b), mp(sp.c), mp(sp.d)));
      break;
  }
  return out;
}

}  // namespace

Certificate build_certificate(const Mesh& m, const CertificateSpec& sp, const Dyadic& at) {
  MovingPoints mp(m, at);
  return build_one(sp, mp);
}

std::vector<Certificate> build_certificates(const Mesh& m, const std::vector<CertificateSpec>& specs,
                                            const Dyadic& at) {
  MovingPoints mp(m, at);
  std::vector<Certificate> out;
  out.reserve(specs.size());
  for (auto& sp : specs) out.push_back(build_one(sp, mp));
  return out;
}

std::vector<Certificate> certificates(const Mesh& m) { return build_certificates(m, certificate_specs(m), Dyadic(0)); }

poly::Polynomial shifted_by_dyadic(const poly::Polynomial& p, const Dyadic& d) {
  if (p.degree() <= 0 || d.is_zero()) return p;
  if (d.is_integer()) return p.shifted_by(d.mantissa() << static_cast<unsigned>(d.exponent()));
  // d = m / 2^e: r(u) = 2^(e·deg) p(u / 2^e) has integer coefficients; r(u + m); back with u = 2^e t.
  const unsigned e = static_cast<unsigned>(-d.exponent());
  const int n = p.degree();
  std::vector<exact::Integer> c(p.coefficients());
  for (int i = 0; i <= n; ++i) c[i] <<= e * static_cast<unsigned>(n - i);
  poly::Polynomial r = poly::Polynomial(c).shifted_by(d.mantissa());
  std::vector<exact::Integer> q(r.coefficients());
  for (std::size_t i = 0; i < q.size(); ++i) q[i] <<= e * static_cast<unsigned>(i);
  return poly::Polynomial(q);
}

bool holds_at(const Certificate& c, const Dyadic& t) {
  if (c.value.is_zero()) return c.kind == Certificate::Delaunay || !c.strict;
  int s = c.value.sign_at(t);
  if (s == 0 && c.kind == Certificate::Delaunay && !c.ccw) return true;  // cocircular now: the perturbation decides
  return c.strict ? s > 0 : s >= 0;
}

bool fails_at_zero(const Certificate& c) { return c.strict && (c.kind != Certificate::Delaunay || c.ccw); }

std::optional<exact::Integer> failure_batch(const poly::LatticeRootSolver& s, bool zero_fails, const Dyadic& from,
                                            const Dyadic& horizon) {
  const int bits = s.lattice_bits();
  // One interval past the horizon: a strict certificate vanishing at the horizon is a batch before it.
  auto f = s.next_failure_after(from, horizon + Dyadic(1, -bits), zero_fails);
  if (!f) return std::nullopt;
  exact::Integer k = *f;
  if (zero_fails && s.lattice_point(k) > from && s.polynomial().sign_at(k, bits) == 0) k -= 1;
  if (!(s.lattice_point(k) < horizon)) return std::nullopt;
  return k;
}

std::optional<std::pair<exact::Integer, std::size_t>> first_failure(const std::vector<Certificate>& certs, int bits,
                                                                    const Dyadic& horizon) {
  std::optional<std::pair<exact::Integer, std::size_t>> best;
  for (std::size_t i = 0; i < certs.size(); ++i) {
    if (certs[i].value.degree() <= 0) continue;
    poly::LatticeRootSolver solver(certs[i].value, bits);
    Dyadic h = best ? Dyadic(best->first, -bits) : horizon;
    auto k = failure_batch(solver, fails_at_zero(certs[i]), Dyadic(0), h);
    if (k && (!best || *k < best->first)) best = {{*k, i}};
  }
  return best;
}

Mesh moved_to(const Mesh& m, const Dyadic& t) {
  Mesh r = m;
  auto vel = vertex_velocities(m);
  std::vector<Point2> p(m.size());
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int k = 0; k < 2; ++k) p[i][k] = m.spanner.position(static_cast<int>(i))[k] + Dyadic(vel[i][k]) * t;
  r.spanner.move_to(p);
  return r;
}

}  // namespace kmr::kmesh
