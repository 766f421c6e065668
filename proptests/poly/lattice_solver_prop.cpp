// Property tests of the lattice root solver (src/poly/sturm.hpp) on polynomials built from planted
// rational roots: p = scale · Π (den·t − num)^mult · Π (t² + c), c > 0. The expected answers come from
// the plant alone (exact rational comparisons), never from kmr::poly:
//  * isolation = the planted roots: each planted distinct root's lattice interval with the right
//    distinct-root count and sign-change parity, nothing else (A2.1-lattice-isolation);
//  * Sturm counts on random dyadic windows = planted roots in them (A2.1-sturm-count);
//  * sign_before / sign_after = the exact sign at a nearby dyadic chosen closer than any other root
//    (A2.1-sign-before-after);
//  * next_failure_after = the first planted interval with odd total multiplicity (A2.1-next-failure);
//  * invariance under positive scaling and under t → −t mirroring.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>
#include <ostream>

#include "poly/sturm.hpp"

namespace kmr_prop {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::poly::LatticeInterval;
using kmr::poly::LatticeRootSolver;
using kmr::poly::Polynomial;

struct PlantedRoot {
  Integer num, den;  // the root num/den, den > 0 (not necessarily reduced)
  int multiplicity = 1;
  int kind = 0;      // 0 on a lattice point, 1 next to one, 2 pair partner closer than δ, 3 generic
};

struct Planted {
  int bits = 0;  // δ = 2^−bits
  std::vector<PlantedRoot> roots;
  std::vector<Integer> free_c;  // root-free factors t² + c, c > 0
  Integer scale{1};             // nonzero
  Polynomial polynomial() const {
    Polynomial p(scale);
    for (const auto& r : roots)
      for (int i = 0; i < r.multiplicity; ++i) p = p * Polynomial(std::vector<Integer>{-r.num, r.den});
    for (const auto& c : free_c) p = p * Polynomial(std::vector<Integer>{c, Integer(0), Integer(1)});
    return p;
  }
};

void showValue(const Planted& p, std::ostream& os) {
  os << "bits=" << p.bits << " scale=" << p.scale << " roots:";
  for (const auto& r : p.roots) os << " (" << r.num << "/" << r.den << ")^" << r.multiplicity << "[kind " << r.kind << "]";
  os << " free:";
  for (const auto& c : p.free_c) os << " t^2+" << c;
}

Integer floor_div(const Integer& a, const Integer& b) {  // b > 0
  Integer q, r;
  boost::multiprecision::divide_qr(a, b, q, r);
  if (r.sign() < 0) q -= 1;
  return q;
}
// sign(num/den − d) for a dyadic d = m·2^e.
int compare_root(const PlantedRoot& r, const Dyadic& d) {
  Integer lhs = r.num, rhs = r.den * d.mantissa();
  if (d.exponent() < 0) lhs <<= static_cast<unsigned>(-d.exponent());
  else rhs <<= static_cast<unsigned>(d.exponent());
  return lhs == rhs ? 0 : (lhs < rhs ? -1 : 1);
}

// The distinct planted roots (equal rationals merged, multiplicities summed), increasing.
struct DistinctRoot {
  Integer num, den;
  int multiplicity;
};
std::vector<DistinctRoot> distinct_roots(const Planted& p) {
  std::vector<DistinctRoot> out;
  for (const auto& r : p.roots) {
    bool merged = false;
    for (auto& d : out)
      if (d.num * r.den == r.num * d.den) {
        d.multiplicity += r.multiplicity;
        merged = true;
      }
    if (!merged) out.push_back({r.num, r.den, r.multiplicity});
  }
  std::sort(out.begin(), out.end(), [](const DistinctRoot& a, const DistinctRoot& b) { return a.num * b.den < b.num * a.den; });
  return out;
}

// Expected lattice intervals with k_from ≤ k < k_to.
std::vector<LatticeInterval> expected_intervals(const std::vector<DistinctRoot>& roots, int bits, const Integer& k_from,
                                                const Integer& k_to) {
  std::map<Integer, std::pair<int, int>> by_k;  // k → (distinct, multiplicity sum)
  for (const auto& r : roots) {
    Integer k = floor_div(r.num << static_cast<unsigned>(bits), r.den);
    if (k < k_from || k >= k_to) continue;
    by_k[k].first += 1;
    by_k[k].second += r.multiplicity;
  }
  std::vector<LatticeInterval> out;
  for (const auto& [k, v] : by_k) out.push_back(LatticeInterval{k, v.first, v.second % 2 == 1});
  return out;
}

Integer gen_integer(int max_bits) {
  int bits = *rc::gen::inRange(0, max_bits + 1);
  Integer x(0);
  for (int i = 0; i < bits; i += 16) x = (x << 16) + Integer(*rc::gen::inRange(0, 1 << 16));
  if (bits % 16) x >>= static_cast<unsigned>(16 - bits % 16);
  return x;
}

rc::Gen<Planted> gen_planted() {
  return rc::gen::exec([] {
    Planted p;
    p.bits = *rc::gen::inRange(0, 13);
    unsigned b = static_cast<unsigned>(p.bits);
    int degree = 0;
    int n = *rc::gen::inRange(0, 8);
    for (int i = 0; i < n; ++i) {
      int mult = *rc::gen::inRange(1, 4);
      if (degree + mult > 16) break;
      PlantedRoot r;
      r.multiplicity = mult;
      r.kind = *rc::gen::inRange(0, 4);
      Integer k(*rc::gen::inRange(-40, 41));
      switch (r.kind) {
        case 0: {  // exactly the lattice point kδ, sometimes in unreduced form
          unsigned extra = static_cast<unsigned>(*rc::gen::inRange(0, 4));
          r.num = k << extra;
          r.den = Integer(1) << (b + extra);
          break;
        }
        case 1: {  // kδ ± 2^−(b+e): just before or after a lattice point
          unsigned e = static_cast<unsigned>(*rc::gen::element(1, 2, 30, 64, 150));
          r.num = (k << e) + (*rc::gen::arbitrary<bool>() ? 1 : -1);
          r.den = Integer(1) << (b + e);
          break;
        }
        case 2: {  // a pair closer than δ: x and x + 2^−(b+e), x = (2k+1)δ/2^... inside one interval or straddling
          if (degree + 2 * mult > 16) continue;
          unsigned e = static_cast<unsigned>(*rc::gen::inRange(1, 40));
          Integer base = (k << e) + Integer(*rc::gen::inRange(-2, 3));
          r.num = base;
          r.den = Integer(1) << (b + e);
          PlantedRoot partner = r;
          partner.num = base + 1;
          partner.multiplicity = *rc::gen::inRange(1, 3);
          if (degree + mult + partner.multiplicity > 16) continue;
          p.roots.push_back(partner);
          degree += partner.multiplicity;
          break;
        }
        default: {  // generic rational num/den, den in 1..40
          r.den = Integer(*rc::gen::inRange(1, 41));
          r.num = Integer(*rc::gen::inRange(-40 * 40, 40 * 40));
          break;
        }
      }
      p.roots.push_back(r);
      degree += mult;
    }
    int nfree = *rc::gen::inRange(0, 3);
    for (int i = 0; i < nfree && degree + 2 <= 16; ++i, degree += 2) p.free_c.push_back(gen_integer(80) + 1);
    p.scale = gen_integer(*rc::gen::element(0, 8, 520)) + 1;
    if (*rc::gen::arbitrary<bool>()) p.scale = -p.scale;
    return p;
  });
}

void classify(const Planted& p, const std::vector<DistinctRoot>& roots) {
  bool on_lattice = false, near_lattice = false, multiple = false, cluster = false, even_only = false;
  for (const auto& r : p.roots) {
    on_lattice |= r.kind == 0;
    near_lattice |= r.kind == 1;
  }
  for (const auto& r : roots) multiple |= r.multiplicity > 1;
  auto all = expected_intervals(roots, p.bits, -(Integer(1) << 40), Integer(1) << 40);
  for (const auto& i : all) {
    cluster |= i.roots > 1;
    even_only |= !i.sign_change;
  }
  RC_CLASSIFY(on_lattice, "root on a lattice point");
  RC_CLASSIFY(near_lattice, "root next to a lattice point");
  RC_CLASSIFY(cluster, "cluster closer than delta");
  RC_CLASSIFY(multiple, "multiple root");
  RC_CLASSIFY(even_only, "interval without sign change");
  RC_CLASSIFY(roots.empty(), "no real root");
  RC_CLASSIFY(p.polynomial().degree() == 0, "constant");
  RC_CLASSIFY(kmr::exact::bit_length(p.scale) > 500, "coefficients over 500 bits");
}

const Dyadic kLo = -Dyadic::pow2(20), kHi = Dyadic::pow2(20);  // holds every planted root (|r| ≤ 41)

Dyadic gen_dyadic_near(int bits) {  // a dyadic in [−48, 48] on or off the lattice
  int e = *rc::gen::element(bits, 12, bits + 3);
  Integer m(*rc::gen::inRange(-(48LL << e), (48LL << e) + 1));
  return Dyadic(m, -e);
}

}  // namespace kmr_prop

