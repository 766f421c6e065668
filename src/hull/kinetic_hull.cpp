// The kinetic hull: Appendix A's MkIHull3DAdaptive (run, incrementalHull, insertVertex,
// findAssociatedFace with search/findFace, rip with ripFace/ripLoop and sort, tent with createFace
// and processEdgeVertex) over kmr::sac. Each function cites its ΔML original. See kinetic_hull.hpp.
//
// Continuation style: a read's continuation is the rest of the ΔML function (sac re-runs exactly the
// continuation of a read whose value changed), so state that flows past a read (rip's pending faces
// and boundary) is captured by value, never mutated in a closure. Face records are write-once
// (their vertices and the boxes of their fields); the fields are imperative boxes (ΔML IBox) as in
// Appendix A's EXTENDED_GEOMETRY: neighbours and killer are set by later insertions.
//
// Invariants the change-propagation proof rests on (§1.3.2):
//  * Every value a continuation uses comes from its reads, its captures, or a face record, and a
//    face record is a pure function of its allocation key (its vertices), so re-executing a read
//    with the same value repeats the same operations.
//  * Allocation keys are unique within an execution: a face (p, u, v) is created only by p's tent;
//    a certificate is keyed by its test and points, and each test is made once per insertion
//    (rip does not re-test an invisible face it already put on the horizon, see rip_loop).
//  * The certificate and face registries are written only by the program (in runs and undo hooks)
//    and never read by it, except for a certificate's current outcome as the initial value of its
//    re-created traceable (the same polynomial, so the same value).
#include "hull/kinetic_hull.hpp"

#include <algorithm>
#include <cmath>

#include "exact/error.hpp"
#include "poly/failure_filter.hpp"
#include "hull/priorities.hpp"

