// The kinetic KDS (kmesh/kds.hpp): every batch repaired by Fig. 4.5, not by a rebuild. After every
// batch and update: every certificate holds at the repair time (L4.3.1), the brute-force checks of
// an updated mesh hold (kmesh/invariants.hpp, sharing no code with the update: spanner, U1, L4.3.2,
// L4.2.6, L4.2.9, L4.2.10, Delaunay, 9/2-well-spacedness), and the vertex set is compared with a
// from-scratch construction at the same time (stability, measured: the thesis claims no equality).
#include <gtest/gtest.h>

#include <set>

#include "exact/error.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh/kds.hpp"
#include "mesh_checks.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;
using kmr::kmesh::test::failures;

namespace {

InputPoint mv(long long x, long long y, long long vx = 0, long long vy = 0) {
  return {Integer(x), Integer(y), Integer(vx), Integer(vy)};
}

// The checks after one batch or update; returns the fraction of Steiner vertices shared with the
// construction from scratch at the same time (÷ the larger count).
double check_batch(const KineticMesh& k) {
  const Mesh& m = k.mesh();
  for (auto& c : k.current_certificates())
    EXPECT_TRUE(holds_at(c, Dyadic(0))) << kind_name(c.kind) << " " << c.a << " " << c.b << " at " << k.now().to_decimal();
  std::string f = failures(check_all_updated(m));
  EXPECT_EQ(f, "") << "at " << k.now().to_decimal();
  return kmr::kmesh::test::shared_steiner_fraction(m, construct(k.trajectories(), k.now()));
}

}  // namespace

TEST(KineticMesh, L4_3_1_EveryKineticBatchRepairedByFig45IsCertifiedAndValid) {
  RecordProperty("claim", "L4.3.1");
  KineticMesh k({mv(0, 0), mv(3, 0, 2, 1), mv(0, 5, -1, 0)}, 3);
  Dyadic last(0);
  int batches = 0, relocating = 0;
  double stab = 0;
  k.run_until(Dyadic(1, -1), [&](const Batch& b) {
    ++batches;
    EXPECT_GT(b.time, last);
    last = b.time;
    EXPECT_GT(b.events, 0u);
    relocating += b.moved > 0;
    stab += check_batch(k);
  });
  EXPECT_EQ(k.now(), Dyadic(1, -1));
  EXPECT_GE(batches, 1);
  EXPECT_GE(relocating, 1);  // some batch went through Updater::relocate
  std::cout << "batches " << batches << " (relocating " << relocating << "), mean stability "
            << stab / std::max(batches, 1) << "\n";
  check_batch(k);
}

TEST(KineticMesh, InsertionsAndDeletionsOfMovingPoints) {
  RecordProperty("claim", "L4.3.2");
  KineticMesh k({mv(0, 0, 1, 0), mv(9, 2, -1, 1)}, 3);
  k.run_until(Dyadic(1, -2), [&](const Batch&) { check_batch(k); });
  k.insert(mv(4, 7, 0, -1));
  check_batch(k);
  EXPECT_THROW(k.erase(mv(1, 1)), kmr::InputError);
  k.run_until(Dyadic(1, -1), [&](const Batch&) { check_batch(k); });
  k.erase(mv(0, 0, 1, 0));
  EXPECT_EQ(k.mesh().n(), 2u);
  check_batch(k);
}
