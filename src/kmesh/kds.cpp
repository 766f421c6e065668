#include "kmesh/kds.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <tuple>
#include <limits>
#include <set>

#include "exact/error.hpp"
#include "poly/sturm.hpp"

namespace kmr::kmesh {

KineticMesh::KineticMesh(std::vector<InputPoint> trajectories, int lattice_bits)
    : bits_(lattice_bits), upd_(std::move(trajectories), Dyadic(0)) {
  refresh("construct", 0, 0);
  batches_.clear();
}

// The global stages after a change: the mesh renumbered with its Delaunay triangulation, and the
// certificates of M and of S_N as polynomials of t − now.
namespace {

// The Steiner vertices of m moved by dt (each with its nucleus), for the stability measure.
std::set<std::pair<Dyadic, Dyadic>> steiner_positions(const Mesh& m, const Dyadic& dt) {
  std::set<std::pair<Dyadic, Dyadic>> s;
  for (std::size_t v = 0; v < m.size(); ++v)
    if (m.info[v].steiner) {
      const Point2& p = m.spanner.position(int(v));
      const InputPoint& q = m.input[m.info[v].nucleus];
      if (dt.is_zero()) s.insert({p[0], p[1]});
      else s.insert({p[0] + Dyadic(q.vx * kScale) * dt, p[1] + Dyadic(q.vy * kScale) * dt});
    }
  return s;
}

}  // namespace

int KineticMesh::intern(const InputPoint& p, Rank rank, int ray) {
  auto [it, fresh] = interned_.try_emplace({p.x, p.y, p.vx, p.vy, rank, ray}, static_cast<int>(interned_.size()));
  return it->second;
}

// The certificates after a change, kept where they did not change (§4.3): every certificate of the
// new mesh (and of S_N) is named by its kind, rank and canonical vertices (an input vertex by its
// trajectory, a Steiner vertex by its nucleus's trajectory, rank and ray); one already kept under
// that name has the same polynomial of absolute time (its vertices kept their motion) and keeps its
// isolated failure; only the others are built. A satellite not converted keeps its witness while it
// is still a vertex of rank ≤ ℓ in the ball; else the nearest one is taken (nearest_witness).
void KineticMesh::recertify() {
  mesh_ = upd_.mesh();
  sn_mesh_ = upd_.input_spanner_mesh();
  mesh_time_ = now();
  constexpr Rank kInputRank = std::numeric_limits<Rank>::min();
  cv_.assign(mesh_.size(), -1);
  for (std::size_t v = 0; v < mesh_.size(); ++v) {
    const VertexInfo& in = mesh_.info[v];
    cv_[v] = in.steiner ? intern(mesh_.input[in.nucleus], in.rank, in.ray) : intern(mesh_.input[v], kInputRank, -1);
  }
  cv_sn_.assign(sn_mesh_.size(), -1);
  for (std::size_t v = 0; v < sn_mesh_.size(); ++v) cv_sn_[v] = intern(sn_mesh_.input[v], kInputRank, -1);
  mesh_id_of_.assign(interned_.size(), -1);
  for (std::size_t v = 0; v < mesh_.size(); ++v) mesh_id_of_[cv_[v]] = static_cast<int>(v);

  auto keep_witness = [&](std::size_t i, const Point2& s) {
    const Considered& c = mesh_.considered[i];
    auto it = witness_.find({cv_[c.nucleus], c.ray, c.rank});
    if (it != witness_.end()) {
      int w = mesh_id_of_[it->second];
      if (w >= 0 && w < c.existing && within(s, mesh_.spanner.position(w), 1, c.rank - 2)) return w;
    }
    return nearest_witness(mesh_, c, s);
  };
  auto specs = certificate_specs(mesh_, keep_witness);
  const std::size_t n_mesh = specs.size();
  for (auto& sp : certificate_specs(sn_mesh_))
    if (sp.kind != Certificate::Delaunay) specs.push_back(sp);

  auto key_of = [&](const CertificateSpec& sp, bool sn) -> Key {
    const std::vector<int>& cv = sn ? cv_sn_ : cv_;
    const int kind = sp.kind + (sn ? 16 : 0);
    int a = cv[sp.a], b = cv[sp.b];
    switch (sp.kind) {
      case Certificate::ParentChild:
        return {kind, sp.rank, a, b, -1, -1};
      case Certificate::BallNotEmpty:
        return {kind, sp.rank, cv[sp.c], sp.d, b, -1};
      case Certificate::Delaunay: {
        if (sp.d < 0) {  // a triangle, its cyclic order kept, smallest canonical vertex first
          std::array<int, 3> t{a, b, cv[sp.c]};
          std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
          return {kind, 0, t[0], t[1], t[2], -1};
        }
        int c = cv[sp.c], d = cv[sp.d];  // edge (b, a) has apexes d, c: the same in-circle polynomial
        return a < b ? Key{kind, 1, a, b, c, d} : Key{kind, 1, b, a, d, c};
      }
      default:  // symmetric in its two ends
        return {kind, sp.rank, std::min(a, b), std::max(a, b), -1, -1};
    }
  };
  std::vector<std::pair<Key, std::size_t>> keys;
  keys.reserve(specs.size());
  for (std::size_t i = 0; i < specs.size(); ++i) keys.push_back({key_of(specs[i], i >= n_mesh), i});
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    KMR_CHECK(keys[i - 1].first != keys[i].first, "recertify: two certificates with one canonical name");

  created_ = destroyed_ = 0;
  std::vector<std::pair<Key, std::size_t>> fresh[2];  // new names: of mesh_, of S_N
  auto it = certs_.begin();
  for (auto& [key, i] : keys) {
    while (it != certs_.end() && it->first < key) {
      unqueue(it->first, it->second);
      it = certs_.erase(it);
      ++destroyed_;
    }
    if (it != certs_.end() && it->first == key) {
      ++it;
      continue;
    }
    fresh[i >= n_mesh].push_back({key, i});
  }
  while (it != certs_.end()) {
    unqueue(it->first, it->second);
    it = certs_.erase(it);
    ++destroyed_;
  }
  for (int sn = 0; sn < 2; ++sn) {  // the new certificates, built together (shared moving points)
    std::vector<CertificateSpec> todo;
    for (auto& [key, i] : fresh[sn]) todo.push_back(specs[i]);
    auto built = build_certificates(sn ? sn_mesh_ : mesh_, todo, now());
    const std::vector<int>& cv = sn ? cv_sn_ : cv_;
    for (std::size_t f = 0; f < todo.size(); ++f) {
      const Key& key = fresh[sn][f].first;
      Kept k{std::move(built[f]), cv[todo[f].a], cv[todo[f].b], sn == 1, std::nullopt, now(), now()};
      if (k.cert.value.degree() > 0) pending_.insert({now(), key});
      certs_.emplace(key, std::move(k));
      ++created_;
    }
  }
  // The witnesses, read from the kept ball-not-empty certificates only: keys are kind-major, so they
  // are one contiguous range of certs_ (S_N's kinds are shifted by 16).
  witness_.clear();
  constexpr int kMin = std::numeric_limits<int>::min();
  for (auto w = certs_.lower_bound(Key{Certificate::BallNotEmpty, std::numeric_limits<Rank>::min(), kMin, kMin, kMin, kMin});
       w != certs_.end() && std::get<0>(w->first) == Certificate::BallNotEmpty; ++w)
    witness_.emplace_hint(witness_.end(), std::tuple{std::get<2>(w->first), std::get<3>(w->first), std::get<1>(w->first)},
                          std::get<4>(w->first));
}

void KineticMesh::unqueue(const Key& key, const Kept& k) {
  if (k.cert.value.degree() <= 0) return;
  if (k.fail) queue_.erase({*k.fail, key});
  else pending_.erase({k.searched_to, key});
}

// The window [now, to) is searched in pieces: a certificate with no failure in [searched_from,
// searched_to) (searched_from ≤ now) is searched on from max(now, searched_to) only, 16 lattice
// steps (or up to T) at a time, so that a short-lived certificate costs no far-ahead isolation.
void KineticMesh::isolate(const Key& key, Kept& k, const Dyadic& T) {
  Dyadic from = !k.fail && k.searched_to > now() ? k.searched_to : now();
  if (k.fail || k.searched_to < now()) k.searched_from = now();
  Dyadic to = std::max(T, from + Dyadic(16) * Dyadic(1, -bits_));
  poly::LatticeRootSolver s(k.cert.value, bits_);
  k.fail = failure_batch(s, fails_at_zero(k.cert), from, to);
  k.searched_to = to;
  if (k.fail) queue_.insert({*k.fail, key});
  else pending_.insert({to, key});
}

// The first lattice interval (counted from now) before T in which a kept certificate fails
// (failure_batch), and every kept certificate failing there. Roots are isolated only for the certificates whose
// cached answer does not cover [now, T): new ones, and those whose failure is behind now.
std::optional<std::pair<exact::Integer, std::vector<const std::pair<const KineticMesh::Key, KineticMesh::Kept>*>>>
KineticMesh::next_failures(const Dyadic& T) {
  std::optional<exact::Integer> best;
  std::vector<const std::pair<const Key, Kept>*> failed;
  const Dyadic start = now().shifted(bits_);
  if (!start.is_integer()) {  // now is not a lattice point: the lattice is taken from now, no cache
    for (auto& e : certs_) {
      const Kept& k = e.second;
      if (k.cert.value.degree() <= 0) continue;
      poly::LatticeRootSolver s(shifted_by_dyadic(k.cert.value, now()), bits_);
      auto f = failure_batch(s, fails_at_zero(k.cert), Dyadic(0), T - now());
      if (!f || (best && *f > *best)) continue;
      if (!best || *f < *best) best = f, failed.clear();
      failed.push_back(&e);
    }
    if (!best) return std::nullopt;
    return std::pair{*best, failed};
  }
  const exact::Integer k0 = start.mantissa() << static_cast<unsigned>(start.exponent());
  while (!queue_.empty() && queue_.begin()->first < k0) {
    Key key = queue_.begin()->second;
    queue_.erase(queue_.begin());
    isolate(key, certs_.at(key), T);
  }
  while (!pending_.empty() && pending_.begin()->first < T) {
    Key key = pending_.begin()->second;
    pending_.erase(pending_.begin());
    isolate(key, certs_.at(key), T);
  }
  if (queue_.empty() || !(Dyadic(queue_.begin()->first, -bits_) < T)) return std::nullopt;
  const exact::Integer K = queue_.begin()->first;
  for (auto it = queue_.begin(); it != queue_.end() && it->first == K; ++it) failed.push_back(&*certs_.find(it->second));
  return std::pair{K - k0, failed};
}

std::vector<Certificate> KineticMesh::current_certificates() const {
  std::vector<int> sn_id_of(interned_.size(), -1);
  for (std::size_t v = 0; v < cv_sn_.size(); ++v) sn_id_of[cv_sn_[v]] = static_cast<int>(v);
  std::vector<Certificate> out;
  for (auto& [key, k] : certs_) {
    const std::vector<int>& id = k.input_spanner ? sn_id_of : mesh_id_of_;
    Certificate c = k.cert;
    c.value = shifted_by_dyadic(k.cert.value, now());
    c.a = id[k.end_a];
    c.b = id[k.end_b];
    if (c.kind == Certificate::Delaunay) {  // named as certificates(mesh()) names it
      std::array<int, 3> t{id[std::get<2>(key)], id[std::get<3>(key)], id[std::get<4>(key)]};
      if (std::get<1>(key) == 0) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      else if (t[0] > t[1]) std::swap(t[0], t[1]);
      c.a = t[0];
      c.b = t[1];
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<Certificate> KineticMesh::recomputed_certificates() const {
  std::vector<Certificate> out = certificates(mesh_);
  for (auto& c : certificates(sn_mesh_))
    if (c.kind != Certificate::Delaunay) out.push_back(std::move(c));
  return out;
}

void KineticMesh::refresh(const std::string& what, std::size_t events, std::size_t moved) {
  auto before = steiner_positions(mesh_, now() - mesh_time_);
  recertify();
  auto after = steiner_positions(mesh_, Dyadic(0));
  std::size_t kept = 0;
  for (auto& p : before) kept += after.count(p);
  Batch b{now(), events, what, mesh_.size(), kept, before.size()};
  if (moved > 0) b.ops = upd_.last().ops, b.affected = upd_.last().affected;
  b.moved = moved;
  b.certs_created = created_;
  b.certs_destroyed = destroyed_;
  batches_.push_back(b);
}

void KineticMesh::run_until(const Dyadic& T, const std::function<void(const Batch&)>& after) {
  KMR_CHECK(T >= now(), "run_until: time runs backwards");
  while (now() < T) {
    auto nb = next_failures(T);
    if (!nb) {
      upd_.advance_to(T);  // no certificate fails: the same mesh, moved
      recertify();
      break;
    }
    // The nuclei of the vertices of the failed certificates (ids of mesh_; an end of an S_N
    // certificate is an input vertex, its own nucleus). Delaunay failures change no vertex of M:
    // their vertices' stars are repaired (Updater::voronoi_repair, at the next mesh()).
    std::set<int> nuclei;
    std::vector<int> voronoi;
    auto& [k, failed] = *nb;
    for (const auto* f : failed) {
      const Kept& c = f->second;
      if (c.cert.kind == Certificate::Delaunay) {
        auto [kind, form, a, b, x, y] = f->first;  // a triangle (a, b, x) or an edge (a, b) with apexes x, y
        for (int cv : {a, b, x, y})
          if (cv >= 0) voronoi.push_back(mesh_id_of_[cv]);
        continue;
      }
      nuclei.insert(mesh_.info[mesh_id_of_[c.end_a]].nucleus);
      nuclei.insert(mesh_.info[mesh_id_of_[c.end_b]].nucleus);
    }
    std::vector<InputPoint> moved;
    for (int v : nuclei) moved.push_back(mesh_.input[v]);
    upd_.voronoi_certificates_failed(voronoi);
    upd_.advance_to(now() + Dyadic(k + 1, -bits_));
    if (!moved.empty()) upd_.relocate(moved);
    events_ += failed.size();
    refresh("events", failed.size(), moved.size());
    if (after) after(batches_.back());
  }
}

CheckResult check_kept_certificates(const KineticMesh& k) {
  CheckResult r{"L4.3.1 (kept certificates = recomputed)", {}, 0};
  auto kept = k.current_certificates();
  for (auto& c : kept)
    if (!holds_at(c, Dyadic(0)))
      r.violations.push_back(std::string(kind_name(c.kind)) + " certificate of " + std::to_string(c.a) + ", " +
                             std::to_string(c.b) + " fails at the repair time " + k.now().to_decimal());
  // A kept ball-not-empty witness must be eligible (§4.3): an input vertex or a Steiner vertex of
  // rank ≤ ℓ (the updater's rule: a same-rank witness is allowed, U2), read from the vertex's own
  // record, not from Considered::existing, which keep_witness itself uses; holds_at above checked
  // that it lies in the ball.
  std::set<std::tuple<int, int, Rank>> not_converted;
  for (const auto& c : k.mesh().considered)
    if (!c.converted) not_converted.insert({c.nucleus, c.ray, c.rank});
  for (auto& c : kept) {
    if (c.kind != Certificate::BallNotEmpty || !not_converted.count({c.a, c.ray, c.rank})) continue;
    const bool exists = c.b >= 0 && c.b < static_cast<int>(k.mesh().size());
    const VertexInfo* w = exists ? &k.mesh().info[static_cast<std::size_t>(c.b)] : nullptr;
    if (!w || (w->steiner && w->rank > c.rank))
      r.violations.push_back("ball-not-empty certificate of the rank-" + std::to_string(c.rank) + " satellite of " +
                             std::to_string(c.a) + " ray " + std::to_string(c.ray) + " keeps witness " +
                             std::to_string(c.b) + (w ? " of rank " + std::to_string(w->rank) : std::string(", not a vertex")) +
                             ", not an input vertex nor of rank ≤ " + std::to_string(c.rank) + ", at " + k.now().to_decimal());
  }
  using Name = std::tuple<int, Rank, bool, int, int, int, std::string>;
  auto names = [](const std::vector<Certificate>& cs) {
    std::vector<Name> out;
    for (auto& c : cs) {
      int a = c.a, b = c.b;
      std::string p = c.value.is_zero() ? "0" : c.value.primitive_part().to_string();
      if (c.kind == Certificate::BallNotEmpty) b = -1, p.clear();  // the satellite (a, ray, rank) only
      else if (c.kind != Certificate::ParentChild && c.kind != Certificate::Delaunay && a > b) std::swap(a, b);
      out.push_back({c.kind, c.rank, c.strict, a, b, c.ray, std::move(p)});
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  auto a = names(kept), b = names(k.recomputed_certificates());
  if (a == b) return r;
  std::vector<Name> only_kept, only_new;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_kept));
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_new));
  for (int kind = Certificate::ParentChild; kind <= Certificate::Delaunay; ++kind) {
    auto count = [&](const std::vector<Name>& v) {
      return std::count_if(v.begin(), v.end(), [&](const Name& x) { return std::get<0>(x) == kind; });
    };
    auto first = [&](const std::vector<Name>& v) -> std::string {
      for (auto& x : v)
        if (std::get<0>(x) == kind)
          return "rank " + std::to_string(std::get<1>(x)) + " ends " + std::to_string(std::get<3>(x)) + ", " +
                 std::to_string(std::get<4>(x)) + (std::get<5>(x) >= 0 ? " ray " + std::to_string(std::get<5>(x)) : "");
      return "none";
    };
    if (count(only_kept) + count(only_new) == 0) continue;
    r.violations.push_back(std::string(kind_name(Certificate::Kind(kind))) + " certificates: " +
                           std::to_string(count(a)) + " kept vs " + std::to_string(count(b)) + " recomputed at " +
                           k.now().to_decimal() + "; " + std::to_string(count(only_kept)) + " only kept (first: " +
                           first(only_kept) + "), " + std::to_string(count(only_new)) + " only recomputed (first: " +
                           first(only_new) + ")");
  }
  return r;
}

void KineticMesh::insert(const InputPoint& p) {
  upd_.insert(p);
  refresh("insert", 0, 1);
}

void KineticMesh::erase(const InputPoint& p) {
  upd_.erase(p);
  refresh("delete", 0, 1);
}

}  // namespace kmr::kmesh
