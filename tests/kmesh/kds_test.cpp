// The kinetic KDS (kmesh/kds.hpp): every batch repaired by Fig. 4.5, not by a rebuild. After every
// batch and update: every certificate holds at the repair time (L4.3.1), the brute-force checks of
// an updated mesh hold (kmesh/invariants.hpp, sharing no code with the update: spanner, U1, L4.3.2,
// L4.2.6, L4.2.9, L4.2.10, Delaunay, 9/2-well-spacedness), and the vertex set is compared with a
// from-scratch construction at the same time (stability, measured: the thesis claims no equality).
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <tuple>

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

namespace {

// A certificate as a comparable record: kind, rank, strictness, its ends (unordered for the
// symmetric kinds) and its polynomial up to a positive factor (primitive part). A ball-not-empty
// certificate is compared by its satellite's nucleus and rank only: its witness is any vertex of
// rank ≤ ℓ in the ball (the kept one stays while it is in the ball; the recomputation takes the
// nearest now), and each kept one must hold now.
using Record = std::tuple<int, Rank, bool, int, int, std::string>;

std::multiset<Record> records(const std::vector<Certificate>& cs) {
  std::multiset<Record> out;
  for (auto& c : cs) {
    int a = c.a, b = c.b;
    if (c.kind != Certificate::ParentChild && c.kind != Certificate::Delaunay && a > b) std::swap(a, b);
    std::string p = c.value.is_zero() ? "0" : c.value.primitive_part().to_string();
    if (c.kind == Certificate::BallNotEmpty) b = -1, p = "";
    out.insert({c.kind, c.rank, c.strict, a, b, p});
  }
  return out;
}

// The kept (incrementally maintained) certificates against certificates recomputed from scratch.
std::string incremental_vs_recomputed(const KineticMesh& k) {
  auto kept = k.current_certificates();
  for (auto& c : kept)
    if (!holds_at(c, Dyadic(0))) return std::string("kept ") + kind_name(c.kind) + " certificate fails now";
  auto a = records(kept), b = records(k.recomputed_certificates());
  if (a == b) return "";
  std::string why = "kept " + std::to_string(a.size()) + " vs recomputed " + std::to_string(b.size());
  std::vector<Record> only_a, only_b;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_a));
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_b));
  if (!only_a.empty()) why += "; first kept only: " + std::string(kind_name(Certificate::Kind(std::get<0>(only_a[0]))));
  if (!only_b.empty()) why += "; first recomputed only: " + std::string(kind_name(Certificate::Kind(std::get<0>(only_b[0]))));
  return why + " (" + std::to_string(only_a.size()) + " / " + std::to_string(only_b.size()) + ")";
}

}  // namespace

// §4.3, incremental maintenance: after every batch and update only the certificates with a new
// canonical name are built (kmesh/kds.hpp); the kept set must equal the from-scratch recomputation.
TEST(KineticMesh, L4_3_1_KeptCertificatesEqualTheRecomputationAfterEveryBatch) {
  RecordProperty("claim", "L4.3.1");
  KineticMesh k({mv(0, 0, 1, 0), mv(9, 2, -1, 1)}, 3);
  EXPECT_EQ(incremental_vs_recomputed(k), "");
  std::size_t kept_total = 0, all_total = 0;
  k.run_until(Dyadic(1, -3), [&](const Batch& b) {
    EXPECT_EQ(incremental_vs_recomputed(k), "") << "batch at " << b.time.to_decimal();
    kept_total += k.current_certificates().size() - b.certs_created;
    all_total += k.current_certificates().size();
  });
  k.insert(mv(4, 7, 0, -1));
  EXPECT_EQ(incremental_vs_recomputed(k), "") << "after an insertion";
  k.run_until(Dyadic(1, -2), [&](const Batch& b) {
    EXPECT_EQ(incremental_vs_recomputed(k), "") << "batch at " << b.time.to_decimal();
  });
  k.erase(mv(0, 0, 1, 0));
  EXPECT_EQ(incremental_vs_recomputed(k), "") << "after a deletion";
  EXPECT_GT(kept_total, 0u);  // the batches did keep certificates
  std::cout << "certificates kept across batches: " << kept_total << " of " << all_total << "\n";
}
