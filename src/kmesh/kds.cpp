#include "kmesh/kds.hpp"

#include <set>

#include "exact/error.hpp"
#include "poly/sturm.hpp"

namespace kmr::kmesh {

std::optional<std::pair<exact::Integer, std::vector<std::size_t>>> next_batch(const std::vector<Certificate>& certs,
                                                                             int bits, const Dyadic& from,
                                                                             const Dyadic& horizon) {
  std::optional<exact::Integer> k;
  std::vector<std::pair<exact::Integer, std::size_t>> found;
  for (std::size_t i = 0; i < certs.size(); ++i) {
    if (certs[i].value.degree() <= 0) continue;
    poly::LatticeRootSolver s(certs[i].value, bits);
    auto f = s.next_failure_after(from, k ? Dyadic(*k + 1, -bits) : horizon);
    if (!f) continue;
    if (!k || *f < *k) k = f;
    found.push_back({*f, i});
  }
  if (!k) return std::nullopt;
  std::vector<std::size_t> batch;
  for (auto& [f, i] : found)
    if (f == *k) batch.push_back(i);
  return std::pair{*k, batch};
}

KineticMesh::KineticMesh(std::vector<InputPoint> trajectories, int lattice_bits)
    : bits_(lattice_bits), upd_(std::move(trajectories), Dyadic(0)) {
  refresh("construct", 0, 0);
  batches_.clear();
}

// The global stages after a change: the mesh renumbered with its Delaunay triangulation, and the
// certificates of M and of S_N as polynomials of t − now.
namespace {

std::set<std::pair<Dyadic, Dyadic>> steiner_positions(const Mesh& m) {
  std::set<std::pair<Dyadic, Dyadic>> s;
  for (std::size_t v = 0; v < m.size(); ++v)
    if (m.info[v].steiner) s.insert({m.spanner.position(int(v))[0], m.spanner.position(int(v))[1]});
  return s;
}

}  // namespace

void KineticMesh::recertify() {
  mesh_ = upd_.mesh();
  mesh_time_ = now();
  certs_ = certificates(mesh_);
  mesh_certs_ = certs_.size();
  Mesh sn = upd_.input_spanner_mesh();
  for (auto& c : certificates(sn))
    if (c.kind != Certificate::Delaunay) certs_.push_back(std::move(c));
}

void KineticMesh::refresh(const std::string& what, std::size_t events, std::size_t moved) {
  auto before = steiner_positions(mesh_time_ == now() ? mesh_ : moved_to(mesh_, now() - mesh_time_));
  recertify();
  auto after = steiner_positions(mesh_);
  std::size_t kept = 0;
  for (auto& p : before) kept += after.count(p);
  Batch b{now(), events, what, mesh_.size(), kept, before.size()};
  if (moved > 0) b.ops = upd_.last().ops, b.affected = upd_.last().affected;
  b.moved = moved;
  batches_.push_back(b);
}

void KineticMesh::run_until(const Dyadic& T, const std::function<void(const Batch&)>& after) {
  KMR_CHECK(T >= now(), "run_until: time runs backwards");
  while (now() < T) {
    auto nb = next_batch(certs_, bits_, Dyadic(0), T - now());
    if (!nb) {
      upd_.advance_to(T);  // no certificate fails: the same mesh, moved
      recertify();
      break;
    }
    auto& [k, failed] = *nb;
    // The nuclei of the vertices of the failed certificates (input ids of mesh_ or of S_N's mesh,
    // which share the canonical input numbering). Delaunay failures change no vertex of M.
    std::set<int> nuclei;
    for (std::size_t i : failed) {
      const Certificate& c = certs_[i];
      if (c.kind == Certificate::Delaunay) continue;
      if (i < mesh_certs_) {
        nuclei.insert(mesh_.info[c.a].nucleus);
        nuclei.insert(mesh_.info[c.b].nucleus);
      } else {
        nuclei.insert(c.a);
        nuclei.insert(c.b);
      }
    }
    std::vector<InputPoint> moved;
    for (int v : nuclei) moved.push_back(mesh_.input[v]);
    upd_.advance_to(now() + Dyadic(k + 1, -bits_));
    if (!moved.empty()) upd_.relocate(moved);
    events_ += failed.size();
    refresh("events", failed.size(), moved.size());
    if (after) after(batches_.back());
  }
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