namespace kmr::hull {

std::uint64_t canon_value(const KineticHull::Killer& k) {
  return sac::mix(sac::mix(0x4b11, static_cast<std::uint64_t>(k.p)), sac::canon_key(k.tent));
}
std::uint64_t canon_value(const KineticHull::Face& f) {
  std::uint64_t h = 0xface;
  for (int v : f.v) h = sac::mix(h, static_cast<std::uint64_t>(v));
  for (auto* b : f.nbr) h = sac::mix(h, sac::canon_key(b));
  return sac::mix(h, sac::canon_key(f.killer));
}
std::uint64_t canon_value(const KineticHull::Tent& t) {
  std::uint64_t h = 0x7e27;
  for (auto* f : t.list()) h = sac::mix(h, sac::canon_key(f));
  return h;
}

namespace {

using KH = KineticHull;
using FaceH = KH::FaceH;
using Face = KH::Face;
using Killer = KH::Killer;
using Tent = KH::Tent;
using Roots = std::array<FaceH, 4>;
using sac::Label;
using sac::Mod;

constexpr Label kFace{"hull.face"}, kNbr{"hull.face.nbr"}, kKiller{"hull.face.killer"}, kFaceHook{"hull.face.hook"},
    kTent{"hull.tent"}, kRoots{"hull.roots"}, kCertInitial{"hull.cert.initial"}, kCertVisible{"hull.cert.visible"},
    kCertSide{"hull.cert.side"}, kFindFace{"hull.find_face"};

struct Border {  // a horizon entry: the invisible neighbour and the ripped face's edge
  FaceH nbr;
  int u, v;
};

// An immutable list shared by the closures that capture it (rip's pending faces and boundary):
// capturing by value copies a pointer, not the list (issue 9: the vectors' copies were a large
// part of the allocations). push puts an element in front.
template <class T>
struct Cell {
  T head;
  std::shared_ptr<const Cell> tail;
};
template <class T>
using List = std::shared_ptr<const Cell<T>>;
template <class T>
List<T> push(List<T> l, T v) {
  return std::make_shared<const Cell<T>>(Cell<T>{std::move(v), std::move(l)});
}
using Pending = List<std::pair<FaceH, int>>;  // a stack: the head is the next (face, slot)
using Boundary = List<Border>;                 // in reverse order of discovery

const Face& rec(KH* kh, FaceH f) { return kh->rt().deref(f); }
sac::IMod<FaceH>* nbr_box(const Face& f, int s) { return static_cast<sac::IMod<FaceH>*>(f.nbr[s]); }
sac::IMod<Killer>* killer_box(const Face& f) { return static_cast<sac::IMod<Killer>*>(f.killer); }

int slot(const Face& f, int a, int b) {
  for (int s = 0; s < 3; ++s) {
    int x = f.v[s], y = f.v[(s + 1) % 3];
    if ((x == a && y == b) || (x == b && y == a)) return s;
  }
  throw ContractError("kinetic hull: face does not have the specified edge");
}

// Geometry.mkNewFace: the face record and its boxes, keyed by the vertices.
FaceH new_face(KH* kh, int a, int b, int c) {
  sac::Runtime& rt = kh->rt();
  FaceH f = rt.alloc<Face>(kFace, a, b, c);
  Face r;
  r.v = {a, b, c};
  for (int s = 0; s < 3; ++s) r.nbr[s] = rt.ialloc<FaceH>(kNbr, FaceH{nullptr}, a, b, c, s);
  r.killer = rt.ialloc<Killer>(kKiller, Killer{}, a, b, c);
  rt.write(f, r);
  std::array<int, 3> key{a, b, c};
  sac::HookId h = rt.on_discard(kFaceHook, [kh, key](sac::HookId self) { kh->face_discarded(key, self); });
  kh->face_created(f, h);
  return f;
}

// Geometry.setFaceNeighbor: f and g become neighbours across the edge {a, b}.
void set_face_neighbor(KH* kh, FaceH f, int a, int b, FaceH g) {
  const Face &F = rec(kh, f), &G = rec(kh, g);
  kh->rt().iwrite(nbr_box(F, slot(F, a, b)), g);
  kh->rt().iwrite(nbr_box(G, slot(G, a, b)), f);
}

// tent (with createFace and processEdgeVertex): one face (p, e) per horizon edge, in the sorted
// order; the faces around p are linked through a table local to this tent (Appendix A keeps it in
// each vertex's lastFace box, read and written only within one tent).
void tent(KH* kh, int p, Mod<Tent>* box, const std::vector<Border>& boundary) {
  std::vector<std::pair<int, FaceH>> last;  // processEdgeVertex's (q, f)
  auto process_edge_vertex = [&](int q, FaceH f) {
    for (auto& [v, g] : last)
      if (v == q) {
        set_face_neighbor(kh, f, p, q, g);
        return;
      }
    last.emplace_back(q, f);
  };
  auto faces = std::make_shared<std::vector<FaceH>>();
  for (const Border& b : boundary) {  // createFace
    FaceH f = new_face(kh, p, b.u, b.v);
    set_face_neighbor(kh, f, b.u, b.v, b.nbr);
    process_edge_vertex(b.u, f);
    process_edge_vertex(b.v, f);
    faces->push_back(f);
  }
  kh->rt().write(box, Tent{std::move(faces)});  // setVertexFaces
}

// ripLoop over pending (face, neighbour slot) pairs, then sort and tent. ripFace is the push of a
// newly ripped face's three neighbours.
void rip_loop(KH* kh, int p, Killer me, Pending pending, Boundary boundary) {
  sac::Runtime& rt = kh->rt();
  if (!pending) {  // sort: the horizon by edge id (Appendix A's quicksort, for stability)
    std::vector<Border> bd;
    for (const Cell<Border>* c = boundary.get(); c; c = c->tail.get()) bd.push_back(c->head);
    std::reverse(bd.begin(), bd.end());  // discovery order, as the list was built
    std::sort(bd.begin(), bd.end(), [](const Border& a, const Border& b) { return std::pair(a.u, a.v) < std::pair(b.u, b.v); });
    tent(kh, p, me.tent, bd);
    return;
  }
  auto [r, s] = pending->head;
  Pending rest = pending->tail;
  const Face& R = rec(kh, r);
  const int eu = R.v[s], ev = R.v[(s + 1) % 3];
  rt.iread(nbr_box(R, s), [kh, p, me, rest, boundary, eu, ev](FaceH g) {
    KMR_CHECK(g != nullptr, "kinetic hull: a face without a neighbour");
    const Face& G = rec(kh, g);
    kh->rt().iread(killer_box(G), [kh, p, me, rest, boundary, eu, ev, g](const Killer& k) {
      if (k.p >= 0) {  // ripped already (by p: g is on the current hull)
        KMR_CHECK(k.p == p, "kinetic hull: a neighbour on the current hull was ripped by another point");
        rip_loop(kh, p, me, rest, boundary);
        return;
      }
      // An invisible face met again across another edge: the answer is the one already read.
      for (const Cell<Border>* c = boundary.get(); c; c = c->tail.get())
        if (c->head.nbr == g) {
          rip_loop(kh, p, me, rest, push(boundary, Border{g, eu, ev}));
          return;
        }
      const Face& G2 = rec(kh, g);
      kh->rt().read(kh->certificate(KH::Test::visible, p, G2.v[0], G2.v[1], G2.v[2]),
                    [kh, p, me, rest, boundary, eu, ev, g](int side) {
                      if (side > 0) {  // halfSpaceTest: visible, ripFace
                        kh->rt().iwrite(killer_box(rec(kh, g)), me);  // setFaceKiller
                        Pending pd = rest;
                        for (int t = 2; t >= 0; --t) pd = push(pd, std::pair(g, t));
                        rip_loop(kh, p, me, std::move(pd), boundary);
                      } else {
                        rip_loop(kh, p, me, rest, push(boundary, Border{g, eu, ev}));
                      }
                    });
    });
  });
}

// mfun rip (p, f): f is alive and visible from p (find_face checked it).
void rip(KH* kh, int p, FaceH f) {
  sac::Runtime& rt = kh->rt();
  Killer me{p, rt.alloc<Tent>(kTent, p)};
  rt.iwrite(killer_box(rec(kh, f)), me);  // ripFace: setFaceKiller
  Pending pd;
  for (int t = 2; t >= 0; --t) pd = push(pd, std::pair(f, t));  // (f, 0) on top
  rip_loop(kh, p, me, std::move(pd), nullptr);
}

void find_face(KH* kh, FaceH f, int x);

// mfun search: the tent face of q whose pyramid contains x (sides (w, u, c) and (u, v, c) of
// face (u = q, v, w)).
void search(KH* kh, int q, Tent tent, std::size_t i, int x) {
  KMR_CHECK(i < tent.list().size(), "kinetic hull: no tent face of point " + std::to_string(q) +
                                        " contains the ray to " + std::to_string(x));
  const Face& g = rec(kh, tent.list()[i]);
  const int v1 = g.v[1], v2 = g.v[2];
  kh->rt().read(kh->certificate(KH::Test::side, x, v2, q, -1), [kh, q, tent, i, x, v1](int side1) {
    if (side1 < 0) {
      search(kh, q, tent, i + 1, x);
      return;
    }
    kh->rt().read(kh->certificate(KH::Test::side, x, q, v1, -1), [kh, q, tent, i, x](int side2) {
      if (side2 < 0) search(kh, q, tent, i + 1, x);
      else find_face(kh, tent.list()[i], x);
    });
  });
}

// mfun findFace: along the killer chain while the located face is visible from x.
void find_face(KH* kh, FaceH f, int x) {
  // Memoized by (f, x) as Appendix A's mfun findFace: a re-executed location that reaches the same
  // face reuses the rest of the insertion (its trace) instead of re-running it (issue 9).
  kh->rt().memo<int>(kFindFace, std::pair(f, x), [kh, f, x] {
    const Face& F = rec(kh, f);
    sac::IMod<Killer>* killer = killer_box(F);
    kh->rt().read(kh->certificate(KH::Test::visible, x, F.v[0], F.v[1], F.v[2]), [kh, f, x, killer](int side) {
      if (side < 0) return;  // not visible: x ∈ pyramid(c, f) ⊂ conv(A_i), discarded
      kh->rt().iread(killer, [kh, f, x](const Killer& k) {
        if (k.p < 0) {
          rip(kh, x, f);  // insertVertex: rip and tent
          return;
        }
        kh->rt().read(k.tent, [kh, q = k.p, x](const Tent& t) { search(kh, q, t, 0, x); });
      });
    });
    return 0;
  });
}

// findAssociatedFace at the root: the initial face whose pyramid contains x (three sides each).
void locate_root(KH* kh, Roots roots, int i, int s, int x) {
  KMR_CHECK(i < 4, "kinetic hull: the initial pyramids do not cover point " + std::to_string(x));
  const Face& f = rec(kh, roots[i]);
  const int u = f.v[s], v = f.v[(s + 1) % 3];
  kh->rt().read(kh->certificate(KH::Test::side, x, u, v, -1), [kh, roots, i, s, x](int side) {
    if (side < 0) locate_root(kh, roots, i + 1, 0, x);
    else if (s < 2) locate_root(kh, roots, i, s + 1, x);
    else find_face(kh, roots[i], x);
  });
}

// incrementalHull's initial faces: conv(A_4), each face counter-clockwise from outside.
void initial_hull(KH* kh, Mod<Roots>* roots, int a, int b, int c, int d, int side) {
  if (side > 0) std::swap(b, c);  // d lies below abc: abc faces outward
  Roots r{new_face(kh, a, b, c), new_face(kh, a, d, b), new_face(kh, b, d, c), new_face(kh, c, d, a)};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Face &f = rec(kh, r[i]), &g = rec(kh, r[j]);
      int shared[2], m = 0;
      for (int u : f.v)
        if (std::count(g.v.begin(), g.v.end(), u)) shared[m++] = u;
      set_face_neighbor(kh, r[i], shared[0], shared[1], r[j]);
    }
  kh->rt().write(roots, r);
}

}  // namespace

