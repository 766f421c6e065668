// The motion simulator (§2.1) on lattices too large for the machine path: a horizon index
// ≥ 2^62 keeps the queue as an ordered set of exact (interval, id) pairs. Judged by failure
// intervals derived by hand (k = floor(root·2^b) for a simple root), not by another simulator.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "exact/error.hpp"
#include "kinetic/motion_simulator.hpp"

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::kinetic::CertificateId;
using kmr::kinetic::MotionSimulator;
using kmr::poly::Polynomial;

namespace {

Polynomial poly(std::vector<Integer> c) { return Polynomial(std::move(c)); }
const Integer two61 = Integer(std::int64_t{1} << 61);
// δ = 1/4 and a horizon of 2^62: the last lattice index is 2^64, past the machine range.
MotionSimulator large() { return MotionSimulator(2, Dyadic::pow2(62)); }

}  // namespace

TEST(LargeLattice, A2_1_BatchesAreTheHandDerivedIntervalsIncludingOnesPastTheMachineRange) {
  RecordProperty("claim", "A2.1-batch");
  MotionSimulator sim = large();
  EXPECT_FALSE(sim.now_index());  // no int64 lattice index on this lattice
  auto a = sim.add(poly({1, -3}));        // root 1/3: k = floor(4/3) = 1
  auto b = sim.add(poly({3, -10}));       // root 3/10: k = 1
  auto c = sim.add_linear(-5, 4);         // root 5/4, on the lattice point 5δ: k = 5
  auto d = sim.add(poly({-two61, 1}));    // root 2^61: k = 2^63, beyond any int64 index
  auto e = sim.add(poly({9, -6, 1}));     // (t−3)²: touches 0, never fails
  EXPECT_EQ(sim.outcome(a), 1);
  EXPECT_EQ(sim.outcome(c), -1);
  EXPECT_EQ(sim.outcome(d), -1);
  EXPECT_EQ(sim.outcome(e), 1);
  EXPECT_FALSE(sim.certificate(e).failure);
  EXPECT_EQ(sim.certificate(d).failure, Integer(two61) * 4);
  EXPECT_EQ(sim.counters().exact_certificates, 5);  // even c0 + c1·t: no machine record here
  EXPECT_EQ(sim.next_failure_interval(), Integer(1));
  auto b1 = sim.next_batch(sim.horizon());
  ASSERT_TRUE(b1);
  EXPECT_EQ(*b1, (std::vector<CertificateId>{a, b}));
  EXPECT_EQ(sim.now(), Dyadic(Integer(1), -1));  // 2δ
  EXPECT_EQ(sim.outcome(a), -1);
  EXPECT_EQ(sim.next_failure_interval(), Integer(5));
  auto b2 = sim.next_batch(sim.horizon());
  ASSERT_TRUE(b2);
  EXPECT_EQ(*b2, std::vector<CertificateId>{c});
  EXPECT_EQ(sim.now(), Dyadic(Integer(3), -1));  // 6δ
  auto b3 = sim.next_batch(sim.horizon());
  ASSERT_TRUE(b3);
  EXPECT_EQ(*b3, std::vector<CertificateId>{d});
  EXPECT_EQ(sim.now(), Dyadic(Integer(two61) * 4 + 1, -2));  // (2^63 + 1)δ
  EXPECT_EQ(sim.outcome(d), 1);
  EXPECT_FALSE(sim.next_batch(sim.horizon()));
  EXPECT_FALSE(sim.next_failure_interval());
  EXPECT_EQ(sim.counters().events, 4);
  EXPECT_EQ(sim.counters().batches, 3);
}

