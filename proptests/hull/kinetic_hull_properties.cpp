// Properties of the kinetic hull (kinetic_hull.hpp) on random motions with degenerate moments,
// judged after every batch by the static algorithm run from scratch just before now, the
// independent hull certificate, and a from-scratch self-adjusting run (trace signature and live
// certificates). Claims C2.2-hull-correct, C2.2-stability, F2.8-compactness.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include <rapidcheck/state.h>

#include "exact/error.hpp"
#include "hull/hull_at_time.hpp"
#include "hull/kinetic_hull.hpp"

namespace {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::hull::KineticHull;
using kmr::hull::MovingPoint;
using kmr::hull::linear;
using kmr::poly::Polynomial;

// Families: 0 generic; 1 every point starts on the plane z = 0; 2 a small grid at t = 0 (coplanar,
// collinear, even equal starting points); 3 most points cross the plane x = 0 together at the lattice
// point t = 1 (x = v·(t − 1)), so several certificates fail in one interval and four or more
// points are coplanar at a lattice point.
rc::Gen<std::vector<MovingPoint>> motions() {
  return rc::gen::exec([] {
    const int family = *rc::gen::inRange(0, 4);
    const int n = *rc::gen::inRange(5, 13);
    std::vector<MovingPoint> pts;
    auto r = [](int lo, int hi) { return static_cast<long long>(*rc::gen::inRange(lo, hi)); };
    for (int i = 0; i < n; ++i) {
      switch (family) {
        case 0: pts.push_back(linear(r(-64, 65), r(-64, 65), r(-64, 65), r(-8, 9), r(-8, 9), r(-8, 9))); break;
        case 1: pts.push_back(linear(r(-64, 65), r(-64, 65), 0, r(-8, 9), r(-8, 9), r(-16, 17))); break;
        case 2: pts.push_back(linear(r(-2, 3), r(-2, 3), r(-2, 3), r(-16, 17), r(-16, 17), r(-16, 17))); break;
        default: {
          long long v = r(-9, 10);
          if (i % 4 == 3) pts.push_back(linear(r(-64, 65), r(-64, 65), r(-64, 65), r(-8, 9), r(-8, 9), r(-8, 9)));
          else pts.push_back(linear(-v, r(-64, 65), r(-64, 65), v, r(-4, 5), r(-4, 5)));
        }
      }
    }
    return pts;
  });
}

bool legitimate_refusal(const std::string& what) {
  return what.find("identical trajectories") != std::string::npos ||
         what.find("stay coplanar for all time") != std::string::npos ||
         what.find("stay collinear for all time") != std::string::npos;
}

}  // namespace

RC_GTEST_PROP(KineticHullProperties, C2_2_EveryBatchMatchesStaticAndScratch, ()) {
  const auto pts = *motions();
  const int bits = *rc::gen::inRange(0, 4);
  const std::uint64_t seed = *rc::gen::inRange(1, 1000);
  const Dyadic until(4);
  kmr::kinetic::MotionSimulator sim(bits, until);
  try {
    KineticHull kh(pts, sim, seed);
    long long batches = 0;
    for (;;) {
      const auto facets = kh.facets();
      RC_ASSERT(facets == kmr::hull::static_hull_before(pts, sim.now(), seed));
      RC_ASSERT(kmr::hull::hull_certificate_failure(pts, sim.now(), facets) == std::string());
      KineticHull scratch(pts, sim.now(), seed);
      RC_ASSERT(kh.signature() == scratch.signature());
      RC_ASSERT(kh.certificate_keys() == scratch.certificate_keys());
      RC_ASSERT(kh.live_certificates() == static_cast<std::size_t>(sim.counters().live()));
      RC_ASSERT(kh.counters().certificates_created == sim.counters().created);
      auto batch = sim.next_batch(until);
      if (!batch) break;
      kh.update(*batch);
      ++batches;
    }
    RC_CLASSIFY(batches == 0, "no event");
    RC_CLASSIFY(sim.counters().max_batch >= 2, "a batch of several failures");
  } catch (const kmr::InputError& e) {
    RC_TAG("refused");
    RC_ASSERT(legitimate_refusal(e.what()));
  }
}