const sac::Label& KineticHull::certificate_label(Test t) {
  switch (t) {
    case Test::initial: return kCertInitial;
    case Test::visible: return kCertVisible;
    default: return kCertSide;
  }
}

KineticHull::KineticHull(std::vector<MovingPoint> points, kinetic::MotionSimulator& sim, std::uint64_t seed,
                         std::vector<bool> present)
    : pts_(std::move(points)), sim_(&sim), t_(sim.now()), present_(std::move(present)) {
  order_ = priority_order(random_priorities(static_cast<int>(pts_.size()), seed));
  start();
}

KineticHull::KineticHull(std::vector<MovingPoint> points, const exact::Dyadic& t, std::uint64_t seed,
                         std::vector<bool> present)
    : pts_(std::move(points)), t_(t), present_(std::move(present)) {
  order_ = priority_order(random_priorities(static_cast<int>(pts_.size()), seed));
  start();
}

void KineticHull::start() {
  if (present_.empty()) present_.assign(pts_.size(), true);
  KMR_CHECK(present_.size() == pts_.size(), "KineticHull: one presence flag per point");
  std::vector<int> live_order;
  for (int x : order_)
    if (present_[x]) live_order.push_back(x);
  refuse_identical_trajectories(pts_);
  machine_.clear();
  for (const MovingPoint& p : pts_) machine_.push_back(machine_point(p));
  simplex_ = initial_simplex_of(pts_, live_order, machine_);  // its tests in machine form (no GMP)
  centre_sum_ = trajectory_sum(pts_[simplex_[0]], pts_[simplex_[1]], pts_[simplex_[2]], pts_[simplex_[3]]);
  refresh_machine_centre();
  // Room for the initial run's certificates up front (about 5 n log2 n, Fig. 2.8; 6 for margin): no
  // table growth or record moves during the run (issue 9; no decision depends on capacities).
  // Geometric, as a hull is started again at every rebuild.
  const double n = static_cast<double>(pts_.size());
  const auto expected = static_cast<std::size_t>(6 * n * std::log2(std::max(2.0, n)));
  certs_.reserve(expected);
  // The runtime's key index holds the certificates and, per face, its record, neighbour and killer
  // boxes: ≈ 1.6 keys per certificate (n = 20 / 40), about `expected`: sized once, no doubling.
  rt_.reserve_keys(expected);
  if (sim_) {
    if (by_sim_.capacity() < by_sim_.size() + expected)
      by_sim_.reserve(std::max(by_sim_.size() + expected, 2 * by_sim_.capacity()));
    sim_->reserve(expected);
  }
  if (present_box_.empty())
    for (std::size_t x = 0; x < pts_.size(); ++x)
      present_box_.push_back(rt_.input<bool>(sac::Label("hull.present"), x, present_[x]));
  run();
}

