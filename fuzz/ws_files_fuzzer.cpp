// Fuzz harness (f): the `kmr wellspaced` INPUT and --updates formats, through the CLI's own entry
// points kmr::cli::parse_ws_points / parse_ws_updates (src/cli/formats.hpp). The first byte picks
// D ∈ {2, 3, 4}; the rest is the point file, then (after a line "%%") the update file. Checks:
//  * only kmr::InputError escapes, and its message names the file and line ("pts.txt:N"/"upd.txt:N");
//  * an accepted point file: every coordinate finite and in [0,1], no two points equal, as many
//    points as the harness counts non-blank, non-comment lines (its own line splitter);
//  * accepted updates replayed on a std::set in the harness are all legal (no inserting a present
//    point, no deleting an absent one, ≥ 2 points after each);
//  * round trip: printing with %.17g and parsing again gives the same points and updates.
#include <cstdio>
#include <set>
#include <sstream>
#include <string>

#include "cli/formats.hpp"
#include "exact/error.hpp"
#include "fuzz_common.hpp"

namespace {

std::size_t content_lines(const std::string& text) {  // lines with a token before any '#'
  std::size_t n = 0;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream ss(line);
    std::string t;
    if (ss >> t) ++n;
  }
  return n;
}

template <std::size_t D>
std::string print(const kmr::wellspaced::Point<D>& p) {
  std::string s;
  char b[40];
  for (double x : p) std::snprintf(b, sizeof b, " %.17g", x), s += b;
  return s;
}

template <std::size_t D>
void check(const std::string& pts, const std::string& upd, bool with_updates) {
  using kmr::wellspaced::Point;
  std::vector<Point<D>> points;
  std::istringstream pin(pts);
  try {
    points = kmr::cli::parse_ws_points<D>(pin, "pts.txt");
  } catch (const kmr::InputError& e) {
    FUZZ_CHECK(std::string(e.what()).rfind("pts.txt:", 0) == 0, std::string("message: ") + e.what());
    return;
  }
  FUZZ_CHECK(points.size() == content_lines(pts), "point count");
  std::set<Point<D>> set;
  std::string again;
  for (const auto& p : points) {
    for (double x : p) FUZZ_CHECK(x >= 0 && x <= 1, "coordinate outside [0,1]:" + print<D>(p));
    FUZZ_CHECK(set.insert(p).second, "duplicate accepted:" + print<D>(p));
    again += print<D>(p);
    again += '\n';
  }
  std::istringstream ain(again);
  FUZZ_CHECK(kmr::cli::parse_ws_points<D>(ain, "again.txt") == points, "round trip:\n" + again);
  if (!with_updates) return;
  std::vector<kmr::cli::WsUpdate<D>> updates;
  std::istringstream uin(upd);
  try {
    updates = kmr::cli::parse_ws_updates<D>(uin, "upd.txt", points);
  } catch (const kmr::InputError& e) {
    FUZZ_CHECK(std::string(e.what()).rfind("upd.txt:", 0) == 0, std::string("message: ") + e.what());
    return;
  }
  FUZZ_CHECK(updates.size() == content_lines(upd), "update count");
  std::string uagain;
  for (const auto& u : updates) {
    FUZZ_CHECK(u.insert ? set.insert(u.p).second : set.erase(u.p) == 1, "illegal update accepted:" + print<D>(u.p));
    FUZZ_CHECK(set.size() >= 2, "fewer than 2 points accepted");
    uagain += u.insert ? '+' : '-';  // separate appends: GCC 12 -Wrestrict false positive on string +
    uagain += print<D>(u.p);
    uagain += '\n';
  }
  std::istringstream uain(uagain);
  auto re = kmr::cli::parse_ws_updates<D>(uain, "again.txt", points);
  FUZZ_CHECK(re.size() == updates.size(), "update round trip");
  for (std::size_t i = 0; i < re.size(); ++i)
    FUZZ_CHECK(re[i].insert == updates[i].insert && re[i].p == updates[i].p, "update round trip:\n" + uagain);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > 8192) return 0;
  std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::size_t sep = text.find("\n%%\n");
  bool with_updates = sep != std::string::npos;
  std::string pts = with_updates ? text.substr(0, sep + 1) : text, upd = with_updates ? text.substr(sep + 4) : "";
  switch (data[0] % 3) {
    case 0: check<2>(pts, upd, with_updates); break;
    case 1: check<3>(pts, upd, with_updates); break;
    default: check<4>(pts, upd, with_updates); break;
  }
  return 0;
}
