#include "kmesh/update.hpp"

#include <algorithm>
#include <limits>

#include "exact/error.hpp"
#include "kmesh/delaunay.hpp"

namespace kmr::kmesh {
namespace {

// The activation rank of a lone input point, and the top rank of a mesh without ranks.
constexpr Rank kNoRank = std::numeric_limits<Rank>::max() / 4;
constexpr Rank kNoHighest = std::numeric_limits<Rank>::min() / 4;

}  // namespace

Updater::Updater(std::vector<InputPoint> points, const Dyadic& t) : now_(t) {
  Mesh m = construct(std::move(points), t);
  const int n = static_cast<int>(m.n());
  std::vector<Point2> pts;
  for (int v = 0; v < n; ++v) {
    inputs_[v] = Input{m.input[v], v, v, n == 1 ? kNoRank : m.info[v].rank};
    key_of_trajectory_[{m.input[v].x, m.input[v].y, m.input[v].vx, m.input[v].vy}] = v;
    sn_to_key_[v] = v;
    pts.push_back(m.spanner.position(v));
  }
  next_key_ = n;
  S_ = m.spanner;
  SN_ = Spanner::build(pts, 8);  // the construction's first spanner: over N alone
  info_ = m.info;
  lowest_ = m.lowest;
  highest_ = n == 1 ? kNoHighest : m.highest;
  for (auto& c : m.considered) {
    Key k{c.rank, c.nucleus, c.ray};
    by_nucleus_[c.nucleus].insert(k);
    if (c.converted) {
      sats_[k] = Sat{true, c.vertex, -1};
    } else {
      int w = ball_witness(sat_position(c.nucleus, c.ray, c.rank), c.rank, c.nucleus);
      KMR_CHECK(w >= 0, "Updater: a satellite not converted by the construction has an empty ball");
      sats_[k] = Sat{};
      set_witness(k, w);
    }
  }
  stars_ = std::move(m.stars);  // the construction's stage 3
  stars_.resize(S_.size());
  S_.touched.clear();
  SN_.touched.clear();
}

Point2 Updater::sat_position(int nucleus, int ray, Rank l) const {
  return satellite_position(S_.position(inputs_.at(nucleus).s), ray, l);
}

bool Updater::has_converted(int nucleus, Rank l) const {
  for (int k : rays_of_rank(l)) {
    auto it = sats_.find(Key{l, nucleus, k});
    if (it != sats_.end() && it->second.converted) return true;
  }
  return false;
}

bool Updater::active(int nucleus, Rank l) const {
  auto it = inputs_.find(nucleus);
  if (it == inputs_.end() || l < it->second.rho || l > highest_) return false;
  return l == it->second.rho || has_converted(nucleus, l - 1);
}

// BallEmpty (§4.2.1, Lemma 4.2.4) over the vertices of rank ≤ ℓ: a vertex among the ℓ′-neighbours of
// s, ℓ′ = ℓ−6 … ℓ−3, in the closed ball B(s, 2^(ℓ−2)), found from the (ℓ+1)-site of the nucleus; −1 if
// none. Steiner vertices converted at a higher rank are not there yet in the order of Fig. 4.2.
int Updater::ball_witness(const Point2& s, Rank l, int nucleus) const {
  int h = S_.rep(inputs_.at(nucleus).s, l + 1);
  std::vector<int> N = S_.centers_near(s, l, h);
  for (Rank r = l - 1; r >= l - 6; --r) {
    N = S_.centers_near_below(s, r, N);
    if (r > l - 3) continue;
    IPoint se = enclose(s);
    for (int x : N) {
      ++S_.ops;
      if (info_[x].steiner && info_[x].rank > l) continue;
      if (within_filtered(s, se, S_.position(x), S_.enclosure(x), 1, l - 2)) return x;
    }
  }
  return -1;
}

void Updater::set_witness(const Key& k, int w) {
  sats_[k].witness = w;
  witness_of_[w].insert(k);
}

void Updater::drop_witness(const Key& k) {
  auto it = sats_.find(k);
  if (it == sats_.end() || it->second.witness < 0) return;
  auto w = witness_of_.find(it->second.witness);
  if (w != witness_of_.end()) {
    w->second.erase(k);
    if (w->second.empty()) witness_of_.erase(w);
  }
  it->second.witness = -1;
}

void Updater::affect_rank(int nucleus, Rank l) {
  for (int k : rays_of_rank(l)) affect(Key{l, nucleus, k});
}

// Before a decision of rank ℓ changes: remember whether the nucleus had a converted ℓ-satellite, so
// that a change of its activity at ℓ+1 is propagated (Fig. 4.5: F_(ℓ+1) gets its (ℓ+1)-satellites).
void Updater::mark(const Key& k) {
  auto [l, v, ray] = k;
  before_.try_emplace({l, v}, has_converted(v, l));
}

void Updater::erase_record(const Key& k) {
  mark(k);
  drop_witness(k);
  sats_.erase(k);
  auto it = by_nucleus_.find(std::get<1>(k));
  if (it != by_nucleus_.end()) {
    it->second.erase(k);
    if (it->second.empty()) by_nucleus_.erase(it);
  }
}

// Remove(S, s): the Steiner vertex leaves the spanner (its orphans are repaired there, the P_ℓ of
// Fig. 4.5); the satellites it witnessed lose their witness and are fully affected.
void Updater::remove_steiner(const Key& k) {
  Sat& st = sats_.at(k);
  KMR_CHECK(st.converted, "Remove of a satellite that is not converted");
  mark(k);
  int x = st.vertex;
  const std::uint64_t ops_before = S_.ops;
  S_.remove(x);
  last_.ops_remove += S_.ops - ops_before;
  touch_delaunay(x);
  info_[x] = VertexInfo{};
  st.converted = false;
  st.vertex = -1;
  ++last_.removed;
  auto w = witness_of_.find(x);
  if (w != witness_of_.end()) {
    for (const Key& kk : w->second) {
      sats_.at(kk).witness = -1;
      affect(kk);
    }
    witness_of_.erase(w);
  }
}

// Every Steiner vertex s″ converted at a rank ℓ″ > above whose ball B(s″, 2^(ℓ″−2)) contains p has a
// violated ball-empty certificate: it is fully affected at ℓ″ and removed now (it would be at ℓ″;
// removing it first keeps it from covering p in the spanner). s″ is an (ℓ″−2)-center (U2: nothing
// lies within 2^(ℓ″−2) of it), so the (ℓ″−2)-centers within c·2^(ℓ″−2) of p contain it.
void Updater::remove_balls_containing(const Point2& p, Rank above) {
  if (highest_ == kNoHighest || above >= highest_) return;
  IPoint pe = enclose(p);
  std::vector<int> L = S_.centers_within(p, highest_ - 2);
  std::vector<Key> hit;
  for (Rank r = highest_ - 2;; --r) {
    for (int w : L) {
      ++S_.ops;
      if (info_[w].steiner && info_[w].rank == r + 2 && within_filtered(p, pe, S_.position(w), S_.enclosure(w), 1, r))
        hit.push_back(Key{r + 2, info_[w].nucleus, info_[w].ray});
    }
    if (r + 2 <= above + 1 || L.empty()) break;
    L = S_.centers_near_below(p, r - 1, L);
  }
  for (const Key& k : hit) {
    remove_steiner(k);
    affect(k);
  }
}

// Convert phase for one fully affected satellite: considered iff its nucleus is active at ℓ; then
// converted iff BallEmpty.
void Updater::decide(const Key& k) {
  auto [l, v, ray] = k;
  if (!active(v, l)) {
    if (sats_.count(k)) erase_record(k);
    return;
  }
  if (!sats_.count(k)) {
    mark(k);
    sats_[k] = Sat{};
    by_nucleus_[v].insert(k);
  }
  Point2 s = sat_position(v, ray, l);
  int w = ball_witness(s, l, v);
  drop_witness(k);
  if (w >= 0) {
    set_witness(k, w);
    return;
  }
  mark(k);
  remove_balls_containing(s, l);
  int id = S_.insert_point(s);
  touch_delaunay(id);
  if (static_cast<std::size_t>(id) >= info_.size()) info_.resize(id + 1);
  info_[id] = VertexInfo{true, v, l, ray};
  Sat& st = sats_.at(k);
  st.converted = true;
  st.vertex = id;
  ++last_.converted;
}

// UpdateStats::reach (Lemma 4.3.4): how far, in units of 2^ℓ, an affected ℓ-satellite is from the
// focus. Counted apart from the operations of Fig. 4.5 (a measurement, not a step of it).
void Updater::measure_reach(const Key& k) {
  auto [l, v, ray] = k;
  if (!inputs_.count(v) || focus_.empty()) return;
  const Point2 s = sat_position(v, ray, l);
  Rank r = std::numeric_limits<Rank>::max();
  for (const Point2& f : focus_) r = std::min(r, f == s ? l : min_rank_within(s, f, 1));
  last_.reach = std::max(last_.reach, r - l);
}

// Stage 2 of Fig. 4.5: ranks in increasing order; Remove, then Convert, then the activity changes
// passed on to the next rank.
void Updater::propagate() {
  while (!F_.empty()) {
    Rank l = F_.begin()->first;
    ++last_.ranks;
    std::set<Key> Fl;
    while (F_.count(l) && !F_[l].empty()) {  // Remove may affect more satellites of rank ℓ
      std::set<Key> batch = std::move(F_[l]);
      F_.erase(l);
      for (const Key& k : batch) {
        if (!Fl.insert(k).second) continue;
        auto it = sats_.find(k);
        if (it != sats_.end() && it->second.converted) remove_steiner(k);
      }
    }
    F_.erase(l);
    last_.affected += Fl.size();
    last_.affected_max_rank = std::max(last_.affected_max_rank, Fl.size());
    for (const Key& k : Fl) measure_reach(k);
    for (const Key& k : Fl) decide(k);
    KMR_CHECK(!F_.count(l), "update: a satellite of the current rank affected after its Convert phase");
    for (auto it = before_.lower_bound({l, std::numeric_limits<int>::min()}); it != before_.end() && it->first.first == l;) {
      int v = it->first.second;
      if (it->second != has_converted(v, l) && l + 1 <= highest_) affect_rank(v, l + 1);
      it = before_.erase(it);
    }
  }
  KMR_CHECK(before_.empty(), "update: an activity change below the processed ranks");
}

void Updater::refresh_rhos(const std::vector<int>& sn_touched) {
  std::set<int> t(sn_touched.begin(), sn_touched.end());
  for (int sn : t) {
    if (!SN_.alive(sn)) continue;
    int key = sn_to_key_.at(sn);
    Input& in = inputs_.at(key);
    Rank r = SN_.alive_count() == 1 ? kNoRank : SN_.min_rank(sn);
    if (r == in.rho) continue;
    std::vector<Rank> ends;
    if (in.rho != kNoRank) ends.push_back(in.rho);
    if (r != kNoRank) ends.push_back(r);
    if (!ends.empty())
      for (Rank l = *std::min_element(ends.begin(), ends.end()); l <= *std::max_element(ends.begin(), ends.end()); ++l)
        affect_rank(key, l);
    in.rho = r;
    info_[in.s].rank = r == kNoRank ? 0 : r;
  }
}

// Λ = max_w ⌈lg |q w|⌉ from the smallest input point q, as Spanner::build defines it; the top rank
// of the conversion is Λ+4. A change of it affects the ranks gained or lost.
Rank Updater::recompute_highest() {
  Rank hi = kNoHighest;
  if (inputs_.size() >= 2) {
    const Input* q = nullptr;
    for (auto& [k, in] : inputs_)
      if (!q || S_.position(in.s) < S_.position(q->s)) q = &in;
    Rank lam = kNoHighest;
    for (auto& [k, in] : inputs_) {
      ++S_.ops;
      if (&in != q) lam = std::max(lam, min_rank_within(S_.position(q->s), S_.position(in.s), 1));
    }
    hi = lam + 4;
  }
  Rank old = highest_;
  highest_ = hi;
  if (hi > old) {
    for (auto& [k, in] : inputs_)
      if (in.rho != kNoRank && in.rho <= hi && (old == kNoHighest || in.rho > old)) affect_rank(k, in.rho);
    if (old != kNoHighest)
      for (auto it = sats_.lower_bound(Key{old, std::numeric_limits<int>::min(), 0});
           it != sats_.end() && std::get<0>(it->first) == old; ++it)
        if (it->second.converted) affect_rank(std::get<1>(it->first), old + 1);
  } else if (hi < old) {
    // The ranks above hi go, and rank hi, now the top, is re-decided whole (Remove, then Convert in
    // key order, as the construction decides it): its old decisions were made as an inner rank, where
    // the 12 satellites of a rank may belong to several nuclei, and the boundary of M must be the 12
    // top satellites of one nucleus, a rigid 12-gon (no certificate watches its convexity;
    // check_rigid_boundary, spec/kmesh.md).
    for (auto it = sats_.lower_bound(Key{hi, std::numeric_limits<int>::min(), 0}); it != sats_.end(); ++it)
      affect(it->first);
  }
  return hi;
}

void Updater::finish(std::uint64_t ops0) {
  propagate();
  S_.touched.clear();
  SN_.touched.clear();
  last_.ops = S_.ops + SN_.ops - ops0;
  total_ops_ += last_.ops;
  if (!sats_.empty()) lowest_ = std::min(lowest_, std::get<0>(sats_.begin()->first));  // keys are rank-major
}

std::map<int, Updater::Input>::iterator Updater::find_trajectory(const InputPoint& p) {
  auto k = key_of_trajectory_.find({p.x, p.y, p.vx, p.vy});
  return k == key_of_trajectory_.end() ? inputs_.end() : inputs_.find(k->second);
}

// Stage 1 of an insertion: S restricted to N, the activation ranks, and the balls the new vertex
// falls into.
void Updater::insert_stage1(const InputPoint& p) {
  Point2 pos = scaled_at(p, now_);
  for (auto& [k, in] : inputs_)
    if (S_.position(in.s) == pos)
      throw InputError("insert of (" + p.x.str() + ", " + p.y.str() + "): the point is already in the input");
  int key = next_key_++;
  SN_.touched.clear();
  int sn = SN_.insert_point(pos);
  sn_to_key_[sn] = key;
  remove_balls_containing(pos, lowest_ - 1);  // lowest_: no satellite was ever considered below it
  int sid = S_.insert_point(pos);
  touch_delaunay(sid);
  if (static_cast<std::size_t>(sid) >= info_.size()) info_.resize(sid + 1);
  info_[sid] = VertexInfo{false, key, 0, -1};
  inputs_[key] = Input{p, sid, sn, kNoRank};
  key_of_trajectory_[{p.x, p.y, p.vx, p.vy}] = key;
  std::vector<int> t = SN_.touched;
  t.push_back(sn);
  refresh_rhos(t);
  recompute_highest();
}

void Updater::insert(const InputPoint& p) {
  last_ = UpdateStats{};
  focus_ = {scaled_at(p, now_)};
  std::uint64_t ops0 = S_.ops + SN_.ops;
  insert_stage1(p);
  finish(ops0);
}

// Stage 1 of a deletion: the satellites of the deleted vertex go (Remove), then the vertex itself.
void Updater::erase_stage1(std::map<int, Input>::iterator it) {
  int key = it->first;
  Input in = it->second;
  key_of_trajectory_.erase({in.p.x, in.p.y, in.p.vx, in.p.vy});
  if (by_nucleus_.count(key)) {
    std::vector<Key> mine(by_nucleus_[key].begin(), by_nucleus_[key].end());
    for (const Key& k : mine) {
      if (sats_.at(k).converted) remove_steiner(k);
      erase_record(k);
      affect(k);
    }
  }
  inputs_.erase(it);
  const std::uint64_t ops_before = S_.ops;
  S_.remove(in.s);
  last_.ops_remove += S_.ops - ops_before;
  touch_delaunay(in.s);
  info_[in.s] = VertexInfo{};
  if (auto w = witness_of_.find(in.s); w != witness_of_.end()) {
    for (const Key& kk : w->second) {
      sats_.at(kk).witness = -1;
      affect(kk);
    }
    witness_of_.erase(w);
  }
  SN_.touched.clear();
  SN_.remove(in.sn);
  sn_to_key_.erase(in.sn);
  refresh_rhos(SN_.touched);
  recompute_highest();
}

void Updater::erase(const InputPoint& p) {
  auto it = find_trajectory(p);
  if (it == inputs_.end()) throw InputError("delete of (" + p.x.str() + ", " + p.y.str() + "): not in the input");
  if (inputs_.size() == 1) throw InputError("delete of the last input point");
  last_ = UpdateStats{};
  focus_ = {S_.position(it->second.s)};
  std::uint64_t ops0 = S_.ops + SN_.ops;
  erase_stage1(it);
  finish(ops0);
}

void Updater::relocate(const std::vector<InputPoint>& moved) {
  last_ = UpdateStats{};
  focus_.clear();
  std::uint64_t ops0 = S_.ops + SN_.ops;
  std::vector<InputPoint> back;
  for (const InputPoint& p : moved) {
    auto it = find_trajectory(p);
    KMR_CHECK(it != inputs_.end(), "relocate: a trajectory that is not in the input");
    if (inputs_.size() == 1) break;  // the last point stays (a lone point has no certificate)
    back.push_back(it->second.p);
    focus_.push_back(S_.position(it->second.s));
    erase_stage1(it);
  }
  propagate();
  for (const InputPoint& p : back) {
    insert_stage1(p);
    propagate();
  }
  finish(ops0);
}

void Updater::advance_to(const Dyadic& t) {
  KMR_CHECK(t >= now_, "advance_to: time runs backwards");
  if (t == now_) return;
  Dyadic dt = t - now_;
  auto moved = [&](const Point2& p, const InputPoint& traj) {
    return Point2{p[0] + Dyadic(traj.vx * kScale) * dt, p[1] + Dyadic(traj.vy * kScale) * dt};
  };
  std::vector<Point2> ps(S_.size());
  for (int x = 0; x < static_cast<int>(S_.size()); ++x)
    ps[x] = S_.alive(x) ? moved(S_.position(x), inputs_.at(info_[x].nucleus).p) : S_.position(x);
  S_.move_to(ps);
  std::vector<Point2> pn(SN_.size());
  for (int x = 0; x < static_cast<int>(SN_.size()); ++x)
    pn[x] = SN_.alive(x) ? moved(SN_.position(x), inputs_.at(sn_to_key_.at(x)).p) : SN_.position(x);
  SN_.move_to(pn);
  now_ = t;
}

std::vector<std::pair<Point2, int>> Updater::canonical_inputs() const {
  std::vector<std::pair<Point2, int>> ins;
  for (auto& [k, in] : inputs_) ins.push_back({S_.position(in.s), k});
  std::sort(ins.begin(), ins.end());
  return ins;
}

Mesh Updater::input_spanner_mesh() const {
  Mesh m;
  auto ins = canonical_inputs();
  std::vector<int> new_id(SN_.size(), -1);
  for (std::size_t i = 0; i < ins.size(); ++i) {
    const Input& in = inputs_.at(ins[i].second);
    new_id[in.sn] = static_cast<int>(i);
    m.input.push_back(in.p);
    m.info.push_back(VertexInfo{false, static_cast<int>(i), in.rho == kNoRank ? 0 : in.rho, -1});
  }
  m.spanner = SN_.compacted(new_id);
  return m;
}

Mesh Updater::mesh() {
  Mesh m;
  auto ins = canonical_inputs();  // sorted by position at now (the construction's order at now)
  std::vector<int> new_id(S_.size(), -1);
  std::map<int, int> input_new;  // input key → new id
  for (std::size_t i = 0; i < ins.size(); ++i) {
    new_id[inputs_.at(ins[i].second).s] = static_cast<int>(i);
    input_new[ins[i].second] = static_cast<int>(i);
    m.input.push_back(inputs_.at(ins[i].second).p);
  }
  const int n = static_cast<int>(ins.size());
  std::vector<std::pair<Key, int>> steiner;
  for (auto& [k, st] : sats_)
    if (st.converted) steiner.push_back({Key{std::get<0>(k), input_new.at(std::get<1>(k)), std::get<2>(k)}, st.vertex});
  std::sort(steiner.begin(), steiner.end());
  for (std::size_t i = 0; i < steiner.size(); ++i) new_id[steiner[i].second] = n + static_cast<int>(i);
  m.spanner = S_.compacted(new_id);
  m.info.resize(n + steiner.size());
  for (int i = 0; i < n; ++i) {
    Rank r = inputs_.at(ins[i].second).rho;
    m.info[i] = VertexInfo{false, i, r == kNoRank ? 0 : r, -1};
  }
  for (std::size_t i = 0; i < steiner.size(); ++i) {
    auto [l, v, ray] = steiner[i].first;
    m.info[n + i] = VertexInfo{true, v, l, ray};
  }
  // considered, in canonical order (ids are rank-major). `existing`: the vertices of lower rank for a
  // converted satellite, of rank ≤ ℓ for one not converted (its witness may be of the same rank), so
  // that the certificates and the L4.2.5 check (which takes the rank's smallest) read as U2.
  std::vector<std::tuple<Rank, int, int, const Sat*>> cons;
  for (auto& [k, st] : sats_) cons.push_back({std::get<0>(k), input_new.at(std::get<1>(k)), std::get<2>(k), &st});
  std::sort(cons.begin(), cons.end());
  std::size_t below = 0, upto = 0;
  for (auto& [l, v, ray, st] : cons) {
    while (below < steiner.size() && std::get<0>(steiner[below].first) < l) ++below;
    while (upto < steiner.size() && std::get<0>(steiner[upto].first) <= l) ++upto;
    int vid = st->converted ? new_id[st->vertex] : -1;
    m.considered.push_back({v, ray, l, st->converted, vid, n + static_cast<int>(st->converted ? below : upto)});
    if (m.ranks.empty() || m.ranks.back().rank != l) m.ranks.push_back(RankStats{l, 0, 0, 0, 0});
    ++m.ranks.back().considered;
    m.ranks.back().converted += st->converted;
  }
  for (auto& r : m.ranks) r.active = r.considered / 12;
  m.lowest = m.ranks.empty() ? 0 : m.ranks.front().rank;
  m.highest = highest_ == kNoHighest ? 0 : highest_;
  s_id_of_mesh_.assign(m.size(), -1);
  for (int x = 0; x < static_cast<int>(S_.size()); ++x)
    if (new_id[x] >= 0) s_id_of_mesh_[new_id[x]] = x;
  repair_delaunay();
  if (n >= 2) m.triangles = triangles_from_stars(stars_, new_id);
  return m;
}

void Updater::repair_delaunay() {
  if (delaunay_touched_.empty()) return;  // nothing changed since: last() keeps the counts of the repair
  std::uint64_t before = S_.ops;
  voronoi_repair();
  last_.ops_delaunay = S_.ops - before;
}

void Updater::voronoi_certificates_failed(const std::vector<int>& mesh_ids) {
  for (int v : mesh_ids) touch_delaunay(s_id_of_mesh_.at(v));
}

bool Updater::canonical_less(int a, int b) const {
  const VertexInfo &A = info_[a], &B = info_[b];
  if (A.steiner != B.steiner) return !A.steiner;
  if (!A.steiner) return S_.position(a) < S_.position(b);
  if (A.rank != B.rank) return A.rank < B.rank;
  if (A.nucleus != B.nucleus) return S_.position(inputs_.at(A.nucleus).s) < S_.position(inputs_.at(B.nucleus).s);
  return A.ray < B.ray;
}

// Stage 3 of Fig. 4.5, locally (see the header): the touched vertices' stars, then those of their
// neighbours before (the stars kept) and after (the stars just recomputed). A vertex's star is
// IdentifyVoronoiNeighbors on its candidates (kmesh/delaunay.hpp), as in the construction.
void Updater::voronoi_repair() {
  stars_.resize(S_.size());
  last_.stars = 0;
  std::set<int> around;
  for (int x : delaunay_touched_) around.insert(stars_[x].ring.begin(), stars_[x].ring.end());
  const LiftOrder lower = [this](int a, int b) { return canonical_less(a, b); };
  auto redo = [&](int x) {
    stars_[x] = S_.alive(x) ? voronoi_star(S_, x, info_[x].rank, lower) : VoronoiStar{};
    ++last_.stars;
  };
  for (int x : delaunay_touched_) {
    redo(x);
    around.insert(stars_[x].ring.begin(), stars_[x].ring.end());
  }
  for (int y : around)
    if (!delaunay_touched_.count(y)) redo(y);
  delaunay_touched_.clear();
}

}  // namespace kmr::kmesh
