#pragma once
// The one tokenizer of kmr's line formats (spec/formats.md): every input file is read through it,
// by the library readers (kinetic, hull) and by cli/formats.
// Guarantees: a '#' starts a comment that runs to the end of the line; blank and comment-only lines
// are skipped; tokens are the whitespace-separated words (CR counts as whitespace, so CRLF files
// read as LF files); line numbers count from 1 and include the skipped lines; a stream error (not
// end of file) throws InputError naming `filename`.
#include <cstddef>
#include <istream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "exact/error.hpp"

namespace kmr::exact {

struct TextLine {
  std::size_t number;               // 1-based line number in the file
  std::vector<std::string> tokens;  // never empty
  // The tokens joined by single spaces, for messages.
  std::string text() const {
    std::string s;
    for (const auto& t : tokens) s += (s.empty() ? "" : " ") + t;
    return s;
  }
};

inline std::vector<TextLine> read_text_lines(std::istream& in, const std::string& filename = "input") {
  std::vector<TextLine> out;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (auto h = line.find('#'); h != std::string::npos) line.resize(h);
    std::istringstream ss(line);
    TextLine l{n, {}};
    for (std::string t; ss >> t;) l.tokens.push_back(std::move(t));
    if (!l.tokens.empty()) out.push_back(std::move(l));
  }
  if (in.bad()) throw InputError(filename + ": read error");
  return out;
}

}  // namespace kmr::exact
