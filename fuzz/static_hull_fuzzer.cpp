// Fuzz harness for the static 3D hull (§2.2, src/hull): small point sets with many duplicates and
// coplanarities (integer coordinates in [−3, 3], some points copied or placed on the plane z = 0),
// judged by a brute-force exact hull written here in 64-bit integers (coordinates ≤ 3·2^k with
// k ≤ 12 keep every product (a dot of two cross products ≤ 2^59) below 2^63):
//  * degenerate input (no four affinely independent points) must be refused with InputError;
//  * vertices = the extreme points (corners of the supporting planes' point sets), lowest index
//    among equal points; every facet lies on a supporting plane, is outward, uses only vertices;
//  * the facets form a closed surface (each directed edge once, its reverse once) and cover each
//    face's polygon exactly (projected areas sum to the polygon's).
// Exact and float versions run; only the exact one is judged (float is not robust).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <vector>

#include "exact/error.hpp"
#include "hull/hull.hpp"

namespace {

using I = long long;
using V = std::array<I, 3>;

#define HULL_CHECK(cond)                                                   \
  do {                                                                     \
    if (!(cond)) {                                                         \
      std::fprintf(stderr, "HULL_CHECK failed: %s at line %d\n", #cond, __LINE__); \
      std::abort();                                                        \
    }                                                                      \
  } while (0)

V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
I dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
int sgn(I x) { return (x > 0) - (x < 0); }
bool zero(V a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int scale = data[0] % 13;  // coordinates times 2^scale (≤ 2^12: every product below 2^62)
  std::vector<V> p;
  for (std::size_t i = 1; i + 2 < size && p.size() < 14; i += 3) {
    std::uint8_t a = data[i], b = data[i + 1], c = data[i + 2];
    if ((c & 0xC0) == 0xC0 && !p.empty()) {
      p.push_back(p[a % p.size()]);  // a duplicate
      continue;
    }
    V v{I(a % 7) - 3, I(b % 7) - 3, (c & 0xC0) == 0x80 ? 0 : I(c % 7) - 3};  // 1/4: on z = 0
    for (I& x : v) x *= (I(1) << scale);
    p.push_back(v);
  }
  const int n = static_cast<int>(p.size());
  std::vector<kmr::hull::Point3d> pts;
  for (const V& v : p) pts.push_back({double(v[0]), double(v[1]), double(v[2])});

  // Brute force: names, supporting planes, corners.
  std::vector<int> name(n);
  for (int i = 0; i < n; ++i) {
    name[i] = i;
    for (int k = 0; k < i; ++k)
      if (p[k] == p[i]) { name[i] = name[k]; break; }
  }
  std::vector<int> u;
  for (int i = 0; i < n; ++i)
    if (name[i] == i) u.push_back(i);
  struct Plane { V normal; int a; std::vector<int> on, corners; };
  std::vector<Plane> planes;
  std::set<std::vector<int>> seen;
  std::set<int> extreme;
  for (std::size_t a = 0; a < u.size(); ++a)
    for (std::size_t b = a + 1; b < u.size(); ++b)
      for (std::size_t c = b + 1; c < u.size(); ++c) {
        V nr = cross(sub(p[u[b]], p[u[a]]), sub(p[u[c]], p[u[a]]));
        if (zero(nr)) continue;
        int pos = 0, neg = 0;
        std::vector<int> on;
        for (int i : u) {
          int s = sgn(dot(nr, sub(p[i], p[u[a]])));
          pos += s > 0, neg += s < 0;
          if (!s) on.push_back(i);
        }
        if ((pos && neg) || (!pos && !neg) || !seen.insert(on).second) continue;
        Plane pl{pos ? V{-nr[0], -nr[1], -nr[2]} : nr, u[a], on, {}};
        for (int q : on) {  // a corner lies in no closed triangle / open segment of the others
          bool in = false;
          for (int r : on)
            for (int s : on) {
              if (in || r == q || s == q || r >= s) continue;
              V d1 = sub(p[r], p[q]), d2 = sub(p[s], p[q]);
              if (zero(cross(d1, d2)) && dot(d1, d2) < 0) in = true;
              for (int t : on) {
                if (in || t == q || t <= s) continue;
                V tn = cross(sub(p[s], p[r]), sub(p[t], p[r]));
                if (zero(tn)) continue;
                if (dot(cross(sub(p[s], p[r]), sub(p[q], p[r])), tn) >= 0 &&
                    dot(cross(sub(p[t], p[s]), sub(p[q], p[s])), tn) >= 0 &&
                    dot(cross(sub(p[r], p[t]), sub(p[q], p[t])), tn) >= 0)
                  in = true;
              }
            }
          if (!in) pl.corners.push_back(q), extreme.insert(q);
        }
        planes.push_back(pl);
      }

  kmr::hull::Hull h;
  try {
    h = kmr::hull::convex_hull(pts, kmr::hull::Arithmetic::exact, data[0]);
  } catch (const kmr::InputError&) {
    HULL_CHECK(planes.empty());  // refused exactly when degenerate
    return 0;
  }
  HULL_CHECK(!planes.empty());
  try {
    kmr::hull::convex_hull(pts, kmr::hull::Arithmetic::floating, data[0]);  // must not crash
  } catch (const std::exception&) {
  }
  HULL_CHECK(std::vector<int>(extreme.begin(), extreme.end()) == h.vertices);
  std::map<std::pair<int, int>, int> edges;
  std::vector<I> covered(planes.size(), 0);
  auto axis = [](const V& nr) { return nr[0] ? 0 : nr[1] ? 1 : 2; };
  auto area = [&](int a, int b, int c, int k) {  // twice the area projected along axis k
    int x = (k + 1) % 3, y = (k + 2) % 3;
    return (p[b][x] - p[a][x]) * (p[c][y] - p[a][y]) - (p[b][y] - p[a][y]) * (p[c][x] - p[a][x]);
  };
  for (auto t : h.facets) {
    HULL_CHECK(t[0] < t[1] && t[0] < t[2]);
    for (int v : t) HULL_CHECK(extreme.count(v));
    int fi = -1;
    for (std::size_t f = 0; f < planes.size(); ++f) {
      auto& on = planes[f].on;
      if (std::count(on.begin(), on.end(), t[0]) && std::count(on.begin(), on.end(), t[1]) &&
          std::count(on.begin(), on.end(), t[2]))
        fi = int(f);
    }
    HULL_CHECK(fi >= 0);
    const V& nr = planes[fi].normal;
    HULL_CHECK(dot(cross(sub(p[t[1]], p[t[0]]), sub(p[t[2]], p[t[0]])), nr) > 0);
    int k = axis(nr);
    covered[fi] += area(t[0], t[1], t[2], k) * sgn(nr[k]);
    for (int e = 0; e < 3; ++e) HULL_CHECK((++edges[{t[e], t[(e + 1) % 3]}] == 1));
  }
  for (auto& [e, c] : edges) HULL_CHECK((c == 1 && edges.count({e.second, e.first})));
  for (std::size_t f = 0; f < planes.size(); ++f) {
    auto c = planes[f].corners;
    const V& nr = planes[f].normal;
    int c0 = c[0], k = axis(nr);
    std::sort(c.begin() + 1, c.end(), [&](int a, int b) { return dot(cross(sub(p[a], p[c0]), sub(p[b], p[c0])), nr) > 0; });
    I want = 0;
    for (std::size_t i = 1; i + 1 < c.size(); ++i) want += area(c0, c[i], c[i + 1], k) * sgn(nr[k]);
    HULL_CHECK(want == covered[f]);
  }
  return 0;
}
