// Uses two installed layers: a well-spaced superset (Ch. 3) and kinetic sorting on the lattice (§2.1).
// Prints "wellspaced ok <|M|>" when the output contains the input and is well-spaced (exact check),
// and "kinetic ok <events>" when two points that cross once give exactly one event.
#include <cstdio>

#include "kinetic/kinetic_sort.hpp"
#include "wellspaced/well_spaced_set.hpp"
#include "wsjudge/brute_force.hpp"

int main() {
  using namespace kmr::wellspaced;
  std::vector<Point<2>> in = {{0.1, 0.1}, {0.9, 0.2}, {0.5, 0.8}, {0.3, 0.31}};
  WellSpacedSet<2> ws(in);
  std::vector<Point<2>> M;
  std::size_t inputs = 0;
  for (const auto& v : ws.vertices()) {
    M.push_back(v.x);
    inputs += !v.is_steiner;
  }
  if (inputs != in.size() || !kmr::wsjudge::is_well_spaced<2>(M, ws.params().rho)) return 1;
  std::printf("wellspaced ok %zu\n", M.size());
  // x0 = 0 moving right at speed 1, x1 = 1 standing still: one swap at t = 1.
  using kmr::kinetic::Polynomial;
  kmr::kinetic::MotionSimulator sim(4, kmr::exact::Dyadic(4));
  kmr::kinetic::KineticSort sort({Polynomial(std::vector<kmr::exact::Integer>{0, 1}), Polynomial(std::vector<kmr::exact::Integer>{1})}, sim);
  sort.run_until(kmr::exact::Dyadic(2));
  if (sort.swaps() != 1 || sort.order() != std::vector<std::size_t>{1, 0}) return 1;
  std::printf("kinetic ok %lld\n", sort.swaps());
  return 0;
}
