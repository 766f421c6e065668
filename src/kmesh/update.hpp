#pragma once
// The update of Fig. 4.5 (§4.3) for dynamic insertions and deletions of input points: change
// propagation over ranks with the fully affected sets F_ℓ (satellites whose conversion decision
// may change), per rank Remove / Convert, the promotions of the spanner's repair, then the Delaunay
// triangulation of the result.
//
// State kept between updates: the spanner S over M (kmesh/spanner_repair.cpp keeps it valid), the
// spanner S_N over the input alone (its minimum ranks are the activation ranks ρ_v), and one record
// per considered satellite (converted or not; for one not converted, a witness vertex in its ball).
//
// Invariants the propagation rests on (checked by brute force after every update in the tests,
// kmesh/invariants.hpp on mesh()):
//  U1 the satellites considered at rank ℓ are exactly the 12 ℓ-satellites of the vertices active at
//     ℓ (ρ_v = ℓ, or v has a converted (ℓ−1)-satellite), for ℓ ≤ Λ+4;
//  U2 (L4.3.2) at each rank ℓ a considered satellite is converted iff no vertex of rank ≤ ℓ (input,
//     or Steiner converted at a rank ≤ ℓ) lies in its closed ball B(s, 2^(ℓ−2)): a maximal
//     independent subset of the proximity graph of rank ℓ;
//  U3 the witness of a satellite not converted is a vertex of rank ≤ ℓ in its ball.
//  U4 the top rank Λ+4 is owned by one nucleus: its 12 satellites are converted, no other nucleus's
//     is, so the boundary of M is a rigid 12-gon (no certificate watches its convexity;
//     check_rigid_boundary). Why it holds: inputs lie within 2^(Λ+1) of each other; a top satellite
//     is ≥ ≈ 6.5·2^Λ from every vertex of lower rank and 8.28·2^Λ from its nucleus's other top
//     satellites, against the ball radius 4·2^Λ, so whichever nucleus is decided first at the top
//     rank converts all 12, and every other top satellite lies within 2^(Λ+1) of the owner's on its
//     ray (a same-rank witness, U2). A rising top rank is new, hence decided whole; a falling one is
//     re-decided whole (recompute_highest); with the top rank unchanged, the owner's top satellites
//     go only all together (its deletion, relocation or activity change) and the others' only
//     witness is the owner's, so its removal re-decides the whole rank. The owner is the first in
//     key order, which can differ from a fresh construction's (keys are input keys).
// So a decision can change only if (a) the nucleus's activity at ℓ changes, (b) a vertex enters a
// converted satellite's ball (an insertion, or a conversion at a lower rank), or (c) the witness of
// one not converted goes: these put the satellite in F_ℓ, and ranks are repaired in increasing order,
// so every change reaches only higher ranks or the current one before its Convert phase.
//
// Deviations from the thesis (spec/kmesh.md): a Steiner vertex enters the spanner by the general
// insertion (its top is the rank below the lowest covering one) instead of Convert's ℓ−2 … ℓ plus
// TryToPromote, and the partially affected set P_ℓ is the spanner's own orphan repair (re-parent or
// promote) inside Remove; Λ (the top rank Λ+4) is recomputed by a scan over the input (O(n)).
//
// Stage 3 (the Voronoi neighbours, Fig. 4.5's last step) is local: the stars of the Delaunay
// triangulation are kept by spanner id, and only those that may have changed are recomputed
// (voronoi_repair): the vertices touched since the last repair — every vertex inserted or removed,
// and every vertex of a failed halfspace (Delaunay) certificate (KineticMesh reports them) — and
// their neighbours before and after. Why that suffices: an edge zw of the new triangulation that
// was not in the old one has an empty circle that held a removed vertex, and shrinking it at z gives
// an old edge from z to a removed vertex; symmetrically an old edge that is gone gives a new edge
// from z to an inserted vertex; motion between batches changes edges only through failed
// certificates. Stars are computed with the canonical lift order of mesh()'s numbering, so the
// triangles equal those of a from-scratch construction (tested in tests/kmesh/kds_test.cpp). The
// renumbering and the listing of the output stay global (O(|M|) integer work).
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "kmesh/construction.hpp"

