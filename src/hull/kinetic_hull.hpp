#pragma once
// The kinetic 3D convex hull of §2.2–§2.3: Appendix A's MkIHull3DAdaptive run as a self-adjusting
// program over kmr::sac, its certificates scheduled by the lattice MotionSimulator (§2.1).
//
// Every comparison the static algorithm makes (hull.hpp) is a certificate: a traceable ±1 created
// during the run, keyed by the points it compares, whose polynomial (moving_points.hpp) is handed to
// the simulator; the simulator flips outcomes batch by batch and change propagation repairs the
// trace. Discarded trace releases its certificates: each is an owned traceable (sac::OwnedMod)
// whose allocation node tells the hull when it is discarded (a fused undo hook).
//
// Guarantees (tests in tests/hull/kinetic_hull_test.cpp):
//  * After construction and after every update(batch), facets() is the convex hull of the points
//    just before the simulator's now() (outcomes are signs just before now, §2.1), in the format
//    of `kmr hull` (counter-clockwise from outside, smallest index first, sorted).
//  * The trace after every propagation equals the trace of a from-scratch run at the current time
//    (signature()), and the live certificates are exactly the from-scratch run's (certificate_keys()).
//  * Every live certificate is scheduled in the simulator exactly once; discarded ones are removed.
//  * Refused with an InputError naming the points: identical trajectories, fewer than four points
//    that are not identically coplanar, and any certificate that is identically zero (e.g. four
//    points that stay coplanar for all time).
//  * Integrated changes (§2.4) keep all of the above: change_motion(x, r), remove_point(x) and
//    insert_point(x) act between batches, each followed by one propagation. The points that may
//    ever take part are given at construction (`present` says which do at first, default all);
//    their priorities are fixed, so an insertion takes its place in the priority order.
//    A change that alters the initial tetrahedron (one of its points removed, a point of higher
//    priority inserted, or an identical degeneracy appearing) rebuilds the run from scratch.
//  * Deterministic: a pure function of (trajectories, seed, presence, the simulator's batches, the
//    integrated changes).
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hull/key_table.hpp"
#include "hull/moving_points.hpp"
#include "kinetic/motion_simulator.hpp"
#include "sac/big_stack.hpp"
#include "sac/runtime.hpp"

namespace kmr::hull {

struct KineticCounters {
  long long certificates_created = 0;  // certificates added to the simulator over the whole run
  long long propagations = 0;
  long long integrated_changes = 0;
  long long rebuilds = 0;  // integrated changes that altered the initial tetrahedron
};

class KineticHull {
 public:
  // The kinetic run: certificates are created in `sim` (its now() is the run's time).
  KineticHull(std::vector<MovingPoint> points, kinetic::MotionSimulator& sim, std::uint64_t seed = 2012,
              std::vector<bool> present = {});
  // A from-scratch self-adjusting run at time t without a simulator (outcomes: signs just before t);
  // the reference of the stability and compactness checks.
  KineticHull(std::vector<MovingPoint> points, const exact::Dyadic& t, std::uint64_t seed = 2012,
              std::vector<bool> present = {});
  ~KineticHull();
  KineticHull(const KineticHull&) = delete;
  KineticHull& operator=(const KineticHull&) = delete;

  // Repairs a batch the simulator returned: changes the failed certificates, then propagates.
  void update(const std::vector<kinetic::CertificateId>& batch);
  // Runs the simulation up to `until`, updating after each batch; after_batch (if given) is called
  // after each update.
  template <class F>
  void run_until(const exact::Dyadic& until, F&& after_batch) {
    while (auto batch = sim_->next_batch(until)) {
      update(*batch);
      after_batch();
    }
  }

  // Integrated changes (outside batches): the motion of x becomes r; x leaves or joins the set.
  void change_motion(int x, MovingPoint r);
  void remove_point(int x);
  void insert_point(int x);
  const std::vector<bool>& present() const { return present_; }

