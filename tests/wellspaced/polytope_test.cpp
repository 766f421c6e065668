// Exact polytope clipping and face distances (§3.2.4), against hand-computed cells.
#include <gtest/gtest.h>

#include "wellspaced/polytope.hpp"

using namespace kmr::wellspaced;

TEST(WellspacedPolytope, SquareCutByBisector) {
  Polytope<2> P = Polytope<2>::box({Q(0), Q(0)}, {Q(1), Q(1)});
  QPoint<2> v{Q(1, 4), Q(1, 2)}, u{Q(3, 4), Q(1, 2)};
  P.clip(bisector<2>(v, u));  // x ≤ 1/2
  ASSERT_EQ(P.v.size(), 4u);
  Q m = P.max_dist2(v);  // farthest: (1/2, 0) or (0,0)/(0,1): (1/4)^2+(1/2)^2 = 5/16
  EXPECT_EQ(m, Q(5, 16));
}
TEST(WellspacedPolytope, DegenerateGridCellIsASquare) {
  // v at the centre of a 3x3 grid: 8 neighbours, 4 of them cut only at the cell's corners.
  QPoint<2> v{Q(1, 2), Q(1, 2)};
  Polytope<2> P = Polytope<2>::box({Q(0), Q(0)}, {Q(1), Q(1)});
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      if (i || j) P.clip(bisector<2>(v, {Q(1, 2) + Q(i, 4), Q(1, 2) + Q(j, 4)}));
  EXPECT_EQ(P.v.size(), 4u);
  EXPECT_EQ(P.max_dist2(v), Q(1, 32));  // corners at (±1/8, ±1/8)
}
TEST(WellspacedPolytope, FaceWithinBall3D) {
  QPoint<3> v{Q(0), Q(0), Q(0)};
  Polytope<3> P = Polytope<3>::box({Q(-4), Q(-4), Q(-4)}, {Q(4), Q(4), Q(4)});
  int j = P.clip(bisector<3>(v, {Q(2), Q(0), Q(0)}));  // x ≤ 1: the face is at distance 1
  EXPECT_TRUE(P.face_within(j, v, Q(1), 6));
  EXPECT_FALSE(P.face_within(j, v, Q(99, 100), 6));
  // a second constraint hides the midpoint: y ≥ 1 on the face x = 1 → nearest point (1,1,0), d² = 2
  int k = P.clip(Halfspace<3>{{Q(0), Q(-1), Q(0)}, Q(-1)});
  (void)k;
  EXPECT_FALSE(P.face_within(j, v, Q(199, 100), 6));
  EXPECT_TRUE(P.face_within(j, v, Q(2), 6));
}