void KineticHull::refresh_machine_point(int x) {
  machine_[static_cast<std::size_t>(x)] = machine_point(pts_[static_cast<std::size_t>(x)]);
  refresh_machine_centre();
}

void KineticHull::refresh_machine_centre() {
  machine_centre_.reset();
  bool all = true;
  for (int v : simplex_) all = all && machine_[v].has_value();
  if (all) machine_centre_ = *machine_[simplex_[0]] + *machine_[simplex_[1]] + *machine_[simplex_[2]] + *machine_[simplex_[3]];
  t_lattice_.reset();
  const exact::Integer& m = t_.mantissa();
  if (t_.exponent() <= 0 && t_.exponent() >= -62 && exact::bit_length(m) <= 52)
    t_lattice_ = std::pair(static_cast<std::int64_t>(m), static_cast<int>(-t_.exponent()));
}

KineticHull::~KineticHull() {
  if (sac::BigStack* s = sac::BigStack::kept_of_thread()) s->trim(kStackKeep);
  if (!sim_) return;
  for (kinetic::CertificateId id = 0; id < by_sim_.size(); ++id)  // increasing id order, not the table's
    if (by_sim_[id]) sim_->remove(id);
}

// run / incrementalHull / app insertVertex: the initial tetrahedron (its orientation a
// certificate), then every other point in priority order.
void KineticHull::run() {
  on_stack([this] {
    rt_.run([this] {
      const int a = simplex_[0], b = simplex_[1], c = simplex_[2], d = simplex_[3];  // (no captured bindings: clang 14)
      Mod<Roots>* roots = rt_.alloc<Roots>(kRoots);
      rt_.read(certificate(Test::initial, a, b, c, d),
               [kh = this, roots, a, b, c, d](int side) { initial_hull(kh, roots, a, b, c, d, side); });
      for (int x : order_) {
        if (x == a || x == b || x == c || x == d) continue;
        // insertVertex x (if x is in the set): findAssociatedFace, then rip and tent.
        rt_.read(present_box_[x], [kh = this, roots, x](bool on) {
          if (on) kh->rt().read(roots, [kh, x](const Roots& r) { locate_root(kh, r, 0, 0, x); });
        });
      }
    });
  });
}

