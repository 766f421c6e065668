#include "cli/formats.hpp"

#include "exact/text_lines.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>

#include "exact/error.hpp"

namespace kmr::cli {

RootsRequest parse_roots_request(const Args& args) {
  RootsRequest r;
  r.bits = static_cast<int>(args.integer("lattice-bits", 10, 0, 4096));
  r.from = exact::Dyadic::parse(args.value("from").value_or("0"));
  r.to = args.value("to") ? exact::Dyadic::parse(*args.value("to")) : exact::Dyadic::pow2(27);
  if (!(r.from < r.to))
    throw InputError("empty window: --from " + r.from.to_decimal() + " is not below --to " + r.to.to_decimal());
  if (args.positional().empty()) throw InputError("no coefficients given (usage: kmr roots -- c0 c1 ... cn)");
  for (const auto& c : args.positional()) r.coefficients.push_back(exact::parse_integer(c));
  return r;
}

namespace {
std::string printable(const std::string& s) {  // NUL and other control bytes shown as \xNN
  std::string out;
  for (unsigned char c : s) {
    if (c < 0x20 || c == 0x7f) {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", c);
      out += b;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}
}  // namespace

double parse_ws_number(const std::string& tok, const std::string& where) {
  const char* b = tok.c_str();
  char* e = nullptr;
  errno = 0;
  double x = std::strtod(b, &e);
  // e must reach the token's end: an embedded NUL byte stops strtod early and is refused too.
  if (e == b || e != b + tok.size()) throw InputError(where + ": '" + printable(tok) + "' is not a number");
  if (!std::isfinite(x)) throw InputError(where + ": '" + tok + "' is not finite");
  if (errno == ERANGE && x == 0) throw InputError(where + ": '" + tok + "' underflows to 0 (nonzero below 2^-1074)");
  return x;
}

namespace {

template <std::size_t D>
wellspaced::Point<D> parse_point(const std::vector<std::string>& toks, std::size_t from, const std::string& where) {
  if (toks.size() - from != D)
    throw InputError(where + ": expected " + std::to_string(D) + " coordinates, got " + std::to_string(toks.size() - from));
  wellspaced::Point<D> p;
  for (std::size_t i = 0; i < D; ++i) {
    p[i] = parse_ws_number(toks[from + i], where);
    if (p[i] < 0 || p[i] > 1) throw InputError(where + ": coordinate '" + toks[from + i] + "' is outside [0,1]");
  }
  return p;
}


}  // namespace

template <std::size_t D>
std::vector<wellspaced::Point<D>> parse_ws_points(std::istream& in, const std::string& name) {
  std::vector<wellspaced::Point<D>> input;
  std::set<wellspaced::Point<D>> seen;
  for (auto& [n, toks] : read_lines(in)) {
    std::string where = name + ":" + std::to_string(n);
    wellspaced::Point<D> p = parse_point<D>(toks, 0, where);
    if (!seen.insert(p).second) throw InputError(where + ": duplicate point");
    input.push_back(p);
  }
  return input;
}

template <std::size_t D>
std::vector<WsUpdate<D>> parse_ws_updates(std::istream& in, const std::string& name,
                                          const std::vector<wellspaced::Point<D>>& input) {
  std::set<wellspaced::Point<D>> current(input.begin(), input.end());  // validate the whole file first
  std::vector<WsUpdate<D>> updates;
  for (auto& [n, toks] : read_lines(in)) {
    std::string where = name + ":" + std::to_string(n);
    if (toks[0] != "+" && toks[0] != "-") throw InputError(where + ": a line must start with '+' or '-'");
    WsUpdate<D> u{toks[0] == "+", parse_point<D>(toks, 1, where), where};
    if (u.insert && !current.insert(u.p).second) throw InputError(where + ": inserting a point that is already in the input");
    if (!u.insert && !current.erase(u.p)) throw InputError(where + ": deleting a point that is not in the input");
    if (current.size() < 2) throw InputError(where + ": fewer than 2 input points would remain");
    updates.push_back(u);
  }
  return updates;
}

template std::vector<wellspaced::Point<2>> parse_ws_points<2>(std::istream&, const std::string&);
template std::vector<wellspaced::Point<3>> parse_ws_points<3>(std::istream&, const std::string&);
template std::vector<wellspaced::Point<4>> parse_ws_points<4>(std::istream&, const std::string&);
template std::vector<WsUpdate<2>> parse_ws_updates<2>(std::istream&, const std::string&, const std::vector<wellspaced::Point<2>>&);
template std::vector<WsUpdate<3>> parse_ws_updates<3>(std::istream&, const std::string&, const std::vector<wellspaced::Point<3>>&);
template std::vector<WsUpdate<4>> parse_ws_updates<4>(std::istream&, const std::string&, const std::vector<wellspaced::Point<4>>&);

// exact::read_text_lines in the (line number, tokens) shape the format parsers use.
std::vector<std::pair<std::size_t, std::vector<std::string>>> read_lines(std::istream& in) {
  std::vector<std::pair<std::size_t, std::vector<std::string>>> out;
  for (exact::TextLine& l : exact::read_text_lines(in)) out.emplace_back(l.number, std::move(l.tokens));
  return out;
}


namespace {
// A decimal integer of a kmesh file, or an error naming its place.
exact::Integer kmesh_integer(const std::string& s, const std::string& where) {
  try {
    return exact::parse_integer(s);
  } catch (const InputError&) {
    throw InputError(where + ": '" + printable(s) + "' is not a decimal integer");
  }
}
}  // namespace

std::vector<KmeshTrajectory> parse_kmesh_points(std::istream& in, const std::string& name) {
  std::vector<KmeshTrajectory> out;
  for (auto& [n, t] : read_lines(in)) {
    std::string where = name + ":" + std::to_string(n);
    if (t.size() != 2 && t.size() != 4)
      throw InputError(where + ": expected 'x y' or 'x y vx vy', got " + std::to_string(t.size()) + " values");
    auto num = [&](const std::string& x) { return kmesh_integer(x, where); };
    out.push_back({num(t[0]), num(t[1]), t.size() == 4 ? num(t[2]) : exact::Integer(0),
                   t.size() == 4 ? num(t[3]) : exact::Integer(0), n});
  }
  if (out.empty()) throw InputError(name + ": no input point");
  return out;
}

exact::Dyadic parse_kmesh_time(const std::string& text, const std::string& where, long long bits) {
  exact::Dyadic t;
  try {
    t = exact::Dyadic::parse(text);
  } catch (const InputError&) {
    throw InputError(where + ": '" + printable(text) + "' is not a dyadic decimal time");
  }
  if (t.sign() < 0) throw InputError(where + ": time " + text + " is negative");
  if (!t.shifted(bits).is_integer())
    throw InputError(where + ": time " + text + " is not a multiple of the lattice step 2^-" + std::to_string(bits));
  return t;
}

std::vector<KmeshUpdate> parse_kmesh_updates(std::istream& in, const std::string& name, long long bits) {
  std::vector<KmeshUpdate> out;
  for (auto& [n, t] : read_lines(in)) {
    std::string where = name + ":" + std::to_string(n);
    if (t.size() != 6 || (t[1] != "+" && t[1] != "-"))
      throw InputError(where + ": expected 'T + x y vx vy' or 'T - x y vx vy'");
    auto num = [&](const std::string& x) { return kmesh_integer(x, where); };
    out.push_back({parse_kmesh_time(t[0], where, bits), t[1] == "+", {num(t[2]), num(t[3]), num(t[4]), num(t[5]), n}, where});
  }
  return out;
}

}  // namespace kmr::cli
