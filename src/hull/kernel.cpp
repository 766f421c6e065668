#include "hull/kernel.hpp"

#include <algorithm>

namespace kmr::hull {

using exact::Dyadic;

ExactKernel::ExactKernel(const std::vector<Point3d>& points) : pts_(points) {
  for (const Point3d& p : pts_) all_safe_ = all_safe_ && geometry::filter_safe(p);
}

int ExactKernel::orientation(int p, int q, int r, int s) {
  ++counts_.orientation_tests;
  if (all_safe_)
    if (int sg = geometry::orientation_filter(pts_[p], pts_[q], pts_[r], pts_[s])) return sg;
  ++counts_.exact_fallbacks;
  return geometry::orientation_exact(pts_[p], pts_[q], pts_[r], pts_[s]);
}

bool ExactKernel::collinear(int p, int q, int r) {
  // (q−p) × (r−p) = 0, component by component, in Dyadic arithmetic.
  auto a = geometry::to_dyadic(pts_[p]), b = geometry::to_dyadic(pts_[q]), c = geometry::to_dyadic(pts_[r]);
  using geometry::operator-;
  auto u = b - a, v = c - a;
  return (u[1] * v[2] - u[2] * v[1]).is_zero() && (u[2] * v[0] - u[0] * v[2]).is_zero() &&
         (u[0] * v[1] - u[1] * v[0]).is_zero();
}

void ExactKernel::set_centre(int a, int b, int c, int d) {
  double eta = 0;
  for (int k = 0; k < 3; ++k) {
    Dyadic s = Dyadic::from_double(pts_[a][k]) + Dyadic::from_double(pts_[b][k]) +
               Dyadic::from_double(pts_[c][k]) + Dyadic::from_double(pts_[d][k]);
    centre_[k] = s.shifted(-2);  // exact: the centroid is dyadic
    centre_approx_[k] = centre_[k].to_double();
    Dyadic diff = centre_[k] - Dyadic::from_double(centre_approx_[k]);
    if (diff.sign() < 0) diff = -diff;
    // to_double is within a few ulps; the factor and the floor make an upper bound.
    if (!diff.is_zero()) eta = std::max(eta, std::max(diff.to_double() * (1 + 0x1p-40), 0x1p-1000));
  }
  eta_ = eta;
  centre_safe_ = all_safe_ && geometry::filter_safe(centre_approx_) && std::isfinite(eta_) && eta_ < 0x1p200;
  double m = 0;
  for (const Point3d& p : pts_)
    for (double x : p) m = std::max(m, std::fabs(x));
  // |A_i|, |B_j| ≤ 2M, six products: Σ_{i≠j}|A_i||B_j| ≤ 24·M² (≤ 2^503 in the safe range).
  centre_error_ = eta_ > 0 ? eta_ * 24 * m * m * (1 + 0x1p-40) + geometry::kOrient3dAbsBound : 0;
}

ExactKernel::ApexFrame::ApexFrame(ExactKernel& k, int apex, int x) : k_(k), apex_(apex), x_(x), fast_(k.centre_safe_) {
  if (!fast_) return;
  const Point3d &a = k.pts_[apex], &p = k.pts_[x], &c = k.centre_approx_;
  const double bx = a[0] - p[0], by = a[1] - p[1], bz = a[2] - p[2];
  const double cx = c[0] - p[0], cy = c[1] - p[1], cz = c[2] - p[2];
  const double byz = by * cz, bzy = bz * cy, bzx = bz * cx, bxz = bx * cz, bxy = bx * cy, byx = by * cx;
  m_[0] = byz - bzy, m_[1] = bzx - bxz, m_[2] = bxy - byx;
  p_[0] = std::fabs(byz) + std::fabs(bzy), p_[1] = std::fabs(bzx) + std::fabs(bxz), p_[2] = std::fabs(bxy) + std::fabs(byx);
}

int ExactKernel::ApexFrame::sign_of(int y) {
  ++k_.counts_.orientation_tests;
  if (fast_) {
    const Point3d &q = k_.pts_[y], &p = k_.pts_[x_];
    const double ax = q[0] - p[0], ay = q[1] - p[1], az = q[2] - p[2];
    const double det = ax * m_[0] + ay * m_[1] + az * m_[2];
    const double perm = std::fabs(ax) * p_[0] + std::fabs(ay) * p_[1] + std::fabs(az) * p_[2];
    const double err = (geometry::kOrient3dErrBound * perm + geometry::kOrient3dAbsBound + k_.centre_error_) * (1 + 0x1p-50);
    if (det > err) return 1;
    if (-det > err) return -1;
  }
  ++k_.counts_.exact_fallbacks;
  // Shewchuk's orient3d(y, apex, c, x) = −orientation(y, apex, c, x) (CGAL's sign).
  return -geometry::orientation(geometry::to_dyadic(k_.pts_[y]), geometry::to_dyadic(k_.pts_[apex_]), k_.centre_,
                                geometry::to_dyadic(k_.pts_[x_]));
}

int ExactKernel::centre_side(int u, int v, int x) {
  ++counts_.orientation_tests;
  const Point3d &pu = pts_[u], &pv = pts_[v], &px = pts_[x];
  if (centre_safe_) {
    double value = 0, bound = 0;
    geometry::orientation_filter(pu, pv, centre_approx_, px, &value, &bound);
    if (eta_ > 0) {
      // |det[v−u, c−c̃, x−u]| ≤ η·Σ_{i≠j}|A_i||B_j| (A = v−u, B = x−u); (1 + 2^-48) covers the
      // rounding of A, B and of the sum; 2^-1070 a possible underflow of η·F.
      double ax = std::fabs(pv[0] - pu[0]), ay = std::fabs(pv[1] - pu[1]), az = std::fabs(pv[2] - pu[2]);
      double bx = std::fabs(px[0] - pu[0]), by = std::fabs(px[1] - pu[1]), bz = std::fabs(px[2] - pu[2]);
      double f = ax * (by + bz) + ay * (bx + bz) + az * (bx + by);
      bound = (bound + eta_ * f * (1 + 0x1p-48) + geometry::kOrient3dAbsBound) * (1 + 0x1p-50);
    }
    if (value > bound) return 1;
    if (-value > bound) return -1;
  }
  ++counts_.exact_fallbacks;
  return geometry::orientation(geometry::to_dyadic(pu), geometry::to_dyadic(pv), centre_, geometry::to_dyadic(px));
}

bool FloatKernel::collinear(int p, int q, int r) const {
  const Point3d &a = pts_[p], &b = pts_[q], &c = pts_[r];
  double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  return uy * vz - uz * vy == 0 && uz * vx - ux * vz == 0 && ux * vy - uy * vx == 0;
}

void FloatKernel::set_centre(int a, int b, int c, int d) {
  for (int k = 0; k < 3; ++k) centre_[k] = (pts_[a][k] + pts_[b][k] + pts_[c][k] + pts_[d][k]) * 0.25;
}

}  // namespace kmr::hull
