#pragma once
// §2.2 step 3(a)–(b), Appendix A's findAssociatedFace: history-based face location along the ray
// from the centre c through the new point x, using the killer relation.
//
// The pyramid of a face f is the cone from c over f. The pyramids of the initial tetrahedron's four
// faces cover space; the pyramids of a point k's tent faces cover exactly the pyramids of the faces
// k killed, and around the line ck they are separated by the planes (k, u, c) through k's tent
// edges, so two side tests through k pick the tent face (Appendix A's facePyramidSides). Tests are
// closed (≥ 0): on a shared side the first face in creation order wins (deterministic).
//
// Guarantees: returns the alive face of the current hull hit by the ray cx if x lies strictly
// beyond its plane (x is outside conv(A_i)); otherwise −1 (x is inside or on conv(A_i): discarded),
// and when x equals a surface vertex of the located face, records it in duplicate_of.
#include <algorithm>
#include <cstdint>

#include "exact/error.hpp"
#include "hull/hull_state.hpp"

namespace kmr::hull {

struct LocationCounts {
  std::uint64_t history_steps = 0;  // faces visited along the killer chain
};

// x is in the pyramid of f = (v0, v1, v2), all three sides tested (the initial faces).
template <class Kernel>
bool in_pyramid(const Face& f, int x, Kernel& k) {
  return k.centre_side(f.v[0], f.v[1], x) >= 0 && k.centre_side(f.v[1], f.v[2], x) >= 0 &&
         k.centre_side(f.v[2], f.v[0], x) >= 0;
}

// Appendix A's search over q's tent faces (q = v0 of each): sides (w, u, c) and (u, v, c).
template <class Kernel>
int search_tent(const HullState& h, int q, int x, Kernel& k) {
  const int end = h.first_face[q] + h.face_count[q];
  auto sides = k.apex_frame(q, x);  // side tests through q, sharing q − x and c − x
  for (int f = h.first_face[q]; f < end; ++f) {
    const Face& face = h.faces[f];  // (q, v1, v2): sides (v2, q, c) and (q, v1, c)
    if (sides.side_before(face.v[2]) >= 0 && sides.side_after(face.v[1]) >= 0) return f;
  }
  throw ContractError("hull: no tent face of point " + std::to_string(q) + " contains the ray to " + std::to_string(x));
}

// The root pyramids' sides are the six planes (c, u, v) through the centre and an edge uv of the
// initial tetrahedron, each shared by the two faces on that edge with opposite orientation. An exact
// kernel's centre_side is antisymmetric (orientation(v, u, c, x) = −orientation(u, v, c, x)), so
// each plane is tested at most once per point: the same answers as in_pyramid face by face, with at
// most 6 tests instead of up to 12. Only kernels that declare `exact = true` (ExactKernel); the
// others (FloatKernel rounds; hull_at_time's names the points of a refused test) keep in_pyramid.
template <class Kernel>
constexpr bool antisymmetric_centre_side = requires { requires Kernel::exact; };

template <class Kernel>
int root_face_of(const HullState& h, int x, Kernel& k) {
  if constexpr (!antisymmetric_centre_side<Kernel>) {
    for (int r : h.root_faces)
      if (in_pyramid(h.faces[r], x, k)) return r;
    return -1;
  } else {
    int lo[6], hi[6], sign[6], used = 0;
    auto side = [&](int u, int v) {  // centre_side(u, v, x), each plane once
      const int a = std::min(u, v), b = std::max(u, v);
      for (int i = 0; i < used; ++i)
        if (lo[i] == a && hi[i] == b) return u == a ? sign[i] : -sign[i];
      const int s = k.centre_side(a, b, x);
      lo[used] = a, hi[used] = b, sign[used++] = s;
      return u == a ? s : -s;
    };
    for (int r : h.root_faces) {
      const Face& f = h.faces[r];
      if (side(f.v[0], f.v[1]) >= 0 && side(f.v[1], f.v[2]) >= 0 && side(f.v[2], f.v[0]) >= 0) return r;
    }
    return -1;
  }
}

template <class Kernel>
int find_associated_face(HullState& h, int x, Kernel& k, LocationCounts& counts) {
  int f = root_face_of(h, x, k);
  KMR_CHECK(f >= 0, "hull: the initial pyramids do not cover point " + std::to_string(x));
  for (;;) {  // findFace
    ++counts.history_steps;
    const Face& face = h.faces[f];
    int side = k.orientation(face.v[0], face.v[1], face.v[2], x);
    if (side <= 0) {  // not visible: x ∈ pyramid(c, f) ⊂ conv(A_i); discard
      if (side == 0)
        for (int v : face.v)
          if (k.equal(v, x)) h.duplicate_of[x] = v;
      return -1;
    }
    if (face.killer < 0) return f;
    f = search_tent(h, face.killer, x, k);
  }
}

}  // namespace kmr::hull
