// Model-vs-system property (rc::state) for the kinetic KDS (kmesh/kds.hpp): the model is the set of
// trajectories and the time; commands advance the time by a few lattice steps (every batch on the
// way repaired by Fig. 4.5), insert a moving point, or delete one. After each batch and command:
// every certificate holds at the repair time (L4.3.1), the brute-force checks of an updated mesh
// hold (kmesh/invariants.hpp check_all_updated: spanner S1–S4, U1, L4.3.2, L4.2.6, L4.2.9, L4.2.10,
// Delaunay, 9/2-well-spaced, rigid boundary) and the mesh's input is the model. Starts, each one its
// own case at a lattice drawn from 2^-3 and the CLI's default 2^-10: random motions, points collinear
// at every time (one line moving), points cocircular at every time (a circle about the origin, the
// points moving tangentially or at rest), two clusters 2^30 apart, the Fig. 4.6 motion (two rows
// ε = 1/4 apart, ×4, the lower row moving by one spacing per unit of time), a grid moving as one,
// and near-duplicate pairs (1 apart, a 64-wide field).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <tuple>

#include "kmesh/invariants.hpp"
#include "kmesh/kds.hpp"
#include "../check_cases.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;

namespace {

template <class T>
rc::Gen<T> uniform(T lo, T hi) {
  return rc::gen::resize(100, rc::gen::inRange<T>(lo, hi));
}

struct Model {
  std::vector<InputPoint> points;
  int bits = 3;  // the lattice 2^-bits
  Dyadic now{0};
};
struct Sut {
  std::unique_ptr<KineticMesh> k;
};

InputPoint mv(long long x, long long y, long long vx, long long vy) { return {Integer(x), Integer(y), Integer(vx), Integer(vy)}; }
auto key(const InputPoint& p) { return std::tuple{p.x, p.y, p.vx, p.vy}; }
bool same(const InputPoint& a, const InputPoint& b) { return key(a) == key(b); }

void verify(const KineticMesh& k, const Model& m) {
  RC_ASSERT(k.now() == m.now);
  auto have = k.trajectories(), want = m.points;
  auto by_key = [](const InputPoint& a, const InputPoint& b) { return key(a) < key(b); };
  std::sort(have.begin(), have.end(), by_key);
  std::sort(want.begin(), want.end(), by_key);
  RC_ASSERT(have.size() == want.size());
  for (std::size_t i = 0; i < have.size(); ++i) RC_ASSERT(same(have[i], want[i]));
  for (auto& c : k.current_certificates())
    if (!holds_at(c, Dyadic(0))) RC_FAIL(std::string("L4.3.1: a ") + kind_name(c.kind) + " certificate fails at the repair time");
  for (auto& c : check_all_updated(k.mesh()))
    if (!c.ok()) RC_FAIL(c.claim + " at " + k.now().to_decimal() + ": " + c.violations[0]);
}

struct Advance : rc::state::Command<Model, Sut> {
  int steps = *uniform(1, 3);
  explicit Advance(const Model&) {}
  Dyadic to(const Model& m) const { return m.now + Dyadic(steps, -m.bits); }
  void checkPreconditions(const Model& m) const override {
    RC_PRE(!first_collision(m.points, m.now, to(m)).has_value());
  }
  void apply(Model& m) const override { m.now = to(m); }
  void run(const Model& m, Sut& s) const override {
    Model next = m;
    apply(next);
    Model during = m;
    s.k->run_until(to(m), [&](const Batch& b) {
      during.now = b.time;
      verify(*s.k, during);
    });
    verify(*s.k, next);
  }
  void show(std::ostream& os) const override { os << "advance " << steps << " lattice steps"; }
};

struct Insert : rc::state::Command<Model, Sut> {
  InputPoint p = mv(*uniform<long long>(0, 33), *uniform<long long>(0, 33), *uniform<long long>(-2, 3), *uniform<long long>(-2, 3));
  explicit Insert(const Model&) {}
  void checkPreconditions(const Model& m) const override {
    for (auto& q : m.points) {
      RC_PRE(!same(p, q));
      // not at the same place now, nor colliding within the next unit of time
      RC_PRE(!first_collision({p, q}, m.now, m.now + Dyadic(1)).has_value());
    }
  }
  void apply(Model& m) const override { m.points.push_back(p); }
  void run(const Model& m, Sut& s) const override {
    Model next = m;
    apply(next);
    s.k->insert(p);
    verify(*s.k, next);
  }
  void show(std::ostream& os) const override {
    os << "insert (" << p.x.str() << ", " << p.y.str() << ") moving (" << p.vx.str() << ", " << p.vy.str() << ")";
  }
};

struct Delete : rc::state::Command<Model, Sut> {
  InputPoint p;
  explicit Delete(const Model& m) {
    RC_PRE(m.points.size() >= 2);
    p = *rc::gen::elementOf(m.points);
  }
  void checkPreconditions(const Model& m) const override {
    RC_PRE(m.points.size() >= 2 &&
           std::any_of(m.points.begin(), m.points.end(), [&](const InputPoint& q) { return same(p, q); }));
  }
  void apply(Model& m) const override {
    m.points.erase(std::find_if(m.points.begin(), m.points.end(), [&](const InputPoint& q) { return same(p, q); }));
  }
  void run(const Model& m, Sut& s) const override {
    Model next = m;
    apply(next);
    s.k->erase(p);
    verify(*s.k, next);
  }
  void show(std::ostream& os) const override { os << "delete (" << p.x.str() << ", " << p.y.str() << ")"; }
};

std::vector<InputPoint> initial(int shape) {
  std::vector<InputPoint> v;
  auto add = [&](InputPoint p) {
    for (auto& q : v)
      if (q == p || first_collision({p, q}, Dyadic(0), Dyadic(1))) return;
    v.push_back(p);
  };
  auto vel = [] { return *uniform<long long>(-2, 3); };
  // Degenerate starts keep at least four points (checked below), so that a degenerate quadruple exists.
  const bool degenerate = shape == 1 || shape == 2 || shape == 5 || shape == 6;
  int n = *uniform(degenerate ? 4 : 2, 6);
  static const long long circle[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}};
  const long long line_vx = vel(), line_vy = vel(), turn = *uniform<long long>(0, 2), grid_vx = vel(), grid_vy = vel();
  for (int i = 0; i < n; ++i) {
    switch (shape) {
      case 0: add(mv(*uniform<long long>(0, 65), *uniform<long long>(0, 65), vel(), vel())); break;
      // On the line y = line_vy·t: every point keeps y = 0 + line_vy·t, moving along it at its own speed.
      case 1: add(mv(*uniform<long long>(0, 65), 0, line_vx + vel(), line_vy)); break;
      // p + t·turn·p⊥ lies on the circle of radius 5·sqrt(1 + turn²t²) about the origin.
      case 2: add(mv(circle[i][0], circle[i][1], -turn * circle[i][1], turn * circle[i][0])); break;
      case 3: add(mv(*uniform<long long>(0, 9) + (i % 2 ? (1LL << 30) : 0), *uniform<long long>(0, 9), vel(), vel())); break;
      case 4: add(i % 2 ? mv(4 * (i / 2), 1, 0, 0) : mv(4 * (i / 2), 0, 4, 0)); break;
      // A grid translating as one (cocircular squares at every time), its first point moving apart, so
      // that certificates fail (a pure translation fails none).
      case 5: add(mv(4 * (i % 3), 4 * (i / 3), i == 0 ? grid_vx + 1 : grid_vx, i == 0 ? grid_vy - 1 : grid_vy)); break;
      default: add(mv(*uniform<long long>(0, 65), *uniform<long long>(0, 65), vel(), vel())); break;
    }
    if (shape == 6 && i % 2 == 0) {  // its near-duplicate: 1 apart, the same motion
      InputPoint q = v.back();
      q.x += 1;
      add(q), ++i;
    }
  }
  RC_PRE(!degenerate || v.size() >= 4);  // add() drops a point that would collide within [0, 1]
  return v;
}

}  // namespace

TEST(KmeshKdsStateProp, L4_3_1_KineticBatchesInsertionsAndDeletionsKeepTheInvariants) {
  RecordProperty("claim", "L4.3.1");
  static const char* names[] = {"random motions", "collinear at every time", "cocircular at every time",
                                "clusters 2^30", "Fig. 4.6 motion", "moving grid", "near-duplicates"};
  for (int shape = 0; shape < 7; ++shape) {
    SCOPED_TRACE(names[shape]);
    // Two cases per start: RapidCheck's first case has size 0 (one command), the second up to 7.
    kmr::proptest::check_cases(2, 6, [shape] {
      Model m{initial(shape), *rc::gen::element(3, 10)};
      RC_CLASSIFY(true, "lattice 2^-" + std::to_string(m.bits));
      Sut s{std::make_unique<KineticMesh>(m.points, m.bits)};
      verify(*s.k, m);
      rc::state::check(m, s, rc::state::gen::execOneOfWithArgs<Advance, Advance, Insert, Delete>());
    });
  }
}
