// Claims measured from the computation graph (Lemmas 3.3.6, 3.3.15) and the lower-bound input of
// §3.4.2 (Theorem 3.4.5), with the helpers of wellspaced/measure.hpp they rely on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>
#include <string>
#include <tuple>
#include <random>
#include <set>

#include "wellspaced/generators.hpp"
#include "wellspaced/measure.hpp"
#include "wellspaced/well_spaced_set.hpp"

using namespace kmr::wellspaced;
using kmr::exact::Dyadic;

namespace {

template <std::size_t D>
void rank_case(gen::Kind k, std::size_t n, std::uint64_t seed, Params p = {}) {
  auto input = gen::points<D>(k, n, seed);
  WellSpacedSet<D> ws(input, p);
  RankRatios R = rank_ratios<D>(ws);
  std::string what = std::string(gen::name(k)) + " D=" + std::to_string(D) + " rho=" + std::to_string(p.rho);
  EXPECT_EQ(R.ops, ws.stats().ops) << what;  // every operation node was read
  EXPECT_EQ(R.above, 0u) << what;
  EXPECT_GT(R.lo, 0) << what;
  EXPECT_LT(R.hi, p.rho) << what;
}

}  // namespace

// Lemma 3.3.6 (upper side, exact): an operation scheduled at rank r got r = ⌊log_ρ d⌋ from a distance
// d ≥ NN_t(v) ≥ NN_∞(v), so NN_∞(v) < ρ^{r+1}.
TEST(WellspacedMeasure, L3_3_6_ScheduledOperationsHaveNNBelowNextRank) {
  RecordProperty("claim", "L3.3.6");
  for (auto k : {gen::Kind::uniform, gen::Kind::clustered, gen::Kind::grid, gen::Kind::close_pair, gen::Kind::boundary})
    rank_case<2>(k, 40, 11);
  rank_case<2>(gen::Kind::uniform, 30, 12, Params{2.0, 4.0});
  rank_case<2>(gen::Kind::uniform, 30, 12, Params{1.25, 2.5});
  rank_case<3>(gen::Kind::uniform, 8, 13);
}

// The structured graph against its printed form: an oracle that parses canonical_graph() (names
// "(x1 .. xD @t)", coordinates in %a) and shares no code with computation_graph().
namespace {
struct ParsedOp {
  std::string name;
  Point<2> v{};
  int rank = 0;
  bool fill = false, input_dispatch = false;
};
bool parse_name(const std::string& name, ParsedOp& op) {
  auto at = name.find(" @");
  if (name.size() < 4 || name.front() != '(' || name.back() != ')' || at == std::string::npos) return false;
  std::string t = name.substr(at + 2, name.size() - at - 3);
  if (t == "0") return false;
  const char* p = name.c_str() + 1;
  for (std::size_t i = 0; i < 2; ++i) {
    char* end = nullptr;
    op.v[i] = std::strtod(p, &end);
    if (end == p) return false;
    p = end;
  }
  op.name = name;
  op.rank = std::stoi(t);
  op.fill = t.find(",F") != std::string::npos;
  return true;
}
std::vector<ParsedOp> parsed_operations(const std::vector<std::string>& canonical) {
  std::set<std::string> from_origin;
  for (const auto& l : canonical)
    if (l.rfind("E (", 0) == 0 && l.find(" @0) -> ") != std::string::npos) from_origin.insert(l.substr(l.find(" -> ") + 4));
  std::vector<ParsedOp> out;
  for (const auto& l : canonical)
    if (l.rfind("O (", 0) == 0) {
      ParsedOp op;
      if (!parse_name(l.substr(2, l.find(')') - 1), op)) continue;
      op.input_dispatch = from_origin.count(op.name) > 0;
      out.push_back(op);
    }
  return out;
}
// The vertices of the operations named in lines of a missing from b.
std::set<Point<2>> parsed_changed(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  std::vector<std::string> gone;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(gone));
  std::set<Point<2>> out;
  for (const auto& line : gone)
    for (std::size_t p = line.find('('); p != std::string::npos; p = line.find('(', p + 1)) {
      std::size_t e = line.find(')', p);
      ParsedOp op;
      if (e != std::string::npos && parse_name(line.substr(p, e - p + 1), op)) out.insert(op.v);
    }
  return out;
}
}  // namespace