void KineticHull::update(const std::vector<kinetic::CertificateId>& batch) {
  KMR_CHECK(sim_ != nullptr, "KineticHull::update on a from-scratch reference");
  for (kinetic::CertificateId id : batch) {
    KMR_CHECK(id < by_sim_.size() && by_sim_[id], "kinetic hull: a batch names a certificate the hull does not own");
    rt_.change(by_sim_[id], sim_->outcome(id));
  }
  propagate();
}

void KineticHull::propagate() {
  if (sim_) t_ = sim_->now();
  on_stack([this] { rt_.propagate(); });
  ++counters_.propagations;
}

void KineticHull::build_point_index() {
  by_point_.assign(pts_.size(), {});
  by_point_live_.assign(pts_.size(), 0);
  by_point_built_ = true;
  std::vector<CertificateKey> keys;  // in key order (not the table's), so the lists are deterministic
  certs_.for_each([&](const CertificateKey& key, const Registration&) { keys.push_back(key); });
  std::sort(keys.begin(), keys.end());
  for (const CertificateKey& key : keys) index_certificate(key, true);
}

void KineticHull::index_certificate(const CertificateKey& key, bool add) {
  if (!by_point_built_) return;  // built at the first change_motion
  if (by_point_.size() < pts_.size()) by_point_.resize(pts_.size()), by_point_live_.resize(pts_.size());
  for (int i = 1; i < 5; ++i) {
    if (key[i] < 0) continue;
    const auto x = static_cast<std::size_t>(key[i]);
    auto& v = by_point_[x];
    if (!add) {
      --by_point_live_[x];
      continue;
    }
    ++by_point_live_[x];
    v.push_back(key);
    if (v.size() > 2 * static_cast<std::size_t>(by_point_live_[x]) + 16) {  // compact: live keys, once each
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
      std::erase_if(v, [this](const CertificateKey& k) { return !certs_.contains(k); });
    }
  }
}

void KineticHull::register_sim(kinetic::CertificateId id, CertificateMod* cert) {
  if (id == by_sim_.size()) {  // the common case: ids are sequential
    by_sim_.push_back(cert);
    return;
  }
  if (by_sim_.size() < id) by_sim_.resize(id + 1, nullptr);
  by_sim_[id] = cert;
}

