#include "cgal_hull.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>
#include <set>

namespace kmr_oracle {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using P3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<P3>;

}  // namespace

std::string compare_with_cgal(const std::vector<Pt>& pts, const std::vector<int>& vertices,
                              const std::vector<Tri>& facets) {
  std::vector<P3> cp;
  std::map<P3, int> name;  // lowest index of each point
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    cp.emplace_back(pts[i][0], pts[i][1], pts[i][2]);
    name.emplace(cp.back(), i);
  }
  Mesh mesh;
  CGAL::convex_hull_3(cp.begin(), cp.end(), mesh);
  std::vector<Tri> theirs;
  for (auto f : mesh.faces()) {
    Tri t;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[k++] = name.at(mesh.point(v));
    theirs.push_back(t);
  }
  auto in_closed_triangle = [&](int w, const Tri& t) {
    const P3 &a = cp[t[0]], &b = cp[t[1]], &c = cp[t[2]], &q = cp[w];
    if (CGAL::orientation(a, b, c, q) != CGAL::COPLANAR) return false;
    return CGAL::coplanar_orientation(a, b, q) != CGAL::NEGATIVE && CGAL::coplanar_orientation(b, c, q) != CGAL::NEGATIVE &&
           CGAL::coplanar_orientation(c, a, q) != CGAL::NEGATIVE;
  };
  std::set<int> want;
  for (auto v : mesh.vertices()) want.insert(name.at(mesh.point(v)));
  for (auto it = want.begin(); it != want.end();) {
    bool interior = false;
    for (const Tri& t : facets)
      if (t[0] != *it && t[1] != *it && t[2] != *it && in_closed_triangle(*it, t)) interior = true;
    it = interior ? want.erase(it) : std::next(it);
  }
  if (std::vector<int>(want.begin(), want.end()) != vertices)
    return "vertex sets differ (ours " + std::to_string(vertices.size()) + ", CGAL's extreme " + std::to_string(want.size()) + ")";
  // face planes as sets of (lowest-named) input points on them
  std::set<int> uniq;
  for (auto& [p, i] : name) uniq.insert(i);
  auto plane_of = [&](const Tri& t) {
    std::vector<int> on;
    for (int i : uniq)
      if (CGAL::orientation(cp[t[0]], cp[t[1]], cp[t[2]], cp[i]) == CGAL::COPLANAR) on.push_back(i);
    return on;
  };
  auto projected = [&](const Tri& t, const std::vector<int>& on) {
    // signed area projected on the coordinate plane dropping the axis of largest |normal| sign
    EK::Point_3 a(pts[t[0]][0], pts[t[0]][1], pts[t[0]][2]), b(pts[t[1]][0], pts[t[1]][1], pts[t[1]][2]),
        c(pts[t[2]][0], pts[t[2]][1], pts[t[2]][2]);
    EK::Vector_3 n = CGAL::cross_product(b - a, c - a);
    (void)on;
    return std::array<EK::FT, 3>{n.x(), n.y(), n.z()};
  };
  std::map<std::vector<int>, std::array<EK::FT, 3>> sum_ours, sum_theirs;
  for (const Tri& t : facets) {
    for (int i : uniq)
      if (CGAL::orientation(cp[t[0]], cp[t[1]], cp[t[2]], cp[i]) == CGAL::POSITIVE)
        return "facet [" + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "] is not outward";
    auto key = plane_of(t);
    auto n = projected(t, key);
    auto& s = sum_ours.try_emplace(key, std::array<EK::FT, 3>{EK::FT(0), EK::FT(0), EK::FT(0)}).first->second;
    for (int k = 0; k < 3; ++k) s[k] = s[k] + n[k];
  }
  for (const Tri& t : theirs) {
    for (int i : uniq)
      if (CGAL::orientation(cp[t[0]], cp[t[1]], cp[t[2]], cp[i]) == CGAL::POSITIVE) return "CGAL's facet is not outward?";
    auto key = plane_of(t);
    auto n = projected(t, key);
    auto& s = sum_theirs.try_emplace(key, std::array<EK::FT, 3>{EK::FT(0), EK::FT(0), EK::FT(0)}).first->second;
    for (int k = 0; k < 3; ++k) s[k] = s[k] + n[k];
  }
  if (sum_ours.size() != sum_theirs.size())
    return "face planes differ: ours " + std::to_string(sum_ours.size()) + ", CGAL's " + std::to_string(sum_theirs.size());
  for (auto& [key, s] : sum_ours) {
    auto it = sum_theirs.find(key);
    if (it == sum_theirs.end()) return "a face plane of ours is not CGAL's";
    for (int k = 0; k < 3; ++k)
      if (CGAL::compare(s[k], it->second[k]) != CGAL::EQUAL)
        return "a face is not covered exactly (area vector differs from CGAL's: " + std::to_string(CGAL::to_double(s[k])) + " vs " + std::to_string(CGAL::to_double(it->second[k])) + ")";
  }
  return "";
}

}  // namespace kmr_oracle
