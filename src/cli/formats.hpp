#pragma once
// The input formats of the kmr commands, parsed by exactly the code the commands run (the fuzz
// harnesses in fuzz/ call these same entry points). What each format accepts: spec/formats.md.
// Guarantees: bad input throws kmr::InputError naming the place ("file:line", the option) and the
// text; nothing is returned unless the whole input is valid.
#include <cstddef>
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "cli/args.hpp"
#include "exact/dyadic.hpp"
#include "exact/integer.hpp"
#include "wellspaced/well_spaced_set.hpp"

namespace kmr::cli {

// The line formats' tokenizer (exact/text_lines.hpp): the non-blank lines of `in` (after '#'
// comments are cut) as (line number, whitespace-separated tokens).
std::vector<std::pair<std::size_t, std::vector<std::string>>> read_lines(std::istream& in);

// `kmr roots [--lattice-bits B] [--from T0] [--to T1] -- c0 ... cn`, all but the zero-polynomial check.
struct RootsRequest {
  int bits = 10;
  exact::Dyadic from, to;
  std::vector<exact::Integer> coefficients;
};
RootsRequest parse_roots_request(const Args& args);

// A decimal number for the wellspaced formats and options (strtod; finite).
double parse_ws_number(const std::string& tok, const std::string& where);

// `kmr wellspaced` INPUT: one point per line, D coordinates in [0,1], '#' comments, no duplicates.
template <std::size_t D>
std::vector<wellspaced::Point<D>> parse_ws_points(std::istream& in, const std::string& name);

// `kmr wellspaced --updates FILE`: '+ x1 .. xD' / '- x1 .. xD', checked in order against the input
// set (no inserting a present point, no deleting an absent one, ≥ 2 points remain).
template <std::size_t D>
struct WsUpdate {
  bool insert;
  wellspaced::Point<D> p;
  std::string where;  // "file:line"
};
template <std::size_t D>
std::vector<WsUpdate<D>> parse_ws_updates(std::istream& in, const std::string& name,
                                          const std::vector<wellspaced::Point<D>>& input);

// `kmr kmesh` FILE: one trajectory per line, 'x y vx vy' or 'x y' (decimal integers of any size;
// vx = vy = 0 when omitted), at least one. Identical or colliding trajectories are the command's check.
struct KmeshTrajectory {
  exact::Integer x, y, vx, vy;
  std::size_t line;
};
std::vector<KmeshTrajectory> parse_kmesh_points(std::istream& in, const std::string& name);

// A `kmr kmesh` time (--until, update times): a dyadic decimal T ≥ 0 that is a multiple of 2^-bits.
exact::Dyadic parse_kmesh_time(const std::string& text, const std::string& where, long long bits);

// `kmr kmesh --updates FILE`: 'T + x y vx vy' (insert) / 'T - x y vx vy' (delete), in file order
// (membership and the order of times are the command's checks).
struct KmeshUpdate {
  exact::Dyadic t;
  bool insert;
  KmeshTrajectory p;
  std::string where;  // "file:line"
};
std::vector<KmeshUpdate> parse_kmesh_updates(std::istream& in, const std::string& name, long long bits);

}  // namespace kmr::cli
