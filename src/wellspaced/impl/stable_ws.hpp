#pragma once
// StableWS (Fig. 3.4): construction, Dispatch, Fill and the Steiner choice (pick).
// Internal: included only by well_spaced_set.cpp (after impl/state.hpp).
#include "wellspaced/impl/state.hpp"

namespace kmr::wellspaced {

template <std::size_t D>
auto WellSpacedSet<D>::Impl::dispatch(const OpKey& k, Op& op) -> void {
  CVResult cv = clipped_voronoi_neighbors(k.v, k.t);
  op.reads = std::move(cv.reads);
  read_leaves = std::move(cv.read_leaves);
  enqueue(k.v, 1, rank_between(k.v, cv.nn), k, op);
  for (const Pt& w : cv.cv) enqueue(w, 1, rank_between(k.v, w), k, op);
  stats.dispatches++;
}

// Pick w ∈ Vor^{(ρ,β)}(v) (cell ∩ {ρ²NN² ≤ |vw|² < β²NN²}), verified exactly; a double when
// one of the candidates 1–4 is, else a finer dyadic (5). Candidates, in order (the first that is
// exactly in the picking region wins):
//  1. toward the farthest vertex x* of the cell, the direction x* − v truncated to a grid of
//     spacing 2^{ℓ(r*)−20} (r* = rank of |vx*|), at squared distances between ρ²NN² and
//     min(β²NN², |d|²) (fractions fr below);
//  2. the same with the direction truncated to 2^{ℓ(r*)−k}, k as large as the exact floor allows
//     (≤ 45), and a ladder of fractions toward both ends: when the cell pokes out of the ρ-ball
//     only by a sliver (collinear and grid inputs: the rounding of earlier Steiner vertices makes
//     near-degenerate cells), the coarse direction misses it (issue 11);
//  3. exact tier only: the doubles around the exact point p of segment v x* at the middle of the
//     sliver (the segment lies in the convex cell), each coordinate rounded down and up;
//  4. exact tier only: the doubles of the cell's box in rings around p (pick_by_enumeration);
//  5. exact tier only: p rounded to a dyadic grid 2^-K, K growing until the point is in the
//     region (pick_dyadic; it always ends: spec/wellspaced.md, "Near-duplicate inputs").
// Candidates 1–2 are functions of v, NN and the cell only (the same in both tiers); the interval
// tier defers 3–5 to the exact tier. Vertices that are doubles make exactly the choices they made
// before VertexPoint (1–4 unchanged), so every output that had an answer is unchanged.
template <std::size_t D>
template <class NT>
auto WellSpacedSet<D>::Impl::pick(const std::array<NT, D>& vq, const Pt& v, const Pt& nn, const NT& nn2, const Polytope<D, NT>& P) -> Pt {
  const typename Polytope<D, NT>::Vert* far = nullptr;
  NT fd = -1;
  for (const auto& x : P.v) {
    NT d = dist2(x.x, vq);
    if (d > fd || (d == fd && x.x < far->x)) {
      fd = d;
      far = &x;
    }
  }
  const NT lo2 = sq<NT>(params.rho) * nn2, bmax = sq<NT>(params.beta) * nn2;
  const double n2 = approx_dist2<D>(nn, v);  // a double estimate of NN² (the candidates are verified exactly)
  const double l = params.rho * params.rho * n2;
  const Point<D>& vd = v.below();  // v, or (finer v) doubles next to it: candidates 1–4 are verified exactly
  auto in_region = [&](const Pt& w) {
    auto wq = relative_to<NT, D>(w, v);
    NT d = dist2(wq, vq);
    return !(d < lo2) && d < bmax && P.contains(wq);
  };
  // the candidates along the ray toward x* truncated to the grid 2^(ℓ(r*) − k)
  const int r_far = rank_in<NT>(fd);
  auto along = [&](int k, const double* fr, std::size_t nf, Point<D>& out) {
    const int e = ell(r_far) - k;
    Point<D> xs;
    for (std::size_t i = 0; i < D; ++i) xs[i] = vd[i] + std::ldexp(floor_div_pow2<NT>(far->x[i], e), e);
    const double F = dist2(xs, vd);
    if (!(F > 0)) return false;
    const double h = std::min(params.beta * params.beta * n2, F);
    for (std::size_t j = 0; j < nf; ++j) {
      double lam = std::sqrt((l + fr[j] * (h - l)) / F);
      Point<D> w;
      for (std::size_t i = 0; i < D; ++i) w[i] = std::clamp(vd[i] + lam * (xs[i] - vd[i]), 0.0, 1.0);
      if (in_region(w)) {
        out = w;
        return true;
      }
    }
    return false;
  };
  Point<D> w;
  // 1. fractions of the way from ρ²NN² to min(β²NN², |vx*|²); 0.2 first gave the smallest
  // outputs against CGAL Mesh_2 (bench/wellspaced_mesh2; spec/wellspaced.md)
  static constexpr double fr[] = {0.2, 0.1, 0.35, 0.05, 0.5, 0.7, 0.9, 0.025};
  if (along(20, fr, std::size(fr), w)) return w;
  // 2. the finest grid the exact floor allows: |x*_i − v_i| < ρ^{r*+1} ≤ 2ρ√D·ℓ(r*), so
  // |x*_i − v_i| / 2^{ℓ−k} < 2ρ√D·2^k < 2^52
  const int kmax = std::min(45, 51 - static_cast<int>(std::ceil(std::log2(2 * params.rho * std::sqrt(double(D))))));
  static constexpr double ladder[] = {0.5,        0.25,        0.75,        0.125,       0.875,
                                      1.0 / 16,   15.0 / 16,   1.0 / 64,    63.0 / 64,   1.0 / 256,
                                      255.0 / 256, 0x1p-12,    1 - 0x1p-12, 0x1p-16,     1 - 0x1p-16,
                                      0x1p-20,    1 - 0x1p-20, 0x1p-26,     1 - 0x1p-26, 0x1p-32,
                                      1 - 0x1p-32, 0x1p-40,    1 - 0x1p-40};
  if (kmax > 20 && along(kmax, ladder, std::size(ladder), w)) return w;
  if constexpr (is_interval_v<NT>) {
    throw Uncertain();  // 3–5 are exact-tier only
  } else {
    // 3. p = v + λ(x* − v) with lo < |vp|² < hi, lo = ρ²NN², hi = min(β²NN², |vx*|²), found by
    // bisection from a double estimate of the middle: the segment is in the cell, so p is in the
    // picking region; try the doubles around p.
    const Q hi = fd < bmax ? fd : bmax;
    const double lam_d = std::sqrt((lo2 + hi).template convert_to<double>() / 2 / fd.template convert_to<double>());
    Q lam = std::min(lam_d, 1.0), a = 0, b = 1;
    for (int it = 0;; ++it) {
      KMR_CHECK(it < 4000, "pick: bisection for the middle of the picking region does not end");
      Q d = lam * lam * fd;
      if (!(d > lo2)) a = lam;
      else if (!(d < hi)) b = lam;
      else break;
      lam = (a + b) / 2;
    }
    const QPoint<D> vx = to_q<D>(v);
    QPoint<D> p;
    for (std::size_t i = 0; i < D; ++i) p[i] = vx[i] + lam * far->x[i];
    for (int mask = 0; mask < (1 << D); ++mask) {
      for (std::size_t i = 0; i < D; ++i) {
        double c = p[i].template convert_to<double>();
        Q cq = c;
        if ((mask >> i) & 1) c = cq < p[i] ? std::nextafter(c, 2.0) : c;
        else c = cq > p[i] ? std::nextafter(c, -1.0) : c;
        w[i] = std::clamp(c, 0.0, 1.0);
      }
      if (in_region(w)) return w;
    }
    // 4. the doubles of the cell's bounding box (within β·NN of v), in Chebyshev rings of
    // growing radius m = 1, 2, 4, … around p in the index space of doubles (the bit patterns of
    // the doubles in [0,1] are consecutive integers), while (2m+1)^D ≤ 2^20. When the rings
    // cover the box, a miss proves that no double lies in the picking region.
    Enumeration en = pick_by_enumeration(vx, p, in_region, P, std::sqrt(params.beta * params.beta * n2));
    if (en.w) return *en.w;
    // 5. no double found (near-duplicate inputs): a finer dyadic point
    stats.dyadic_steiner++;
    return pick_dyadic(p, std::sqrt(n2), in_region);
  }
}

// Step 5 of pick (exact tier): p rounded coordinatewise to the nearest multiple of 2^-K, for
// K = K0, K0 + 8, … until the rounded point is in the picking region. It ends (spec/wellspaced.md,
// "Near-duplicate inputs"): p lies strictly inside every constraint of the region except the
// faces of [0,1]^D it lies on, where its coordinate is 0 or 1 (on every grid); so all points
// within some ε > 0 of p that keep those coordinates are in the region, and the rounding moves p
// by at most √D·2^-K-1.
template <std::size_t D>
template <class InRegion>
auto WellSpacedSet<D>::Impl::pick_dyadic(const QPoint<D>& p, double nn, const InRegion& in_region) -> Pt {
  int e0 = 0;
  std::frexp(nn, &e0);  // NN < 2^e0
  for (int K = std::max(53, 20 - e0);; K += 8) {
    KMR_CHECK(K < 1 << 16, "pick_dyadic: no dyadic point of the picking region found");
    std::array<exact::Dyadic, D> x;
    for (std::size_t i = 0; i < D; ++i) {
      // ⌊p_i·2^K + ½⌋ = ⌊(2·num·2^K + den) / (2·den)⌋
      Q t = p[i];
      auto* r = t.backend().data();
      mpq_mul_2exp(r, r, static_cast<mp_bitcnt_t>(K));
      exact::Integer num = numerator(t), den = denominator(t);
      exact::Integer m = (2 * num + den) / (2 * den);  // p_i ≥ 0: truncation is the floor
      x[i] = exact::Dyadic(m, -K);
    }
    Pt w = Pt::exactly(x);
    if (in_region(w)) return w;
  }
}

template <std::size_t D>
template <class InRegion>
auto WellSpacedSet<D>::Impl::pick_by_enumeration(const QPoint<D>& v, const std::array<Q, D>& p, const InRegion& in_region, const Polytope<D, Q>& P, double B) -> Enumeration {
  auto idx = [](double x) { return static_cast<std::int64_t>(std::bit_cast<std::uint64_t>(x)); };
  auto at = [](std::int64_t i) { return std::bit_cast<double>(static_cast<std::uint64_t>(i)); };
  auto down = [](const Q& x) {  // the largest double ≤ x
    double c = x.template convert_to<double>();
    return Q(c) > x ? std::nextafter(c, -2.0) : c;
  };
  auto up = [](const Q& x) {  // the smallest double ≥ x
    double c = x.template convert_to<double>();
    return Q(c) < x ? std::nextafter(c, 2.0) : c;
  };
  Enumeration out;
  std::array<std::int64_t, D> lo, hi, c;
  const Q b = Q(B) * Q(1 + 0x1p-20);  // B is a double estimate of β·NN; widened
  for (std::size_t i = 0; i < D; ++i) {
    Q mn = P.v.front().x[i], mx = mn;
    for (const auto& x : P.v) {
      if (x.x[i] < mn) mn = x.x[i];
      if (x.x[i] > mx) mx = x.x[i];
    }
    if (mn < -b) mn = -b;
    if (mx > b) mx = b;
    lo[i] = idx(std::max(0.0, up(v[i] + mn)));
    hi[i] = idx(std::min(1.0, down(v[i] + mx)));
    if (lo[i] > hi[i]) {
      out.complete = true;  // the box holds no double
      return out;
    }
    c[i] = std::clamp(idx(std::clamp(down(p[i]), 0.0, 1.0)), lo[i], hi[i]);
  }
  std::int64_t prev = -1;  // the rings of Chebyshev radius ≤ prev are done
  for (std::int64_t m = 1;; m *= 2) {
    double count = 1;
    for (std::size_t i = 0; i < D; ++i) count *= double(2 * m + 1);
    if (count > 0x1p20) return out;
    bool covers = true;
    for (std::size_t i = 0; i < D; ++i) covers = covers && c[i] - m <= lo[i] && c[i] + m >= hi[i];
    std::array<std::int64_t, D> off;
    off.fill(-m);
    for (;;) {
      std::int64_t cheb = 0;
      bool inside = true;
      Point<D> w;
      for (std::size_t i = 0; i < D; ++i) {
        cheb = std::max<std::int64_t>(cheb, off[i] < 0 ? -off[i] : off[i]);
        const std::int64_t j = c[i] + off[i];
        inside = inside && j >= lo[i] && j <= hi[i];
        if (inside) w[i] = at(j);
      }
      if (cheb > prev && inside) {
        ++out.tried;
        if (in_region(w)) {
          out.w = w;
          return out;
        }
      }
      std::size_t i = 0;
      while (i < D && off[i] == m) off[i++] = -m;
      if (i == D) break;
      ++off[i];
    }
    if (covers) {
      out.complete = true;
      return out;
    }
    prev = m;
  }
}

// ⌊x / 2^e⌋ as a double, for |x / 2^e| < 2^52 (exact there).
template <std::size_t D>
template <class NT>
auto WellSpacedSet<D>::Impl::floor_div_pow2(const NT& x, int e) -> double {
  if constexpr (is_interval_v<NT>) {
    double a = std::floor(std::ldexp(x.lo(), -e)), b = std::floor(std::ldexp(x.hi(), -e));
    KMR_CHECK(std::fabs(a) < 0x1p52 && std::fabs(b) < 0x1p52, "floor_div_pow2 out of range");
    if (a != b) throw Uncertain();
    return a;
  } else {
    Q y = x;
    auto* r = y.backend().data();
    if (e < 0) mpz_mul_2exp(mpq_numref(r), mpq_numref(r), static_cast<unsigned>(-e));
    else mpz_mul_2exp(mpq_denref(r), mpq_denref(r), static_cast<unsigned>(e));
    mpq_canonicalize(r);
    mpz_t f;
    mpz_init(f);
    mpz_fdiv_q(f, mpq_numref(r), mpq_denref(r));
    bool ok = mpz_cmpabs_d(f, 0x1p52) < 0;
    double out = mpz_get_d(f);
    mpz_clear(f);
    KMR_CHECK(ok, "floor_div_pow2 out of range");
    return out;
  }
}

// The Steiner vertices a fill on v inserts, in order: while Vor_CV(v) ∩ [0,1]^D is not inside
// the ball of radius ρ·NN, pick a point of the picking region and cut the cell by its bisector.
template <std::size_t D>
template <class NT>
auto WellSpacedSet<D>::Impl::fill_tier(const Pt& v, const CVResult& cv) -> std::vector<Pt> {
  const std::array<NT, D> vq{};  // the cell is computed relative to v
  auto rel = [&](const Pt& u) { return relative_to<NT, D>(u, v); };
  std::array<NT, D> lo, hi;
  const std::array<NT, D> vn = point_in<NT, D>(v);
  for (std::size_t i = 0; i < D; ++i) {
    lo[i] = NT(0) - vn[i];
    hi[i] = NT(1) - vn[i];
  }
  Polytope<D, NT>& P = fill_cell<NT>();  // Vor_CV(v) ∩ [0,1]^D (storage reused across fills)
  P.reset_box(lo, hi);
  for (const Pt& u : cv.cv) P.clip(bisector_of_origin<D, NT>(rel(u)));
  const NT nn2 = dist2(rel(cv.nn), vq);
  const NT lim = sq<NT>(params.rho) * nn2;
  std::vector<Pt> out;
  while (P.some_vertex_beyond(vq, lim)) {  // v is not ρ-well-spaced
    KMR_CHECK(out.size() < 100000, "fill does not terminate");
    Pt w = pick<NT>(vq, v, cv.nn, nn2, P);
    out.push_back(w);
    P.clip(bisector_of_origin<D, NT>(rel(w)));
  }
  return out;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::fill(const OpKey& k, Op& op) -> void {
  CVResult cv = clipped_voronoi_neighbors(k.v, k.t);
  op.reads = std::move(cv.reads);
  read_leaves = std::move(cv.read_leaves);
  std::vector<Pt> ws;
  try {
    if (params.exact_only) throw Uncertain();
    ws = fill_tier<IntervalNT>(k.v, cv);
  } catch (const Uncertain&) {
    stats.exact_fallbacks++;
    ws = fill_tier<Q>(k.v, cv);
  }
  for (const Pt& w : ws) {
    KMR_CHECK(!vtx.count(w), "Steiner vertex coincides with a vertex");
    Vtx W;
    W.steiner = true;
    W.created = k.t;
    vtx.emplace(w, std::move(W));
    place(w);  // QTInsertSteiner
    op.steiners.push_back(w);
    enqueue(w, 0, rank_between(w, k.v), k, op);
  }
  stats.fills++;
  stats.steiner_per_fill_max = std::max<std::uint64_t>(stats.steiner_per_fill_max, ws.size());
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::construct(const std::vector<Point<D>>& input) -> void {
  auto t0 = std::chrono::steady_clock::now();
  if (input.size() < 2) throw InputError("at least 2 input points are needed (got " + std::to_string(input.size()) + ")");
  std::set<Point<D>> seen;
  for (std::size_t i = 0; i < input.size(); ++i) {
    validate_point<D>(input[i], "point " + std::to_string(i + 1));
    if (!seen.insert(input[i]).second) throw InputError("point " + std::to_string(i + 1) + " is a duplicate");
  }
  std::vector<Point<D>> sorted(seen.begin(), seen.end());
  tree.build(sorted);  // QTBuild
  int depth = 0;
  for (const K& l : tree.leaves()) depth = std::max(depth, l.level);
  refuse_out_of_reach(depth);
  for (const K& l : tree.leaves()) leaf_of(l);
  for (const Point<D>& p : sorted) {
    Vtx V;
    V.created = Time{};
    vtx.emplace(p, std::move(V));
    place(p);
  }
  n_input = sorted.size();
  for (const Point<D>& p : sorted) set_input_dispatch(p);
  propagate();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace kmr::wellspaced
