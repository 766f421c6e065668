// The simulator's machine fast path against its exact path (SimulatorOptions{false}: Polynomial,
// LatticeRootSolver, GMP) on adversarial certificates and on kinetic sorting with simultaneous
// crossings: every outcome, every scheduled failure and every batch must be the same.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "kinetic/kinetic_sort.hpp"

namespace {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::kinetic::CertificateId;
using kmr::kinetic::MotionSimulator;
using kmr::kinetic::SimulatorOptions;
using kmr::poly::Polynomial;

Polynomial linear(std::int64_t c0, std::int64_t c1) { return Polynomial(std::vector<Integer>{Integer(c0), Integer(c1)}); }

// Certificates for lattice bits b and a horizon of H lattice steps: roots on lattice points (the
// start, the last interval before the horizon, the horizon), within 2^-40 and within one part in
// 2^52 of a lattice point, coefficients at 2^53 and at the machine limit, beyond it (exact path in
// both), and double roots / clusters of degree 2 (exact path in both).
std::vector<Polynomial> adversarial(int b, std::int64_t H, std::mt19937_64& rng) {
  auto uniform = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
  std::vector<Polynomial> out;
  const std::int64_t two40 = std::int64_t{1} << 40, limit = (std::int64_t{1} << 62) - 1;
  for (int i = 0; i < 60; ++i) {
    std::int64_t k = uniform(0, H + 1), u = uniform(1, 1 << 6) * (uniform(0, 1) ? 1 : -1);
    std::int64_t lattice = k << (40 - b);  // kδ = lattice·2^−40
    out.push_back(linear(-u * lattice, u * two40));          // root exactly at kδ
    for (std::int64_t d : {-1, 1}) out.push_back(linear(-u * lattice + u * d, u * two40));  // kδ ∓ 2^−40
    std::int64_t big = uniform(std::int64_t{1} << 52, (std::int64_t{1} << 53) - 1);
    out.push_back(linear(-(big / (H + 1)) * k, big / (H + 1)));                          // large, on kδ·2^b
    out.push_back(linear(limit - uniform(0, 9), -(limit / (H + 2)) - uniform(0, 9)));      // machine limit
    out.push_back(Polynomial(std::vector<Integer>{-(Integer(1) << 70) * k, Integer(1) << (70 + b)}));  // beyond it
    Polynomial r = linear(-k, std::int64_t{1} << b);  // root kδ, then doubled and clustered
    out.push_back(r * r);
    out.push_back(r * linear(-(k << 20) - 1, std::int64_t{1} << (b + 20)));
  }
  return out;
}

TEST(MachinePath, A2_1_SameOutcomesFailuresAndBatchesAsTheExactPath) {
  RecordProperty("claim", "A2.1-machine-filter");
  std::mt19937_64 rng(7);
  long long batches = 0;
  for (int b : {0, 3, 10, 20}) {
    const std::int64_t H = 64;
    Dyadic horizon(Integer(H), -b);
    MotionSimulator fast(b, horizon), exact(b, horizon, SimulatorOptions{false});
    std::vector<CertificateId> ids;
    for (const Polynomial& p : adversarial(b, H, rng)) {
      CertificateId a = fast.add(p), e = exact.add(p);
      ASSERT_EQ(a, e);
      ids.push_back(a);
      EXPECT_EQ(fast.outcome(a), exact.outcome(e)) << p.to_string();
      EXPECT_EQ(fast.certificate(a).failure, exact.certificate(e).failure) << p.to_string();
    }
    EXPECT_GT(fast.counters().filter_fallbacks, 0);
    EXPECT_GT(fast.counters().filter_decided, 0);
    EXPECT_EQ(exact.counters().filter_decided + exact.counters().filter_fallbacks, 0);
    for (;;) {
      auto x = fast.next_batch(horizon), y = exact.next_batch(horizon);
      ASSERT_EQ(x.has_value(), y.has_value());
      if (!x) break;
      ++batches;
      ASSERT_EQ(*x, *y) << "at t = " << exact.now().to_decimal();
      ASSERT_EQ(fast.now(), exact.now());
      for (CertificateId id : ids) {
        ASSERT_EQ(fast.outcome(id), exact.outcome(id));
        ASSERT_EQ(fast.next_failure_interval(), exact.next_failure_interval());
      }
    }
  }
  EXPECT_GT(batches, 40);
}

// §2.4-style points plus every 7th point through the place of point 0 at t = 3 (simultaneous
// crossings, roots on a lattice point), on both paths: same order after every batch.
TEST(MachinePath, A2_1_KineticSortIsTheSameOnBothPaths) {
  RecordProperty("claim", "A2.1-machine-filter");
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<long long> pos(-(1LL << 20), 1LL << 20), vel(-(1LL << 8), 1LL << 8);
  std::vector<std::pair<long long, long long>> m;
  for (int i = 0; i < 250; ++i) m.emplace_back(pos(rng), vel(rng) << 12);
  for (std::size_t i = 7; i < m.size(); i += 7) {
    long long v = m[0].second - 4096 * static_cast<long long>(i);  // x_i(3) = x_0(3)
    m[i] = {m[0].first + (m[0].second - v) * 3, v};
  }
  std::sort(m.begin(), m.end());
  m.erase(std::unique(m.begin(), m.end()), m.end());
  std::vector<Polynomial> x;
  for (auto& [x0, v] : m) x.push_back(linear(x0, v));
  const int b = 10;
  Dyadic until(Integer(8));
  MotionSimulator fast(b, until), exact(b, until, SimulatorOptions{false});
  kmr::kinetic::KineticSort a(x, fast), e(x, exact);
  ASSERT_EQ(a.order(), e.order());
  long long batches = 0;
  for (;;) {
    auto p = fast.next_batch(until), q = exact.next_batch(until);
    ASSERT_EQ(p.has_value(), q.has_value());
    if (!p) break;
    ASSERT_EQ(*p, *q);
    a.update(*p);
    e.update(*q);
    ASSERT_EQ(a.order(), e.order()) << "at t = " << exact.now().to_decimal();
    ++batches;
  }
  EXPECT_EQ(a.swaps(), e.swaps());
  EXPECT_GT(fast.counters().max_batch, 30);  // the meeting of 35 points at t = 3 is one batch
  EXPECT_EQ(fast.counters().exact_certificates, 0);
  EXPECT_GT(exact.counters().exact_certificates, 0);
  EXPECT_GT(batches, 100);
}

}  // namespace

