// exact/text_lines.hpp: each guarantee of its header, on hand-written files.
#include <gtest/gtest.h>

#include <sstream>

#include "exact/text_lines.hpp"

namespace {
using kmr::exact::read_text_lines;

TEST(TextLines, CommentsBlankLinesAndNumbering) {
  std::istringstream in("# header\n\n1 2  # tail\n   \n\t3\t4 5\n#\n6");
  auto lines = read_text_lines(in, "f");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].number, 3u);
  EXPECT_EQ(lines[0].tokens, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(lines[1].number, 5u);
  EXPECT_EQ(lines[1].text(), "3 4 5");
  EXPECT_EQ(lines[2].number, 7u);  // a last line without a newline counts
  EXPECT_EQ(lines[2].tokens, (std::vector<std::string>{"6"}));
}

TEST(TextLines, CrlfReadsAsLf) {
  std::istringstream crlf("1 2\r\n\r\n3 4\r\n"), lf("1 2\n\n3 4\n");
  auto a = read_text_lines(crlf), b = read_text_lines(lf);
  ASSERT_EQ(a.size(), 2u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].number, b[i].number);
    EXPECT_EQ(a[i].tokens, b[i].tokens);
  }
}

TEST(TextLines, AStreamErrorNamesTheFile) {
  std::istringstream in("1 2\n");
  in.setstate(std::ios::badbit);
  try {
    read_text_lines(in, "points.txt");
    FAIL() << "no error";
  } catch (const kmr::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("points.txt: read error"), std::string::npos);
  }
}
}  // namespace