using namespace kmr_prop;

RC_GTEST_PROP(LatticeSolverProp, A2_1_IsolationEqualsPlantedRoots, ()) {
  ::testing::Test::RecordProperty("claim", "A2.1-lattice-isolation");
  Planted plant = *gen_planted();
  auto roots = distinct_roots(plant);
  classify(plant, roots);
  Polynomial p = plant.polynomial();
  LatticeRootSolver solver(p, plant.bits);
  RC_ASSERT(solver.distinct_real_roots() == static_cast<int>(roots.size()));
  auto everything = solver.isolate(kLo, kHi);
  RC_ASSERT(everything == expected_intervals(roots, plant.bits, -(Integer(1) << (20 + plant.bits)), Integer(1) << (20 + plant.bits)));
  Dyadic a = gen_dyadic_near(plant.bits), b = gen_dyadic_near(plant.bits);
  if (b < a) std::swap(a, b);
  Integer ka = a.shifted(plant.bits).ceil(), kb = b.shifted(plant.bits).ceil();
  RC_ASSERT(solver.isolate(a, b) == expected_intervals(roots, plant.bits, ka, kb));
}

RC_GTEST_PROP(LatticeSolverProp, A2_1_SturmCountEqualsPlantedRoots, ()) {
  ::testing::Test::RecordProperty("claim", "A2.1-sturm-count");
  Planted plant = *gen_planted();
  auto roots = distinct_roots(plant);
  LatticeRootSolver solver(plant.polynomial(), plant.bits);
  Dyadic a = gen_dyadic_near(plant.bits), b = gen_dyadic_near(plant.bits);
  if (b < a) std::swap(a, b);
  // Also exactly at a planted root, when there is one.
  if (!roots.empty() && *rc::gen::arbitrary<bool>()) {
    const auto& r = roots[static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, roots.size()))];
    if (boost::multiprecision::lsb(r.den) == boost::multiprecision::msb(r.den))  // den a power of 2
      a = Dyadic(r.num, -static_cast<std::int64_t>(boost::multiprecision::msb(r.den)));
    if (b < a) std::swap(a, b);
  }
  int want = 0;
  for (const auto& r : roots) {
    PlantedRoot pr{r.num, r.den, r.multiplicity, 0};
    want += compare_root(pr, a) >= 0 && compare_root(pr, b) < 0;
  }
  RC_ASSERT(solver.count_roots(a, b) == want);
}