// The failure filter for exact-path certificates (poly/failure_filter.hpp) against Sturm alone,
// on cubics like the hull's orient3d certificates: random ones, double and triple roots on lattice
// points, roots closer than δ. Every batch and every outcome must be the same.
kmr::kinetic::SimulatorCounters same_batches_with_and_without_filter(const std::vector<Polynomial>& certs, int b,
                                                                     std::int64_t H) {
  Dyadic horizon(Integer(H), -b);
  MotionSimulator with(b, horizon), without(b, horizon, SimulatorOptions{true, false});
  std::vector<CertificateId> a, z;
  for (const auto& p : certs) {
    a.push_back(with.add(p));
    z.push_back(without.add(p));
  }
  long long batches = 0;
  for (;;) {
    auto x = with.next_batch(horizon), y = without.next_batch(horizon);
    EXPECT_EQ(x.has_value(), y.has_value());
    if (!x || !y) break;
    EXPECT_EQ(*x, *y) << "batch " << batches;
    EXPECT_EQ(with.now(), without.now());
    ++batches;
  }
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(with.outcome(a[i]), without.outcome(z[i])) << certs[i].to_string();
  EXPECT_GT(batches, 50);
  EXPECT_EQ(without.counters().poly_filter_decided + without.counters().poly_filter_fallbacks, 0);
  EXPECT_LE(with.counters().sturm_queries, without.counters().sturm_queries);
  return with.counters();
}

