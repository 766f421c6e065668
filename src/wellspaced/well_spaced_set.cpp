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
#include <unordered_set>
#include <algorithm>

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
    QPoint<D> q;
    bool steiner = false;
    Time created;
    K leaf;
  };
  struct Leaf {
    const Pt* input = nullptr;
    std::vector<Pt> verts;  // vertices (input and Steiner) inside
  };

  Params params;
  Q rho2, beta2;
  int kappa = 0;
  int rmax = 0;
  Quadtree<D> tree;
  std::map<Pt, Vtx> vtx;
  std::unordered_map<K, Leaf, KeyHash<D>> leaves;
  std::map<OpKey, Op> ops;
  std::map<Pt, std::set<Time>> ops_by_vertex;
  std::unordered_map<K, std::set<OpKey>, KeyHash<D>> readers;
  std::set<OpKey> pending;
  std::map<int, Q> rho_pow2;  // ρ^{2r}
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
  void place(const Pt& x) {
    auto& V = vtx.at(x);
    K l = tree.locate(x);
    V.leaf = l;
    auto& L = leaves[l];
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
  // Enqueue(w, flag, nn, v_(t)): nn given squared.
  void enqueue(const Pt& w, int type, const Q& nn2, const OpKey& from, Op& fromop) {
    Time tw;
    tw.rank = rank_of(nn2);
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
  struct CVResult {
    std::vector<K> reads;
    std::vector<std::pair<Pt, Q>> cv;  // neighbour, squared distance
    Q nn2;
  };
  static double box_dist2(const Pt& v, const K& s) {
    double h = s.side(), d = 0;
    for (std::size_t i = 0; i < D; ++i) {
      double lo = double(s.k[i]) * h, hi = lo + h, x = 0;
      if (v[i] < lo) x = lo - v[i];
      else if (v[i] > hi) x = v[i] - hi;
      d += x * x;
    }
    return d;
  }
  // QTClippedVoronoi (Fig. 3.6). Phase 1 scans squares in Euclidean order until NN(v) is known
  // exactly. Phase 2 maintains C = Vor_seen(v) ∩ box(v, R), R ≥ β·NN, and reads a square only if it
  // meets the certificate region of C — the union of the balls B(c, |cv|) over the vertices c of C
  // (a linear-in-c test, so vertices suffice) — which can only shrink as vertices are seen. Unseen
  // vertices then lie outside every certificate ball, so C ∩ B(v, β·NN) = Vor_M(v) ∩ B(v, β·NN);
  // the β-clipped neighbours are decided exactly on C. Reads vertices created before t only.
  CVResult clipped_voronoi_neighbors(const Pt& v, const Time& t) {
    CVResult res;
    const QPoint<D>& vq = vtx.at(v).q;
    using QE = std::pair<double, K>;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE>> heap;
    std::unordered_set<K, KeyHash<D>> seen;
    K start = vtx.at(v).leaf;
    heap.push({0.0, start});
    seen.insert(start);
    std::vector<std::pair<double, Pt>> cand;  // approximate squared distance, vertex
    std::vector<K> late;                      // squares popped after NN was fixed
    double best = std::numeric_limits<double>::infinity();
    bool nn_fixed = false;
    double limit = std::numeric_limits<double>::infinity();
    const double slack = 1 + 1e-9;
    std::optional<Polytope<D>> P;
    std::vector<int> cidx;  // constraint index of cand[i] in P (−1: bisector misses P)
    double maxd = 0;
    const auto vd0 = to_d<D>(vq);
    unsigned cache_version = ~0u;
    std::vector<std::pair<Pt, double>> vd;  // vertices of C in doubles, |cv|²
    auto clip_from = [&](std::size_t i0) {
      for (std::size_t i = i0; i < cand.size(); ++i) {
        // the bisector misses C if |vu|/2 > max_{c∈C}|vc| (pruning only: clipping is always safe)
        if (cand[i].first > 4 * maxd * (1 + 1e-6)) {
          cidx.push_back(-1);
          continue;
        }
        unsigned ver = P->version;
        cidx.push_back(P->clip(bisector<D>(vq, vtx.at(cand[i].second).q)));
        if (P->version != ver) maxd = P->max_dist2_approx(vd0);
      }
      limit = 4 * maxd * slack;
    };
    auto fix_nn = [&]() {
      res.nn2 = -1;  // exact minimum among the candidates near the approximate minimum
      for (auto& [d, u] : cand)
        if (d <= best * (1 + 1e-9)) {
          Q e = dist2<D>(vtx.at(u).q, vq);
          if (res.nn2 < 0 || e < res.nn2) res.nn2 = e;
        }
      nn_fixed = true;
      // box half-width R ≥ β·NN: β·NN rounded up to 8 significant bits (exactly checked)
      Q r2 = beta2 * res.nn2;
      double bn = params.beta * std::sqrt(res.nn2.template convert_to<double>());
      int e = static_cast<int>(std::ceil(std::log2(bn))) - 8;
      Q R(std::ldexp(std::ceil(std::ldexp(bn, -e)), e));
      Q step(std::ldexp(1.0, e));
      while (R * R < r2) R += step;
      QPoint<D> lo, hi;
      for (std::size_t i = 0; i < D; ++i) {
        lo[i] = vq[i] - R;
        hi[i] = vq[i] + R;
      }
      P = Polytope<D>::box(lo, hi);
      maxd = P->max_dist2_approx(vd0);
      std::sort(cand.begin(), cand.end());
      clip_from(0);
    };
    // does square s meet the certificate region of C? (double filter, exact fallback)
    auto meets_certificate_region = [&](const K& s) {
      if (cache_version != P->version) {
        vd.clear();
        for (const auto& c : P->v) {
          Pt cd;
          for (std::size_t i = 0; i < D; ++i) cd[i] = c.x[i].template convert_to<double>();
          vd.emplace_back(cd, dist2<D>(c.x, vq).template convert_to<double>());
        }
        cache_version = P->version;
      }
      double h = s.side();
      for (std::size_t j = 0; j < vd.size(); ++j) {
        double d = 0;
        for (std::size_t i = 0; i < D; ++i) {
          double lo = double(s.k[i]) * h, hi = lo + h, c = vd[j].first[i], x = 0;
          if (c < lo) x = lo - c;
          else if (c > hi) x = c - hi;
          d += x * x;
        }
        double r = vd[j].second;
        if (d <= r * (1 - 1e-9)) return true;
        if (d <= r * (1 + 1e-9)) {  // too close to call in doubles: exact
          const auto& c = P->v[j].x;
          Q hq = Q(1);
          for (int l = 0; l < s.level; ++l) hq /= 2;
          Q dq = 0;
          for (std::size_t i = 0; i < D; ++i) {
            Q lo = Q(static_cast<long long>(s.k[i])) * hq, hi = lo + hq, x = 0;
            if (c[i] < lo) x = lo - c[i];
            else if (c[i] > hi) x = c[i] - hi;
            dq += x * x;
          }
          if (dq <= dist2<D>(c, vq)) return true;
        }
      }
      return false;
    };
    while (!heap.empty()) {
      auto [key, s] = heap.top();
      if (!nn_fixed && key > best * slack) fix_nn();
      if (nn_fixed && key > limit) break;
      heap.pop();
      if (nn_fixed && !(s == start) && !meets_certificate_region(s)) continue;
      if (nn_fixed) late.push_back(s);
      else res.reads.push_back(s);
      std::size_t before = cand.size();
      auto it = leaves.find(s);
      if (it != leaves.end()) {
        std::vector<Pt> here;
        for (const Pt& u : it->second.verts)
          if (!(u == v) && vtx.at(u).created < t) here.push_back(u);
        std::sort(here.begin(), here.end());
        for (const Pt& u : here) {
          double d = 0;
          for (std::size_t i = 0; i < D; ++i) d += (u[i] - v[i]) * (u[i] - v[i]);
          cand.emplace_back(d, u);
          best = std::min(best, d);
        }
      }
      if (nn_fixed && cand.size() > before) clip_from(before);
      for (const K& n : tree.adjacent_leaves(s))
        if (seen.insert(n).second) heap.push({box_dist2(v, n), n});
    }
    KMR_CHECK(!cand.empty(), "clipped Voronoi scan found no vertex");
    if (!nn_fixed) fix_nn();
    // The squares read are those of the NN phase and those meeting the certificate region of the
    // FINAL cell: a function of the data, not of the order in which squares were popped (squares
    // popped earlier against a larger region hold only vertices that cannot affect the result).
    for (const K& s : late)
      if (meets_certificate_region(s)) res.reads.push_back(s);
    std::sort(res.reads.begin(), res.reads.end());
    // exact decision: u ∈ CV iff the face of C on the bisector of v, u has a point within β·NN
    Q r2 = beta2 * res.nn2;
    const double r2d = r2.template convert_to<double>();
    for (std::size_t i = 0; i < cand.size(); ++i) {
      if (cidx[i] < 0 || cand[i].first > 4 * r2d * (1 + 1e-6)) continue;  // pruning only
      if (P->face_within(cidx[i], vq, r2, 2 * static_cast<int>(D)))
        res.cv.emplace_back(cand[i].second, dist2<D>(vtx.at(cand[i].second).q, vq));
    }
    std::sort(res.cv.begin(), res.cv.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
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
    enqueue(k.v, 1, cv.nn2, k, op);
    for (auto& [w, d2] : cv.cv) enqueue(w, 1, d2, k, op);
    stats.dispatches++;
  }

  // Pick w ∈ Vor^{(ρ,β)}(v): on the segment from v to the farthest vertex x* of the cell, at a
  // squared distance between ρ²NN² and min(β²NN², |vx*|²), rounded to doubles, verified exactly.
  // Deterministic: depends only on v, NN(v) and the clipped cell.
  Pt pick(const QPoint<D>& vq, const Pt& v, const Q& nn2, const Polytope<D>& P) {
    const QPoint<D>* far = nullptr;
    Q fd = -1;
    for (const auto& x : P.v) {
      Q d = dist2<D>(x.x, vq);
      if (d > fd || (d == fd && x.x < *far)) {
        fd = d;
        far = &x.x;
      }
    }
    Q lo2 = rho2 * nn2, bmax = beta2 * nn2;
    Q hi2 = fd < bmax ? fd : bmax;
    double l = lo2.template convert_to<double>(), h = hi2.template convert_to<double>(), F = fd.template convert_to<double>();
    Pt xs;
    for (std::size_t i = 0; i < D; ++i) xs[i] = (*far)[i].template convert_to<double>();
    const double fr[] = {0.5, 0.25, 0.75, 0.125, 0.875, 0.375, 0.625, 0.0625, 0.9375, 0.03125};
    for (double f : fr) {
      double T = l + f * (h - l);
      double lam = std::sqrt(T / F);
      Pt w;
      for (std::size_t i = 0; i < D; ++i) w[i] = std::clamp(v[i] + lam * (xs[i] - v[i]), 0.0, 1.0);
      QPoint<D> wq = to_q<D>(w);
      Q d = dist2<D>(wq, vq);
      if (d < lo2 || !(d < bmax)) continue;
      if (!P.contains(wq)) continue;
      return w;
    }
    throw ContractError("no double-precision point found in the picking region (degenerate cell)");
  }

  void fill(const OpKey& k, Op& op) {
    CVResult cv = clipped_voronoi_neighbors(k.v, k.t);
    op.reads = cv.reads;
    const QPoint<D> vq = vtx.at(k.v).q;
    QPoint<D> lo, hi;
    for (std::size_t i = 0; i < D; ++i) {
      lo[i] = 0;
      hi[i] = 1;
    }
    Polytope<D> P = Polytope<D>::box(lo, hi);  // Vor_CV(v) ∩ [0,1]^D
    for (auto& [u, d2] : cv.cv) P.clip(bisector<D>(vq, vtx.at(u).q));
    Q lim = rho2 * cv.nn2;
    std::uint64_t count = 0;
    while (P.some_vertex_beyond(vq, lim)) {  // v is not ρ-well-spaced
      Pt w = pick(vq, k.v, cv.nn2, P);
      KMR_CHECK(!vtx.count(w), "Steiner vertex coincides with a vertex");
      Vtx W;
      W.q = to_q<D>(w);
      W.steiner = true;
      W.created = k.t;
      Q dw = dist2<D>(W.q, vq);
      QPoint<D> wq = W.q;
      vtx.emplace(w, std::move(W));
      place(w);  // QTInsertSteiner
      op.steiners.push_back(w);
      enqueue(w, 0, dw, k, op);
      P.clip(bisector<D>(vq, wq));
      ++count;
    }
    stats.fills++;
    stats.steiner_per_fill_max = std::max(stats.steiner_per_fill_max, count);
  }

  // ---------- change propagation (Fig. 3.8) ----------
  void undo(const OpKey& k, Op& op) {
    for (const K& s : op.reads) {
      auto it = readers.find(s);
      if (it != readers.end()) {
        it->second.erase(k);
        if (it->second.empty()) readers.erase(it);
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
      for (const K& s : op.reads) readers[s].insert(k);
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
    for (const K& l : tree.leaves()) leaves[l];
    for (const Pt& p : sorted) {
      Vtx V;
      V.q = to_q<D>(p);
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
    for (const K& s : ch.fresh) leaves[s];
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
    V.q = to_q<D>(p);
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
  std::vector<Point<D>> out;
  for (auto& [w, d] : res.cv) out.push_back(w);
  std::sort(out.begin(), out.end());
  return out;
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
      if (u != v) byd.emplace_back(dist2<D>(q[u], q[v]), u);
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
      Q d = dist2<D>(x, mq[v]);
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
        Q d = dist2<D>(mq[u], mq[v]);
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
      Q d = dist2<D>(q[u], q[v]);
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
