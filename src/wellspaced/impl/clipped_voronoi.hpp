#pragma once
// QTClippedVoronoi (Fig. 3.6, Lemma 3.2.1): the β-clipped Voronoi neighbours of v by an exact
// certificate-region scan of the 2^D-tree, in two tiers (intervals, then rationals).
// Internal: included only by well_spaced_set.cpp (after impl/state.hpp).
#include "wellspaced/impl/state.hpp"

namespace kmr::wellspaced {

// 2^-L for 0 ≤ L ≤ 1022, exactly (std::ldexp's library call was 2.6 % of a 2D run; issue 11 §4).
inline double pow2_neg(int L) { return std::bit_cast<double>(static_cast<std::uint64_t>(1023 - L) << 52); }

// Enclosure of square s = [k·2^-L, (k+1)·2^-L) per axis (endpoints widened when not doubles).
template <std::size_t D>
auto WellSpacedSet<D>::Impl::square_bounds(const K& s) -> std::array<std::pair<IntervalNT, IntervalNT>, D> {
  std::array<std::pair<IntervalNT, IntervalNT>, D> b;
  for (std::size_t i = 0; i < D; ++i) {
    auto at = [&](std::uint64_t k) {
      double x = std::ldexp(static_cast<double>(k), -s.level);
      if (static_cast<std::uint64_t>(static_cast<double>(k)) == k) return IntervalNT(x);
      return IntervalNT::hull(std::nextafter(x, -1.0), std::nextafter(x, 2.0));
    };
    b[i] = {at(s.k[i]), at(s.k[i] + 1)};
  }
  return b;
}

// max(0, lo − c, c − hi) as an interval: the distance along one axis from c to [lo, hi].
template <std::size_t D>
auto WellSpacedSet<D>::Impl::axis_gap(const IntervalNT& c, const IntervalNT& lo, const IntervalNT& hi) -> IntervalNT {
  IntervalNT a = lo - c, b = c - hi;
  return IntervalNT::hull(std::max({0.0, a.lo(), b.lo()}), std::max({0.0, a.hi(), b.hi()}));
}

// A lower bound on the squared distance from v to square s (orders the scan; prunes it). At
// levels ≤ 52 the corners k·2^-L are exact doubles, so each gap has one rounding and the sum of D ≤ 4
// squares has relative error < (D+3)·2^-53 < 2^-48; deeper squares go through intervals.
template <std::size_t D>
auto WellSpacedSet<D>::Impl::box_dist2_lower(const Pt& v, const IPoint<D>& vi, const K& s) -> double {
  if (s.level <= 52 && v.is_double()) {
    double h = pow2_neg(s.level), d = 0;
    for (std::size_t i = 0; i < D; ++i) {
      const double vx = v.below()[i];
      double lo = static_cast<double>(s.k[i]) * h, hi = lo + h, g = 0;
      if (vx < lo) g = lo - vx;
      else if (vx > hi) g = vx - hi;
      d += g * g;
    }
    return d * (1 - 0x1p-48);
  }
  auto b = square_bounds(s);
  IntervalNT d = 0;
  for (std::size_t i = 0; i < D; ++i) {
    IntervalNT g = axis_gap(vi[i], b[i].first, b[i].second);
    d += g * g;
  }
  return d.lo();
}

// Exact: does square s meet B(c, |cv|) for some vertex c of C (the certificate region of C)?
// C is relative to its site v, which sits at the origin; `R` holds its vertices' bounds.
// `d2_lower` ≤ the squared distance from v to s (rigorous): a ball B(c, |cv|) lies within 2|cv| of v,
// so once 4·|cv|² < d2_lower for the vertices by decreasing |cv|², the rest miss s (issue 11 §5:
// this test was 45 % of a 4D run). The answer is an "exists": the order in which the vertices are
// tried (the hint first, then by radius) decides nothing, only how soon it is known.
template <std::size_t D>
template <class NT>
auto WellSpacedSet<D>::Impl::meets_certificate_region(const Polytope<D, NT>& C, CertificateRegion& R, const Pt& v, const K& s, double d2_lower) -> bool {
  const std::vector<VertexBounds>& vb = R.vb;
  R.undecided.clear();
  if (s.level <= 52) {  // fast path: the square's corners are doubles; plain double arithmetic,
    // each squared gap sum within a relative 2^-49 of its value (≤ 7 roundings), decided only
    // when the margin 2^-48 separates it from the enclosure of |cv|²
    const double h = pow2_neg(s.level);
    std::array<double, D> sl, sh;
    for (std::size_t i = 0; i < D; ++i) {
      sl[i] = static_cast<double>(s.k[i]) * h;
      sh[i] = sl[i] + h;
    }
    // 1: surely meets, −1: surely misses, 0: undecided
    auto test = [&](const VertexBounds& c) {
      double glo = 0, ghi = 0;
      for (std::size_t i = 0; i < D; ++i) {
        const double a = std::max(0.0, std::max(sl[i] - c.hi[i], c.lo[i] - sh[i]));
        const double b = std::max(0.0, std::max(sl[i] - c.lo[i], c.hi[i] - sh[i]));
        glo += a * a;
        ghi += b * b;
      }
      if (ghi * (1 + 0x1p-48) < c.r_lo) return 1;
      if (!(glo * (1 - 0x1p-48) > c.r_hi)) return 0;
      return -1;
    };
    if (R.hint < vb.size() && test(vb[R.hint]) > 0) return true;
    for (std::uint32_t j : R.by_radius) {
      const VertexBounds& c = vb[j];
      if (d2_lower > 4 * c.r_hi) break;  // this ball and all later (smaller) ones miss s
      const int t = test(c);
      if (t > 0) {
        R.hint = j;
        return true;
      }
      if (t == 0) R.undecided.push_back(j);
    }
    if (R.undecided.empty()) return false;
    std::sort(R.undecided.begin(), R.undecided.end());  // the exact tests below in index order
  } else {
    for (std::uint32_t j = 0; j < vb.size(); ++j) R.undecided.push_back(j);
  }
  auto b = square_bounds(s);
  const IPoint<D> vabs = point_in<IntervalNT, D>(v);
  for (std::size_t i = 0; i < D; ++i) {
    b[i].first -= vabs[i];
    b[i].second -= vabs[i];
  }
  for (std::uint32_t j : R.undecided) {
    const auto& c = C.v[j];
    IntervalNT gap = 0;
    for (std::size_t i = 0; i < D; ++i) {
      IntervalNT g = axis_gap(c.xi[i], b[i].first, b[i].second);
      if (g.hi() > 0) gap += g * g;
    }
    IntervalNT radius = IntervalNT::hull(vb[j].r_lo, vb[j].r_hi);
    if (gap.hi() < radius.lo()) return true;
    int sg = filtered_sign<NT>(gap - radius, [&] {
      const std::array<NT, D> vn = point_in<NT, D>(v);
      const NT side(std::ldexp(1.0, -s.level));  // 2^-L: a double (L ≤ 56)
      NT g2 = 0;
      for (std::size_t i = 0; i < D; ++i) {
        // k < 2^56 may not be a double: k = hi·2^28 + lo with both halves exact
        const std::uint64_t k = s.k[i];
        NT lo = (NT(static_cast<double>(k >> 28)) * NT(0x1p28) + NT(static_cast<double>(k & 0xFFFFFFFu))) * side - vn[i];
        NT hi = lo + side, g = 0;
        if (c.x[i] < lo) g = lo - c.x[i];
        else if (c.x[i] > hi) g = c.x[i] - hi;
        g2 += g * g;
      }
      return g2 - dot(c.x, c.x);
    });
    if (sg <= 0) return true;
  }
  return false;
}

// QTClippedVoronoi (Fig. 3.6), one tier. Phase 1 scans squares in Euclidean order until NN(v) is
// known. Phase 2 maintains C = Vor_seen(v) ∩ box(v, R), R ≥ β·NN, and reads a square only if it
// meets the certificate region of C — the union of the balls B(c, |cv|) over the vertices c of C
// (|c−p|² − |c−v|² is linear in c, so vertices suffice) — which only shrinks as vertices are
// seen. Unseen vertices then lie outside every certificate ball, so C ∩ B(v, β·NN) =
// Vor_M(v) ∩ B(v, β·NN); the β-clipped neighbours are decided exactly on C. Reads vertices
// created before t only.
template <std::size_t D>
template <class NT>
auto WellSpacedSet<D>::Impl::clipped_voronoi_tier(const Pt& v, const Time& t) -> CVResult {
  using NPt = std::array<NT, D>;
  CVResult res;
  const NPt vq{};  // the cell is computed relative to v
  const IPoint<D> vi{};
  const IPoint<D> vabs = point_in<IntervalNT, D>(v);
  auto rel = [&](const Pt& u) { return relative_to<NT, D>(u, v); };
  ScanBuffers& buf = scan_buffers;
  std::vector<ScanSquare>& heap = buf.heap;  // a min-heap by std::greater
  heap.clear();
  const std::greater<ScanSquare> later;
  auto push = [&](const ScanSquare& q) {
    heap.push_back(q);
    std::push_heap(heap.begin(), heap.end(), later);
  };
  const std::uint64_t stamp = ++scan_stamp;  // squares reached by this scan carry it
  const K start = vtx.at(v).leaf;
  Leaf& start_leaf = leaves.at(start);
  push({0.0, &start_leaf});
  start_leaf.stamp = stamp;
  using Cand = ScanCandidate;
  std::vector<Cand>& cand = buf.cand;
  cand.clear();
  std::vector<std::pair<Leaf*, double>>& late = buf.late;  // squares popped after NN was fixed, with their heap keys
  late.clear();
  double best = std::numeric_limits<double>::infinity();  // upper bound on NN²
  bool nn_fixed = false;
  double limit = std::numeric_limits<double>::infinity();
  Polytope<D, NT>* C = nullptr;  // set when NN is fixed
  std::vector<int>& cidx = buf.cidx;  // constraint index of cand[i] in C (−1: its bisector misses C)
  cidx.clear();
  double maxd = 0;        // upper bound on max_{c ∈ C} |cv|²
  auto clip_from = [&](std::size_t i0) {
    for (std::size_t i = i0; i < cand.size(); ++i) {
      // |uv|/2 > max_c |cv| means the bisector of v, u misses C
      if (cand[i].d.lo() > 4 * maxd) {
        cidx.push_back(-1);
        continue;
      }
      unsigned ver = C->version;
      cidx.push_back(C->clip(bisector_of_origin<D, NT>(rel(cand[i].u))));
      if (C->version != ver) maxd = C->max_dist2_upper(vi);
    }
    limit = 4 * maxd;  // a point of a certificate ball B(c, |cv|) is within 2|cv| of v
  };
  auto fix_nn = [&]() {
    NT nn2 = -1;
    bool have = false;
    for (const Cand& c : cand)
      if (c.d.lo() <= best) {
        NT e = dist2(rel(c.u), vq);
        if (!have || e < nn2 || (e == nn2 && c.u < res.nn)) {
          nn2 = e;
          res.nn = c.u;
          have = true;
        }
      }
    nn_fixed = true;
    // box half-width R ≥ β·NN: β·NN rounded up to 8 significant bits, from doubles of the chosen
    // nearest vertex (so R is the same in both tiers), checked exactly
    NT r2 = sq<NT>(params.beta) * nn2;
    double nd = approx_dist2<D>(res.nn, v);
    double bn = params.beta * std::sqrt(nd);
    int e = static_cast<int>(std::ceil(std::log2(bn))) - 8;
    double R = std::ldexp(std::ceil(std::ldexp(bn, -e)), e);
    while (NT(R) * NT(R) < r2) R += std::ldexp(1.0, e);
    NPt lo, hi;
    for (std::size_t i = 0; i < D; ++i) {
      lo[i] = NT(-R);
      hi[i] = NT(R);
    }
    C = &scan_cell<NT>();
    C->reset_box(lo, hi);
    maxd = C->max_dist2_upper(vi);
    std::sort(cand.begin(), cand.end(), [](const Cand& a, const Cand& b) {
      return a.approx != b.approx ? a.approx < b.approx : a.u < b.u;
    });
    clip_from(0);
  };
  CertificateRegion& region = buf.region;  // bounds of the vertices of C
  region.hint = 0;
  unsigned vb_version = ~0u;
  auto meets = [&](const K& s, double d2_lower) {
    std::vector<VertexBounds>& vb = region.vb;
    if (vb_version != C->version || vb.size() != C->v.size()) {
      vb.clear();
      for (const auto& c : C->v) {
        VertexBounds b;
        for (std::size_t i = 0; i < D; ++i) {
          IntervalNT x = c.xi[i] + vabs[i];
          b.lo[i] = x.lo();
          b.hi[i] = x.hi();
        }
        const IntervalNT& r = c.n2i;  // = dist2(c.xi, vi): vi is the origin
        b.r_lo = r.lo();
        b.r_hi = r.hi();
        vb.push_back(b);
      }
      region.by_radius.resize(vb.size());
      for (std::uint32_t j = 0; j < vb.size(); ++j) region.by_radius[j] = j;
      std::sort(region.by_radius.begin(), region.by_radius.end(), [&](std::uint32_t a, std::uint32_t b) {
        return vb[a].r_hi != vb[b].r_hi ? vb[a].r_hi > vb[b].r_hi : a < b;
      });
      vb_version = C->version;
    }
    return meets_certificate_region<NT>(*C, region, v, s, d2_lower);
  };
  std::vector<Pt>& here = buf.here;  // the visible vertices of a square, sorted
  while (!heap.empty()) {
    const double key = heap.front().key;
    Leaf& L = *heap.front().leaf;
    const K& s = L.key;
    if (!nn_fixed && key > best) fix_nn();
    if (nn_fixed && key > limit) break;
    std::pop_heap(heap.begin(), heap.end(), later);
    heap.pop_back();
    if (nn_fixed && !(s == start) && !meets(s, key)) continue;
    if (nn_fixed) late.push_back({&L, key});
    else res.read_leaves.push_back(&L);
    std::size_t before = cand.size();
    {
      here.clear();
      for (std::size_t i = 0; i < L.verts.size(); ++i)
        if (L.born[i] < t && !(L.verts[i] == v)) here.push_back(L.verts[i]);
      std::sort(here.begin(), here.end());
      for (const Pt& u : here) {
        IntervalNT d = dist2(point_in<IntervalNT, D>(u), vabs);
        cand.push_back({d.approx(), d, u});
        best = std::min(best, d.hi());
      }
    }
    if (nn_fixed && cand.size() > before) clip_from(before);
    for (Leaf* n : adjacent_leaves(L))
      if (n->stamp != stamp) {
        n->stamp = stamp;
        push({box_dist2_lower(v, vabs, n->key), n});
      }
  }
  KMR_CHECK(!cand.empty(), "clipped Voronoi scan found no vertex");
  if (!nn_fixed) fix_nn();
  // The squares read are those of the NN phase and those meeting the certificate region of the
  // FINAL cell: a function of the data, not of the order in which squares were popped (squares
  // popped earlier against a larger region hold only vertices that cannot affect the result).
  for (const auto& [l, key] : late)
    if (meets(l->key, key)) res.read_leaves.push_back(l);
  std::sort(res.read_leaves.begin(), res.read_leaves.end(), [](const Leaf* a, const Leaf* b) { return a->key < b->key; });
  res.reads.reserve(res.read_leaves.size());
  for (const Leaf* l : res.read_leaves) res.reads.push_back(l->key);
  // exact decision: u ∈ CV iff the face of C on the bisector of v, u has a point within β·NN
  NT r2 = sq<NT>(params.beta) * dist2(rel(res.nn), vq);
  const double r2_hi = exact::enclose(r2).hi();
  for (std::size_t i = 0; i < cand.size(); ++i) {
    if (cidx[i] < 0 || cand[i].d.lo() > 4 * r2_hi) continue;  // the face is beyond β·NN
    if (C->face_within(cidx[i], vq, r2, 2 * static_cast<int>(D))) res.cv.push_back(cand[i].u);
  }
  std::sort(res.cv.begin(), res.cv.end());
  return res;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::clipped_voronoi_neighbors(const Pt& v, const Time& t) -> CVResult {
  CVResult res;
  try {
    if (params.exact_only) throw Uncertain();
    res = clipped_voronoi_tier<IntervalNT>(v, t);
  } catch (const Uncertain&) {
    stats.exact_fallbacks++;
    res = clipped_voronoi_tier<Q>(v, t);
  }
  if (upd) {
    upd->cv_calls++;
    upd->cv_squares_total += res.reads.size();
  }
  stats.cv_calls++;
  stats.cv_squares_total += res.reads.size();
  stats.cv_squares_max = std::max<std::uint64_t>(stats.cv_squares_max, res.reads.size());
  stats.cv_neighbors_max = std::max<std::uint64_t>(stats.cv_neighbors_max, res.cv.size());
  return res;
}

}  // namespace kmr::wellspaced
