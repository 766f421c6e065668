#pragma once
// The certificates of §4.1.2 and §4.3 for a constructed mesh of moving points, as certificate
// polynomials of time (the kinetic KDS, kmesh/kds.hpp, keeps them between batches: it enumerates
// them with certificate_specs and builds only the new ones with build_certificate).
// Every vertex moves like its nucleus: position(t) = position(0) + kScale·(vx, vy)·t.
// Kinds and the inequality each certifies (value(t) ≥ 0, or > 0 when `strict`):
//  * ParentChild   |x parent|² ≤ (2^(top+1))²            (§4.1.2)
//  * Separation    |x y|² > (2^ℓ)² for ℓ-neighbours        (§4.1.2)
//  * Edge          |x y|² ≤ (c·2^ℓ)² for ℓ-neighbours      (§4.1.2)
//  * Potential     |x y|² > (c·2^ℓ)² for ℓ-centers that are cousins but not neighbours (§4.1.2)
//  * BallNotEmpty  |s w|² ≤ (2^(ℓ−2))² for a witness w of a satellite s that was not converted (§4.3)
//  * BallEmpty     |s v|² > (2^(ℓ−2))² for every earlier ℓ′-neighbour v, ℓ′ ∈ [ℓ−6, ℓ−1], of a
//                  converted ℓ-satellite s (§4.3)
//  * Delaunay      every triangle stays counter-clockwise, and the in-circle certificate of every interior edge (a, b) of the triangulation with
//                  apexes c, d: d outside the circle (a, b, c). It stands for the thesis's halfspace
//                  certificates of the local Voronoi cells (same events: a Voronoi neighbour change).
//                  A polynomial ≡ 0 (four satellites of one nucleus, rigidly cocircular) is decided
//                  by the symbolic perturbation for all times and never fails.
// Guarantees (tests/kmesh/certificates_test.cpp): every certificate holds at t = 0 (L4.3.1 at the
// construction time); first_failure() is the first lattice interval (kδ, (k+1)δ] where one fails
// (failure_batch); at any dyadic time up to kδ, the mesh moved to that time still passes the
// brute-force spanner, ball and Delaunay checks.
#include <functional>
#include <optional>
#include <vector>

#include "kmesh/construction.hpp"
#include "poly/polynomial.hpp"
#include "poly/sturm.hpp"

namespace kmr::kmesh {

struct Certificate {
  enum Kind { ParentChild, Separation, Edge, Potential, BallNotEmpty, BallEmpty, Delaunay };
  Kind kind;
  int a, b;  // the vertices it is about (Delaunay: the edge)
  Rank rank;
  bool strict;
  poly::Polynomial value;  // holds while value(t) ≥ 0 (strict: > 0)
  int ray = -1;  // ball-not-empty: the satellite's ray (with its rank and nucleus a, its name)
  bool ccw = false;  // Delaunay: an orientation certificate (a triangle stays counter-clockwise)
};

const char* kind_name(Certificate::Kind k);

// The velocity of every vertex of m in stored units (kScale·(vx, vy) of its nucleus).
std::vector<std::array<exact::Integer, 2>> vertex_velocities(const Mesh& m);

std::vector<Certificate> certificates(const Mesh& m);

// A certificate before its polynomial (what it names, as ids of the mesh): certificates(m) is
// build_certificate over certificate_specs(m). c, d: the third vertex of a Delaunay triangle (d = −1)
// or the apexes of an interior edge (a, b) (c left of a→b); for the ball certificates c = the
// satellite's nucleus, d = its ray (a = the nucleus again for BallNotEmpty, as in Certificate).
struct CertificateSpec {
  Certificate::Kind kind;
  int a, b;
  Rank rank;
  bool strict;
  int c = -1, d = -1;
};
// The witness of a satellite not converted (index into m.considered, its position): by default the
// nearest vertex of rank ≤ ℓ in its ball (brute force; ties: smaller id).
using WitnessChoice = std::function<int(std::size_t considered, const Point2& s)>;
int nearest_witness(const Mesh& m, const Considered& c, const Point2& s);
std::vector<CertificateSpec> certificate_specs(const Mesh& m, const WitnessChoice& witness = {});
// The polynomial of one spec in the variable τ, m's positions being those at τ = at (certificates(m):
// at = 0, polynomials of t − now; the kinetic KDS: at = now, polynomials of absolute time).
Certificate build_certificate(const Mesh& m, const CertificateSpec& s, const Dyadic& at);
// The same for many specs, each vertex's moving point built once.
std::vector<Certificate> build_certificates(const Mesh& m, const std::vector<CertificateSpec>& specs, const Dyadic& at);

// p(t + d) for a dyadic d, times a positive power of two (same signs; integer coefficients).
poly::Polynomial shifted_by_dyadic(const poly::Polynomial& p, const Dyadic& d);

// Whether c holds at the dyadic time t (exact; an identically zero Delaunay polynomial holds — a
// triangle's cannot be, its vertices are not collinear at construction — and so does an in-circle
// one at a zero: cocircular, the perturbation decides; a triangle flat at t does not).
bool holds_at(const Certificate& c, const Dyadic& t);

// Whether c is violated where its polynomial vanishes: a strict certificate, except a Delaunay
// in-circle one (a zero of it is decided by the symbolic perturbation). A triangle's orientation
// certificate fails at its zero: the triangle is flat there (L4.3.1).
bool fails_at_zero(const Certificate& c);

// The batch of a certificate (δ = 2^−bits, s its polynomial's solver): the first lattice index
// k with (k+1)δ > from and kδ < horizon such that it fails in (kδ, (k+1)δ], so that repairing it at (k+1)δ
// leaves it holding at every lattice time before. The solver's sign-change interval f, [fδ, (f+1)δ),
// is batch f, except when the certificate fails at a zero (fails_at_zero) and vanishes at fδ > from:
// it is violated at fδ itself, so it is batch f − 1, repaired at fδ (and found before a horizon fδ).
// Such a certificate also fails at a zero at a lattice time fδ > from without a sign change across
// [fδ, (f+1)δ) (a zero of even multiplicity, or a second root in that interval: next_failure_after
// with zero_fails); otherwise a zero of even multiplicity is no failure (the solver's semantics).
// A zero at `from` is never one.
std::optional<exact::Integer> failure_batch(const poly::LatticeRootSolver& s, bool zero_fails, const Dyadic& from,
                                            const Dyadic& horizon);

// The first batch k (δ = 2^−bits; failure_batch with fails_at_zero, from 0) with kδ < horizon, i.e.
// the first lattice interval (kδ, (k+1)δ] in which some certificate fails, and that certificate
// (the lowest index among those of that batch); nullopt if none does. Every certificate holds at
// every time in [0, kδ].
std::optional<std::pair<exact::Integer, std::size_t>> first_failure(const std::vector<Certificate>& certs, int bits,
                                                                    const Dyadic& horizon);

// The mesh with every vertex moved to time t (same combinatorics: spanner pointers, triangles).
Mesh moved_to(const Mesh& m, const Dyadic& t);

}  // namespace kmr::kmesh
