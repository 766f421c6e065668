#pragma once
// The predicates the incremental hull (§2.2) asks, over points given by input index. Two kernels:
//
//  * ExactKernel: every answer is the true sign. orientation is geometry::filtered_orientation
//    (Shewchuk-style filter, Dyadic fallback). The centre c = (a+b+c+d)/4 of the initial
//    tetrahedron is kept exactly as a Dyadic point (the sum of four doubles is dyadic; /4 is a
//    shift, so no scaling by 4 is needed); centre tests orientation(u, v, c, x) are filtered with c
//    rounded to a double c̃ and the extra error |det[v−u, c−c̃, x−u]| ≤ η·Σ_{i≠j}|A_i||B_j|
//    (A = v−u, B = x−u, η ≥ max_k |c_k − c̃_k|) added to the orientation filter's bound.
//  * FloatKernel: the same questions in plain double arithmetic, with c̃ as the centre. Not robust:
//    near-degenerate inputs may get wrong signs (the Fig. 2.4 baseline only).
//
// Both count their orientation tests and (exact) the filter failures that went to Dyadic.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "exact/dyadic.hpp"
#include "geometry/filtered_orientation.hpp"

namespace kmr::hull {

using Point3d = geometry::Point3d;

struct PredicateCounts {
  std::uint64_t orientation_tests = 0;  // orientation and centre tests together
  std::uint64_t exact_fallbacks = 0;    // decided by Dyadic arithmetic (ExactKernel only)
};

class ExactKernel {
 public:
  explicit ExactKernel(const std::vector<Point3d>& points);
  static constexpr bool exact = true;

  int orientation(int p, int q, int r, int s);
  bool equal(int p, int q) const { return pts_[p] == pts_[q]; }
  bool collinear(int p, int q, int r);
  // Fixes the centre to the centroid of the initial tetrahedron a, b, c, d.
  void set_centre(int a, int b, int c, int d);
  // orientation(u, v, centre, x): ≥ 0 iff x lies on the side of plane (u, v, c) the pyramid of
  // face (u, v, w) occupies.
  int centre_side(int u, int v, int x);
  const PredicateCounts& counts() const { return counts_; }

  // The side tests around one tent apex k for one point x (history.hpp's search_tent asks
  // orientation(w, k, c, x) and orientation(k, v, c, x) for many w, v): the same exact answers as
  // centre_side, with k − x, c̃ − x and their 2×2 minors computed once. The filter evaluates
  // det[y−x; k−x; c̃−x] by cofactors along its first row — the same operation tree as Shewchuk's
  // orient3d (a difference times a 2×2 minor of differences, three terms summed), so the same bound
  // (7 + 56ε)ε·P̃ + 2^-1070 holds, plus the centre term (static: η·24·M², M the largest |coordinate|).
  class ApexFrame {
   public:
    ApexFrame(ExactKernel& k, int apex, int x);
    int side_before(int w) { return -cached(w); }  // orientation(w, apex, c, x)
    int side_after(int v) { return cached(v); }    // orientation(apex, v, c, x)

   private:
    // Each ring vertex y of the tent is v1 of one face and v2 of the next: both tests are the sign
    // of one determinant, computed once per search.
    int cached(int y) {
      for (int i = 0; i < used_; ++i)
        if (seen_[i] == y) return sign_[i];
      int s = sign_of(y);
      if (used_ < kCache) seen_[used_] = y, sign_[used_++] = s;
      return s;
    }
    int sign_of(int y);  // sign of det[y−x; apex−x; c̃−x] (Shewchuk's orient3d(y, apex, c, x))
    static constexpr int kCache = 16;
    ExactKernel& k_;
    int apex_, x_;
    bool fast_;
    double m_[3], p_[3];
    int used_ = 0, seen_[kCache], sign_[kCache];
  };
  ApexFrame apex_frame(int apex, int x) { return ApexFrame(*this, apex, x); }

 private:
  double centre_error_ = 0;  // η·24·M²·(1 + 2^-40): bounds |det[v−u, c−c̃, x−u]| for all inputs
  const std::vector<Point3d>& pts_;
  bool all_safe_ = true;  // every input coordinate in the filter's safe range
  bool centre_safe_ = false;
  Point3d centre_approx_{};
  double eta_ = 0;  // ≥ max_k |c_k − c̃_k|
  geometry::Point<3, exact::Dyadic> centre_;
  PredicateCounts counts_;
};

class FloatKernel {
 public:
  explicit FloatKernel(const std::vector<Point3d>& points) : pts_(points) {}
  static constexpr bool exact = false;

  int orientation(int p, int q, int r, int s) {
    ++counts_.orientation_tests;
    return sign(det(pts_[p], pts_[q], pts_[r], pts_[s]));
  }
  bool equal(int p, int q) const { return pts_[p] == pts_[q]; }
  bool collinear(int p, int q, int r) const;
  void set_centre(int a, int b, int c, int d);
  int centre_side(int u, int v, int x) {
    ++counts_.orientation_tests;
    return sign(det(pts_[u], pts_[v], centre_, pts_[x]));
  }
  const PredicateCounts& counts() const { return counts_; }

  class ApexFrame {  // plain-double twin of ExactKernel::ApexFrame
   public:
    ApexFrame(FloatKernel& k, int apex, int x) : k_(k), x_(x) {
      const Point3d &a = k.pts_[apex], &p = k.pts_[x], &c = k.centre_;
      const double bx = a[0] - p[0], by = a[1] - p[1], bz = a[2] - p[2];
      const double cx = c[0] - p[0], cy = c[1] - p[1], cz = c[2] - p[2];
      m_[0] = by * cz - bz * cy, m_[1] = bz * cx - bx * cz, m_[2] = bx * cy - by * cx;
    }
    int side_before(int w) { return -cached(w); }
    int side_after(int v) { return cached(v); }

   private:
    int cached(int y) {
      for (int i = 0; i < used_; ++i)
        if (seen_[i] == y) return sign_[i];
      ++k_.counts_.orientation_tests;
      const Point3d &q = k_.pts_[y], &p = k_.pts_[x_];
      int s = sign((q[0] - p[0]) * m_[0] + (q[1] - p[1]) * m_[1] + (q[2] - p[2]) * m_[2]);
      if (used_ < kCache) seen_[used_] = y, sign_[used_++] = s;
      return s;
    }
    static constexpr int kCache = 16;
    FloatKernel& k_;
    int x_;
    double m_[3];
    int used_ = 0, seen_[kCache], sign_[kCache];
  };
  ApexFrame apex_frame(int apex, int x) { return ApexFrame(*this, apex, x); }

 private:
  static int sign(double v) { return (v > 0) - (v < 0); }
  // det[q−p, r−p, s−p] in doubles (CGAL's orientation, unfiltered).
  static double det(const Point3d& p, const Point3d& q, const Point3d& r, const Point3d& s) {
    double ux = q[0] - p[0], uy = q[1] - p[1], uz = q[2] - p[2];
    double vx = r[0] - p[0], vy = r[1] - p[1], vz = r[2] - p[2];
    double wx = s[0] - p[0], wy = s[1] - p[1], wz = s[2] - p[2];
    return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  }
  const std::vector<Point3d>& pts_;
  Point3d centre_{};
  PredicateCounts counts_;
};

}  // namespace kmr::hull