TEST(FailureFilterPath, A2_1_CubicCertificatesGiveTheSameBatchesWithAndWithoutTheFilter) {
  std::mt19937_64 rng(21);
  auto uniform = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
  const int b = 6;
  const std::int64_t H = 4000;  // horizon in lattice steps
  std::vector<Polynomial> random, degenerate;
  for (int i = 0; i < 120; ++i) {
    std::vector<Integer> c;
    for (int j = 0; j < 4; ++j) c.emplace_back(uniform(-(1 << 20), 1 << 20));
    c[3] = c[3] == 0 ? Integer(1) : c[3];
    random.emplace_back(c);
    Polynomial r = linear(-uniform(0, H), std::int64_t{1} << b);  // a root on a lattice point
    Polynomial s = linear(-uniform(0, H) * 8 - uniform(-3, 3), std::int64_t{1} << (b + 3));  // near one
    switch (i % 4) {
      case 0: degenerate.push_back(r * r * s); break;                     // double root
      case 1: degenerate.push_back(r * r * r); break;                     // triple root
      case 2: degenerate.push_back(r * s * linear(uniform(-5, 5), 1)); break;
      default: degenerate.push_back(s * s * linear(-uniform(0, 60), 1)); break;
    }
  }
  auto cr = same_batches_with_and_without_filter(random, b, H);
  EXPECT_GT(cr.poly_filter_decided, 20 * cr.poly_filter_fallbacks);  // random cubics: nearly all decided
  if (cr.poly_filter_fallbacks == 0) EXPECT_EQ(cr.sturm_queries, 0);  // Sturm only behind the filter
  std::vector<Polynomial> all = random;
  all.insert(all.end(), degenerate.begin(), degenerate.end());
  auto ca = same_batches_with_and_without_filter(all, b, H);
  EXPECT_GT(ca.poly_filter_fallbacks, 0);  // double and triple roots ahead go to Sturm
  EXPECT_GT(ca.poly_filter_decided, 0);
}

