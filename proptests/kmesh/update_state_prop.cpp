// Model-vs-system property (rc::state) for the update of Fig. 4.5 (kmesh/update.hpp): the model is
// the input set; commands insert a point or delete one. After each update the brute-force checks
// (kmesh/invariants.hpp check_all_updated: spanner S1–S4, U1, L4.3.2, L4.2.6, L4.2.9, L4.2.10,
// Delaunay, 9/2-well-spaced, rigid boundary) hold and the mesh's input is the model. Starts: uniform, collinear,
// cocircular, two clusters 2^30 apart, and the Fig. 4.6 rows (two lines ε = 1/4 apart, scaled).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <memory>
#include <sstream>

#include "kmesh/invariants.hpp"
#include "kmesh/update.hpp"
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
};
struct Sut {
  std::unique_ptr<Updater> u;
};

InputPoint ip(long long x, long long y) { return {Integer(x), Integer(y)}; }

InputPoint gen_point() {
  long long far = *rc::gen::element(0LL, 0LL, 0LL, 1LL << 30);
  return ip(*uniform<long long>(0, 33) + far, *uniform<long long>(0, 33));
}

void verify(Updater& u, const Model& m) {
  Mesh mesh = u.mesh();
  auto want = m.points;
  std::sort(want.begin(), want.end());
  RC_ASSERT(mesh.input == want);
  for (auto& c : check_all_updated(mesh)) {
    if (!c.ok()) RC_FAIL(c.claim + ": " + c.violations[0]);
  }
}

struct Insert : rc::state::Command<Model, Sut> {
  InputPoint p = gen_point();
  explicit Insert(const Model&) {}
  void checkPreconditions(const Model& m) const override {
    RC_PRE(std::find(m.points.begin(), m.points.end(), p) == m.points.end());
  }
  void apply(Model& m) const override { m.points.push_back(p); }
  void run(const Model& m, Sut& s) const override {
    Model next = m;
    apply(next);
    s.u->insert(p);
    verify(*s.u, next);
  }
  void show(std::ostream& os) const override { os << "insert (" << p.x.str() << ", " << p.y.str() << ")"; }
};

struct Delete : rc::state::Command<Model, Sut> {
  InputPoint p;
  explicit Delete(const Model& m) {
    RC_PRE(m.points.size() >= 2);
    p = *rc::gen::elementOf(m.points);
  }
  void checkPreconditions(const Model& m) const override {
    RC_PRE(m.points.size() >= 2 && std::find(m.points.begin(), m.points.end(), p) != m.points.end());
  }
  void apply(Model& m) const override { m.points.erase(std::find(m.points.begin(), m.points.end(), p)); }
  void run(const Model& m, Sut& s) const override {
    Model next = m;
    apply(next);
    s.u->erase(p);
    verify(*s.u, next);
  }
  void show(std::ostream& os) const override { os << "delete (" << p.x.str() << ", " << p.y.str() << ")"; }
};

std::vector<InputPoint> initial() {
  int shape = *rc::gen::element(0, 1, 2, 3, 4);
  static const char* names[] = {"uniform", "collinear", "cocircular", "clusters 2^30", "Fig. 4.6 rows"};
  RC_CLASSIFY(true, names[shape]);
  std::vector<InputPoint> v;
  auto add = [&](InputPoint p) {
    if (std::find(v.begin(), v.end(), p) == v.end()) v.push_back(p);
  };
  int n = *uniform(2, 6);
  static const long long circle[][2] = {{25, 0}, {24, 7}, {20, 15}, {15, 20}, {7, 24}, {0, 25}, {-7, 24}, {-15, 20}};
  for (int i = 0; i < n; ++i) {
    switch (shape) {
      case 0: add(ip(*uniform<long long>(0, 65), *uniform<long long>(0, 65))); break;
      case 1: add(ip(*uniform<long long>(0, 65), 0)); break;
      case 2: add(ip(circle[i][0], circle[i][1])); break;
      case 3: add(ip(*uniform<long long>(0, 9) + (i % 2 ? (1LL << 30) : 0), *uniform<long long>(0, 9))); break;
      default: add(ip(4 * (i / 2), i % 2)); break;  // (k, 0) and (k, ε) with ε = 1/4, times 4
    }
  }
  return v;
}

}  // namespace

TEST(KmeshUpdateStateProp, L4_3_2_InsertionsAndDeletionsKeepTheInvariants) {
  kmr::proptest::check_cases(3, 4, [] {
    Model m{initial()};
    Sut s{std::make_unique<Updater>(m.points)};
    rc::state::check(m, s, rc::state::gen::execOneOfWithArgs<Insert, Insert, Delete>());
  });
}