namespace kmr::kmesh {

struct UpdateStats {
  std::size_t affected = 0;   // satellites taken from the F_ℓ sets (with repeats over ranks)
  std::size_t removed = 0, converted = 0, ranks = 0;
  std::uint64_t ops = 0;          // spanner and propagation operations of stages 1–2 (local)
  std::uint64_t ops_delaunay = 0; // stage 3 of the last mesh() (local: voronoi_repair)
  std::size_t stars = 0;          // stars recomputed by that voronoi_repair
  // Locality of the update (§4.3.1), counted for tests/kmesh/locality_test.cpp. The focus: the
  // inserted, deleted or relocated input points.
  std::size_t affected_max_rank = 0;  // L4.3.5: the largest |F_ℓ| over the ranks processed
  // L4.3.4: the largest r − ℓ over the satellites s taken from F_ℓ, r the least rank with
  // |s f| ≤ 2^r for a focus f (satellites of a deleted nucleus are skipped: it is the focus);
  // kNoReach if none was measured.
  static constexpr Rank kNoReach = std::numeric_limits<Rank>::min();
  Rank reach = kNoReach;
  std::uint64_t ops_remove = 0;  // L4.3.6: spanner operations of the Remove calls (S.remove)
};

class Updater {
 public:
  // The construction of Fig. 4.2 (kmesh/construction.hpp) on static points, adopted as the state.
  // At time t (default 0) the points sit at their trajectories' positions at t (kmesh/kds.hpp moves
  // them on with advance_to).
  explicit Updater(std::vector<InputPoint> points, const Dyadic& t = Dyadic(0));
  // Fig. 4.5 for one dynamic change; InputError (nothing changed) for a duplicate or a missing point,
  // or the deletion of the last point.
  void insert(const InputPoint& p);
  void erase(const InputPoint& p);
  // Fig. 4.5 for a kinetic batch at now() (kmesh/kds.hpp): the listed trajectories (the nuclei of the
  // vertices of the failed certificates) leave together with their satellites (stage 1 of a deletion
  // for all of them, then one propagation over the ranks), then come back one by one at their
  // positions at now() (Fig. 4.5 insertions). Every certificate not about them must hold at now().
  void relocate(const std::vector<InputPoint>& moved);
  // Every vertex moves like its nucleus to its position at time t (≥ now()); nothing else changes
  // (the structure stays valid while the certificates hold: L4.3.1).
  void advance_to(const Dyadic& t);
  const Dyadic& now() const { return now_; }
  // S_N (the spanner over the input alone, whose minimum ranks are the activation ranks) as a mesh
  // without satellites, numbered like mesh()'s inputs: its certificates are the kinetic ones of ρ.
  Mesh input_spanner_mesh() const;
  // The vertices (ids of the last mesh()) of failed halfspace (Delaunay) certificates: their stars,
  // and their neighbours', are recomputed at the next mesh() (kmesh/kds.hpp, after a batch).
  void voronoi_certificates_failed(const std::vector<int>& mesh_ids);
  // The current mesh, renumbered canonically (inputs sorted, then Steiner vertices by rank, nucleus,
  // ray), with its Delaunay triangulation (stage 3) and `considered` rebuilt from the records
  // (`existing` = the vertices of lower rank, so L4.2.5 reads as U2). Stage 3 runs here
  // (repair_delaunay), so the stars are repaired once for all the changes since the last call; the
  // listing itself is Θ(|M|) (the output), the rest of an update is local.
  Mesh mesh();
  // Stage 3 of Fig. 4.5 alone (local: the stars of the vertices touched since the last repair and
  // their neighbours'), without listing the mesh; mesh() calls it first. last().ops_delaunay and
  // last().stars count it.
  void repair_delaunay();
  const UpdateStats& last() const { return last_; }
  std::size_t input_size() const { return inputs_.size(); }
  std::uint64_t total_ops() const { return total_ops_; }

 private:
  struct Input {
    InputPoint p;
    int s = -1, sn = -1;  // ids in S and in S_N
    Rank rho = 0;
  };
  struct Sat {
    bool converted = false;
    int vertex = -1;   // id in S when converted
    int witness = -1;  // id in S of a vertex in the ball when not
  };
  using Key = std::tuple<Rank, int, int>;  // (rank, nucleus input key, ray)

  Point2 sat_position(int nucleus, int ray, Rank l) const;
  bool active(int nucleus, Rank l) const;
  bool has_converted(int nucleus, Rank l) const;
  int ball_witness(const Point2& s, Rank l, int nucleus) const;
  void affect(const Key& k) { F_[std::get<0>(k)].insert(k); }
  void affect_rank(int nucleus, Rank l);
  void set_witness(const Key& k, int w);
  void drop_witness(const Key& k);
  Rank recompute_highest();
  void refresh_rhos(const std::vector<int>& sn_touched);
  void propagate();
  void measure_reach(const Key& k);
  void mark(const Key& k);
  void remove_steiner(const Key& k);
  void remove_balls_containing(const Point2& p, Rank above);
  void decide(const Key& k);
  void erase_record(const Key& k);
  void finish(std::uint64_t ops0);
  std::map<int, Input>::iterator find_trajectory(const InputPoint& p);
  void erase_stage1(std::map<int, Input>::iterator it);
  void insert_stage1(const InputPoint& p);
  std::vector<std::pair<Point2, int>> canonical_inputs() const;  // (position at now, key), sorted
  // Stage 3: a vertex whose star may have changed (inserted, removed, or in a failed halfspace
  // certificate); voronoi_repair recomputes its star and its old and new neighbours'.
  void touch_delaunay(int x) { delaunay_touched_.insert(x); }
  void voronoi_repair();
  bool canonical_less(int a, int b) const;  // a before b in mesh()'s numbering (the lift order)

  std::vector<InputPoint> sorted_;  // the live input (for messages and rebuilds)
  std::map<int, Input> inputs_;     // by input key (stable: the first ids are the sorted input)
  // trajectory (x, y, vx, vy) → input key: find_trajectory in O(log n)
  std::map<std::tuple<exact::Integer, exact::Integer, exact::Integer, exact::Integer>, int> key_of_trajectory_;
  std::map<int, int> sn_to_key_;    // S_N id → input key
  int next_key_ = 0;
  Spanner S_, SN_;
  std::vector<VertexInfo> info_;  // per id of S (nucleus = input key); steiner=false, nucleus=-1 when dead
  std::map<Key, Sat> sats_;
  std::map<int, std::set<Key>> witness_of_;  // S id → satellites it witnesses
  std::map<Rank, std::set<Key>> F_;
  std::map<int, std::set<Key>> by_nucleus_;
  std::map<std::pair<Rank, int>, bool> before_;  // (rank, nucleus) → had a converted satellite there
  VoronoiStars stars_;             // per id of S: its Delaunay star (empty when dead)
  std::set<int> delaunay_touched_;  // ids of S touched since the last voronoi_repair
  std::vector<int> s_id_of_mesh_;   // the last mesh()'s ids → ids of S
  std::vector<Point2> focus_;       // the focus of the update in progress (UpdateStats::reach)
  Rank lowest_ = 0, highest_ = 0;
  Dyadic now_{0};
  UpdateStats last_;
  std::uint64_t total_ops_ = 0;
};

}  // namespace kmr::kmesh