// Certificates of degree ≥ 2 created mid-run, at every batch's now: roots exactly at now (simple,
// double, triple), just before and after it, and random cubics; some removed again. Three
// simulators: the filter and filtered signs (default), Sturm alone (failure_filter = false), and
// the exact path throughout (SimulatorOptions{false}: poly::sign_before at creation and in the
// self-check). The same ids, batches, times and outcomes.
TEST(FailureFilterPath, A2_1_CertificatesCreatedAtNowGiveTheSameBatchesOnAllThreePaths) {
  std::mt19937_64 rng(77);
  auto uniform = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
  const int b = 5;
  const std::int64_t H = 3000;
  Dyadic horizon(Integer(H), -b);
  MotionSimulator fil(b, horizon), stu(b, horizon, SimulatorOptions{true, false}), ex(b, horizon, SimulatorOptions{false});
  MotionSimulator mac(b, horizon);  // the same certificates given as MachinePolynomials (issue 9)
  std::vector<CertificateId> live;
  std::map<CertificateId, Polynomial> polys;
  auto add = [&](const Polynomial& p) {
    kmr::poly::MachinePolynomial m;
    for (int d = p.degree(); d >= 0; --d) m = m * kmr::poly::MachinePolynomial::linear(0, 1) + kmr::poly::MachinePolynomial(static_cast<long long>(p[d]));
    ASSERT_EQ(m.to_polynomial(), p);
    CertificateId i = fil.add(p), j = stu.add(p), k = ex.add(p), l = mac.add(m);
    ASSERT_EQ(i, j);
    ASSERT_EQ(i, k);
    ASSERT_EQ(i, l);
    EXPECT_EQ(mac.outcome(i), ex.outcome(i)) << p.to_string() << " at " << ex.now().to_decimal();
    polys[i] = p;
    EXPECT_EQ(fil.outcome(i), ex.outcome(i)) << p.to_string() << " at " << ex.now().to_decimal();
    EXPECT_EQ(stu.outcome(i), ex.outcome(i)) << p.to_string();
    live.push_back(i);
  };
  auto spawn = [&](std::int64_t now_k) {
    Polynomial at_now = linear(-now_k, std::int64_t{1} << b);  // root exactly at now
    Polynomial q = linear(-uniform(0, H), std::int64_t{1} << b);
    Polynomial s = linear(-(now_k << 8) + uniform(-3, 3), std::int64_t{1} << (b + 8));  // within 2^−8 steps of now
    std::vector<Integer> c;
    for (int j = 0; j < 4; ++j) c.emplace_back(uniform(-(1 << 16), 1 << 16));
    c[3] = c[3] == 0 ? Integer(1) : c[3];
    switch (uniform(0, 5)) {
      case 0: add(at_now * q); break;
      case 1: add(at_now * at_now * q); break;
      case 2: add(at_now * at_now * at_now); break;
      case 3: add(-(s * q)); break;
      case 4: add(s * s * at_now); break;
      default: add(Polynomial(c)); break;
    }
  };
  for (int i = 0; i < 40; ++i) spawn(0);
  long long batches = 0;
  for (;;) {
    auto x = fil.next_batch(horizon), y = stu.next_batch(horizon), z = ex.next_batch(horizon), w = mac.next_batch(horizon);
    ASSERT_EQ(x.has_value(), z.has_value());
    ASSERT_EQ(y.has_value(), z.has_value());
    ASSERT_EQ(w.has_value(), z.has_value());
    if (!z) break;
    ASSERT_EQ(*x, *z) << "batch " << batches;
    ASSERT_EQ(*y, *z) << "batch " << batches;
    ASSERT_EQ(*w, *z) << "batch " << batches;
    ASSERT_EQ(fil.now(), ex.now());
    ASSERT_EQ(mac.now(), ex.now());
    for (CertificateId id : *z) EXPECT_EQ(fil.outcome(id), ex.outcome(id));
    for (CertificateId id : *z) EXPECT_EQ(mac.outcome(id), ex.outcome(id));
    if (batches % 10 == 0)  // the view of a machine record: its exact polynomial and scheduled failure
      for (CertificateId id : live) {
        const auto& v = mac.certificate(id);
        EXPECT_EQ(v.polynomial, polys[id]);
        EXPECT_EQ(v.failure, ex.certificate(id).failure) << polys[id].to_string();
        EXPECT_EQ(v.outcome, ex.outcome(id));
      }
    ++batches;
    std::int64_t now_k = *fil.now_index();
    for (int j = 0; j < 3; ++j) spawn(now_k);
    if (live.size() > 60) {
      std::size_t at = static_cast<std::size_t>(uniform(0, static_cast<std::int64_t>(live.size()) - 1));
      fil.remove(live[at]), stu.remove(live[at]), ex.remove(live[at]), mac.remove(live[at]);
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(at));
    }
  }
  for (CertificateId id : live) EXPECT_EQ(fil.outcome(id), ex.outcome(id));
  for (CertificateId id : live) EXPECT_EQ(mac.outcome(id), ex.outcome(id));
  EXPECT_GT(mac.counters().machine_polynomials, 100);
  EXPECT_GT(batches, 50);
  EXPECT_GT(fil.counters().poly_filter_decided, 0);
  EXPECT_GT(fil.counters().poly_filter_fallbacks, 0);
}