// Removing a scheduled certificate takes it out of the ordered set: it is never reported, and a
// batch interval that held only it is no batch at all.
TEST(LargeLattice, RemovedCertificatesAreNeverReported) {
  MotionSimulator sim = large();
  auto a = sim.add(poly({1, -3}));      // k = 1
  auto b = sim.add(poly({3, -10}));     // k = 1
  auto c = sim.add(poly({-5, 4}));      // k = 5
  auto d = sim.add(poly({-two61, 1}));  // k = 2^63
  sim.remove(b);
  sim.remove(c);
  EXPECT_EQ(sim.counters().live(), 2);
  auto b1 = sim.next_batch(sim.horizon());
  ASSERT_TRUE(b1);
  EXPECT_EQ(*b1, std::vector<CertificateId>{a});
  EXPECT_EQ(sim.next_failure_interval(), Integer(two61) * 4);  // interval 5 held only c
  sim.remove(d);
  EXPECT_FALSE(sim.next_failure_interval());
  EXPECT_FALSE(sim.next_batch(sim.horizon()));
  EXPECT_EQ(sim.now(), Dyadic(Integer(1), -1));  // unchanged since the one batch
  sim.remove(a);  // unscheduled after its failure (a line fails once): nothing to take out
  EXPECT_EQ(sim.counters().live(), 0);
}

// `until` bounds the batches: a failure in interval k is processed at (k+1)δ, which must not pass
// `until`; refusing leaves now() where it was.
TEST(LargeLattice, UntilBeforeTheFailureGivesNoBatchAndKeepsNow) {
  MotionSimulator sim = large();
  auto c = sim.add(poly({-5, 4}));  // k = 5, processed at 6δ = 3/2
  EXPECT_FALSE(sim.next_batch(Dyadic(1)));
  EXPECT_FALSE(sim.next_batch(Dyadic(Integer(5), -2)));  // 5/4 < 3/2
  EXPECT_EQ(sim.now(), Dyadic(0));
  auto b = sim.next_batch(Dyadic(Integer(3), -1));  // exactly 3/2
  ASSERT_TRUE(b);
  EXPECT_EQ(*b, std::vector<CertificateId>{c});
  EXPECT_FALSE(sim.next_batch(sim.horizon()));  // nothing left
}

// On a machine lattice, coefficients of 2^62 or more leave the int64 record for the exact path,
// with the same hand-derived answers; the lattice bits and horizon are checked first.
TEST(LargeLattice, HugeCoefficientsOnAMachineLatticeTakeTheExactPath) {
  MotionSimulator sim(2, Dyadic(2));
  const std::int64_t big = std::int64_t{1} << 62;
  auto c = sim.add_linear(-5 * (big / 8), 4 * (big / 8));  // 2^59·(4t − 5): coefficients < 2^62, machine
  auto h = sim.add_linear(-big, big);                      // 2^62·(t − 1): root 1, on 4δ: k = 4
  auto h2 = sim.add(poly({Integer(big) * -3, Integer(big) * 4}));  // root 3/4 on 3δ: k = 3
  EXPECT_EQ(sim.counters().exact_certificates, 2);
  EXPECT_EQ(sim.outcome(h), -1);
  EXPECT_EQ(sim.certificate(h).failure, Integer(4));
  EXPECT_EQ(sim.certificate(h2).failure, Integer(3));
  EXPECT_EQ(sim.certificate(c).failure, Integer(5));
  auto b1 = sim.next_batch(sim.horizon());
  ASSERT_TRUE(b1);
  EXPECT_EQ(*b1, std::vector<CertificateId>{h2});
  auto b2 = sim.next_batch(sim.horizon());
  ASSERT_TRUE(b2);
  EXPECT_EQ(*b2, std::vector<CertificateId>{h});
  EXPECT_EQ(sim.outcome(h), 1);
  auto b3 = sim.next_batch(sim.horizon());  // 6δ = 3/2 ≤ 2
  ASSERT_TRUE(b3);
  EXPECT_EQ(*b3, std::vector<CertificateId>{c});
  EXPECT_THROW(MotionSimulator(63, Dyadic(1)), kmr::InputError);
  EXPECT_THROW(MotionSimulator(-1, Dyadic(1)), kmr::InputError);
  EXPECT_THROW(MotionSimulator(2, Dyadic(-1)), kmr::InputError);
  EXPECT_THROW(sim.add_linear(0, 0), kmr::InputError);
}
