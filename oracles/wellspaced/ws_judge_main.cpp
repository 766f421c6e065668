// kmr_oracle_ws_judge: judges a point-set file (e.g. `kmr wellspaced` stdout) with the exact CGAL
// oracle: ρ-well-spacedness (T3.3.4) and, given the input, size conformity (Lemma 3.3.3).
// Usage: kmr_oracle_ws_judge --dim D (--rho R | --rho-squared Q) [--input IN] OUTPUT
//   Files: one point per line, D coordinates (decimal: read as doubles, converted exactly; hex
//   floats "0x1.8p-1" of any length: read exactly, as `kmr wellspaced` prints coordinates finer
//   than doubles), optionally
//   followed by more columns (ignored, e.g. the 0/1 Steiner flag); '#' starts a comment.
// Prints one line per verdict; exit 0 if all hold, 1 if one fails, 2 on bad input.
#include <cmath>
#include <cstdio>
#include <optional>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "exact/error.hpp"
#include "ws_oracle.hpp"

namespace ws = kmr::oracle::ws;
using kmr::exact::Dyadic;

namespace {

template <std::size_t D>
std::vector<ws::XPoint<D>> read(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw kmr::InputError("cannot open " + path);
  std::vector<ws::XPoint<D>> pts;
  std::string line;
  for (std::size_t no = 1; std::getline(f, line); ++no) {
    if (auto h = line.find('#'); h != std::string::npos) line.erase(h);
    std::istringstream in(line);
    ws::XPoint<D> p;
    std::size_t k = 0;
    std::string tok;
    while (k < D && in >> tok) {
      if (auto x = ws::parse_hex_exact(tok)) {
        p[k++] = *x;
        continue;
      }
      char* end = nullptr;
      const double d = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != '\0' || !std::isfinite(d))
        throw kmr::InputError(path + ":" + std::to_string(no) + ": not a number: " + tok);
      p[k++] = Dyadic::from_double(d);
    }
    if (k == 0) continue;
    if (k < D) throw kmr::InputError(path + ":" + std::to_string(no) + ": fewer than D coordinates");
    pts.push_back(p);
  }
  return pts;
}

template <std::size_t D>
int run(const ws::Rho& rho, const std::string& input, const std::string& output) {
  auto M = read<D>(output);
  auto w = ws::judge_well_spaced<D>(M, rho);
  std::printf("well-spaced %s: %zu vertices, %zu violations, max R/NN = %.6f at vertex %zu (rho = %.6f)\n",
              w.ok ? "yes" : "NO", w.vertices, w.violations, w.worst_ratio, w.worst_vertex, rho.approx());
  bool ok = w.ok;
  if (!input.empty()) {
    auto s = ws::judge_size_conforming<D>(M, read<D>(input), rho);
    std::printf("size-conforming %s: %zu violations, max lfs/NN = %.6f at vertex %zu (c = %.6f)\n",
                s.ok ? "yes" : "NO", s.violations, s.worst_ratio, s.worst_vertex, s.c);
    ok = ok && s.ok;
  }
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    int dim = 0;
    ws::Rho rho;
    bool have_rho = false;
    std::string input, output;
    for (int i = 1; i < argc; ++i) {
      std::string a = argv[i];
      auto next = [&]() -> std::string {
        if (i + 1 >= argc) throw kmr::InputError(a + " needs a value");
        return argv[++i];
      };
      if (a == "--dim") dim = std::atoi(next().c_str());
      else if (a == "--rho") rho = ws::Rho::exactly(Dyadic::from_double(std::strtod(next().c_str(), nullptr))), have_rho = true;
      else if (a == "--rho-squared") rho = ws::Rho::sqrt_of(Dyadic::from_double(std::strtod(next().c_str(), nullptr))), have_rho = true;
      else if (a == "--input") input = next();
      else if (a == "--help") {
        std::puts("usage: kmr_oracle_ws_judge --dim D (--rho R | --rho-squared Q) [--input IN] OUTPUT");
        return 0;
      } else output = a;
    }
    if (!have_rho || output.empty()) throw kmr::InputError("need --rho and an OUTPUT file (see --help)");
    switch (dim) {
      case 2: return run<2>(rho, input, output);
      case 3: return run<3>(rho, input, output);
      case 4: return run<4>(rho, input, output);
      default: throw kmr::InputError("--dim must be 2, 3 or 4");
    }
  } catch (const kmr::InputError& e) {
    std::fprintf(stderr, "kmr_oracle_ws_judge: %s\n", e.what());
    return 2;
  }
}