// Lazy isolation (issue 8/9): machine cubics whose roots lie far beyond now get checkpoints, not
// failure intervals. Against the exact path (SimulatorOptions{false}: Sturm on every certificate)
// over a long horizon: the same batches, outcomes, views (certificate().failure) and
// next_failure_interval(); certificates are created at every batch and removed at random, some
// before and some after their checkpoints. Families: products of linear factors with roots spread
// over the horizon (some on lattice points, some doubled), a complex pair, random coefficients.
TEST(FailureFilterPath, A2_1_CheckpointedCubicsGiveTheSameBatchesAsTheExactPath) {
  RecordProperty("claim", "A2.1-machine-filter");
  for (int b : {0, 4, 10}) {
    std::mt19937_64 rng(41 + static_cast<unsigned>(b));
    auto uniform = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
    const std::int64_t H = std::int64_t{1} << 22;  // horizon in lattice steps
    const Dyadic horizon(Integer(H), -b);
    MotionSimulator mac(b, horizon), ex(b, horizon, SimulatorOptions{false});
    std::vector<CertificateId> live;
    std::map<CertificateId, Polynomial> polys;
    auto add = [&](const kmr::poly::MachinePolynomial& p) {
      CertificateId i = mac.add(p), j = ex.add(p.to_polynomial());
      ASSERT_EQ(i, j);
      ASSERT_EQ(mac.outcome(i), ex.outcome(i));
      polys[i] = p.to_polynomial();
      live.push_back(i);
    };
    using M = kmr::poly::MachinePolynomial;
    auto spawn = [&](std::int64_t now_k) {
      auto root = [&] {  // a root at (now_k + d)·δ, d spread over 2^0 … 2^22 steps, maybe off the lattice
        std::int64_t d = uniform(0, std::int64_t{1} << uniform(0, 22));
        std::int64_t off = uniform(0, 3) == 0 ? 0 : uniform(-3, 3);
        return M::linear(-((now_k + d) * 8 + off), std::int64_t{8} << b);
      };
      switch (uniform(0, 4)) {
        case 0: add(root() * root() * root() * M(uniform(0, 1) ? 1 : -5)); break;
        case 1: { M r = root(); add(r * r * root()); break; }
        case 2: add(root() * root() * M::linear(uniform(1, 1000), 1)); break;  // and a negative root
        case 3: add(root() * (M::linear(uniform(1, 99), 0) + M::linear(0, 1) * M::linear(0, 1))); break;  // a complex pair
        default: {
          M p = M::linear(uniform(-(1 << 30), 1 << 30), uniform(-(1 << 20), 1 << 20)) + M::cubic_terms(uniform(-(1 << 10), 1 << 10), uniform(-4, 4));
          if (!p.is_zero()) add(p);
        }
      }
    };
    for (int i = 0; i < 150; ++i) spawn(0);
    long long batches = 0;
    for (;;) {
      auto x = mac.next_batch(horizon), z = ex.next_batch(horizon);
      ASSERT_EQ(x.has_value(), z.has_value());
      if (!z) break;
      ASSERT_EQ(*x, *z) << "batch " << batches << " b " << b;
      ASSERT_EQ(mac.now(), ex.now());
      for (CertificateId id : *z) ASSERT_EQ(mac.outcome(id), ex.outcome(id));
      if (batches % 25 == 0) {
        ASSERT_EQ(mac.next_failure_interval(), ex.next_failure_interval()) << "batch " << batches;
        for (CertificateId id : live) ASSERT_EQ(mac.certificate(id).failure, ex.certificate(id).failure) << polys[id].to_string();
      }
      ++batches;
      const std::int64_t now_k = *mac.now_index();
      if (batches < 300)  // then the remaining certificates run out (each fails at most three times)
        for (int j = 0; j < 2; ++j) spawn(now_k);
      for (int j = 0; j < 2 && live.size() > 150; ++j) {
        std::size_t at = static_cast<std::size_t>(uniform(0, static_cast<std::int64_t>(live.size()) - 1));
        mac.remove(live[at]), ex.remove(live[at]);
        live.erase(live.begin() + static_cast<std::ptrdiff_t>(at));
      }
    }
    for (CertificateId id : live) EXPECT_EQ(mac.outcome(id), ex.outcome(id));
    EXPECT_GT(batches, 100) << "b " << b;
    // The lazy paths must be taken: windows given, checkpoints reached and resolved.
    EXPECT_GT(mac.counters().lazy_deferred, 100) << "b " << b;
    EXPECT_GT(mac.counters().lazy_checkpoints_reached, 20) << "b " << b;
    EXPECT_GT(mac.counters().lazy_no_root, 0) << "b " << b;
  }
}