TEST(WellspacedMeasure, StructuredGraphEqualsTheCanonicalGraph) {
  auto input = gen::points<2>(gen::Kind::uniform, 20, 14);
  WellSpacedSet<2> ws(input);
  auto ops = ws.computation_graph();
  auto parsed = parsed_operations(ws.canonical_graph());
  ASSERT_EQ(ops.size(), ws.stats().ops);
  ASSERT_EQ(ops.size(), parsed.size());
  std::set<Point<2>> M, dispatched;
  for (const auto& v : ws.vertices()) M.insert(v.x);
  std::size_t inputs = 0, edges = 0;
  std::map<std::tuple<Point<2>, int, bool>, const ParsedOp*> by_key;
  for (const auto& p : parsed) by_key[{p.v, p.rank, p.fill}] = &p;
  for (const auto& op : ops) {
    auto it = by_key.find({op.v, op.rank, op.fill});
    const ParsedOp* p = it == by_key.end() ? nullptr : it->second;
    ASSERT_TRUE(p) << "no printed operation for a structured one";
    EXPECT_EQ(op.input_dispatch, p->input_dispatch) << p->name;
    EXPECT_TRUE(M.count(op.v)) << p->name;
    EXPECT_GE(op.rank, ws.stats().min_rank);
    EXPECT_LE(op.rank, ws.stats().max_rank);
    if (op.input_dispatch) {
      ++inputs;
      EXPECT_FALSE(op.fill) << p->name;
      EXPECT_TRUE(std::binary_search(input.begin(), input.end(), op.v)) << p->name;
    }
    if (!op.fill) {
      EXPECT_TRUE(dispatched.insert(op.v).second) << "two dispatches of " << p->name;  // one per vertex
    }
    edges += op.targets.size() + op.reads.size() + op.steiners.size() + op.input_dispatch;
  }
  EXPECT_EQ(inputs, input.size());
  EXPECT_EQ(dispatched, M);
  std::size_t printed_edges = 0;
  for (const auto& l : ws.canonical_graph()) printed_edges += l[0] == 'E' || l[0] == 'R' || l[0] == 'W';
  EXPECT_EQ(edges, printed_edges);
}

// Lemma 3.3.15's M̂ and M̂′ from the structured graphs equal those from the printed ones, over
// insertions and deletions near and far from input vertices.
TEST(WellspacedMeasure, L3_3_15_ChangedOperationsEqualTheCanonicalGraphDifference) {
  RecordProperty("claim", "L3.3.15");
  auto input = gen::points<2>(gen::Kind::uniform, 30, 17);
  WellSpacedSet<2> ws(input);
  std::mt19937_64 rng(17);
  std::size_t nonempty = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const auto& b = input[rng() % input.size()];
    Point<2> q{b[0] + (b[0] < 0.5 ? 1 : -1) * std::ldexp(1.0, -8 - 4 * trial), b[1]};
    auto G = ws.computation_graph();
    auto C = ws.canonical_graph();
    ws.insert(q);
    auto G2 = ws.computation_graph();
    auto C2 = ws.canonical_graph();
    ws.erase(q);
    for (auto [a, bb, ca, cb] : {std::tuple{&G, &G2, &C, &C2}, std::tuple{&G2, &G, &C2, &C}}) {
      auto mine = vertices_of_changed_operations<2>(*a, *bb);
      EXPECT_EQ(mine, parsed_changed(*ca, *cb)) << "trial " << trial;
      nonempty += !mine.empty();
    }
  }
  EXPECT_EQ(nonempty, 12u);
}

TEST(WellspacedMeasure, BelowNextRankIsExact) {
  // ρ = 1.5, r = 1: NN < ρ² = 2.25 ⇔ NN² < 5.0625
  EXPECT_FALSE(below_next_rank(Dyadic::from_double(5.0625), 1.5, 1));
  EXPECT_TRUE(below_next_rank(Dyadic::from_double(5.0625 - std::ldexp(1.0, -40)), 1.5, 1));
  // ρ = 1.5, r = -2: NN < ρ^{-1} ⇔ NN²·2.25 < 1
  EXPECT_TRUE(below_next_rank(Dyadic::from_double(0.444), 1.5, -2));
  EXPECT_FALSE(below_next_rank(Dyadic::from_double(0.4445), 1.5, -2));
  // ρ = 2, r = -31: NN < 2^-30 exactly
  EXPECT_FALSE(below_next_rank(Dyadic::pow2(-60), 2.0, -31));
  EXPECT_TRUE(below_next_rank(Dyadic::pow2(-60) - Dyadic::pow2(-120), 2.0, -31));
}

