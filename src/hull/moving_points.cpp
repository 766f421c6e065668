#include "hull/moving_points.hpp"

#include <algorithm>
#include <initializer_list>
#include <numeric>
#include <sstream>

#include "exact/error.hpp"
#include "exact/text_lines.hpp"
#include "geometry/predicates.hpp"

namespace kmr::hull {

std::vector<MovingPoint> parse_hull_motions(std::istream& in, const std::string& filename) {
  std::vector<MovingPoint> points;
  for (const exact::TextLine& l : exact::read_text_lines(in, filename)) {
    auto where = [&] { return filename + ":" + std::to_string(l.number) + ": "; };
    if (l.tokens.size() != 6)
      throw InputError(where() + "expected 6 integers 'x y z vx vy vz', found " + std::to_string(l.tokens.size()) +
                       " fields: '" + l.text() + "'");
    MovingPoint p;
    try {
      for (int k = 0; k < 3; ++k)
        p[k] = Polynomial(std::vector<exact::Integer>{exact::parse_integer(l.tokens[k]), exact::parse_integer(l.tokens[k + 3])});
    } catch (const InputError& e) {
      throw InputError(where() + e.what());
    }
    points.push_back(std::move(p));
  }
  if (points.empty()) throw InputError(filename + ": no points");
  return points;
}

Polynomial orientation_polynomial(const MovingPoint& p, const MovingPoint& q, const MovingPoint& r,
                                  const MovingPoint& s) {
  return geometry::orientation_value<Polynomial>(p, q, r, s);
}

Polynomial side_of_sphere_polynomial(const MovingPoint& p, const MovingPoint& q, const MovingPoint& r,
                                     const MovingPoint& s, const MovingPoint& t) {
  return geometry::side_of_oriented_sphere_value<Polynomial>(p, q, r, s, t);
}

namespace {
MovingPoint times4(const MovingPoint& p) {
  MovingPoint r;
  for (int k = 0; k < 3; ++k) r[k] = exact::Integer(4) * p[k];
  return r;
}
}  // namespace

Polynomial centre_side_polynomial(const MovingPoint& u, const MovingPoint& v, const MovingPoint& x,
                                  const MovingPoint& centre_sum) {
  // det[4v − 4u, S − 4u, 4x − 4u] = 64·det[v − u, c − u, x − u] with c = S/4.
  return geometry::orientation_value<Polynomial>(times4(u), times4(v), centre_sum, times4(x));
}

std::optional<MachinePoint> machine_point(const MovingPoint& p) {
  MachinePoint m;
  for (int k = 0; k < 3; ++k) {
    const auto& cs = p[k].coefficients();
    if (cs.size() > 2) return std::nullopt;
    std::int64_t c[2] = {0, 0};
    for (std::size_t j = 0; j < cs.size(); ++j) {
      // |c| < 2^36, read from the mpz directly (Boost's conversion to long long goes through a
      // decimal string, and bit_length copies |c|: ≈ 7·10^3 instructions per point, issue 9).
      const auto* z = cs[j].backend().data();
      if (mpz_sgn(z) != 0 && mpz_sizeinbase(z, 2) > 36) return std::nullopt;
      c[j] = mpz_get_si(z);
    }
    m.x[k] = c[0], m.v[k] = c[1];
  }
  return m;
}

namespace {
using I = __int128;
// For 3-vectors with |entries| ≤ 2^39: b × c (|entries| ≤ 2^79) and a · x (|a · x| < 3·2^39·2^80
// < 2^121), so det3(a, b, c) = det[a; b; c] = a · (b × c) never overflows.
using V3 = std::array<std::int64_t, 3>;
using I3 = std::array<I, 3>;
I3 cross(const V3& b, const V3& c) {
  return {I(b[1]) * c[2] - I(b[2]) * c[1], I(b[2]) * c[0] - I(b[0]) * c[2], I(b[0]) * c[1] - I(b[1]) * c[0]};
}
I dot(const V3& a, const I3& x) { return a[0] * x[0] + a[1] * x[1] + a[2] * x[2]; }
// det of the rows (x_i + v_i·t), i = 0, 1, 2, as a cubic (multilinearity in the rows):
// c0 = det3(u.x, v.x, w.x), c1 = det3(u.v, v.x, w.x) + det3(u.x, v.v, w.x) + det3(u.x, v.x, w.v),
// c2 = det3(u.x, v.v, w.v) + det3(u.v, v.x, w.v) + det3(u.v, v.v, w.x), c3 = det3(u.v, v.v, w.v),
// with the four cross products of v's and w's rows shared (exact integers: the same coefficients).
// When every entry of v's and w's rows is below 2^31 in magnitude (§2.4's inputs: ≤ 2^23), each
// cross product entry fits int64 (|b1·c2 − b2·c1| ≤ 2·(2^31 − 1)^2 < 2^63) and each term of a dot
// product is one 64×64 → 128-bit product: the same exact integers with fewer wide multiplies.
// (The two mixed cross products are dotted separately: their sum may exceed int64.)
using L3 = std::array<std::int64_t, 3>;
L3 cross64(const V3& b, const V3& c) {
  return {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
}
I dot64(const V3& a, const L3& x) { return I(a[0]) * x[0] + I(a[1]) * x[1] + I(a[2]) * x[2]; }
bool below_2_31(const MachinePoint& p) {
  constexpr std::int64_t lim = std::int64_t{1} << 31;
  bool ok = true;
  for (int k = 0; k < 3; ++k) ok = ok && p.x[k] > -lim && p.x[k] < lim && p.v[k] > -lim && p.v[k] < lim;
  return ok;
}
poly::MachinePolynomial rows_determinant(const MachinePoint& u, const MachinePoint& v, const MachinePoint& w) {
  if (below_2_31(v) && below_2_31(w)) {
    const L3 xx = cross64(v.x, w.x), vv = cross64(v.v, w.v), m0 = cross64(v.v, w.x), m1 = cross64(v.x, w.v);
    return poly::MachinePolynomial::cubic(dot64(u.x, xx), dot64(u.v, xx) + dot64(u.x, m0) + dot64(u.x, m1),
                                          dot64(u.x, vv) + dot64(u.v, m0) + dot64(u.v, m1), dot64(u.v, vv));
  }
  const I3 xx = cross(v.x, w.x), vv = cross(v.v, w.v), mixed0 = cross(v.v, w.x), mixed1 = cross(v.x, w.v);
  const I3 mixed{mixed0[0] + mixed1[0], mixed0[1] + mixed1[1], mixed0[2] + mixed1[2]};
  const I c0 = dot(u.x, xx);
  const I c1 = dot(u.v, xx) + dot(u.x, mixed);
  const I c2 = dot(u.x, vv) + dot(u.v, mixed);
  const I c3 = dot(u.v, vv);
  return poly::MachinePolynomial::cubic(c0, c1, c2, c3);
}
MachinePoint difference(const MachinePoint& a, const MachinePoint& b, std::int64_t ka = 1, std::int64_t kb = 1) {
  MachinePoint r;
  for (int k = 0; k < 3; ++k) r.x[k] = ka * a.x[k] - kb * b.x[k], r.v[k] = ka * a.v[k] - kb * b.v[k];
  return r;
}
}  // namespace

// orientation_value(p, q, r, s) = det[q − p, r − p, s − p] (geometry/predicates.hpp).
poly::MachinePolynomial orientation_polynomial(const MachinePoint& p, const MachinePoint& q, const MachinePoint& r,
                                               const MachinePoint& s) {
  return rows_determinant(difference(q, p), difference(r, p), difference(s, p));
}

// As the Polynomial version: det[4v − 4u, S − 4u, 4x − 4u] (entries ≤ 2^39).
poly::MachinePolynomial centre_side_polynomial(const MachinePoint& u, const MachinePoint& v, const MachinePoint& x,
                                               const MachinePoint& centre_sum) {
  return rows_determinant(difference(v, u, 4, 4), difference(centre_sum, u, 1, 4), difference(x, u, 4, 4));
}

MovingPoint linear(long long x, long long y, long long z, long long vx, long long vy, long long vz) {
  MovingPoint p;
  const long long pos[3] = {x, y, z}, vel[3] = {vx, vy, vz};
  for (int k = 0; k < 3; ++k) p[k] = Polynomial(std::vector<exact::Integer>{exact::Integer(pos[k]), exact::Integer(vel[k])});
  return p;
}

MovingPoint trajectory_sum(const MovingPoint& a, const MovingPoint& b, const MovingPoint& c, const MovingPoint& d) {
  MovingPoint s;
  for (int k = 0; k < 3; ++k) s[k] = a[k] + b[k] + c[k] + d[k];
  return s;
}

void refuse_identical_trajectories(const std::vector<MovingPoint>& points) {
  std::vector<int> by(points.size());
  std::iota(by.begin(), by.end(), 0);
  auto refuse = [](int a, int b) {
    throw InputError("points " + std::to_string(a) + " and " + std::to_string(b) +
                     " have identical trajectories (they coincide for all time)");
  };
  // All points in machine form (the common case): the same trajectories are equal (x, v) words,
  // since a Polynomial is canonical (no zero leading coefficient); no Integer is copied. The
  // lowest pair is found as below (groups of equal keys, by index within a group).
  std::vector<MachinePoint> machine;
  machine.reserve(points.size());
  for (const MovingPoint& p : points) {
    auto m = machine_point(p);
    if (!m) break;
    machine.push_back(*m);
  }
  if (machine.size() == points.size()) {
    auto key = [&](int i) { return std::pair(machine[static_cast<std::size_t>(i)].x, machine[static_cast<std::size_t>(i)].v); };
    std::sort(by.begin(), by.end(), [&](int a, int b) { return std::pair(key(a), a) < std::pair(key(b), b); });
    int best_a = -1, best_b = -1;
    for (std::size_t i = 1; i < by.size(); ++i)
      if (key(by[i - 1]) == key(by[i]) && (best_a < 0 || std::pair(by[i - 1], by[i]) < std::pair(best_a, best_b)))
        best_a = by[i - 1], best_b = by[i];
    if (best_a >= 0) refuse(best_a, best_b);
    return;
  }
  auto key = [&](int i) {
    std::vector<exact::Integer> c;
    for (int k = 0; k < 3; ++k) {
      const auto& cs = points[i][k].coefficients();
      c.push_back(exact::Integer(static_cast<long long>(cs.size())));
      c.insert(c.end(), cs.begin(), cs.end());
    }
    return c;
  };
  std::vector<std::vector<exact::Integer>> keys;
  keys.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) keys.push_back(key(static_cast<int>(i)));
  std::sort(by.begin(), by.end(), [&](int a, int b) { return keys[a] != keys[b] ? keys[a] < keys[b] : a < b; });
  int best_a = -1, best_b = -1;
  for (std::size_t i = 1; i < by.size(); ++i)
    if (keys[by[i - 1]] == keys[by[i]] && (best_a < 0 || std::pair(by[i - 1], by[i]) < std::pair(best_a, best_b)))
      best_a = by[i - 1], best_b = by[i];
  if (best_a >= 0) refuse(best_a, best_b);
}

namespace {
// (q − p) × (r − p) ≡ 0 as polynomials in t, for machine points (entries of the differences
// ≤ 2^37, within cross's bound): u × w = ux×wx + (ux×wv + uv×wx)·t + uv×wv·t².
bool machine_collinear(const MachinePoint& p, const MachinePoint& q, const MachinePoint& r) {
  const MachinePoint u = difference(q, p), w = difference(r, p);
  const I3 c0 = cross(u.x, w.x), c1a = cross(u.x, w.v), c1b = cross(u.v, w.x), c2 = cross(u.v, w.v);
  for (int k = 0; k < 3; ++k)
    if (c0[k] != 0 || c1a[k] + c1b[k] != 0 || c2[k] != 0) return false;
  return true;
}

// §2.2: the first point in `order`, the next not identically equal (all trajectories differ), the
// next not identically collinear with them, the next not identically coplanar; each test in
// machine form when its points have one (machine == nullptr: Polynomial tests only).
std::array<int, 4> choose_initial_simplex(const std::vector<MovingPoint>& pts, const std::vector<int>& order,
                                          const std::vector<std::optional<MachinePoint>>* machine) {
  const std::size_t n = order.size();
  if (n < 4) throw InputError("fewer than four points: a 3D hull needs four affinely independent points");
  KMR_CHECK(!machine || machine->size() == pts.size(), "initial_simplex_of: one machine form per point");
  auto in_machine_form = [&](std::initializer_list<int> xs) {
    if (!machine) return false;
    for (int x : xs)
      if (!(*machine)[static_cast<std::size_t>(x)]) return false;
    return true;
  };
  auto m = [&](int x) -> const MachinePoint& { return *(*machine)[static_cast<std::size_t>(x)]; };
  const int a = order[0], b = order[1];  // trajectories are distinct (refused otherwise)
  auto collinear = [&](int x) {
    if (in_machine_form({a, b, x})) return machine_collinear(m(a), m(b), m(x));
    using geometry::operator-;
    auto u = pts[b] - pts[a], v = pts[x] - pts[a];
    return (u[1] * v[2] - u[2] * v[1]).is_zero() && (u[2] * v[0] - u[0] * v[2]).is_zero() &&
           (u[0] * v[1] - u[1] * v[0]).is_zero();
  };
  std::size_t i = 2;
  while (i < n && collinear(order[i])) ++i;
  if (i == n) throw InputError("all points stay collinear for all time: a 3D hull needs four affinely independent points");
  const int c = order[i];
  auto coplanar = [&](int x) {
    if (in_machine_form({a, b, c, x})) return orientation_polynomial(m(a), m(b), m(c), m(x)).is_zero();
    return orientation_polynomial(pts[a], pts[b], pts[c], pts[x]).is_zero();
  };
  while (i < n && coplanar(order[i])) ++i;
  if (i == n) throw InputError("all points stay coplanar for all time: a 3D hull needs four affinely independent points");
  return {a, b, c, order[i]};
}
}  // namespace

std::array<int, 4> initial_simplex_of(const std::vector<MovingPoint>& pts, const std::vector<int>& order) {
  return choose_initial_simplex(pts, order, nullptr);
}

std::array<int, 4> initial_simplex_of(const std::vector<MovingPoint>& pts, const std::vector<int>& order,
                                      const std::vector<std::optional<MachinePoint>>& machine) {
  return choose_initial_simplex(pts, order, &machine);
}

MovingPoint three_quarters(const MovingPoint& r) {
  MovingPoint out;
  for (int k = 0; k < 3; ++k) {
    std::vector<exact::Integer> c;
    for (const exact::Integer& a : r[k].coefficients()) c.push_back(exact::Integer(3) * a / 4);
    out[k] = Polynomial(c);
  }
  return out;
}

std::array<exact::Dyadic, 3> position_at(const MovingPoint& p, const exact::Dyadic& t) {
  std::array<exact::Dyadic, 3> r;
  for (int k = 0; k < 3; ++k) {
    exact::Dyadic acc(0);
    const auto& cs = p[k].coefficients();
    for (std::size_t j = cs.size(); j-- > 0;) acc = acc * t + exact::Dyadic(cs[j], 0);
    r[k] = acc;
  }
  return r;
}

}  // namespace kmr::hull