// ---- integrated changes (§2.4) as an rc::state machine -------------------------------------------
namespace {

struct Model {
  int n = 0;
  std::vector<bool> present;
};

struct Sut {
  std::vector<MovingPoint> initial;
  std::uint64_t seed = 1;
  Dyadic until{16};
  std::unique_ptr<kmr::kinetic::MotionSimulator> sim;
  std::unique_ptr<KineticHull> kh;
  bool refused = false;  // a legitimate InputError ended the run
  void judge() const {
    const auto& pts = kh->points();
    const auto& present = kh->present();
    const auto facets = kh->facets();
    RC_ASSERT(facets == kmr::hull::static_hull_before(pts, sim->now(), seed, present));
    RC_ASSERT(kmr::hull::hull_certificate_failure(pts, sim->now(), facets, present) == std::string());
    KineticHull scratch(pts, sim->now(), seed, present);
    RC_ASSERT(kh->signature() == scratch.signature());
    RC_ASSERT(kh->certificate_keys() == scratch.certificate_keys());
    RC_ASSERT(kh->live_certificates() == static_cast<std::size_t>(sim->counters().live()));
    RC_ASSERT(kh->counters().certificates_created == sim->counters().created);
  }
  template <class F>
  void act(F&& f) {
    if (refused) return;
    try {
      f();
    } catch (const kmr::InputError& e) {
      RC_ASSERT(legitimate_refusal(e.what()));
      refused = true;
      return;
    }
    judge();
  }
};

using Cmd = rc::state::Command<Model, Sut>;

struct Advance : Cmd {
  void run(const Model&, Sut& s) const override {
    s.act([&] {
      if (auto batch = s.sim->next_batch(s.until)) s.kh->update(*batch);
    });
  }
  void show(std::ostream& os) const override { os << "advance one batch"; }
};

struct ThreeQuarters : Cmd {
  int x;
  explicit ThreeQuarters(const Model& m) : x(*rc::gen::inRange(0, m.n)) {}
  void run(const Model&, Sut& s) const override {
    s.act([&] { s.kh->change_motion(x, kmr::hull::three_quarters(s.kh->points()[x])); });
  }
  void show(std::ostream& os) const override { os << "motion of " << x << " becomes 3/4 r(t)"; }
};

struct NewMotion : Cmd {
  int x;
  long long v[3];
  explicit NewMotion(const Model& m) : x(*rc::gen::inRange(0, m.n)) {
    for (auto& c : v) c = *rc::gen::inRange(-12, 13);
  }
  void run(const Model&, Sut& s) const override {
    s.act([&] {
      MovingPoint r = s.kh->points()[x];
      // The same start, a new velocity (the point jumps to its new trajectory now).
      MovingPoint q;
      for (int k = 0; k < 3; ++k) q[k] = Polynomial(std::vector<Integer>{r[k].is_zero() ? Integer(0) : r[k][0], Integer(v[k])});
      s.kh->change_motion(x, q);
    });
  }
  void show(std::ostream& os) const override { os << "point " << x << " gets velocity (" << v[0] << ", " << v[1] << ", " << v[2] << ")"; }
};

struct Remove : Cmd {
  int x;
  explicit Remove(const Model& m) : x(*rc::gen::inRange(0, m.n)) {}
  void checkPreconditions(const Model& m) const override {
    RC_PRE(m.present[x]);
    RC_PRE(std::count(m.present.begin(), m.present.end(), true) > 5);
  }
  void apply(Model& m) const override { m.present[x] = false; }
  void run(const Model&, Sut& s) const override { s.act([&] { s.kh->remove_point(x); }); }
  void show(std::ostream& os) const override { os << "remove " << x; }
};

struct Insert : Cmd {
  int x;
  explicit Insert(const Model& m) : x(*rc::gen::inRange(0, m.n)) {}
  void checkPreconditions(const Model& m) const override { RC_PRE(!m.present[x]); }
  void apply(Model& m) const override { m.present[x] = true; }
  void run(const Model&, Sut& s) const override { s.act([&] { s.kh->insert_point(x); }); }
  void show(std::ostream& os) const override { os << "insert " << x; }
};

}  // namespace

RC_GTEST_PROP(KineticHullProperties, IntegratedChangesKeepEveryJudge, ()) {
  Sut s;
  s.initial = *motions();
  s.seed = *rc::gen::inRange(1, 1000);
  const int n = static_cast<int>(s.initial.size());
  Model m;
  m.n = n;
  m.present.assign(n, true);
  for (int i = 0; i < n; ++i)
    if (i % 5 == 4) m.present[i] = false;  // some points wait to be inserted
  s.sim = std::make_unique<kmr::kinetic::MotionSimulator>(*rc::gen::inRange(0, 4), s.until);
  try {
    s.kh = std::make_unique<KineticHull>(s.initial, *s.sim, s.seed, m.present);
  } catch (const kmr::InputError& e) {
    RC_TAG("refused at the start");
    RC_ASSERT(legitimate_refusal(e.what()));
    return;
  }
  s.judge();
  rc::state::check(m, s, rc::state::gen::execOneOfWithArgs<Advance, Advance, ThreeQuarters, NewMotion, Remove, Insert>());
  RC_CLASSIFY(s.refused, "refused during the run");
  RC_CLASSIFY(s.kh->counters().rebuilds > 0, "a new tetrahedron");
}
