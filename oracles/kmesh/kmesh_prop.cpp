// RapidCheck properties of the Chapter 4 construction, judged by CGAL (kmesh_oracle.hpp) and by the
// library's brute-force lemma checks: random sets, clusters with spread 2^30, collinear and
// cocircular starts, and duplicates (refused).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <set>

#include "exact/error.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh_oracle.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;
namespace ko = kmr::oracle::kmesh;

namespace {

void judge_all(std::vector<InputPoint> in) {
  std::sort(in.begin(), in.end());
  in.erase(std::unique(in.begin(), in.end()), in.end());
  Mesh m = construct(in);
  std::vector<std::array<Dyadic, 2>> pos;
  for (std::size_t i = 0; i < m.size(); ++i) pos.push_back(m.spanner.position(static_cast<int>(i)));
  auto r = ko::judge_mesh(pos, m.n(), m.triangles);
  RC_ASSERT(r.ok());
  for (auto& c : {check_ball_empty(m), check_independent_set(m), check_voronoi_candidates(m)})
    RC_ASSERT(c.ok());
}

}  // namespace

RC_GTEST_PROP(KmeshProp, L4_2_RandomSmallSets, ()) {
  int n = *rc::gen::inRange(2, 7);
  auto xs = *rc::gen::container<std::vector<int>>(n, rc::gen::inRange(-64, 64));
  auto ys = *rc::gen::container<std::vector<int>>(n, rc::gen::inRange(-64, 64));
  std::vector<InputPoint> in;
  for (int i = 0; i < n; ++i) in.push_back({Integer(xs[i]), Integer(ys[i])});
  judge_all(in);
}

RC_GTEST_PROP(KmeshProp, L4_2_ClusterSpread2To30, ()) {
  int k = *rc::gen::inRange(1, 4);
  std::vector<InputPoint> in{{Integer(0), Integer(0)}};
  for (int i = 0; i < k; ++i) in.push_back({Integer(*rc::gen::inRange(-3, 4)), Integer(*rc::gen::inRange(-3, 4))});
  in.push_back({Integer(1) << 30, Integer(*rc::gen::inRange(-1000, 1000))});
  judge_all(in);
}

RC_GTEST_PROP(KmeshProp, L4_2_CollinearAndCocircularStarts, ()) {
  bool collinear = *rc::gen::arbitrary<bool>();
  std::vector<InputPoint> in;
  if (collinear) {
    int n = *rc::gen::inRange(2, 6), step = *rc::gen::inRange(1, 9);
    for (int i = 0; i < n; ++i) in.push_back({Integer(i * step), Integer(2 * i * step)});
  } else {
    // Points of the circle x² + y² = 25 (all 12 integer points), a random subset.
    const int c[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    for (int i = 0; i < 12; ++i)
      if (*rc::gen::inRange(0, 3) > 0) in.push_back({Integer(c[i][0]), Integer(c[i][1])});
    if (in.size() < 2) in = {{Integer(5), Integer(0)}, {Integer(-5), Integer(0)}};
  }
  judge_all(in);
}

RC_GTEST_PROP(KmeshProp, DuplicatesAreRefused, ()) {
  int x = *rc::gen::inRange(-100, 100), y = *rc::gen::inRange(-100, 100);
  std::vector<InputPoint> in{{Integer(x), Integer(y)}, {Integer(x + 1), Integer(y)}, {Integer(x), Integer(y)}};
  RC_ASSERT_THROWS_AS(construct(in), kmr::InputError);
}
