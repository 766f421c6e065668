#include "kmesh/rebuild_simulation.hpp"

#include <algorithm>
#include <set>

#include "exact/error.hpp"
#include "poly/sturm.hpp"

namespace kmr::kmesh {
namespace {

std::set<std::pair<Dyadic, Dyadic>> steiner_positions(const Mesh& m, const Dyadic& dt) {
  std::set<std::pair<Dyadic, Dyadic>> s;
  Mesh x = dt.is_zero() ? m : moved_to(m, dt);
  for (std::size_t v = 0; v < x.size(); ++v)
    if (x.info[v].steiner) s.insert({x.spanner.position(int(v))[0], x.spanner.position(int(v))[1]});
  return s;
}

}  // namespace

std::optional<std::tuple<CollisionTime, std::size_t, std::size_t>> first_collision(const std::vector<InputPoint>& t,
                                                                                  const Dyadic& from, const Dyadic& to) {
  std::optional<std::tuple<CollisionTime, std::size_t, std::size_t>> best;
  using Q = CollisionTime;
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = i + 1; j < t.size(); ++j) {
      exact::Integer dx = t[j].x - t[i].x, dy = t[j].y - t[i].y, dvx = t[j].vx - t[i].vx, dvy = t[j].vy - t[i].vy;
      // dx + dvx·s = 0 and dy + dvy·s = 0 for one s.
      std::optional<Q> s;
      bool never = false;
      for (auto [d, dv] : {std::pair{dx, dvx}, std::pair{dy, dvy}}) {
        if (dv == 0) {
          if (d != 0) never = true;
          continue;
        }
        Q si(-d, dv);
        if (s && *s != si) never = true;
        s = si;
      }
      if (never) continue;
      KMR_CHECK(s.has_value(), "first_collision: identical trajectories");
      auto as_q = [](const Dyadic& x) {
        return x.exponent() >= 0 ? Q(exact::Integer(x.mantissa() << static_cast<unsigned>(x.exponent())))
                                 : Q(x.mantissa(), exact::Integer(1) << static_cast<unsigned>(-x.exponent()));
      };
      if (*s < as_q(from) || *s > as_q(to)) continue;
      if (!best || *s < std::get<0>(*best)) best = {{*s, i, j}};
    }
  return best;
}

RebuildSimulation::RebuildSimulation(std::vector<InputPoint> trajectories, int lattice_bits)
    : traj_(std::move(trajectories)), bits_(lattice_bits) {
  mesh_ = construct(traj_, now_);
  certs_ = certificates(mesh_);
}

void RebuildSimulation::rebuild(const std::string& what, std::size_t events) {
  auto before = steiner_positions(mesh_, now_ - built_at_);
  mesh_ = construct(traj_, now_);
  built_at_ = now_;
  certs_ = certificates(mesh_);
  auto after = steiner_positions(mesh_, Dyadic(0));
  std::size_t kept = 0;
  for (auto& p : before) kept += after.count(p);
  batches_.push_back({now_, events, what, mesh_.size(), kept, before.size()});
}

void RebuildSimulation::run_until(const Dyadic& T, const std::function<void(const Batch&)>& after) {
  KMR_CHECK(T >= now_, "run_until: time runs backwards");
  while (now_ < T) {
    // Certificates are polynomials of u = t − built_at; the lattice is absolute, built_at is on it.
    Dyadic from = now_ - built_at_, horizon = T - built_at_;
    std::optional<exact::Integer> k;
    for (auto& c : certs_) {
      if (c.value.degree() <= 0) continue;
      poly::LatticeRootSolver s(c.value, bits_);
      auto f = failure_batch(s, fails_at_zero(c), from, k ? Dyadic(*k + 1, -bits_) : horizon);
      if (f && (!k || *f < *k)) k = f;
    }
    if (!k) {
      now_ = T;
      break;
    }
    std::size_t n = 0;  // the batch: every certificate whose first failure is interval k
    for (auto& c : certs_) {
      if (c.value.degree() <= 0) continue;
      poly::LatticeRootSolver s(c.value, bits_);
      auto f = failure_batch(s, fails_at_zero(c), from, Dyadic(*k + 1, -bits_));
      if (f && *f == *k) ++n;
    }
    now_ = built_at_ + Dyadic(*k + 1, -bits_);
    events_ += n;
    rebuild("events", n);
    if (after) after(batches_.back());
  }
}

void RebuildSimulation::insert(const InputPoint& p) {
  traj_.push_back(p);
  try {
    rebuild("insert", 0);
  } catch (...) {
    traj_.pop_back();
    throw;
  }
}

void RebuildSimulation::erase(const InputPoint& p) {
  auto it = std::find_if(traj_.begin(), traj_.end(), [&](const InputPoint& q) {
    return q.x == p.x && q.y == p.y && q.vx == p.vx && q.vy == p.vy;
  });
  if (it == traj_.end()) throw InputError("delete of a trajectory that is not present");
  if (traj_.size() == 1) throw InputError("delete of the last trajectory");
  InputPoint saved = *it;
  traj_.erase(it);
  rebuild("delete", 0);
  (void)saved;
}

}  // namespace kmr::kmesh
