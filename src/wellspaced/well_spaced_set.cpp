// StableWS (Fig. 3.4), QTClippedVoronoi (Fig. 3.6) and PropagateWS / Insert / Delete (Fig. 3.8).
// See well_spaced_set.hpp for the guarantees and spec/wellspaced.md for the design choices.
#include "wellspaced/well_spaced_set.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <set>
#include <unordered_map>
#include <algorithm>
#include <bit>

#include "exact/error.hpp"
#include "wellspaced/polytope.hpp"
#include "wellspaced/quadtree.hpp"

namespace kmr::wellspaced {

namespace {

// Time of an operation (§3.2.3): (rank, D < F, color); time 0 is rank = INT_MIN.
struct Time {
  int rank = std::numeric_limits<int>::min();
  int type = 0;  // 0 dispatch, 1 fill
  std::int64_t color = 0;
  friend bool operator==(const Time&, const Time&) = default;
  friend auto operator<=>(const Time&, const Time&) = default;
  bool is_origin() const { return rank == std::numeric_limits<int>::min(); }
  std::string str() const {
    if (is_origin()) return "0";
    return std::to_string(rank) + (type ? ",F," + std::to_string(color) : std::string(",D"));
  }
};

template <std::size_t D>
std::string fmt_point(const Point<D>& x) {
  std::string s;
  char buf[64];
  for (std::size_t i = 0; i < D; ++i) {
    std::snprintf(buf, sizeof buf, "%a", x[i]);
    s += (i ? " " : "") + std::string(buf);
  }
  return s;
}

template <std::size_t D>
void validate_point(const Point<D>& p, const std::string& where) {
  for (std::size_t i = 0; i < D; ++i) {
    if (!std::isfinite(p[i])) throw InputError(where + ": coordinate " + std::to_string(i + 1) + " is not finite");
    if (p[i] < 0.0 || p[i] > 1.0)
      throw InputError(where + ": coordinate " + std::to_string(i + 1) + " = " + std::to_string(p[i]) + " is outside [0,1]");
  }
}

}  // namespace

template <std::size_t D>
struct WellSpacedSet<D>::Impl {
  using K = Key<D>;
  using Pt = Point<D>;
  struct OpKey {
    Time t;
    Pt v;
    friend bool operator==(const OpKey&, const OpKey&) = default;
    friend auto operator<=>(const OpKey&, const OpKey&) = default;
  };
  struct Op {
    bool input_source = false;      // edge v_(0) → this (input dispatch)
    std::vector<OpKey> sources;     // operations that enqueued this one
    bool executed = false;
    std::vector<K> reads;           // squares read (edges s → op)
    std::vector<OpKey> targets;     // operations enqueued (edges op → op)
    std::vector<Pt> steiners;       // Steiner vertices inserted (edges op → square of w)
  };
  struct Vtx {
    bool steiner = false;
    Time created;
    K leaf;
  };
  struct Leaf {
    const Pt* input = nullptr;
    std::vector<Pt> verts;  // vertices (input and Steiner) inside
    K key;
    // cache of tree.adjacent_leaves(key), valid if adjacent_ok; the pointers stay valid while it is
    // (unordered_map nodes do not move; a vanished leaf's neighbours are all invalidated)
    std::vector<Leaf*> adjacent;
    bool adjacent_ok = false;
    std::uint64_t stamp = 0;  // the last scan that reached this square
  };

  Params params;
  Q rho2, beta2;
  int kappa = 0;
  int rmax = 0;
  Quadtree<D> tree;
  std::map<Pt, Vtx> vtx;
  std::unordered_map<K, Leaf, KeyHash<D>> leaves;
  std::uint64_t scan_stamp = 0;  // numbers the clipped-Voronoi scans (Leaf::stamp)
  std::map<OpKey, Op> ops;
  std::map<Pt, std::set<Time>> ops_by_vertex;
  std::unordered_map<K, std::vector<OpKey>, KeyHash<D>> readers;  // square → its readers (unordered)
  std::set<OpKey> pending;
  std::map<int, Q> rho_pow2;  // ρ^{2r}
  std::map<int, IntervalNT> rho_pow2_i;  // enclosures of ρ^{2r}
  std::map<int, int> ell_exp; // ℓ(r) = 2^{ell_exp}
  Stats stats;
  UpdateStats* upd = nullptr;
  std::size_t n_input = 0;

  // ---------- parameters, ranks, colors (§3.2.1–3.2.2, Lemma 3.3.12) ----------
  void set_params(const Params& p) {
    if (!(std::isfinite(p.rho) && p.rho > 1.0)) throw InputError("rho must be a finite number > 1");
    if (!(std::isfinite(p.beta) && p.beta > p.rho)) throw InputError("beta must be a finite number > rho");
    if (p.rho > 64 || p.beta > 256) throw InputError("rho/beta too large (rho ≤ 64, beta ≤ 256)");
    params = p;
    refuse_out_of_reach(0);  // r_max = ⌊log_ρ √D⌋ alone can be out of reach
    rho2 = Q(p.rho) * Q(p.rho);
    beta2 = Q(p.beta) * Q(p.beta);
    kappa = static_cast<int>(std::floor(1.0 + 6.0 * p.beta * p.rho * std::sqrt(double(D)) * (1 + 1e-12))) + 1;
    rmax = rank_of(Q(static_cast<long long>(D)));
  }
  const Q& rpow(int r) {
    auto it = rho_pow2.find(r);
    if (it != rho_pow2.end()) return it->second;
    Q base = r >= 0 ? rho2 : Q(1) / rho2;
    Q x = 1;
    for (int i = 0; i < std::abs(r); ++i) x *= base;
    return rho_pow2.emplace(r, x).first->second;
  }
  // ⌊log_ρ sqrt(d2)⌋, exactly.
  int rank_of(const Q& d2) {
    double dd = d2.template convert_to<double>();
    int r = static_cast<int>(std::floor(std::log(dd) / (2 * std::log(params.rho))));
    while (rpow(r + 1) <= d2) ++r;
    while (rpow(r) > d2) --r;
    return r;
  }
  // ⌊log_ρ |ab|⌋, exactly: decided on intervals when they suffice, else in rationals.
  int rank_between(const Pt& a, const Pt& b) {
    try {
      return rank_in<IntervalNT>(dist2<IntervalNT, D>(point_in<IntervalNT, D>(a), point_in<IntervalNT, D>(b)));
    } catch (const Uncertain&) {
      return rank_of(dist2<Q, D>(to_q<D>(a), to_q<D>(b)));
    }
  }
  // ⌊log_ρ sqrt(d2)⌋ in NT (Uncertain when intervals do not decide it).
  template <class NT>
  int rank_in(const NT& d2) {
    if constexpr (!is_interval_v<NT>) {
      return rank_of(d2);
    } else {
      int r = static_cast<int>(std::floor(std::log(d2.approx()) / (2 * std::log(params.rho))));
      while (rpow_i(r + 1) <= d2) ++r;
      while (rpow_i(r) > d2) --r;
      return r;
    }
  }
  const IntervalNT& rpow_i(int r) {
    auto it = rho_pow2_i.find(r);
    if (it != rho_pow2_i.end()) return it->second;
    return rho_pow2_i.emplace(r, exact::enclose(rpow(r))).first->second;
  }
  // ℓ(r): the largest power of two 2^e with 2^{2e}·D < ρ^{2r} (so ℓ(r) < ρ^r/√D).
  int ell(int r) {
    auto it = ell_exp.find(r);
    if (it != ell_exp.end()) return it->second;
    const Q& target = rpow(r);
    int e = static_cast<int>(std::floor(r * std::log2(params.rho) - 0.5 * std::log2(double(D)))) + 2;
    auto ok = [&](int ee) {  // 2^{2ee}·D < ρ^{2r}
      Q p2 = 1;
      Q b = ee >= 0 ? Q(4) : Q(1, 4);
      for (int i = 0; i < std::abs(ee); ++i) p2 *= b;
      return p2 * Q(static_cast<long long>(D)) < target;
    };
    while (!ok(e)) --e;
    while (ok(e + 1)) ++e;
    return ell_exp.emplace(r, e).first->second;
  }
  std::int64_t color(const Pt& w, int r) {
    int e = ell(r);
    std::int64_t c = 0;
    for (std::size_t i = 0; i < D; ++i) {
      double f = std::floor(std::ldexp(w[i], -e));
      auto ci = static_cast<std::int64_t>(std::fmod(f, double(kappa)));
      c = c * kappa + ci;
    }
    return c;
  }

