// The one CGAL translation unit of the Chapter 4 oracle (see kmesh_oracle.hpp).
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <set>

#include <boost/multiprecision/gmp.hpp>

#include "kmesh_oracle.hpp"

namespace kmr::oracle::kmesh {
namespace {

using K = CGAL::Epeck;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
using P = K::Point_2;
using FT = K::FT;
using ET = FT::ET;
using Q = boost::multiprecision::mpq_rational;

FT to_ft(const exact::Dyadic& d) {
  Q q;
  if (d.exponent() >= 0)
    q = Q(exact::Integer(d.mantissa() << static_cast<unsigned>(d.exponent())));
  else
    q = Q(d.mantissa(), exact::Integer(1) << static_cast<unsigned>(-d.exponent()));
  return FT(ET(q.backend().data()));
}

void add(Report& r, const std::string& s) {
  if (r.violations.size() < 20) r.violations.push_back(s);
}

DT triangulate(const std::vector<P>& pts, std::size_t count) {
  std::vector<std::pair<P, int>> v;
  for (std::size_t i = 0; i < count; ++i) v.push_back({pts[i], static_cast<int>(i)});
  return DT(v.begin(), v.end());
}

}  // namespace

Report judge_mesh(const std::vector<std::array<exact::Dyadic, 2>>& M, std::size_t n_input,
                  const std::vector<std::array<int, 3>>& triangles) {
  Report r;
  const std::size_t N = M.size();
  std::vector<P> pts;
  for (auto& p : M) pts.push_back(P(to_ft(p[0]), to_ft(p[1])));
  DT dt = triangulate(pts, N);
  if (dt.number_of_vertices() != N) add(r, "CGAL: duplicate vertices in M");
  r.cgal_faces = dt.number_of_faces();
  std::vector<DT::Vertex_handle> vh(N);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) vh[v->info()] = v;

  // Delaunay.
  if (triangles.size() != dt.number_of_faces())
    add(r, "triangle count " + std::to_string(triangles.size()) + " differs from CGAL's " + std::to_string(dt.number_of_faces()));
  std::set<std::array<int, 3>> mine;
  for (auto t : triangles) {
    if (CGAL::orientation(pts[t[0]], pts[t[1]], pts[t[2]]) != CGAL::LEFT_TURN) {
      add(r, "a triangle is not counter-clockwise");
      continue;
    }
    P c = CGAL::circumcenter(pts[t[0]], pts[t[1]], pts[t[2]]);
    auto nv = dt.nearest_vertex(c);
    if (CGAL::compare_squared_distance(c, nv->point(), CGAL::squared_distance(c, pts[t[0]])) == CGAL::SMALLER)
      add(r, "vertex " + std::to_string(nv->info()) + " is inside the circumcircle of a triangle");
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    if (!mine.insert(t).second) add(r, "a triangle is listed twice");
  }
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    bool strict = true;
    for (int i = 0; i < 3 && strict; ++i) {
      auto g = f->neighbor(i);
      if (dt.is_infinite(g)) continue;
      auto apex = g->vertex(g->index(f));
      if (CGAL::side_of_oriented_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                                        apex->point()) != CGAL::ON_NEGATIVE_SIDE)
        strict = false;
    }
    if (!strict) continue;
    std::array<int, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    if (!mine.count(t)) add(r, "CGAL's (non-degenerate) Delaunay triangle (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ") is missing");
  }

  // 9/2-well-spacedness over the Voronoi vertices of each vertex.
  if (N >= 2)
    for (std::size_t i = 0; i < N; ++i) {
      auto v = vh[i];
      FT nn2 = -1;
      auto c = dt.incident_vertices(v), done = c;
      do {
        if (dt.is_infinite(c)) continue;
        FT d = CGAL::squared_distance(v->point(), c->point());
        if (nn2 < 0 || d < nn2) nn2 = d;
      } while (++c != done);
      auto f = dt.incident_faces(v), fdone = f;
      if (f != nullptr) do {
          if (dt.is_infinite(f)) continue;
          P cc = dt.circumcenter(f);
          FT R2 = CGAL::squared_distance(v->point(), cc);
          if (4 * R2 > 81 * nn2) add(r, "vertex " + std::to_string(i) + " is not 9/2-well-spaced");
          r.max_well_spaced = std::max(r.max_well_spaced, std::sqrt(CGAL::to_double(R2) / CGAL::to_double(nn2)));
        } while (++f != fdone);
    }

  // Size conformity: lfs(v) = distance to the second-nearest input point, through CGAL's DT of N
  // (the second nearest site of a query is a Delaunay neighbour of the nearest).
  if (n_input >= 2 && N >= 2) {
    DT dn = triangulate(pts, n_input);
    for (std::size_t i = 0; i < N; ++i) {
      auto u1 = dn.nearest_vertex(pts[i]);
      FT d1 = CGAL::squared_distance(pts[i], u1->point()), d2 = -1;
      auto c = dn.incident_vertices(u1), done = c;
      do {
        if (dn.is_infinite(c)) continue;
        FT d = CGAL::squared_distance(pts[i], c->point());
        if (d2 < 0 || d < d2) d2 = d;
      } while (++c != done);
      FT lfs2 = i < n_input ? std::max(d1, d2) : d2;  // an input point is its own nearest
      FT nn2 = -1;
      auto w = dt.incident_vertices(vh[i]), wd = w;
      do {
        if (dt.is_infinite(w)) continue;
        FT d = CGAL::squared_distance(pts[i], w->point());
        if (nn2 < 0 || d < nn2) nn2 = d;
      } while (++w != wd);
      r.max_size_ratio = std::max(r.max_size_ratio, std::sqrt(CGAL::to_double(lfs2) / CGAL::to_double(nn2)));
    }
  }
  return r;
}

}  // namespace kmr::oracle::kmesh
