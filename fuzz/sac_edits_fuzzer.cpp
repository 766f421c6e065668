// Fuzz harness: random edit sequences on the self-adjusting list programs (src/sacprograms: map,
// filter, sum, quicksort, mergesort, quickhull; thesis Ch. 1's change propagation, §1.3), judged
// after every propagate() by:
//  * output = the static twin's output on the current input (ListSession::static_output);
//  * output = a reference written here, sharing no code with kmr: 3x+1, the (x & 3) != 0 filter,
//    a wrapping sum, std::sort, and a gift-wrapping hull in __int128 (strict vertices, ccw from the
//    lexicographically smallest point);
//  * trace signature, trace node count and live mod count = those of a from-scratch run on the same
//    input values and element ids (sac::Runtime's guarantee: the updated trace is the one a fresh
//    run builds).
// Input bytes: program (1 byte), initial length 0..15, values, then rounds of 1..3 edits (insert,
// erase, set at a position) each followed by propagate(). Values are small (−8..7: duplicates,
// collinear and coincident points) or, with the high bit of their head byte, large (up to 2^40 for
// map, where 3x+1 must not overflow; full 64-bit for the others; quickhull coordinates < 2^29).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "sacprograms/session.hpp"

namespace {

using kmr::sacprograms::ListSession;
using kmr::sacprograms::Snapshot;

long long px(long long p) { return p >> 32; }
long long py(long long p) { return static_cast<std::int32_t>(static_cast<std::uint32_t>(p & 0xffffffffLL)); }
long long pack(long long x, long long y) {
  return static_cast<long long>((static_cast<unsigned long long>(x) << 32) | (static_cast<unsigned long long>(y) & 0xffffffffULL));
}

// Twice the signed area of (a, b, c), exact in 128 bits.
__int128 turn(long long a, long long b, long long c) {
  __int128 ux = px(b) - px(a), uy = py(b) - py(a), vx = px(c) - px(a), vy = py(c) - py(a);
  return ux * vy - uy * vx;
}
__int128 dist2(long long a, long long b) {
  __int128 dx = px(b) - px(a), dy = py(b) - py(a);
  return dx * dx + dy * dy;
}

// Gift wrapping: from the lexicographically smallest point, repeatedly the point q such that no
// point lies to the right of (cur, q), the farthest such on ties (so collinear points are skipped).
std::vector<long long> wrap_hull(const std::vector<long long>& in) {
  std::vector<long long> pts;
  for (long long p : in)
    if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
  if (pts.size() <= 1) return pts;
  auto lex = [](long long a, long long b) { return px(a) != px(b) ? px(a) < px(b) : py(a) < py(b); };
  long long start = *std::min_element(pts.begin(), pts.end(), lex);
  std::vector<long long> hull{start};
  long long cur = start;
  for (std::size_t guard = 0; guard <= pts.size(); ++guard) {
    long long best = cur;
    for (long long q : pts) {
      if (q == cur) continue;
      if (best == cur) { best = q; continue; }
      __int128 t = turn(cur, best, q);
      if (t < 0 || (t == 0 && dist2(cur, q) > dist2(cur, best))) best = q;
    }
    if (best == start) return hull;
    hull.push_back(best);
    cur = best;
  }
  FUZZ_CHECK(false, "wrap_hull did not close");
  return hull;
}

std::vector<long long> reference(const std::string& name, const std::vector<long long>& in) {
  std::vector<long long> out;
  if (name == "map") {
    for (long long x : in) out.push_back(3 * x + 1);
  } else if (name == "filter") {
    for (long long x : in)
      if ((x & 3) != 0) out.push_back(x);
  } else if (name == "sum") {
    std::uint64_t s = 0;
    for (long long x : in) s += static_cast<std::uint64_t>(x);
    out.push_back(static_cast<long long>(s));
  } else if (name == "quicksort" || name == "mergesort") {
    out = in;
    std::sort(out.begin(), out.end());
  } else if (name == "quickhull") {
    out = wrap_hull(in);
  } else {
    FUZZ_CHECK(false, "unknown program " + name);
  }
  return out;
}

std::string show(const std::vector<long long>& v) {
  std::string s = "[";
  for (long long x : v) {  // separate appends: GCC 12 -Wrestrict false positive on string +
    if (s.size() > 1) s += ' ';
    s += std::to_string(x);
  }
  s += ']';
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  kmr_fuzz::ByteReader in(data, size);
  const auto& programs = kmr::sacprograms::list_programs();
  const auto& program = programs[in.byte() % programs.size()];
  const bool hull = program.name == "quickhull";
  auto value = [&]() -> long long {
    std::uint8_t head = in.byte();
    bool large = head & 0x80;
    auto small = [&](std::uint8_t b) { return static_cast<long long>(b % 16) - 8; };
    auto wide = [&](int bytes) {
      std::uint64_t x = 0;
      for (int j = 0; j < bytes; ++j) x = (x << 8) | in.byte();
      return x;
    };
    if (hull) {
      if (!large) return pack(small(head), small(in.byte()));
      auto coord = [&] { return static_cast<long long>(wide(4) % ((2ULL << 29) - 1)) - ((1LL << 29) - 1); };
      long long x = coord();
      return pack(x, coord());
    }
    if (!large) return small(head);
    if (program.name == "map") return static_cast<long long>(wide(5) % (1ULL << 41)) - (1LL << 40);
    return static_cast<long long>(wide(8));
  };
  std::vector<long long> values;
  for (int n = in.byte() % 16, i = 0; i < n; ++i) values.push_back(value());
  ListSession s(program, values);
  auto judge = [&](const std::string& when) {
    Snapshot a = s.snapshot();
    auto cur = s.values();
    std::string what = program.name + " " + when + " on " + show(cur);
    FUZZ_CHECK(a.output == s.static_output(), what + ": output " + show(a.output) + " differs from the static twin");
    FUZZ_CHECK(a.output == reference(program.name, cur), what + ": output " + show(a.output) + " differs from the reference");
    Snapshot b = kmr::sacprograms::from_scratch(program, cur, s.ids());
    FUZZ_CHECK(a.signature == b.signature, what + ": trace signature differs from a from-scratch run");
    FUZZ_CHECK(a.trace_nodes == b.trace_nodes && a.live_mods == b.live_mods,
               what + ": trace size differs from a from-scratch run");
  };
  judge("initial run");
  for (int round = 0; round < 12 && !in.empty(); ++round) {
    for (int e = 0, edits = 1 + in.byte() % 3; e < edits; ++e) {
      std::size_t n = s.values().size();
      int kind = in.byte() % 3;
      std::size_t pos = in.byte();
      if (n == 0 || kind == 0) s.insert(pos % (n + 1), value());
      else if (kind == 1) s.erase(pos % n);
      else s.set(pos % n, value());
    }
    s.propagate();
    judge("after round " + std::to_string(round));
  }
  return 0;
}
