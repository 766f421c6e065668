// CGAL translation unit of the Chapter 3 oracles, D = 2 and 3: Delaunay adjacency and nearest-site
// queries with Exact_predicates_exact_constructions_kernel. Nothing else of the oracle is here:
// the clipped cells and every comparison are computed in ws_oracle.cpp with GMP rationals.
// Guarantees: exact predicates on exact (rational) coordinates; neighbour lists are sorted and
// independent of insertion order up to the (degenerate) choice of a Delaunay triangulation, which
// never changes any oracle answer (extra edges of a cospherical cell give redundant half-spaces).
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <utility>

#include "exact/error.hpp"
#include "ws_cgal_ft.hpp"
#include "ws_oracle.hpp"

namespace kmr::oracle::ws {
namespace {

using K = CGAL::Epeck;
using FT = K::FT;
using ET = CGAL::internal::Exact_field_selector<double>::Type;

FT to_ft(const exact::Dyadic& d) { return detail::to_ft<FT, ET>(d); }

using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Tds2 = CGAL::Triangulation_data_structure_2<Vb2>;
using DT2 = CGAL::Delaunay_triangulation_2<K, Tds2>;
using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3>;
using DT3 = CGAL::Delaunay_triangulation_3<K, Tds3>;

K::Point_2 pt(const XPoint<2>& p) { return K::Point_2(to_ft(p[0]), to_ft(p[1])); }
K::Point_3 pt(const XPoint<3>& p) { return K::Point_3(to_ft(p[0]), to_ft(p[1]), to_ft(p[2])); }
DT2::Face_handle incident(DT2::Vertex_handle v) { return v->face(); }
DT3::Cell_handle incident(DT3::Vertex_handle v) { return v->cell(); }

template <class DT, std::size_t D>
DT build(const std::vector<XPoint<D>>& pts) {
  std::vector<std::pair<typename DT::Point, std::uint32_t>> in;
  in.reserve(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) in.emplace_back(pt(pts[i]), static_cast<std::uint32_t>(i));
  DT dt(in.begin(), in.end());
  if (dt.number_of_vertices() != pts.size())
    throw InputError("CGAL Delaunay oracle: duplicate points in the input");
  return dt;
}

void finish(std::vector<std::vector<std::uint32_t>>& adj) {
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
}

std::pair<std::uint32_t, std::uint32_t> ends(const DT2::Edge& e) {
  return {e.first->vertex(DT2::cw(e.second))->info(), e.first->vertex(DT2::ccw(e.second))->info()};
}
std::pair<std::uint32_t, std::uint32_t> ends(const DT3::Edge& e) {
  return {e.first->vertex(e.second)->info(), e.first->vertex(e.third)->info()};
}

// Sorted neighbour lists from the finite edges (works in every current dimension 1..D).
template <class DT, std::size_t D>
std::vector<std::vector<std::uint32_t>> adjacency(const std::vector<XPoint<D>>& pts) {
  std::vector<std::vector<std::uint32_t>> adj(pts.size());
  if (pts.size() < 2) return adj;
  DT dt = build<DT, D>(pts);
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    auto [a, b] = ends(*e);
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  finish(adj);
  return adj;
}

// Index of a nearest site per query; each answer's vertex is the hint of the next location.
template <class DT, std::size_t D>
std::vector<std::uint32_t> nearest(const std::vector<XPoint<D>>& sites,
                                   const std::vector<XPoint<D>>& queries) {
  DT dt = build<DT, D>(sites);
  std::vector<std::uint32_t> out;
  out.reserve(queries.size());
  typename DT::Vertex_handle last;
  for (const auto& q : queries) {
    last = last == typename DT::Vertex_handle() ? dt.nearest_vertex(pt(q))
                                                : dt.nearest_vertex(pt(q), incident(last));
    out.push_back(last->info());
  }
  return out;
}

}  // namespace

template <>
std::vector<std::vector<std::uint32_t>> cgal_delaunay_adjacency<2>(const std::vector<XPoint<2>>& pts) {
  return adjacency<DT2, 2>(pts);
}

template <>
std::vector<std::vector<std::uint32_t>> cgal_delaunay_adjacency<3>(const std::vector<XPoint<3>>& pts) {
  return adjacency<DT3, 3>(pts);
}

template <>
std::vector<std::uint32_t> cgal_nearest_site<2>(const std::vector<XPoint<2>>& sites,
                                                const std::vector<XPoint<2>>& queries) {
  return nearest<DT2, 2>(sites, queries);
}

template <>
std::vector<std::uint32_t> cgal_nearest_site<3>(const std::vector<XPoint<3>>& sites,
                                                const std::vector<XPoint<3>>& queries) {
  return nearest<DT3, 3>(sites, queries);
}

}  // namespace kmr::oracle::ws
