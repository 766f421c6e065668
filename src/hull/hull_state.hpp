#pragma once
// The hull's history structure: Appendix A's EXTENDED_GEOMETRY_3D (vertices, faces, neighbours,
// killers), as plain arrays indexed by point index and face id (faces numbered in creation order,
// so every run is deterministic).
//
// Invariants (kept by rip_and_tent.hpp and checked by the tests through the output):
//  * A face f = (v0, v1, v2) is counter-clockwise seen from outside the hull it was created in:
//    orientation(v0, v1, v2, x) < 0 for every point x interior to that hull.
//  * nbr[0], nbr[1], nbr[2] are the faces across edges (v0,v1), (v1,v2), (v2,v0) in the hull the
//    face belongs to; the faces with killer < 0 (alive) form a closed triangulated surface: the
//    boundary of the current hull conv(A_i).
//  * killer ≥ 0 is the point whose insertion removed (ripped) the face.
//  * The faces created by the insertion of point p (its tent) are the ids
//    [first_face[p], first_face[p] + face_count[p]), each with v0 = p.
#include <array>
#include <vector>

#include "exact/error.hpp"

namespace kmr::hull {

struct Face {
  std::array<int, 3> v;
  std::array<int, 3> nbr{-1, -1, -1};
  int killer = -1;
};

struct Edge {  // an edge of a face, oriented as in that face (Appendix A's edge = vertex * vertex)
  int u, v;
};

struct HullState {
  explicit HullState(int n)
      : first_face(n, -1), face_count(n, 0), last_point(n, -1), last_face(n, -1), duplicate_of(n, -1) {}

  std::vector<Face> faces;
  std::vector<int> root_faces;  // the four faces of the initial tetrahedron
  // Per point (Appendix A's Vertex fields):
  std::vector<int> first_face, face_count;  // its tent (getVertexFaces)
  std::vector<int> last_point, last_face;   // getVertexLastFace: (idP, f) while tenting p
  std::vector<int> duplicate_of;            // a discarded point equal to a surface vertex: that vertex

  int new_face(int a, int b, int c) {
    faces.push_back(Face{{a, b, c}});
    return static_cast<int>(faces.size()) - 1;
  }
  static int slot(const Face& f, int a, int b) {
    for (int s = 0; s < 3; ++s) {
      int x = f.v[s], y = f.v[(s + 1) % 3];
      if ((x == a && y == b) || (x == b && y == a)) return s;
    }
    throw ContractError("hull: face does not have the specified edge");
  }
  // setFaceNeighbor: f and g become neighbours across the edge {a, b} (both directions).
  void set_face_neighbor(int f, int a, int b, int g) {
    faces[f].nbr[slot(faces[f], a, b)] = g;
    faces[g].nbr[slot(faces[g], a, b)] = f;
  }
};

}  // namespace kmr::hull