// A dyadic ε > 0 such that no planted root lies in [x − ε, x) ∪ (x, x + ε].
Dyadic isolating_epsilon(const std::vector<DistinctRoot>& roots, const Dyadic& x) {
  Dyadic eps = Dyadic::pow2(-8);
  for (;;) {
    bool clear = true;
    for (const auto& r : roots) {
      PlantedRoot pr{r.num, r.den, 1, 0};
      int lo = compare_root(pr, x - eps), at = compare_root(pr, x), hi = compare_root(pr, x + eps);
      if (at != 0 && lo >= 0 && hi <= 0) clear = false;
    }
    if (clear) return eps;
    eps = eps.shifted(-4);
  }
}

RC_GTEST_PROP(LatticeSolverProp, A2_1_SignBeforeAfterMatchNearbyEvaluation, ()) {
  ::testing::Test::RecordProperty("claim", "A2.1-sign-before-after");
  Planted plant = *gen_planted();
  auto roots = distinct_roots(plant);
  Polynomial p = plant.polynomial();
  RC_PRE(!p.is_zero());
  // x: a planted dyadic root (often a multiple one), a lattice point, or an arbitrary dyadic.
  Dyadic x = gen_dyadic_near(plant.bits);
  std::vector<Dyadic> dyadic_roots;
  for (const auto& r : roots)
    if (boost::multiprecision::lsb(r.den) == boost::multiprecision::msb(r.den))
      dyadic_roots.push_back(Dyadic(r.num, -static_cast<std::int64_t>(boost::multiprecision::msb(r.den))));
  if (!dyadic_roots.empty() && *rc::gen::arbitrary<bool>())
    x = dyadic_roots[static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, dyadic_roots.size()))];
  Dyadic eps = isolating_epsilon(roots, x);
  RC_CLASSIFY(p.sign_at(x) == 0, "at a root");
  RC_ASSERT(kmr::poly::sign_before(p, x) == p.sign_at(x - eps));
  RC_ASSERT(kmr::poly::sign_after(p, x) == p.sign_at(x + eps));
  // Mirroring: p just after x is p(−t) just before −x.
  RC_ASSERT(kmr::poly::sign_after(p, x) == kmr::poly::sign_before(p.mirrored(), -x));
  // The lattice helper agrees on lattice points.
  LatticeRootSolver solver(p, plant.bits);
  Integer k = x.shifted(plant.bits).floor();
  Dyadic kd(k, -plant.bits);
  RC_ASSERT(solver.sign_before_lattice(k) == p.sign_at(kd - isolating_epsilon(roots, kd)));
}

