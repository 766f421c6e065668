#pragma once
// Moving points of the kinetic hull (§2.3): each coordinate an integer polynomial of time, and the
// certificate polynomials of the hull's two predicates (§2.1: a comparison of moving points is a
// polynomial whose sign is the comparison's outcome).
//
// Guarantees:
//  * parse_hull_motions reads `x y z vx vy vz` per line (decimal integers of any size; '#' comments,
//    blank lines skipped): position (x, y, z) + (vx, vy, vz)·t. A malformed line is an InputError
//    naming file:line; an empty file too.
//  * orientation_polynomial(p, q, r, s) = orientation_value over Polynomial (CGAL's sign: > 0 iff
//    s lies on the positive side of the oriented plane pqr), a cubic for linear motion.
//  * centre_side_polynomial(u, v, x, S) is a positive multiple (64) of orientation(u, v, c, x) with
//    c = S/4 the centroid of the initial tetrahedron (S the sum of its four trajectories): every
//    coefficient stays an integer, and the sign is the sign of the centre test.
//  * refuse_identical_trajectories throws an InputError naming the lowest two points that share a
//    trajectory (their certificates would be identically zero).
//  * initial_simplex_of: the first four points in priority order that are not *identically*
//    degenerate (b ≠ a, c not identically collinear with a, b, d not identically coplanar with
//    a, b, c). Under the §2.1 rule (a certificate takes its sign just before t) only identical
//    degeneracy is degeneracy, so this choice is the same at every time; InputError if none.
#include <array>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "kinetic/trajectory.hpp"
#include "poly/machine_polynomial.hpp"

namespace kmr::hull {

using MovingPoint = kinetic::Trajectory<3>;
using poly::Polynomial;

std::vector<MovingPoint> parse_hull_motions(std::istream& in, const std::string& filename);

Polynomial orientation_polynomial(const MovingPoint& p, const MovingPoint& q, const MovingPoint& r,
                                  const MovingPoint& s);
// side_of_oriented_sphere_value over Polynomial (CGAL's sign: > 0 iff t lies inside the sphere
// through p, q, r, s when orientation(p, q, r, s) > 0), degree ≤ 5 for linear motion; alternating in
// its five arguments. Fig. 2.3's kinetic Delaunay baseline (bench/hull) certifies with it.
Polynomial side_of_sphere_polynomial(const MovingPoint& p, const MovingPoint& q, const MovingPoint& r,
                                     const MovingPoint& s, const MovingPoint& t);
Polynomial centre_side_polynomial(const MovingPoint& u, const MovingPoint& v, const MovingPoint& x,
                                  const MovingPoint& centre_sum);
MovingPoint trajectory_sum(const MovingPoint& a, const MovingPoint& b, const MovingPoint& c, const MovingPoint& d);

// The machine form (issue 9): a trajectory whose coordinates are of degree ≤ 1 with every
// coefficient |c| ≤ 2^36 as MachinePolynomials, else nothing. Then both certificate polynomials
// below fit __int128 (coordinates ×4 and the centre sum stay ≤ 2^38, differences ≤ 2^39, every
// cubic coefficient < 2^123), and each equals the Polynomial version's exactly (a test holds them
// side by side): the same certificate, built without GMP. The cubic comes from multilinearity:
// the coefficient of t^k is the sum of the determinants with k rows taken from the velocities.
struct MachinePoint {
  std::array<std::int64_t, 3> x{}, v{};  // x + v·t per coordinate
  friend MachinePoint operator+(const MachinePoint& a, const MachinePoint& b) {
    MachinePoint r;
    for (int k = 0; k < 3; ++k) r.x[k] = a.x[k] + b.x[k], r.v[k] = a.v[k] + b.v[k];
    return r;
  }
};
std::optional<MachinePoint> machine_point(const MovingPoint& p);
poly::MachinePolynomial orientation_polynomial(const MachinePoint& p, const MachinePoint& q, const MachinePoint& r,
                                               const MachinePoint& s);
poly::MachinePolynomial centre_side_polynomial(const MachinePoint& u, const MachinePoint& v, const MachinePoint& x,
                                               const MachinePoint& centre_sum);  // centre_sum: four machine points' sum

// A linearly moving point (x, y, z) + (vx, vy, vz)·t.
MovingPoint linear(long long x, long long y, long long z, long long vx, long long vy, long long vz);

void refuse_identical_trajectories(const std::vector<MovingPoint>& points);
std::array<int, 4> initial_simplex_of(const std::vector<MovingPoint>& points, const std::vector<int>& order);
// The same choice, each test in machine form where its points have one (machine[i] =
// machine_point(points[i]); the same polynomials, without GMP: issue 9, Fig. 2.4's initial run).
std::array<int, 4> initial_simplex_of(const std::vector<MovingPoint>& points, const std::vector<int>& order,
                                      const std::vector<std::optional<MachinePoint>>& machine);

// §2.4's integrated motion change r(t) ↦ ¾·r(t), kept an integer motion: every coefficient c
// becomes 3c/4 truncated toward zero (exactly ¾·r(t) when the coefficients are multiples of 4).
MovingPoint three_quarters(const MovingPoint& r);

// A moving point's position at a dyadic time (exact).
std::array<exact::Dyadic, 3> position_at(const MovingPoint& p, const exact::Dyadic& t);

}  // namespace kmr::hull