  // ---------- vertices and squares ----------
  const Pt* leaf_input(const K& leaf) const {
    auto it = leaves.find(leaf);
    return it == leaves.end() ? nullptr : it->second.input;
  }
  // The leaf record of square s (created on first use).
  Leaf& leaf_of(const K& s) {
    auto [it, fresh] = leaves.try_emplace(s);
    if (fresh) it->second.key = s;
    return it->second;
  }
  // Leaves adjacent to leaf L (sorted by key), cached per leaf (apply_tree_change invalidates).
  const std::vector<Leaf*>& adjacent_leaves(Leaf& L) {
    if (!L.adjacent_ok) {
      L.adjacent.clear();
      for (const K& n : tree.adjacent_leaves(L.key)) L.adjacent.push_back(&leaves.at(n));
      L.adjacent_ok = true;
    }
    return L.adjacent;
  }
  void place(const Pt& x) {
    auto& V = vtx.at(x);
    K l = tree.locate(x);
    V.leaf = l;
    auto& L = leaf_of(l);
    L.verts.push_back(x);
    if (!V.steiner) {
      KMR_CHECK(L.input == nullptr, "crowding violated: two inputs in one square");
      L.input = &vtx.find(x)->first;
    }
  }
  void unplace(const Pt& x) {
    auto& V = vtx.at(x);
    auto& L = leaves.at(V.leaf);
    L.verts.erase(std::find(L.verts.begin(), L.verts.end(), x));
    if (!V.steiner) L.input = nullptr;
  }

  // ---------- operations and the computation graph (§3.2.3) ----------
  void mark_readers(const K& s, const Time& t) {  // MarkReaders(s, t)
    auto it = readers.find(s);
    if (it == readers.end()) return;
    for (const OpKey& k : it->second)
      if (k.t > t) pending.insert(k);
  }
  Op& get_op(const OpKey& k) {
    auto [it, fresh] = ops.try_emplace(k);
    if (fresh) {
      pending.insert(k);
      ops_by_vertex[k.v].insert(k.t);
    }
    return it->second;
  }
  void erase_op(typename std::map<OpKey, Op>::iterator it) {
    auto bv = ops_by_vertex.find(it->first.v);
    bv->second.erase(it->first.t);
    if (bv->second.empty()) ops_by_vertex.erase(bv);
    ops.erase(it);
  }
  // Enqueue(w, flag, nn, v_(t)), with nn given by its rank ⌊log_ρ nn⌋.
  void enqueue(const Pt& w, int type, int rank, const OpKey& from, Op& fromop) {
    Time tw;
    tw.rank = rank;
    tw.type = type;
    tw.color = type ? color(w, tw.rank) : 0;
    if (!(tw > from.t)) return;
    OpKey k{tw, w};
    if (std::find(fromop.targets.begin(), fromop.targets.end(), k) != fromop.targets.end()) return;
    Op& op = get_op(k);
    op.sources.push_back(from);
    fromop.targets.push_back(k);
  }
  Time input_dispatch_time(const Pt& v) {
    K l = vtx.at(v).leaf;
    Q side2 = Q(1);
    Q quarter(1, 4);
    for (int i = 0; i < l.level; ++i) side2 *= quarter;
    Time t;
    t.rank = rank_of(side2);
    t.type = 0;
    return t;
  }