  std::vector<std::array<int, 3>> facets() const;  // alive faces, kmr hull's format
  std::vector<int> vertices() const;
  std::string signature() const { return rt_.signature(); }
  using CertificateKey = std::array<int, 5>;  // (test, points...; −1 where unused)
  std::vector<CertificateKey> certificate_keys() const;  // live certificates, increasing
  std::size_t live_certificates() const { return certs_.size(); }
  const KineticCounters& counters() const { return counters_; }
  // The hull's certificate bookkeeping agrees with its simulator's (issue 9; a check after each
  // batch in tests and in `kmr simulate hull --check-every`): every certificate handed to the
  // simulator was counted once (certificates_created == the simulator's created) and exactly the
  // live ones are scheduled (live_certificates() == the simulator's live); and every live
  // certificate's table hash (CertificateHash of its key) is its traceable's allocation name, which
  // init_certificate and certificate_released pass instead of hashing. Else a ContractError naming
  // both values. Meaningful when the simulator serves this hull alone, from its start.
  void check_simulator_counts() const;
  const sac::Runtime& runtime() const { return rt_; }
  const std::vector<MovingPoint>& points() const { return pts_; }

  // The program's internals (kinetic_hull.cpp); public so its free functions can reach them.
  // Appendix A's Face: vertices, the boxes of the neighbours across (v0,v1), (v1,v2), (v2,v0)
  // (IMod<FaceH>) and of the killer (IMod<Killer>), held by their non-template base so that Face is
  // complete before Mod<Face> is named (kinetic_hull.cpp casts them back).
  struct Face {
    std::array<int, 3> v{};
    std::array<sac::IModBase*, 3> nbr{};
    sac::IModBase* killer = nullptr;
    bool operator==(const Face&) const = default;
  };
  using FaceH = sac::Mod<Face>*;
  struct Tent {  // Appendix A's getVertexFaces: the faces a point's insertion created, in order
    // Immutable and shared: closures capture a Tent by value without copying the list (issue 9).
    std::shared_ptr<const std::vector<FaceH>> faces;
    const std::vector<FaceH>& list() const {
      static const std::vector<FaceH> none;
      return faces ? *faces : none;
    }
    bool operator==(const Tent& o) const { return list() == o.list(); }
  };
  struct Killer {  // the point that ripped a face and the box of its tent faces (−1: alive)
    int p = -1;
    sac::Mod<Tent>* tent = nullptr;
    bool operator==(const Killer&) const = default;
  };
  enum class Test : std::uint8_t { initial, visible, side };
  // A certificate's traceable: its outcome, and (the owner's record) its key and whether it holds
  // the key's registration (false once a successor re-created under the key took it over).
  struct CertificateRecord {
    CertificateKey key{};
    bool current = false;
  };
  using CertificateMod = sac::OwnedMod<int, CertificateRecord>;
  static const sac::Label& certificate_label(Test t);  // the allocation label of a test's certificates
  // Inside runs: the certificate of a test (created, or reused with its trace).
  sac::Mod<int>* certificate(Test test, int a, int b, int c, int d);
  void face_created(FaceH f, sac::HookId hook);
  void face_discarded(const std::array<int, 3>& key, sac::HookId self);
  void certificate_released(CertificateMod* m);  // its allocation node was discarded
  sac::Runtime& rt() { return rt_; }
  const std::vector<int>& order() const { return order_; }
  const std::array<int, 4>& simplex() const { return simplex_; }

 private:
  void run();
  void start();                           // chooses the tetrahedron and centre, then run()
  void propagate();
  void set_present(int x, bool on);
  void index_certificate(const CertificateKey& key, bool add);
  struct Registration;
  void register_sim(kinetic::CertificateId id, CertificateMod* cert);
  // A certificate's polynomial: in machine form when its points have one (moving_points.hpp), else
  // as a Polynomial; the two are the same polynomial.
  struct CertificatePolynomial {
    std::optional<poly::MachinePolynomial> machine;
    Polynomial exact;  // when !machine
    bool is_zero() const { return machine ? machine->is_zero() : exact.is_zero(); }
  };
  CertificatePolynomial polynomial(Test test, int a, int b, int c, int d) const;
  // The machine form alone (false, out untouched, when a point or the centre has none).
  bool machine_polynomial(Test test, int a, int b, int c, int d, poly::MachinePolynomial& out) const;
  int sign_before_t(const CertificatePolynomial& p) const;  // outcome in a from-scratch reference run
  // The machine form of point x, then refresh_machine_centre (start() fills machine_ for all points).
  void refresh_machine_point(int x);
  void refresh_machine_centre();  // machine_centre_ and t_lattice_ from machine_, simplex_ and t_
  std::string describe(Test test, int a, int b, int c, int d) const;