// §2.4's motion change: every live certificate whose polynomial involves x (all centre tests and
// the tetrahedron's orientation too if x is one of its points, since the centre moves with them)
// gets its new polynomial: the simulator's certificate is replaced and the traceable takes the new
// polynomial's sign just before now; then one propagation repairs the trace.
void KineticHull::change_motion(int x, MovingPoint r) {
  KMR_CHECK(x >= 0 && x < static_cast<int>(pts_.size()), "change_motion: no such point");
  for (std::size_t y = 0; y < pts_.size(); ++y)
    if (static_cast<int>(y) != x && pts_[y] == r)
      throw InputError("points " + std::to_string(std::min<int>(x, y)) + " and " + std::to_string(std::max<int>(x, y)) +
                       " would have identical trajectories after the motion change");
  const std::array<int, 4> before = simplex_;
  MovingPoint old = pts_[x];
  const MovingPoint old_sum = centre_sum_;
  pts_[x] = std::move(r);
  auto restore = [&] {
    pts_[x] = old;
    centre_sum_ = old_sum;
    refresh_machine_point(x);
  };
  std::vector<int> live_order;
  for (int y : order_)
    if (present_[y]) live_order.push_back(y);
  std::array<int, 4> after;
  machine_[static_cast<std::size_t>(x)] = machine_point(pts_[static_cast<std::size_t>(x)]);  // restore() refreshes it back
  try {
    after = initial_simplex_of(pts_, live_order, machine_);
  } catch (const InputError&) {
    restore();
    throw;
  }
  ++counters_.integrated_changes;
  if (after != before) {  // an identical degeneracy appeared or went: a new tetrahedron
    ++counters_.rebuilds;
    rt_.reset();
    start();
    return;
  }
  const bool centre = std::count(before.begin(), before.end(), x) > 0;
  if (centre) centre_sum_ = trajectory_sum(pts_[before[0]], pts_[before[1]], pts_[before[2]], pts_[before[3]]);
  refresh_machine_point(x);
  if (!by_point_built_) build_point_index();
  std::vector<CertificateKey> affected;
  if (centre)
    certs_.for_each([&](const CertificateKey& key, const Registration&) {
      if (key[0] != static_cast<int>(Test::visible)) affected.push_back(key);
    });
  if (static_cast<std::size_t>(x) < by_point_.size())
    for (const CertificateKey& key : by_point_[x])
      if (certs_.contains(key)) affected.push_back(key);
  std::sort(affected.begin(), affected.end());
  affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
  std::vector<CertificatePolynomial> polys;  // all computed first: a refused change changes nothing
  for (const CertificateKey& key : affected) {
    const Test test = static_cast<Test>(key[0]);
    polys.push_back(polynomial(test, key[1], key[2], key[3], key[4]));
    if (polys.back().is_zero()) {
      restore();
      --counters_.integrated_changes;
      throw InputError(describe(test, key[1], key[2], key[3], key[4]) + " (after the motion change)");
    }
  }
  for (std::size_t i = 0; i < affected.size(); ++i) {
    Registration& reg = *certs_.find(affected[i]);  // (no insert or erase in this loop)
    int outcome;
    if (sim_) {
      sim_->remove(reg.sim);
      by_sim_[reg.sim] = nullptr;
      reg.sim = polys[i].machine ? sim_->add(*polys[i].machine) : sim_->add(polys[i].exact);
      register_sim(reg.sim, reg.cert);
      ++counters_.certificates_created;
      outcome = sim_->outcome(reg.sim);
    } else {
      outcome = sign_before_t(polys[i]);
    }
    rt_.change(reg.cert, outcome);
  }
  propagate();
}

void KineticHull::set_present(int x, bool on) {
  KMR_CHECK(x >= 0 && x < static_cast<int>(pts_.size()), "insert/remove: no such point");
  if (present_[x] == on) return;
  ++counters_.integrated_changes;
  present_[x] = on;
  std::vector<int> live_order;
  for (int y : order_)
    if (present_[y]) live_order.push_back(y);
  std::array<int, 4> now_simplex;
  try {
    now_simplex = initial_simplex_of(pts_, live_order, machine_);
  } catch (const InputError&) {
    present_[x] = !on;
    throw;
  }
  rt_.change(present_box_[x], on);
  if (now_simplex != simplex_) {
    ++counters_.rebuilds;
    rt_.reset();
    start();
    return;
  }
  propagate();
}

