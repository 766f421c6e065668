// CGAL translation unit of the Chapter 3 oracles, D = 4: Delaunay adjacency from CGAL's dD
// Delaunay_triangulation over Epeck_d<Dimension_tag<4>> (exact predicates and constructions).
// Used to cross-check 4D Delaunay neighbourhoods; the 4D cells are clipped in ws_oracle.cpp.
// Guarantees: exact predicates on the exact input coordinates; sorted neighbour lists; duplicate
// points are refused with InputError.
#include <CGAL/Delaunay_triangulation.h>
#include <CGAL/Epeck_d.h>
#include <CGAL/Triangulation_data_structure.h>
#include <CGAL/Triangulation_full_cell.h>
#include <CGAL/Triangulation_vertex.h>

#include <algorithm>
#include <vector>

#include "exact/error.hpp"
#include "ws_cgal_ft.hpp"
#include "ws_oracle.hpp"

namespace kmr::oracle::ws {
namespace {

using K = CGAL::Epeck_d<CGAL::Dimension_tag<4>>;
using Vertex = CGAL::Triangulation_vertex<K, std::uint32_t>;
using Cell = CGAL::Triangulation_full_cell<K>;
using TDS = CGAL::Triangulation_data_structure<CGAL::Dimension_tag<4>, Vertex, Cell>;
using DT = CGAL::Delaunay_triangulation<K, TDS>;
using FT = K::FT;
using ET = CGAL::internal::Exact_field_selector<double>::Type;

FT to_ft(const exact::Dyadic& d) { return detail::to_ft<FT, ET>(d); }

}  // namespace

template <>
std::vector<std::vector<std::uint32_t>> cgal_delaunay_adjacency<4>(const std::vector<XPoint<4>>& pts) {
  std::vector<std::vector<std::uint32_t>> adj(pts.size());
  if (pts.size() < 2) return adj;
  DT dt(4);
  DT::Full_cell_handle hint;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::vector<FT> c;
    for (const auto& x : pts[i]) c.push_back(to_ft(x));
    K::Point_d p(c.begin(), c.end());
    auto v = hint == DT::Full_cell_handle() ? dt.insert(p) : dt.insert(p, hint);
    if (dt.number_of_vertices() != i + 1) throw InputError("CGAL dD Delaunay oracle: duplicate points");
    v->data() = static_cast<std::uint32_t>(i);
    hint = v->full_cell();
  }
  const int cd = dt.current_dimension();
  for (auto c = dt.finite_full_cells_begin(); c != dt.finite_full_cells_end(); ++c) {
    for (int i = 0; i <= cd; ++i)
      for (int j = i + 1; j <= cd; ++j) {
        std::uint32_t a = c->vertex(i)->data(), b = c->vertex(j)->data();
        adj[a].push_back(b);
        adj[b].push_back(a);
      }
  }
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  return adj;
}

}  // namespace kmr::oracle::ws