  void init_certificate(CertificateMod& m, Test test, int a, int b, int c, int d);
  struct Registration {
    CertificateMod* cert = nullptr;  // the traceable holding the key (payload.current)
    kinetic::CertificateId sim = 0;
  };
  std::vector<MovingPoint> pts_;
  kinetic::MotionSimulator* sim_ = nullptr;  // null: a from-scratch reference at time t_
  exact::Dyadic t_;
  std::vector<int> order_;
  std::vector<bool> present_;
  std::vector<sac::Mod<bool>*> present_box_;                          // inputs, one per point
  // point → keys of its certificates: every live one, plus removed ones (skipped and compacted
  // away lazily, so a removal costs nothing); by_point_live_ counts the live ones. Built at the
  // first change_motion (from the live certificates), kept from then on: a simulation without
  // motion changes never pays for it.
  std::vector<std::vector<CertificateKey>> by_point_;
  std::vector<int> by_point_live_;
  bool by_point_built_ = false;
  void build_point_index();
  std::array<int, 4> simplex_{};
  MovingPoint centre_sum_;
  std::vector<std::optional<MachinePoint>> machine_;  // machine forms of pts_ (issue 9)
  std::optional<MachinePoint> machine_centre_;        // of centre_sum_, when all four have one
  std::optional<std::pair<std::int64_t, int>> t_lattice_;  // t_ = k·2^-b with |k| < 2^53, 0 ≤ b ≤ 62
  sac::Runtime rt_;
  // Runs and propagations nest a continuation per insertion: they run on the thread's kept 1 GiB
  // (virtual) stack, mapped once per thread and warm after the first run (issue 9; spec/hull.md
  // "Kinetic performance"); a hull that ends returns its pages below the top kStackKeep bytes.
  static constexpr std::size_t kStackBytes = std::size_t{1} << 30, kStackKeep = std::size_t{32} << 20;
  template <class F>
  static void on_stack(F&& f) {
    sac::BigStack::of_thread(kStackBytes).run(f);
  }
  // Lookup-only flat tables (key_table.hpp; iteration order never reaches a result: what is
  // listed is sorted first).
  struct KeyHash {  // two ints per 64-bit word, a multiply per word, one finalizer (sac::mix)
    template <std::size_t N>
    std::size_t operator()(const std::array<int, N>& k) const {
      std::uint64_t h = 0x6b6579;
      for (std::size_t i = 0; i < N; i += 2) {
        std::uint64_t w = static_cast<std::uint32_t>(k[i]);
        if (i + 1 < N) w |= static_cast<std::uint64_t>(static_cast<std::uint32_t>(k[i + 1])) << 32;
        h = (h ^ w) * 0x9e3779b97f4a7c15ULL;
        h ^= h >> 29;
      }
      return static_cast<std::size_t>(sac::mix(h, N));
    }
  };
  // The live certificates, hashed by their traceables' allocation name (sac::alloc_name of the
  // certificate's label and points): init_certificate and certificate_released pass the name their
  // traceable already holds (KeyTable::Hashed) instead of hashing the key a second time.
  struct CertificateHash {
    std::uint64_t operator()(const CertificateKey& k) const {
      return sac::alloc_name(certificate_label(static_cast<Test>(k[0])), k[1], k[2], k[3], k[4]);
    }
  };
  KeyTable<CertificateKey, Registration, CertificateHash> certs_;  // live certificates
  std::vector<CertificateMod*> by_sim_;  // simulator id → the traceable holding its key, or null
  KeyTable<std::array<int, 3>, std::pair<FaceH, sac::HookId>, KeyHash> faces_;  // live faces by vertices
  KineticCounters counters_;
};

std::uint64_t canon_value(const KineticHull::Killer& k);
std::uint64_t canon_value(const KineticHull::Face& f);
std::uint64_t canon_value(const KineticHull::Tent& t);

}  // namespace kmr::hull