void KineticHull::remove_point(int x) { set_present(x, false); }
void KineticHull::insert_point(int x) { set_present(x, true); }

bool KineticHull::machine_polynomial(Test test, int a, int b, int c, int d, poly::MachinePolynomial& out) const {
  const auto& M = machine_;
  switch (test) {
    case Test::initial:
      if (!(M[a] && M[b] && M[c] && M[d])) return false;
      out = orientation_polynomial(*M[a], *M[b], *M[c], *M[d]);
      return true;
    case Test::visible:  // face bcd, point a
      if (!(M[a] && M[b] && M[c] && M[d])) return false;
      out = orientation_polynomial(*M[b], *M[c], *M[d], *M[a]);
      return true;
    default:  // point a, side (b, c, centre)
      if (!(M[a] && M[b] && M[c] && machine_centre_)) return false;
      out = centre_side_polynomial(*M[b], *M[c], *M[a], *machine_centre_);
      return true;
  }
}

KineticHull::CertificatePolynomial KineticHull::polynomial(Test test, int a, int b, int c, int d) const {
  CertificatePolynomial r;
  if (poly::MachinePolynomial mp; machine_polynomial(test, a, b, c, d, mp)) {
    r.machine = mp;
    return r;
  }
  switch (test) {
    case Test::initial: r.exact = orientation_polynomial(pts_[a], pts_[b], pts_[c], pts_[d]); break;
    case Test::visible: r.exact = orientation_polynomial(pts_[b], pts_[c], pts_[d], pts_[a]); break;  // face bcd, point a
    default: r.exact = centre_side_polynomial(pts_[b], pts_[c], pts_[a], centre_sum_);  // point a, side (b, c, centre)
  }
  return r;
}

int KineticHull::sign_before_t(const CertificatePolynomial& p) const {
  if (p.machine && t_lattice_) return poly::sign_before_lattice(*p.machine, t_lattice_->first, t_lattice_->second);
  return poly::sign_before(p.machine ? p.machine->to_polynomial() : p.exact, t_);
}

std::string KineticHull::describe(Test test, int a, int b, int c, int d) const {
  auto s = [](int i) { return std::to_string(i); };
  if (test == Test::side)
    return "points " + s(b) + ", " + s(c) + ", " + s(a) + " and the centre (the centroid of points " + s(simplex_[0]) +
           ", " + s(simplex_[1]) + ", " + s(simplex_[2]) + ", " + s(simplex_[3]) +
           ") stay coplanar for all time: an identically zero certificate";
  int lo[4] = {a, b, c, d};
  std::sort(lo, lo + 4);
  return "points " + s(lo[0]) + ", " + s(lo[1]) + ", " + s(lo[2]) + " and " + s(lo[3]) +
         " stay coplanar for all time: an identically zero certificate";
}

// A reused certificate (its key found in the re-executed interval) keeps its traceable, value and
// registration: nothing is looked up. A new traceable is initialised by init_certificate.
sac::Mod<int>* KineticHull::certificate(Test test, int a, int b, int c, int d) {
  return rt_.owned<int, CertificateRecord>(
      certificate_label(test), this, [](void* kh, CertificateMod* m) { static_cast<KineticHull*>(kh)->certificate_released(m); },
      [&](CertificateMod& m) { init_certificate(m, test, a, b, c, d); }, a, b, c, d);
}

