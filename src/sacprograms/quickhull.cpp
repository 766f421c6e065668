// 2D quickhull (ΔML / CEAL benchmark set) over exact integer predicates, self-adjusting and static.
#include <algorithm>

#include "geometry/predicates.hpp"
#include "sacprograms/internal.hpp"

namespace kmr::sacprograms {

long long encode_point(long long x, long long y) {
  if (x <= -kCoordLimit || x >= kCoordLimit || y <= -kCoordLimit || y >= kCoordLimit)
    throw InputError("quickhull: coordinate (" + std::to_string(x) + ", " + std::to_string(y) +
                     ") outside (-2^29, 2^29)");
  return static_cast<long long>((static_cast<unsigned long long>(x) << 32) | (static_cast<unsigned long long>(y) & 0xffffffffULL));
}
long long point_x(long long p) { return p >> 32; }
long long point_y(long long p) { return static_cast<long long>(static_cast<std::int32_t>(p & 0xffffffffLL)); }

namespace {
using P2 = geometry::Point<2, long long>;
P2 pt(long long p) { return P2{point_x(p), point_y(p)}; }
// Exact: coordinates below 2^29 keep every product below 2^61 (no overflow in long long).
long long orient(long long a, long long b, long long c) { return geometry::orientation_value<long long>(pt(a), pt(b), pt(c)); }
bool lex_less(long long p, long long q) { return std::make_pair(point_x(p), point_y(p)) < std::make_pair(point_x(q), point_y(q)); }

// The farthest point right of a→b: largest −orient, then largest projection on b−a (the extreme of
// a support segment, so it is a strict hull vertex), then lexicographically smallest.
long long farther(std::pair<long long, long long> ab, long long p, long long q) {
  auto [a, b] = ab;
  long long dp = -orient(a, b, p), dq = -orient(a, b, q);
  if (dp != dq) return dp > dq ? p : q;
  long long ex = point_x(b) - point_x(a), ey = point_y(b) - point_y(a);
  long long pp = (point_x(p) - point_x(a)) * ex + (point_y(p) - point_y(a)) * ey;
  long long pq = (point_x(q) - point_x(a)) * ex + (point_y(q) - point_y(a)) * ey;
  if (pp != pq) return pp > pq ? p : q;
  return lex_less(q, p) ? q : p;
}

using Ctx = std::pair<long long, long long>;
struct MinOp {
  using Ctx = long long;
  static constexpr Label kHalf{"qh.min.half"}, kAbsorb{"qh.min.absorb"}, kReduce{"qh.min.reduce"};
  static long long combine(Ctx, long long a, long long b) { return lex_less(b, a) ? b : a; }
  static long long identity(Ctx) { return 0; }
};
struct MaxOp {
  using Ctx = long long;
  static constexpr Label kHalf{"qh.max.half"}, kAbsorb{"qh.max.absorb"}, kReduce{"qh.max.reduce"};
  static long long combine(Ctx, long long a, long long b) { return lex_less(a, b) ? b : a; }
  static long long identity(Ctx) { return 0; }
};
struct FarOp {
  using Ctx = std::pair<long long, long long>;
  static constexpr Label kHalf{"qh.far.half"}, kAbsorb{"qh.far.absorb"}, kReduce{"qh.far.reduce"};
  static long long combine(Ctx ab, long long p, long long q) { return farther(ab, p, q); }
  static long long identity(Ctx) { return 0; }
};
struct RightOf {  // strictly right of the directed line a→b
  using Ctx = std::pair<long long, long long>;
  static constexpr Label kFilter{"qh.filter"}, kCell{"qh.filter.cell"};
  static constexpr bool kByValue = false;  // points repeat: keys must stay unique
  static bool keep(Ctx ab, long long p) { return orient(ab.first, ab.second, p) < 0; }
};

constexpr Label kSide{"qh.side"}, kFar{"qh.far"}, kL1{"qh.l1"}, kL2{"qh.l2"}, kMid{"qh.mid"}, kMidTail{"qh.midtail"},
    kMin{"qh.min"}, kMax{"qh.max"}, kLow{"qh.lower"}, kUp{"qh.upper"}, kNil{"qh.nil"}, kBCell{"qh.b"},
    kBTail{"qh.btail"}, kATail{"qh.atail"}, kHead{"qh.head"}, kOut{"qh.out"};

// side(l, a, b, rest): the hull vertices strictly right of a→b, from a to b, followed by rest.
Unit side(Runtime* rt, List* l, long long a, long long b, List* rest, List* dest) {
  rt->memo_read<void>(kSide, std::make_tuple(l, a, b, rest, dest), l, [rt, l, a, b, rest, dest](const Cell& c) {
    if (c.nil) {
      rt->read(rest, [rt, dest](const Cell& v) { rt->write(dest, v); });
      return;
    }
    Mod<long long>* far = rt->alloc<long long>(kFar, a, b);
    Reduce<FarOp>::run(rt, l, Ctx{a, b}, 0, far);
    rt->read(far, [rt, l, a, b, rest, dest](long long f) {
      List* l1 = rt->alloc<Cell>(kL1, a, f);
      List* l2 = rt->alloc<Cell>(kL2, f, b);
      Filter<RightOf>::into(rt, l, Ctx{a, f}, l1);
      Filter<RightOf>::into(rt, l, Ctx{f, b}, l2);
      List* mid = rt->alloc<Cell>(kMid, a, b);
      List* midtail = rt->alloc<Cell>(kMidTail, a, b);
      side(rt, l2, f, b, rest, midtail);
      rt->write(mid, Cell{false, f, midtail});
      side(rt, l1, a, f, mid, dest);
    });
  });
  return Unit{};
}
}  // namespace

Root* sa_quickhull(Runtime& rt, Root* in) {
  return run_list_program(rt, in, kOut, [](Runtime* r, List* l) {
    List* head = r->alloc<Cell>(kHead);
    r->read(l, [r, l, head](const Cell& c) {
      if (c.nil) {
        r->write(head, Cell{});
        return;
      }
      Mod<long long>* mn = r->alloc<long long>(kMin);
      Mod<long long>* mx = r->alloc<long long>(kMax);
      Reduce<MinOp>::run(r, l, 0, 0, mn);
      Reduce<MaxOp>::run(r, l, 0, 0, mx);
      r->read(mn, [r, l, head, mx](long long a) {
        r->read(mx, [r, l, head, a](long long b) {
          List* nil = r->alloc<Cell>(kNil);
          r->write(nil, Cell{});
          if (a == b) {
            r->write(head, Cell{false, a, nil});
            return;
          }
          List* lower = r->alloc<Cell>(kLow);
          List* upper = r->alloc<Cell>(kUp);
          Filter<RightOf>::into(r, l, Ctx{a, b}, lower);
          Filter<RightOf>::into(r, l, Ctx{b, a}, upper);
          List* btail = r->alloc<Cell>(kBTail);
          side(r, upper, b, a, nil, btail);
          List* bcell = r->alloc<Cell>(kBCell);
          r->write(bcell, Cell{false, b, btail});
          List* atail = r->alloc<Cell>(kATail);
          side(r, lower, a, b, bcell, atail);
          r->write(head, Cell{false, a, atail});
        });
      });
    });
    return head;
  });
}

// ---- the static twin: the same algorithm with its own arithmetic (no code shared with the
// self-adjusting program's orient/farther, so a bug in one is not mirrored in the other) ----------
namespace twin {
struct Pt {
  long long x, y;
};
Pt at(long long p) { return Pt{p >> 32, static_cast<std::int32_t>(static_cast<std::uint32_t>(p))}; }
// Twice the signed area of (a, b, c), as the cross product (b − a) × (c − a); > 0 counterclockwise.
// Exact in long long: |coordinates| < 2^29, so differences < 2^30 and products < 2^61.
long long cross(long long a, long long b, long long c) {
  Pt A = at(a), B = at(b), C = at(c);
  return (B.x - A.x) * (C.y - A.y) - (B.y - A.y) * (C.x - A.x);
}
bool before(long long p, long long q) {  // lexicographic (x, then y)
  Pt P = at(p), Q = at(q);
  return P.x != Q.x ? P.x < Q.x : P.y < Q.y;
}
// Farthest right of a→b: the larger distance, then the larger projection on b − a, then the
// lexicographically smaller point (the same tie-breaking rule, derived separately).
long long farther(long long a, long long b, long long p, long long q) {
  long long dp = cross(a, b, p), dq = cross(a, b, q);  // right of a→b: negative
  if (dp != dq) return dp < dq ? p : q;
  Pt A = at(a), B = at(b), P = at(p), Q = at(q);
  long long ex = B.x - A.x, ey = B.y - A.y;
  long long sp = (P.x - A.x) * ex + (P.y - A.y) * ey, sq = (Q.x - A.x) * ex + (Q.y - A.y) * ey;
  if (sp != sq) return sp > sq ? p : q;
  return before(q, p) ? q : p;
}
std::vector<long long> right_of(const std::vector<long long>& s, long long a, long long b) {
  std::vector<long long> r;
  for (long long p : s)
    if (cross(a, b, p) < 0) r.push_back(p);
  return r;
}
void side(const std::vector<long long>& s, long long a, long long b, std::vector<long long>& out) {
  if (s.empty()) return;
  long long f = s[0];
  for (std::size_t i = 1; i < s.size(); ++i) f = farther(a, b, f, s[i]);
  std::vector<long long> s1 = right_of(s, a, f), s2 = right_of(s, f, b);
  side(s1, a, f, out);
  out.push_back(f);
  side(s2, f, b, out);
}
}  // namespace twin

std::vector<long long> static_quickhull(const SCell* l) {
  std::vector<long long> pts;
  for (; l; l = l->tail) pts.push_back(l->head);
  if (pts.empty()) return {};
  long long a = pts[0], b = pts[0];
  for (long long p : pts) {
    if (twin::before(p, a)) a = p;
    if (twin::before(b, p)) b = p;
  }
  if (a == b) return {a};
  std::vector<long long> lower = twin::right_of(pts, a, b), upper = twin::right_of(pts, b, a), out{a};
  twin::side(lower, a, b, out);
  out.push_back(b);
  twin::side(upper, b, a, out);
  return out;
}

}  // namespace kmr::sacprograms