RC_GTEST_PROP(LatticeSolverProp, A2_1_NextFailureIsFirstOddInterval, ()) {
  ::testing::Test::RecordProperty("claim", "A2.1-next-failure");
  Planted plant = *gen_planted();
  auto roots = distinct_roots(plant);
  LatticeRootSolver solver(plant.polynomial(), plant.bits);
  Dyadic t = gen_dyadic_near(plant.bits);
  Dyadic horizon = t + Dyadic(Integer(*rc::gen::inRange(1, 100)), 0);
  Integer kt = t.shifted(plant.bits).ceil(), kh = horizon.shifted(plant.bits).ceil();
  std::optional<Integer> want;
  for (const auto& i : expected_intervals(roots, plant.bits, kt, kh))
    if (i.sign_change) {
      want = i.k;
      break;
    }
  RC_CLASSIFY(want.has_value(), "a failure exists");
  RC_ASSERT(solver.next_failure_after(t, horizon) == want);
}

// Chapter 4's variant (zero_fails): an interval that starts at a root after t also fails, with or
// without a sign change.
RC_GTEST_PROP(LatticeSolverProp, A2_1_NextFailureWithZeroFailsAlsoStopsAtALatticeRootAfterT, ()) {
  ::testing::Test::RecordProperty("claim", "A2.1-next-failure");
  Planted plant = *gen_planted();
  LatticeRootSolver solver(plant.polynomial(), plant.bits);
  Dyadic t = gen_dyadic_near(plant.bits);
  // Half the time start exactly at a planted root on the lattice: that zero is not after t.
  for (const auto& r : plant.roots) {
    Dyadic at(floor_div(r.num << static_cast<unsigned>(plant.bits), r.den), -plant.bits);
    if (compare_root(r, at) == 0 && *rc::gen::arbitrary<bool>()) t = at;
  }
  Dyadic horizon = t + Dyadic(Integer(*rc::gen::inRange(1, 100)), 0);
  Integer kt = t.shifted(plant.bits).ceil(), kh = horizon.shifted(plant.bits).ceil();
  std::optional<Integer> want;
  bool by_zero = false;
  for (const auto& i : expected_intervals(distinct_roots(plant), plant.bits, kt, kh)) {
    Dyadic start(i.k, -plant.bits);
    bool root_at_start = false;
    for (const auto& r : plant.roots) root_at_start |= compare_root(r, start) == 0;
    if (i.sign_change || (root_at_start && start > t)) {
      want = i.k;
      by_zero = !i.sign_change;
      break;
    }
  }
  RC_CLASSIFY(by_zero, "stops at a zero without a sign change");
  RC_CLASSIFY(solver.polynomial().sign_at(kt, plant.bits) == 0 && Dyadic(kt, -plant.bits) == t, "starts at a zero");
  RC_ASSERT(solver.next_failure_after(t, horizon, /*zero_fails=*/true) == want);
}

