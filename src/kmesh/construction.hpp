#pragma once
// The construction of Fig. 4.2 (§4.2): a spanner over the input, then rank by rank (λ … Λ+4) the
// conversion of the ℓ-satellites of the active input vertices whose certificate ball B(s, 2^(ℓ−2))
// is empty (BallEmpty, Convert) and the promotion of the Steiner ℓ-centers (TryToPromote), then the
// Delaunay triangulation of the output M from the candidates at ranks ℓ−6 … ℓ−3 (kmesh/delaunay.hpp).
//
// Guarantees (tests/kmesh/construction_test.cpp, oracles/kmesh):
//  * the result depends only on the set of input points: they are sorted (x, then y) first, and
//    every later loop runs in id order, so a permuted input gives the same mesh;
//  * the spanner invariants S1–S4 hold over all of M after the construction;
//  * the balls are closed: a vertex at distance exactly 2^(ℓ−2) of s blocks its conversion;
//  * BallEmpty looks only at spanner neighbours at ranks ℓ−6 … ℓ−3 (Lemma 4.2.4); its answer is
//    checked against a brute-force scan in kmesh/invariants.hpp (L4.2.4);
//  * refuses (InputError) duplicate points; a single point gives M = N and no triangle.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "exact/integer.hpp"
#include "kmesh/delaunay.hpp"
#include "kmesh/spanner.hpp"

namespace kmr::kmesh {

struct InputPoint {
  exact::Integer x, y;
  exact::Integer vx{0}, vy{0};  // velocity (the trajectory is (x + vx·t, y + vy·t)); ignored by construct()
  friend bool operator==(const InputPoint& a, const InputPoint& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator<(const InputPoint& a, const InputPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
};

struct VertexInfo {
  bool steiner = false;
  int nucleus = -1;  // the input vertex (itself for an input vertex)
  Rank rank = 0;     // activation rank ρ_v for an input vertex; conversion rank ℓ for a satellite
  int ray = -1;
};

// One satellite considered (for the L4.2.4 / L4.2.5 checks).
struct Considered {
  int nucleus;
  int ray;
  Rank rank;
  bool converted;
  int vertex;    // its id if converted, else −1
  int existing;  // the number of vertices of M when it was considered
};

struct RankStats {
  Rank rank = 0;
  std::size_t active = 0, considered = 0, converted = 0, promoted = 0;
};

struct Mesh {
  Spanner spanner;                // ids 0..n−1: input vertices (sorted); then Steiner vertices
  std::vector<VertexInfo> info;   // per vertex
  std::vector<InputPoint> input;  // sorted input (unscaled)
  std::vector<Considered> considered;
  std::vector<RankStats> ranks;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise, sorted
  VoronoiStars stars;  // by id, from construct() (its stage 3); empty in Updater::mesh() (kept there)
  std::uint64_t ops_spanner = 0, ops_convert = 0, ops_delaunay = 0;
  std::size_t n() const { return input.size(); }
  std::size_t size() const { return info.size(); }
  // The activation rank range [λ, Λ+4] the conversion ran over.
  Rank lowest = 0, highest = 0;
};

// Scaled exact position of an input point (kScale·(x, y)), and of its trajectory at time t.
Point2 scaled(const InputPoint& p);
Point2 scaled_at(const InputPoint& p, const Dyadic& t);

// Fig. 4.2, all three stages, on the positions at time t (default 0). Points are sorted by their
// position at t; two points in the same place at t are refused (InputError naming it).
Mesh construct(std::vector<InputPoint> points, const Dyadic& t = Dyadic(0));

}  // namespace kmr::kmesh