  // ---------- QTClippedVoronoi (§3.2.4) ----------
  // Every geometric decision below is made by a two-tier filter (spec/wellspaced.md, "Exactness"):
  // the tier templated on NT = IntervalNT runs first and throws Uncertain when some decision is too
  // close to call; the call is then redone with NT = Q. Both tiers make the same decisions, so the
  // results do not depend on which tier answered. Doubles only order work and prune it rigorously.
  struct CVResult {
    std::vector<K> reads;  // squares read, sorted
    Pt nn{};               // a nearest visible vertex (the lexicographically least on ties)
    std::vector<Pt> cv;    // β-clipped Voronoi neighbours, sorted
  };
  // Enclosure of square s = [k·2^-L, (k+1)·2^-L) per axis (endpoints widened when not doubles).
  static std::array<std::pair<IntervalNT, IntervalNT>, D> square_bounds(const K& s) {
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
  static IntervalNT axis_gap(const IntervalNT& c, const IntervalNT& lo, const IntervalNT& hi) {
    IntervalNT a = lo - c, b = c - hi;
    return IntervalNT::hull(std::max({0.0, a.lo(), b.lo()}), std::max({0.0, a.hi(), b.hi()}));
  }
  // A lower bound on the squared distance from v to square s (orders the scan; prunes it). At
  // levels ≤ 52 the corners k·2^-L are exact doubles, so each gap has one rounding and the sum of D ≤ 4
  // squares has relative error < (D+3)·2^-53 < 2^-48; deeper squares go through intervals.
  static double box_dist2_lower(const Pt& v, const IPoint<D>& vi, const K& s) {
    if (s.level <= 52) {
      double h = std::ldexp(1.0, -s.level), d = 0;
      for (std::size_t i = 0; i < D; ++i) {
        double lo = static_cast<double>(s.k[i]) * h, hi = lo + h, g = 0;
        if (v[i] < lo) g = lo - v[i];
        else if (v[i] > hi) g = v[i] - hi;
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
  // Enclosures, per vertex c of a cell C around v, of c's absolute coordinates and of |cv|².
  struct VertexBounds {
    std::array<double, D> lo, hi;
    double r_lo, r_hi;
  };
  // Exact: does square s meet B(c, |cv|) for some vertex c of C (the certificate region of C)?
  // C is relative to its site v, which sits at the origin; `vb` holds its vertices' bounds.
  template <class NT>
  static bool meets_certificate_region(const Polytope<D, NT>& C, const std::vector<VertexBounds>& vb, const Pt& v,
                                       const K& s) {
    if (s.level <= 52) {  // fast path: the square's corners are doubles; plain double arithmetic,
      // each squared gap sum within a relative 2^-49 of its value (≤ 7 roundings), decided only
      // when the margin 2^-48 separates it from the enclosure of |cv|²
      const double h = std::ldexp(1.0, -s.level);
      bool undecided = false;
      for (const VertexBounds& c : vb) {
        double glo = 0, ghi = 0;
        for (std::size_t i = 0; i < D; ++i) {
          double sl = static_cast<double>(s.k[i]) * h, sh = sl + h;
          double a = std::max({0.0, sl - c.hi[i], c.lo[i] - sh}), b = std::max({0.0, sl - c.lo[i], c.hi[i] - sh});
          glo += a * a;
          ghi += b * b;
        }
        if (ghi * (1 + 0x1p-48) < c.r_lo) return true;
        if (!(glo * (1 - 0x1p-48) > c.r_hi)) undecided = true;
      }
      if (!undecided) return false;
    }
    auto b = square_bounds(s);
    for (std::size_t i = 0; i < D; ++i) {
      b[i].first -= IntervalNT(v[i]);
      b[i].second -= IntervalNT(v[i]);
    }
    for (std::size_t j = 0; j < C.v.size(); ++j) {
      const auto& c = C.v[j];
      IntervalNT gap = 0;
      for (std::size_t i = 0; i < D; ++i) {
        IntervalNT g = axis_gap(c.xi[i], b[i].first, b[i].second);
        if (g.hi() > 0) gap += g * g;
      }
      IntervalNT radius = IntervalNT::hull(vb[j].r_lo, vb[j].r_hi);
      if (gap.hi() < radius.lo()) return true;
      int sg = filtered_sign<NT>(gap - radius, [&] {
        const NT side(std::ldexp(1.0, -s.level));  // 2^-L: a double (L ≤ 56)
        NT g2 = 0;
        for (std::size_t i = 0; i < D; ++i) {
          // k < 2^56 may not be a double: k = hi·2^28 + lo with both halves exact
          const std::uint64_t k = s.k[i];
          NT lo = (NT(static_cast<double>(k >> 28)) * NT(0x1p28) + NT(static_cast<double>(k & 0xFFFFFFFu))) * side - NT(v[i]);
          NT hi = lo + side, g = 0;
          if (c.x[i] < lo) g = lo - c.x[i];
          else if (c.x[i] > hi) g = c.x[i] - hi;
          g2 += g * g;
        }
        return g2 - dot<NT, D>(c.x, c.x);
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
  template <class NT>
  CVResult clipped_voronoi_tier(const Pt& v, const Time& t) {
    using NPt = std::array<NT, D>;
    CVResult res;
    const NPt vq{};  // the cell is computed relative to v
    const IPoint<D> vi{};
    const IPoint<D> vabs = point_in<IntervalNT, D>(v);
    auto rel = [&](const Pt& u) { return relative_to<NT, D>(u, v); };
    struct QE {  // a square to scan, ordered by (lower bound on its distance, key)
      double key;
      Leaf* leaf;
      bool operator>(const QE& o) const { return key != o.key ? key > o.key : leaf->key > o.leaf->key; }
    };
    std::priority_queue<QE, std::vector<QE>, std::greater<QE>> heap;
    const std::uint64_t stamp = ++scan_stamp;  // squares reached by this scan carry it
    const K start = vtx.at(v).leaf;
    Leaf& start_leaf = leaves.at(start);
    heap.push({0.0, &start_leaf});
    start_leaf.stamp = stamp;
    struct Cand {
      double approx;   // |uv|² rounded (the clipping order)
      IntervalNT d;    // |uv|² enclosed
      Pt u;
    };
    std::vector<Cand> cand;
    std::vector<K> late;  // squares popped after NN was fixed
    double best = std::numeric_limits<double>::infinity();  // upper bound on NN²
    bool nn_fixed = false;
    double limit = std::numeric_limits<double>::infinity();
    std::optional<Polytope<D, NT>> C;
    std::vector<int> cidx;  // constraint index of cand[i] in C (−1: its bisector misses C)
    double maxd = 0;        // upper bound on max_{c ∈ C} |cv|²
    auto clip_from = [&](std::size_t i0) {
      for (std::size_t i = i0; i < cand.size(); ++i) {
        // |uv|/2 > max_c |cv| means the bisector of v, u misses C
        if (cand[i].d.lo() > 4 * maxd) {
          cidx.push_back(-1);
          continue;
        }
        unsigned ver = C->version;
        cidx.push_back(C->clip(bisector<D, NT>(vq, rel(cand[i].u))));
        if (C->version != ver) maxd = C->max_dist2_upper(vi);
      }
      limit = 4 * maxd;  // a point of a certificate ball B(c, |cv|) is within 2|cv| of v
    };
    auto fix_nn = [&]() {
      NT nn2 = -1;
      bool have = false;
      for (const Cand& c : cand)
        if (c.d.lo() <= best) {
          NT e = dist2<NT, D>(rel(c.u), vq);
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
      double nd = 0;
      for (std::size_t i = 0; i < D; ++i) nd += (res.nn[i] - v[i]) * (res.nn[i] - v[i]);
      double bn = params.beta * std::sqrt(nd);
      int e = static_cast<int>(std::ceil(std::log2(bn))) - 8;
      double R = std::ldexp(std::ceil(std::ldexp(bn, -e)), e);
      while (NT(R) * NT(R) < r2) R += std::ldexp(1.0, e);
      NPt lo, hi;
      for (std::size_t i = 0; i < D; ++i) {
        lo[i] = NT(-R);
        hi[i] = NT(R);
      }
      C = Polytope<D, NT>::box(lo, hi);
      maxd = C->max_dist2_upper(vi);
      std::sort(cand.begin(), cand.end(), [](const Cand& a, const Cand& b) {
        return a.approx != b.approx ? a.approx < b.approx : a.u < b.u;
      });
      clip_from(0);
    };
    std::vector<VertexBounds> vb;  // bounds of the vertices of C
    unsigned vb_version = ~0u;
    auto meets = [&](const K& s) {
      if (vb_version != C->version || vb.size() != C->v.size()) {
        vb.clear();
        for (const auto& c : C->v) {
          VertexBounds b;
          for (std::size_t i = 0; i < D; ++i) {
            IntervalNT x = c.xi[i] + vabs[i];
            b.lo[i] = x.lo();
            b.hi[i] = x.hi();
          }
          IntervalNT r = dist2<IntervalNT, D>(c.xi, vi);
          b.r_lo = r.lo();
          b.r_hi = r.hi();
          vb.push_back(b);
        }
        vb_version = C->version;
      }
      return meets_certificate_region<NT>(*C, vb, v, s);
    };
    while (!heap.empty()) {
      const double key = heap.top().key;
      Leaf& L = *heap.top().leaf;
      const K& s = L.key;
      if (!nn_fixed && key > best) fix_nn();
      if (nn_fixed && key > limit) break;
      heap.pop();
      if (nn_fixed && !(s == start) && !meets(s)) continue;
      if (nn_fixed) late.push_back(s);
      else res.reads.push_back(s);
      std::size_t before = cand.size();
      {
        std::vector<Pt> here;
        for (const Pt& u : L.verts)
          if (!(u == v) && vtx.at(u).created < t) here.push_back(u);
        std::sort(here.begin(), here.end());
        for (const Pt& u : here) {
          IntervalNT d = dist2<IntervalNT, D>(point_in<IntervalNT, D>(u), vabs);
          cand.push_back({d.approx(), d, u});
          best = std::min(best, d.hi());
        }
      }
      if (nn_fixed && cand.size() > before) clip_from(before);
      for (Leaf* n : adjacent_leaves(L))
        if (n->stamp != stamp) {
          n->stamp = stamp;
          heap.push({box_dist2_lower(v, vabs, n->key), n});
        }
    }
    KMR_CHECK(!cand.empty(), "clipped Voronoi scan found no vertex");
    if (!nn_fixed) fix_nn();
    // The squares read are those of the NN phase and those meeting the certificate region of the
    // FINAL cell: a function of the data, not of the order in which squares were popped (squares
    // popped earlier against a larger region hold only vertices that cannot affect the result).
    for (const K& s : late)
      if (meets(s)) res.reads.push_back(s);
    std::sort(res.reads.begin(), res.reads.end());
    // exact decision: u ∈ CV iff the face of C on the bisector of v, u has a point within β·NN
    NT r2 = sq<NT>(params.beta) * dist2<NT, D>(rel(res.nn), vq);
    const double r2_hi = exact::enclose(r2).hi();
    for (std::size_t i = 0; i < cand.size(); ++i) {
      if (cidx[i] < 0 || cand[i].d.lo() > 4 * r2_hi) continue;  // the face is beyond β·NN
      if (C->face_within(cidx[i], vq, r2, 2 * static_cast<int>(D))) res.cv.push_back(cand[i].u);
    }
    std::sort(res.cv.begin(), res.cv.end());
    return res;
  }
  template <class NT>
  static NT sq(double x) { return NT(x) * NT(x); }

  CVResult clipped_voronoi_neighbors(const Pt& v, const Time& t) {
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

  // ---------- Dispatch and Fill (Fig. 3.4) ----------
  void dispatch(const OpKey& k, Op& op) {
    CVResult cv = clipped_voronoi_neighbors(k.v, k.t);
    op.reads = cv.reads;
    enqueue(k.v, 1, rank_between(k.v, cv.nn), k, op);
    for (const Pt& w : cv.cv) enqueue(w, 1, rank_between(k.v, w), k, op);
    stats.dispatches++;
  }

  // Pick w ∈ Vor^{(ρ,β)}(v) (cell ∩ {ρ²NN² ≤ |vw|² < β²NN²}), a double, verified exactly.
  // Candidates, in order (the first that is exactly in the picking region wins):
  //  1. toward the farthest vertex x* of the cell, the direction x* − v truncated to a grid of
  //     spacing 2^{ℓ(r*)−20} (r* = rank of |vx*|), at squared distances between ρ²NN² and
  //     min(β²NN², |d|²) (fractions fr below);
  //  2. the same with the direction truncated to 2^{ℓ(r*)−k}, k as large as the exact floor allows
  //     (≤ 45), and a ladder of fractions toward both ends: when the cell pokes out of the ρ-ball
  //     only by a sliver (collinear and grid inputs: the rounding of earlier Steiner vertices makes
  //     near-degenerate cells), the coarse direction misses it (issue 11);
  //  3. exact tier only: the doubles around the exact point of segment v x* at the middle of the
  //     sliver (the segment lies in the convex cell), each coordinate rounded down and up.
  // Candidates 1–2 are functions of v, NN and the cell only (the same in both tiers); the interval
  // tier defers 3 to the exact tier. Only a sliver thinner than the double spacing near x* (no
  // double within one ulp of that point of segment v x*) is left, reported as a ContractError.
  template <class NT>
  Pt pick(const std::array<NT, D>& vq, const Pt& v, const Pt& nn, const NT& nn2, const Polytope<D, NT>& P) {
    const typename Polytope<D, NT>::Vert* far = nullptr;
    NT fd = -1;
    for (const auto& x : P.v) {
      NT d = dist2<NT, D>(x.x, vq);
      if (d > fd || (d == fd && x.x < far->x)) {
        fd = d;
        far = &x;
      }
    }
    const NT lo2 = sq<NT>(params.rho) * nn2, bmax = sq<NT>(params.beta) * nn2;
    double n2 = 0;
    for (std::size_t i = 0; i < D; ++i) n2 += (nn[i] - v[i]) * (nn[i] - v[i]);
    const double l = params.rho * params.rho * n2;
    auto in_region = [&](const Pt& w) {
      auto wq = relative_to<NT, D>(w, v);
      NT d = dist2<NT, D>(wq, vq);
      return !(d < lo2) && d < bmax && P.contains(wq);
    };
    // the candidates along the ray toward x* truncated to the grid 2^(ℓ(r*) − k)
    const int r_far = rank_in<NT>(fd);
    auto along = [&](int k, const double* fr, std::size_t nf, Pt& out) {
      const int e = ell(r_far) - k;
      Pt xs;
      for (std::size_t i = 0; i < D; ++i) xs[i] = v[i] + std::ldexp(floor_div_pow2<NT>(far->x[i], e), e);
      double F = 0;
      for (std::size_t i = 0; i < D; ++i) F += (xs[i] - v[i]) * (xs[i] - v[i]);
      if (!(F > 0)) return false;
      const double h = std::min(params.beta * params.beta * n2, F);
      for (std::size_t j = 0; j < nf; ++j) {
        double lam = std::sqrt((l + fr[j] * (h - l)) / F);
        Pt w;
        for (std::size_t i = 0; i < D; ++i) w[i] = std::clamp(v[i] + lam * (xs[i] - v[i]), 0.0, 1.0);
        if (in_region(w)) {
          out = w;
          return true;
        }
      }
      return false;
    };
    Pt w;
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
      throw Uncertain();  // 3. is exact-tier only
    } else {
      // 3. p = v + λ(x* − v) with |vp|² = (lo + hi)/2, lo = ρ²NN², hi = min(β²NN², |vx*|²): the
      // segment is in the cell, so p is in the picking region; try the doubles around p.
      const Q hi = fd < bmax ? fd : bmax;
      const double lam_d = std::sqrt((lo2 + hi).template convert_to<double>() / 2 / fd.template convert_to<double>());
      // λ ∈ (0, 1] with λ²|vx*|² ∈ [lo, hi] (hi excluded when it is β²NN²), by bisection from
      // a double estimate
      Q lam = std::min(lam_d, 1.0), a = 0, b = 1;
      for (int it = 0; it < 400; ++it) {
        Q d = lam * lam * fd;
        if (d < lo2) a = lam;
        else if (d > hi || (d == hi && hi == bmax)) b = lam;
        else break;
        lam = (a + b) / 2;
      }
      std::array<Q, D> p;
      for (std::size_t i = 0; i < D; ++i) p[i] = Q(v[i]) + lam * far->x[i];
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
      Enumeration en = pick_by_enumeration(v, p, in_region, P, std::sqrt(params.beta * params.beta * n2));
      if (en.w) return *en.w;
      char buf[160];
      std::snprintf(buf, sizeof buf, "|vv'| = %.3g, %llu doubles tried%s", std::sqrt(n2),
                    static_cast<unsigned long long>(en.tried),
                    en.complete ? ": none lies in the picking region" : " near the picking region, none in it");
      throw ContractError("no double-precision Steiner vertex for the fill of v = (" + fmt_point<D>(v) + "), " + buf +
                          " (Steiner vertices are doubles; near-duplicate inputs need finer ones: spec/wellspaced.md, issue 11)");
    }
  }
  // Step 4 of pick (exact tier): the first double w (in ring order around p, then offsets in
  // lexicographic order) with in_region(w) among the doubles of the box of P (relative to v)
  // ∩ [v − B, v + B] ∩ [0,1]^D. complete: the rings covered that box (so a miss is a proof).
  struct Enumeration {
    std::optional<Pt> w;
    bool complete = false;
    std::uint64_t tried = 0;
  };
  template <class InRegion>
  static Enumeration pick_by_enumeration(const Pt& v, const std::array<Q, D>& p, const InRegion& in_region,
                                         const Polytope<D, Q>& P, double B) {
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
      lo[i] = idx(std::max(0.0, up(Q(v[i]) + mn)));
      hi[i] = idx(std::min(1.0, down(Q(v[i]) + mx)));
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
        Pt w;
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
  template <class NT>
  static double floor_div_pow2(const NT& x, int e) {
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
  template <class NT>
  std::vector<Pt> fill_tier(const Pt& v, const CVResult& cv) {
    const std::array<NT, D> vq{};  // the cell is computed relative to v
    auto rel = [&](const Pt& u) { return relative_to<NT, D>(u, v); };
    std::array<NT, D> lo, hi;
    for (std::size_t i = 0; i < D; ++i) {
      lo[i] = NT(0) - NT(v[i]);
      hi[i] = NT(1) - NT(v[i]);
    }
    Polytope<D, NT> P = Polytope<D, NT>::box(lo, hi);  // Vor_CV(v) ∩ [0,1]^D
    for (const Pt& u : cv.cv) P.clip(bisector<D, NT>(vq, rel(u)));
    const NT nn2 = dist2<NT, D>(rel(cv.nn), vq);
    const NT lim = sq<NT>(params.rho) * nn2;
    std::vector<Pt> out;
    while (P.some_vertex_beyond(vq, lim)) {  // v is not ρ-well-spaced
      KMR_CHECK(out.size() < 100000, "fill does not terminate");
      Pt w = pick<NT>(vq, v, cv.nn, nn2, P);
      out.push_back(w);
      P.clip(bisector<D, NT>(vq, rel(w)));
    }
    return out;
  }

  void fill(const OpKey& k, Op& op) {
    CVResult cv = clipped_voronoi_neighbors(k.v, k.t);
    op.reads = cv.reads;
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

  // ---------- change propagation (Fig. 3.8) ----------
  void undo(const OpKey& k, Op& op) {
    for (const K& s : op.reads) {
      auto it = readers.find(s);
      if (it != readers.end()) {
        auto& rs = it->second;
        auto at = std::find(rs.begin(), rs.end(), k);
        KMR_CHECK(at != rs.end(), "undo: operation missing from its square's readers");
        *at = rs.back();
        rs.pop_back();
        if (rs.empty()) readers.erase(it);
      }
    }
    for (const OpKey& t : op.targets) {
      auto& src = ops.at(t).sources;
      src.erase(std::find(src.begin(), src.end(), k));
    }
    for (const Pt& w : op.steiners) {
      unplace(w);
      vtx.erase(w);
    }
    op.reads.clear();
    op.executed = false;
  }

  void process(const OpKey& k) {
    auto it = ops.find(k);
    if (it == ops.end()) return;
    Op& op = it->second;
    bool had = op.executed;
    std::vector<OpKey> old_targets = op.targets;
    std::vector<Pt> old_steiners = op.steiners;
    std::vector<K> old_steiner_leaves;
    for (const Pt& w : old_steiners) old_steiner_leaves.push_back(vtx.at(w).leaf);
    if (had) undo(k, op);
    op.targets.clear();
    op.steiners.clear();
    bool exists = op.input_source || !op.sources.empty();
    if (exists && k.t.rank <= rmax) {
      KMR_CHECK(vtx.count(k.v), "operation on a vertex that does not exist");
      if (k.t.type == 0) dispatch(k, op);
      else fill(k, op);
      op.executed = true;
      for (const K& s : op.reads) readers[s].push_back(k);
    }
    // targets no longer enqueued by k
    for (const OpKey& t : old_targets)
      if (std::find(op.targets.begin(), op.targets.end(), t) == op.targets.end()) {
        const Op& o = ops.at(t);
        if (!o.input_source && o.sources.empty()) pending.insert(t);
      }
    // Steiner vertices changed: MarkReaders(square of w, t)
    for (std::size_t i = 0; i < old_steiners.size(); ++i)
      if (std::find(op.steiners.begin(), op.steiners.end(), old_steiners[i]) == op.steiners.end()) {
        mark_readers(old_steiner_leaves[i], k.t);
        if (upd) upd->steiner_deleted++;
      }
    for (const Pt& w : op.steiners)
      if (std::find(old_steiners.begin(), old_steiners.end(), w) == old_steiners.end()) {
        mark_readers(vtx.at(w).leaf, k.t);
        if (upd) upd->steiner_inserted++;
      }
    if (upd) {
      if (had && exists) upd->inconsistent++;
      else if (had && !exists) upd->obsolete++;
      else if (!had && exists) upd->fresh++;
      else upd->obsolete++;
    }
    if (!exists) erase_op(it);
  }

  void propagate() {
    while (!pending.empty()) {
      OpKey k = *pending.begin();
      pending.erase(pending.begin());
      process(k);
    }
  }

  void set_input_dispatch(const Pt& v) {
    Time t = input_dispatch_time(v);
    OpKey k{t, v};
    Op& op = get_op(k);
    op.input_source = true;
    pending.insert(k);
  }
  void clear_input_dispatch(const Pt& v) {
    // the input dispatch of v is the unique dispatch of v with input_source
    for (auto& [k, op] : ops_of(v))
      if (op->input_source) {
        op->input_source = false;
        pending.insert(k);
      }
  }
  std::vector<std::pair<OpKey, Op*>> ops_of(const Pt& v) {
    std::vector<std::pair<OpKey, Op*>> out;
    auto bv = ops_by_vertex.find(v);
    if (bv == ops_by_vertex.end()) return out;
    for (const Time& t : bv->second) {
      OpKey k{t, v};
      out.emplace_back(k, &ops.at(k));
    }
    return out;
  }

  // ---------- construction, updates ----------
  // Refuses (InputError) a run whose exact rank thresholds are out of reach. Ranks run from
  // ⌊log_ρ NN_min⌋ to r_max, and the thresholds ρ^{2r} are exact rationals of 2|r|·b bits (b = the
  // significant bits of the double ρ). With the smallest leaf 2^-L (leaves are Θ(lfs), Lemma 3.1.5),
  // the ranks span about log_ρ(2^L·√D) (the size constant c = 2ρ/(ρ−1) of Lemma 3.3.3 would widen
  // this by log_ρ c; the measured runs did not need it). The measured cost grows
  // faster than linearly in 2|r|·b (3 points, 2D: 18k bits 0.45 s, 83k 2.7 s, 207k 37 s; issue 11:
  // ρ = 1.0000001 ran for minutes silently), so more than 2^17 bits is refused with a message.
  void refuse_out_of_reach(int depth) const {
    int ex = 0;
    const double m = std::frexp(params.rho, &ex);  // ρ = m·2^ex, m ∈ [0.5, 1)
    std::uint64_t mant = static_cast<std::uint64_t>(std::ldexp(m, 53));
    int bits = 53;
    while (bits > 1 && !(mant & 1)) {
      mant >>= 1;
      --bits;
    }
    const double ranks = (depth * std::log(2.0) + 0.5 * std::log(double(D))) / std::log(params.rho);
    const double work = 2 * ranks * bits;
    if (work > 0x1p17) {
      char msg[400];
      std::snprintf(msg, sizeof msg,
                    "rho = %.17g is too close to 1 for this input: about %.0f ranks between the smallest "
                    "square and the domain, with exact rank thresholds rho^(2r) of about %.0f bits (limit 131072); "
                    "use a larger rho or one with fewer significant bits (e.g. 1 + 2^-k)",
                    params.rho, ranks, work);
      throw InputError(msg);
    }
  }

  void construct(const std::vector<Pt>& input) {
    auto t0 = std::chrono::steady_clock::now();
    if (input.size() < 2) throw InputError("at least 2 input points are needed (got " + std::to_string(input.size()) + ")");
    std::set<Pt> seen;
    for (std::size_t i = 0; i < input.size(); ++i) {
      validate_point<D>(input[i], "point " + std::to_string(i + 1));
      if (!seen.insert(input[i]).second) throw InputError("point " + std::to_string(i + 1) + " is a duplicate");
    }
    std::vector<Pt> sorted(seen.begin(), seen.end());
    tree.build(sorted);  // QTBuild
    int depth = 0;
    for (const K& l : tree.leaves()) depth = std::max(depth, l.level);
    refuse_out_of_reach(depth);
    for (const K& l : tree.leaves()) leaf_of(l);
    for (const Pt& p : sorted) {
      Vtx V;
      V.created = Time{};
      vtx.emplace(p, std::move(V));
      place(p);
    }
    n_input = sorted.size();
    for (const Pt& p : sorted) set_input_dispatch(p);
    propagate();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  // Applies a tree change: moves the vertices of obsolete squares into the fresh ones, and returns
  // the input vertices that moved (their dispatch time may change).
  std::vector<Pt> apply_tree_change(const typename Quadtree<D>::Change& ch) {
    std::vector<Pt> moved;
    for (const K& s : ch.obsolete) {
      auto it = leaves.find(s);
      if (it == leaves.end()) continue;
      for (const Pt& x : it->second.verts) moved.push_back(x);
      leaves.erase(it);
    }
    for (const K& s : ch.fresh) leaf_of(s);
    // a leaf's adjacency changes only if an adjacent leaf appeared or disappeared; every leaf now
    // covering a vanished leaf's region is fresh, so the fresh leaves and their neighbours suffice
    for (const K& s : ch.fresh)
      for (const K& n : tree.adjacent_leaves(s)) leaves.at(n).adjacent_ok = false;
    std::vector<Pt> inputs;
    for (const Pt& x : moved) {
      place(x);
      if (!vtx.at(x).steiner) inputs.push_back(x);
    }
    std::sort(inputs.begin(), inputs.end());
    return inputs;
  }

  void redo_input_dispatch(const Pt& u) {
    Time t = input_dispatch_time(u);
    for (auto& [k, op] : ops_of(u))
      if (op->input_source && !(k.t == t)) {
        op->input_source = false;
        pending.insert(k);
      }
    OpKey k{t, u};
    Op& op = get_op(k);
    if (!op.input_source) {
      op.input_source = true;
      pending.insert(k);
    }
  }

  UpdateStats insert(const Pt& p) {
    auto t0 = std::chrono::steady_clock::now();
    validate_point<D>(p, "inserted point");
    if (vtx.count(p) && !vtx.at(p).steiner) throw InputError("inserted point " + fmt_point<D>(p) + " is already an input point");
    UpdateStats us;
    upd = &us;
    auto ch = tree.update(p, +1, [&](const K& l) { return leaf_input(l); });  // QTInsertInput (may throw: nothing changed)
    us.obsolete_squares = ch.obsolete.size();
    us.fresh_squares = ch.fresh.size();
    for (const K& s : ch.obsolete) mark_readers(s, Time{});  // MarkReaders(s, 0)
    // A Steiner vertex at exactly p becomes an input vertex: take it from its creator, which is
    // re-executed (it reads p's square after time 0).
    if (vtx.count(p)) {
      for (auto& [k, op] : ops) {
        auto w = std::find(op.steiners.begin(), op.steiners.end(), p);
        if (w == op.steiners.end()) continue;
        op.steiners.erase(w);
        mark_readers(vtx.at(p).leaf, k.t);
        pending.insert(k);
        break;
      }
      unplace(p);
      vtx.erase(p);
      us.steiner_deleted++;
    }
    std::vector<Pt> moved = apply_tree_change(ch);
    Vtx V;
    vtx.emplace(p, std::move(V));
    place(p);
    ++n_input;
    mark_readers(vtx.at(p).leaf, Time{});
    for (const Pt& u : moved) redo_input_dispatch(u);
    set_input_dispatch(p);
    propagate();
    upd = nullptr;
    us.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return us;
  }

  UpdateStats erase(const Pt& p) {
    auto t0 = std::chrono::steady_clock::now();
    validate_point<D>(p, "deleted point");
    auto it = vtx.find(p);
    if (it == vtx.end() || it->second.steiner) throw InputError("deleted point " + fmt_point<D>(p) + " is not an input point");
    if (n_input <= 2) throw InputError("cannot delete: at least 2 input points must remain");
    UpdateStats us;
    upd = &us;
    K old_leaf = it->second.leaf;
    auto ch = tree.update(p, -1, [&](const K& l) { return leaf_input(l); });  // QTDeleteInput
    us.obsolete_squares = ch.obsolete.size();
    us.fresh_squares = ch.fresh.size();
    mark_readers(old_leaf, Time{});
    for (const K& s : ch.obsolete) mark_readers(s, Time{});
    unplace(p);
    clear_input_dispatch(p);
    vtx.erase(p);
    --n_input;
    std::vector<Pt> moved = apply_tree_change(ch);
    for (const Pt& u : moved) redo_input_dispatch(u);
    propagate();
    upd = nullptr;
    us.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return us;
  }

  // The indexes the canonical graph does not show (issue 11 §2), checked after every command of
  // the Lemma 3.4.2 property: readers are exactly the inverse of the reads, sources exactly the
  // inverse of the targets, every vertex in the leaf locate() gives (and listed there), leaves are
  // the tree's leaves, nothing pending, valid adjacency caches equal the tree's adjacency.
  std::string check_internal_indexes() const {
    auto name = [](const OpKey& k) { return "(" + fmt_point<D>(k.v) + " @" + k.t.str() + ")"; };
    if (!pending.empty()) return std::to_string(pending.size()) + " operations pending";
    std::size_t reads = 0;
    for (const auto& [k, op] : ops) {
      for (const K& s : op.reads) {
        ++reads;
        auto it = readers.find(s);
        if (it == readers.end() || std::count(it->second.begin(), it->second.end(), k) != 1)
          return "square " + s.str() + " read by " + name(k) + " does not list it once as a reader";
      }
      for (const OpKey& t : op.targets) {
        auto it = ops.find(t);
        if (it == ops.end()) return name(k) + " targets a missing operation " + name(t);
        if (std::count(it->second.sources.begin(), it->second.sources.end(), k) != 1)
          return name(t) + " does not list its source " + name(k) + " once";
      }
      for (const OpKey& src : op.sources) {
        auto it = ops.find(src);
        if (it == ops.end() || std::count(it->second.targets.begin(), it->second.targets.end(), k) != 1)
          return name(k) + " lists a source " + name(src) + " that does not target it once";
      }
    }
    std::size_t listed = 0;
    for (const auto& [s, rs] : readers) {
      listed += rs.size();
      for (const OpKey& k : rs) {
        auto it = ops.find(k);
        if (it == ops.end() || std::count(it->second.reads.begin(), it->second.reads.end(), s) != 1)
          return name(k) + " is a reader of " + s.str() + " without reading it";
      }
    }
    if (listed != reads) return "reader lists hold " + std::to_string(listed) + " entries for " + std::to_string(reads) + " reads";
    auto tl = tree.leaves();
    if (tl.size() != leaves.size()) return "leaf store holds " + std::to_string(leaves.size()) + " squares, the tree " + std::to_string(tl.size());
    std::size_t inside = 0;
    for (const K& l : tl) {
      auto it = leaves.find(l);
      if (it == leaves.end()) return "tree leaf " + l.str() + " missing from the leaf store";
      const Leaf& L = it->second;
      inside += L.verts.size();
      for (const Pt& x : L.verts)
        if (!(tree.locate(x) == l) || !vtx.count(x) || !(vtx.at(x).leaf == l))
          return "vertex " + fmt_point<D>(x) + " listed in " + l.str() + " but located elsewhere";
      if (L.adjacent_ok) {
        auto want = tree.adjacent_leaves(l);
        if (want.size() != L.adjacent.size()) return "stale adjacency cache at " + l.str();
        for (std::size_t i = 0; i < want.size(); ++i)
          if (!(L.adjacent[i]->key == want[i])) return "stale adjacency cache at " + l.str();
      }
    }
    if (inside != vtx.size()) return std::to_string(vtx.size()) + " vertices, " + std::to_string(inside) + " listed in leaves";
    return "";
  }

  std::vector<std::string> canonical_graph() const {
    std::vector<std::string> out;
    for (const K& l : tree.leaves()) out.push_back("S " + l.str());
    for (const auto& [k, op] : ops) {
      std::string name = "(" + fmt_point<D>(k.v) + " @" + k.t.str() + ")";
      out.push_back("O " + name + (op.executed ? " x" : ""));
      if (op.input_source) out.push_back("E (" + fmt_point<D>(k.v) + " @0) -> " + name);
      for (const OpKey& t : op.targets)
        out.push_back("E " + name + " -> (" + fmt_point<D>(t.v) + " @" + t.t.str() + ")");
      for (const K& s : op.reads) out.push_back("R " + s.str() + " -> " + name);
      for (const Pt& w : op.steiners) out.push_back("W " + name + " -> " + tree.locate(w).str() + " [" + fmt_point<D>(w) + "]");
    }
    std::sort(out.begin(), out.end());
    return out;
  }
};

template <std::size_t D>
WellSpacedSet<D>::WellSpacedSet(const std::vector<Point<D>>& input, Params params) : impl_(std::make_unique<Impl>()) {
  impl_->set_params(params);
  impl_->construct(input);
}
template <std::size_t D>
WellSpacedSet<D>::~WellSpacedSet() = default;
template <std::size_t D>
WellSpacedSet<D>::WellSpacedSet(WellSpacedSet&&) noexcept = default;
template <std::size_t D>
WellSpacedSet<D>& WellSpacedSet<D>::operator=(WellSpacedSet&&) noexcept = default;

template <std::size_t D>
UpdateStats WellSpacedSet<D>::insert(const Point<D>& p) {
  return impl_->insert(p);
}
template <std::size_t D>
UpdateStats WellSpacedSet<D>::erase(const Point<D>& p) {
  return impl_->erase(p);
}
template <std::size_t D>
std::vector<Vertex<D>> WellSpacedSet<D>::vertices() const {
  std::vector<Vertex<D>> out;
  for (const auto& [x, V] : impl_->vtx) out.push_back({x, V.steiner});
  return out;
}
template <std::size_t D>
std::vector<Point<D>> WellSpacedSet<D>::input() const {
  std::vector<Point<D>> out;
  for (const auto& [x, V] : impl_->vtx)
    if (!V.steiner) out.push_back(x);
  return out;
}
template <std::size_t D>
std::vector<std::string> WellSpacedSet<D>::canonical_graph() const {
  return impl_->canonical_graph();
}
template <std::size_t D>
std::string WellSpacedSet<D>::check_internal_indexes() const {
  return impl_->check_internal_indexes();
}
template <std::size_t D>
std::vector<std::string> WellSpacedSet<D>::tree_internal_nodes() const {
  std::vector<std::string> out;
  for (const auto& k : impl_->tree.internal_nodes()) out.push_back(k.str());
  return out;
}
template <std::size_t D>
std::vector<std::string> WellSpacedSet<D>::tree_leaves() const {
  std::vector<std::string> out;
  for (const auto& k : impl_->tree.leaves()) out.push_back(k.str());
  return out;
}
template <std::size_t D>
std::vector<Point<D>> WellSpacedSet<D>::clipped_voronoi_neighbors(const Point<D>& v, std::size_t* squares_read) const {
  if (!impl_->vtx.count(v)) throw InputError("clipped_voronoi_neighbors: " + fmt_point<D>(v) + " is not an output vertex");
  Time end;
  end.rank = std::numeric_limits<int>::max();
  auto res = impl_->clipped_voronoi_neighbors(v, end);
  if (squares_read) *squares_read = res.reads.size();
  return res.cv;
}
template <std::size_t D>
const Params& WellSpacedSet<D>::params() const {
  return impl_->params;
}
template <std::size_t D>
int WellSpacedSet<D>::kappa() const {
  return impl_->kappa;
}
template <std::size_t D>
const Stats& WellSpacedSet<D>::stats() const {
  Stats& s = impl_->stats;
  s.steiner = 0;
  for (const auto& [x, V] : impl_->vtx) s.steiner += V.steiner;
  s.ops = impl_->ops.size();
  s.squares = impl_->leaves.size();
  s.min_rank = std::numeric_limits<int>::max();
  s.max_rank = std::numeric_limits<int>::min();
  for (const auto& [k, op] : impl_->ops) {
    s.min_rank = std::min(s.min_rank, k.t.rank);
    s.max_rank = std::max(s.max_rank, k.t.rank);
  }
  return s;
}

// ---------- exact brute-force checks ----------
template <std::size_t D>
bool is_well_spaced(const std::vector<Point<D>>& M, double rho, std::string* why) {
  Q r2 = Q(rho) * Q(rho);
  std::vector<QPoint<D>> q;
  for (const auto& p : M) q.push_back(to_q<D>(p));
  for (std::size_t v = 0; v < M.size(); ++v) {
    std::vector<std::pair<Q, std::size_t>> byd;
    for (std::size_t u = 0; u < M.size(); ++u)
      if (u != v) byd.emplace_back(dist2(q[u], q[v]), u);
    if (byd.empty()) continue;
    std::sort(byd.begin(), byd.end());
    QPoint<D> lo, hi;
    for (std::size_t i = 0; i < D; ++i) {
      lo[i] = 0;
      hi[i] = 1;
    }
    Polytope<D> P = Polytope<D>::box(lo, hi);
    Q maxd = P.max_dist2(q[v]);
    for (auto& [d, u] : byd) {
      if (d > 4 * maxd) break;
      P.clip(bisector<D>(q[v], q[u]));
      maxd = P.max_dist2(q[v]);
    }
    if (maxd > r2 * byd.front().first) {
      if (why) *why = "vertex " + fmt_point<D>(M[v]) + " is not rho-well-spaced";
      return false;
    }
  }
  return true;
}

template <std::size_t D>
bool is_size_conforming(const std::vector<Point<D>>& N, const std::vector<Point<D>>& M, double rho, std::string* why) {
  Q c = Q(2) * Q(rho) / (Q(rho) - 1);
  Q c2 = c * c;
  std::vector<QPoint<D>> nq, mq;
  for (const auto& p : N) nq.push_back(to_q<D>(p));
  for (const auto& p : M) mq.push_back(to_q<D>(p));
  for (std::size_t v = 0; v < M.size(); ++v) {
    // lfs(v): radius of the smallest ball around v containing two input points
    Q a = -1, b = -1;
    for (const auto& x : nq) {
      Q d = dist2(x, mq[v]);
      if (a < 0 || d < a) {
        b = a;
        a = d;
      } else if (b < 0 || d < b) {
        b = d;
      }
    }
    Q nn = -1;
    for (std::size_t u = 0; u < M.size(); ++u)
      if (u != v) {
        Q d = dist2(mq[u], mq[v]);
        if (nn < 0 || d < nn) nn = d;
      }
    if (b < 0 || nn < 0) continue;
    if (c2 * nn < b) {
      if (why) *why = "vertex " + fmt_point<D>(M[v]) + " violates NN >= lfs/c";
      return false;
    }
  }
  return true;
}

template <std::size_t D>
std::vector<std::size_t> brute_clipped_voronoi_neighbors(const std::vector<Point<D>>& M, std::size_t v, double beta) {
  std::vector<QPoint<D>> q;
  for (const auto& p : M) q.push_back(to_q<D>(p));
  Q nn = -1;
  for (std::size_t u = 0; u < M.size(); ++u)
    if (u != v) {
      Q d = dist2(q[u], q[v]);
      if (nn < 0 || d < nn) nn = d;
    }
  Q r2 = Q(beta) * Q(beta) * nn;
  // box far enough: [v − 8·R, v + 8·R] with R = 1 + sqrt(D) covers everything
  QPoint<D> lo, hi;
  for (std::size_t i = 0; i < D; ++i) {
    lo[i] = q[v][i] - 16;
    hi[i] = q[v][i] + 16;
  }
  Polytope<D> P = Polytope<D>::box(lo, hi);
  std::vector<int> idx(M.size(), -1);
  for (std::size_t u = 0; u < M.size(); ++u)
    if (u != v) idx[u] = P.clip(bisector<D>(q[v], q[u]));
  std::vector<std::size_t> out;
  for (std::size_t u = 0; u < M.size(); ++u)
    if (u != v && P.face_within(idx[u], q[v], r2, 2 * static_cast<int>(D))) out.push_back(u);
  return out;
}

#define KMR_WS_INSTANTIATE(DIM)                                                                               \
  template class WellSpacedSet<DIM>;                                                                         \
  template bool is_well_spaced<DIM>(const std::vector<Point<DIM>>&, double, std::string*);                   \
  template bool is_size_conforming<DIM>(const std::vector<Point<DIM>>&, const std::vector<Point<DIM>>&, double, \
                                        std::string*);                                                       \
  template std::vector<std::size_t> brute_clipped_voronoi_neighbors<DIM>(const std::vector<Point<DIM>>&, std::size_t, double);
KMR_WS_INSTANTIATE(2)
KMR_WS_INSTANTIATE(3)
KMR_WS_INSTANTIATE(4)

}  // namespace kmr::wellspaced