RC_GTEST_PROP(LatticeSolverProp, InvariantUnderPositiveScalingAndMirroring, ()) {
  ::testing::Test::RecordProperty("claim", "A2.1-lattice-isolation");
  Planted plant = *gen_planted();
  Polynomial p = plant.polynomial();
  Integer c = gen_integer(200) + 1;
  LatticeRootSolver s(p, plant.bits), scaled(c * p, plant.bits);
  RC_ASSERT(s.isolate(kLo, kHi) == scaled.isolate(kLo, kHi));
  RC_ASSERT(s.next_failure_after(Dyadic(-50), Dyadic(50)) == scaled.next_failure_after(Dyadic(-50), Dyadic(50)));
  // t → −t: the mirrored polynomial has exactly the negated planted roots.
  Planted mirror = plant;
  for (auto& r : mirror.roots) r.num = -r.num;
  // (den·(−t) − num) = −(den·t + num): p(−t) = (−1)^deg · mirror.
  RC_ASSERT((p.degree() % 2 == 0 ? mirror.polynomial() : -mirror.polynomial()) == p.mirrored());
  auto mroots = distinct_roots(mirror);
  LatticeRootSolver m(p.mirrored(), plant.bits);
  RC_ASSERT(m.distinct_real_roots() == s.distinct_real_roots());
  RC_ASSERT(m.isolate(kLo, kHi) ==
            expected_intervals(mroots, plant.bits, -(Integer(1) << (20 + plant.bits)), Integer(1) << (20 + plant.bits)));
  // Intervals not touching a lattice point map k → −k−1 with the same counts.
  for (const auto& i : s.isolate(kLo, kHi)) {
    bool touches = false;
    for (const auto& r : plant.roots)
      touches |= compare_root(r, Dyadic(i.k, -plant.bits)) == 0 || compare_root(r, Dyadic(i.k + 1, -plant.bits)) == 0;
    if (touches) continue;
    auto mi = m.isolate(Dyadic(-i.k - 1, -plant.bits), Dyadic(-i.k, -plant.bits));
    RC_ASSERT(mi.size() == 1u);
    RC_ASSERT(mi[0].roots == i.roots);
    RC_ASSERT(mi[0].sign_change == i.sign_change);
  }
}