void KineticHull::init_certificate(CertificateMod& m, Test test, int a, int b, int c, int d) {
  const CertificateKey key{static_cast<int>(test), a, b, c, d};
  decltype(certs_)::Probe probe;  // one probe for the lookup and the insert, hashed by m's name (its key's)
  if (Registration* it = certs_.find(key, decltype(certs_)::Hashed{m.name}, probe)) {  // re-created under its key before its predecessor's
    m.value = it->cert->value;  // release: the simulator keeps its certificate (the same outcome)
    it->cert->payload.current = false;
    it->cert = &m;
    if (sim_) register_sim(it->sim, &m);
  } else {
    kinetic::CertificateId sid = 0;
    poly::MachinePolynomial mp;
    if (sim_ && machine_polynomial(test, a, b, c, d, mp)) {
      // The common case: the machine cubic goes straight to the simulator, with no Polynomial
      // built (not even an empty one) per certificate; the simulator builds the exact polynomial
      // from it if its filter leaves a decision open (MotionSimulator::exact_of).
      if (mp.is_zero()) throw InputError(describe(test, a, b, c, d));
      sid = sim_->add(mp);
      m.value = sim_->outcome(sid);
      ++counters_.certificates_created;
    } else {
      CertificatePolynomial P = polynomial(test, a, b, c, d);
      if (P.is_zero()) throw InputError(describe(test, a, b, c, d));
      if (sim_) {
        sid = P.machine ? sim_->add(*P.machine) : sim_->add(P.exact);
        m.value = sim_->outcome(sid);
        ++counters_.certificates_created;
      } else {
        m.value = sign_before_t(P);
      }
    }
    certs_.insert(key, Registration{&m, sid}, probe);  // (nothing inserted or erased since the probe)
    index_certificate(key, true);
    if (sim_) register_sim(sid, &m);
  }
  m.payload.key = key;
  m.payload.current = true;
}

void KineticHull::certificate_released(CertificateMod* m) {
  if (!m->payload.current) return;  // a successor's registration
  const CertificateKey key = m->payload.key;
  const decltype(certs_)::Hashed h{m->name};  // its allocation name: the table's hash of key
  const Registration* it = certs_.find(key, h);
  KMR_CHECK(it != nullptr && it->cert == m, "kinetic hull: a released certificate is not registered");
  if (sim_) {
    sim_->remove(it->sim);
    by_sim_[it->sim] = nullptr;
  }
  certs_.erase(key, h);
  index_certificate(key, false);
}

void KineticHull::face_created(FaceH f, sac::HookId hook) { faces_.assign(rt_.deref(f).v, {f, hook}); }

void KineticHull::face_discarded(const std::array<int, 3>& key, sac::HookId self) {
  const auto* it = faces_.find(key);
  if (it && it->second == self) faces_.erase(key);
}

std::vector<std::array<int, 3>> KineticHull::facets() const {
  std::vector<std::array<int, 3>> out;
  faces_.for_each([&](const std::array<int, 3>&, const std::pair<FaceH, sac::HookId>& reg) {
    const Face& f = rt_.deref(reg.first);
    const Killer& k = *static_cast<const Killer*>(killer_box(f)->last->value);  // the latest write
    if (k.p >= 0) return;
    std::array<int, 3> t = f.v;
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  });
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> KineticHull::vertices() const {
  std::vector<int> v;
  for (const auto& t : facets()) v.insert(v.end(), t.begin(), t.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

void KineticHull::check_simulator_counts() const {
  KMR_CHECK(sim_ != nullptr, "check_simulator_counts on a from-scratch reference");
  const kinetic::SimulatorCounters& c = sim_->counters();
  KMR_CHECK(counters_.certificates_created == c.created,
            "kinetic hull: " + std::to_string(counters_.certificates_created) + " certificates created, the simulator created " +
                std::to_string(c.created));
  KMR_CHECK(static_cast<long long>(live_certificates()) == c.live(),
            "kinetic hull: " + std::to_string(live_certificates()) + " live certificates, the simulator holds " +
                std::to_string(c.live()));
  certs_.for_each([](const CertificateKey& key, const Registration& reg) {
    KMR_CHECK(CertificateHash{}(key) == reg.cert->name,
              "kinetic hull: certificate (" + std::to_string(key[0]) + ", " + std::to_string(key[1]) + ", " +
                  std::to_string(key[2]) + ", " + std::to_string(key[3]) + ", " + std::to_string(key[4]) +
                  ") is hashed " + std::to_string(CertificateHash{}(key)) + ", its traceable is named " +
                  std::to_string(reg.cert->name));
  });
}

std::vector<KineticHull::CertificateKey> KineticHull::certificate_keys() const {
  std::vector<CertificateKey> k;
  certs_.for_each([&](const CertificateKey& key, const Registration&) { k.push_back(key); });
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace kmr::hull