TEST(WellspacedMeasure, NearestNeighborDistancesEqualBruteForce) {
  for (auto k : {gen::Kind::uniform, gen::Kind::grid, gen::Kind::close_pair, gen::Kind::line}) {
    auto P = gen::points<2>(k, 60, 15);
    auto nn = nearest_neighbor_dist2<2>(P);
    ASSERT_EQ(nn.size(), P.size());
    for (const auto& p : P) {
      std::optional<Dyadic> best;
      for (const auto& q : P)
        if (q != p && (!best || dist2_exact<2>(p, q) < *best)) best = dist2_exact<2>(p, q);
      EXPECT_EQ(nn.at(p), *best) << gen::name(k);
    }
  }
}

// Lemma 3.3.15's measurement: identical graphs affect nothing; an insertion affects v̂ itself (its
// dispatch is fresh) at ratio 0, and every affected vertex has a finite ratio.
TEST(WellspacedMeasure, L3_3_15_AffectedVerticesOfAnInsertion) {
  RecordProperty("claim", "L3.3.15");
  auto input = gen::points<2>(gen::Kind::uniform, 16, 16);
  WellSpacedSet<2> ws(input);
  auto G = ws.computation_graph();
  auto M = ws.vertices();
  EXPECT_EQ(affected_ratio<2>(G, M, G, M, input[0]).vertices, 0u);
  Point<2> q{input[0][0] + (input[0][0] < 0.5 ? 1 : -1) * std::ldexp(1.0, -20), input[0][1]};
  ws.insert(q);
  AffectedRatio A = affected_ratio<2>(G, M, ws.computation_graph(), ws.vertices(), q);
  EXPECT_GT(A.vertices, 20u);  // rings around v̂ (Lemma 3.4.4)
  EXPECT_GT(A.max_ratio, 0);
  EXPECT_TRUE(std::isfinite(A.max_ratio));
}

// §3.4.2's tiled gadgets: counts, domain, dyadic exactness, and each dynamic vertex at distance
// exactly 2^-k from its gadget's centre, which is its nearest input vertex.
TEST(WellspacedGenerators, T3_4_5_GadgetTiling) {
  RecordProperty("claim", "T3.4.5");
  auto check = [](auto G, std::size_t D, int j, int k, long g) {
    long tiles = 1L << (j * D), lattice = std::lround(std::pow(double((1L << j) * g + 1), double(D))),
         inner = std::lround(std::pow(double((1L << j) * (g - 1)), double(D)));
    EXPECT_EQ(G.dynamic.size(), std::size_t(tiles));
    EXPECT_EQ(G.input.size(), std::size_t(lattice - inner + tiles));
    std::set<typename decltype(G.input)::value_type> in(G.input.begin(), G.input.end());
    EXPECT_EQ(in.size(), G.input.size());
    for (const auto& p : G.input)
      for (double x : p) EXPECT_TRUE(x >= 0 && x <= 1);
    for (const auto& x : G.dynamic) {
      EXPECT_FALSE(in.count(x));
      auto c = x;
      c[0] -= std::ldexp(1.0, -k);  // exact: both are multiples of 2^-k in [0,1]
      EXPECT_TRUE(in.count(c));
      for (const auto& p : G.input) {
        double d = 0;
        for (std::size_t i = 0; i < D; ++i) d += (p[i] - x[i]) * (p[i] - x[i]);
        if (p != c) {
          EXPECT_GT(d, std::ldexp(1.0, -2 * k));
        }
      }
    }
  };
  for (int j : {0, 1, 2}) check(gen::gadget_tiling<2>(j, 10), 2, j, 10, 4);
  check(gen::gadget_tiling<2>(1, 30, 3), 2, 1, 30, 3);
  check(gen::gadget_tiling<3>(1, 12), 3, 1, 12, 4);
}
