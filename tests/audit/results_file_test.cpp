// The audit's results file (`kmr audit --json FILE`, read back by `--include FILE`): read_json on
// hand-written files (the expectations are typed here, not produced by write_json), its refusal of
// malformed files naming the file and the problem, and status() on what it read.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "audit/audit.hpp"
#include "exact/error.hpp"

namespace {

using namespace kmr::audit;

class ResultsFile : public ::testing::Test {
 protected:
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "kmr_results_file_test";
  void SetUp() override {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string file(const std::string& name, const std::string& text) {
    std::ofstream((dir / name).string(), std::ios::binary) << text;
    return (dir / name).string();
  }
  // The message of the InputError read_json throws on `text`, or "" when it throws none.
  std::string refusal(const std::string& text) {
    std::string path = file("bad.json", text);
    try {
      read_json(path);
    } catch (const kmr::InputError& e) {
      return e.what();
    }
    return "";
  }
};

// One file as a benchmark would write it by hand: the three target states, a result of before
// targets and plots existed (no "target", "target_met", "thesis", "replay" or "plots": defaults),
// "null" coordinates (NaN) and an integer-valued seconds field.
TEST_F(ResultsFile, HandWrittenResultsReadWithTheirTargetsAndDefaults) {
  std::string path = file("in.json", R"([
 {"claim":"A","title":"met","pass":true,"summary":"s","seconds":1.5,"target":"x <= 2","target_met":true,"figures":{"x":"1.9"}},
 {"claim":"B","title":"missed","pass":true,"summary":"","seconds":2,"target":"x <= 1","target_met":false,"figures":{}},
 {"claim":"C","title":"none","pass":false,"summary":"broke","seconds":0,"target_met":null,"figures":{},"replay":"bench --x",
  "plots":[{"title":"p","x":{"label":"n","unit":"","log":false,"categories":[]},"y":{"label":"t","unit":"s","log":true,"categories":["a","b"]},
            "series":[{"name":"k","points":[[1,null],[2,0.25]]}],"bounds":[]}]},
 {"claim":"D","title":"old","pass":true,"summary":"before targets","seconds":3,"figures":{"a":"1","b":"2"}}
])");
  auto r = read_json(path);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0].claim, "A");
  ASSERT_TRUE(r[0].verdict.target_met.has_value());
  EXPECT_TRUE(*r[0].verdict.target_met);
  EXPECT_EQ(r[0].verdict.target, "x <= 2");
  EXPECT_STREQ(verdict_word(r[0].verdict), "PASS");
  EXPECT_EQ(r[0].seconds, 1.5);
  ASSERT_EQ(r[0].verdict.figures.size(), 1u);
  EXPECT_EQ(r[0].verdict.figures[0], (std::pair<std::string, std::string>{"x", "1.9"}));
  ASSERT_TRUE(r[1].verdict.target_met.has_value());
  EXPECT_FALSE(*r[1].verdict.target_met);
  EXPECT_STREQ(verdict_word(r[1].verdict), "MISSED");
  EXPECT_EQ(r[1].seconds, 2.0);
  EXPECT_FALSE(r[2].verdict.target_met.has_value());
  EXPECT_STREQ(verdict_word(r[2].verdict), "FAIL");
  EXPECT_EQ(r[2].replay, "bench --x");
  ASSERT_EQ(r[2].verdict.plots.size(), 1u);
  const auto& plot = r[2].verdict.plots[0];
  EXPECT_FALSE(plot.x.log);
  EXPECT_TRUE(plot.y.log);
  EXPECT_EQ(plot.y.categories, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(plot.series.size(), 1u);
  ASSERT_EQ(plot.series[0].points.size(), 2u);
  EXPECT_EQ(plot.series[0].points[0].x, 1.0);
  EXPECT_TRUE(std::isnan(plot.series[0].points[0].y));
  EXPECT_EQ(plot.series[0].points[1].y, 0.25);
  EXPECT_FALSE(r[3].verdict.target_met.has_value());
  EXPECT_EQ(r[3].verdict.target, "");
  EXPECT_EQ(r[3].verdict.thesis, "");
  EXPECT_EQ(r[3].replay, "");
  EXPECT_TRUE(r[3].verdict.plots.empty());
  EXPECT_EQ(r[3].verdict.figures.size(), 2u);
  EXPECT_EQ(status(r), 1);  // C failed
  EXPECT_EQ(status({r[0], r[1], r[3]}), 0);  // a missed target is no failure
  EXPECT_EQ(status({}), 1);                  // nothing ran: no success
}

// Every malformed file is an InputError that names the file and what is wrong with it.
TEST_F(ResultsFile, MalformedFilesAreRefusedNamingFileAndProblem) {
  const std::string good = R"("claim":"A","title":"t","pass":true,"summary":"s","figures":{})";
  auto with = [&](const std::string& extra) { return "[{" + good + "," + extra + "}]"; };
  std::string m = refusal(with(R"("seconds":1,"target_met":"maybe")"));
  EXPECT_NE(m.find("bad.json"), std::string::npos) << m;
  EXPECT_NE(m.find("target_met must be true, false or null, not 'maybe'"), std::string::npos) << m;
  m = refusal(with(R"("seconds":"1.5s")"));
  EXPECT_NE(m.find("not a number: '1.5s'"), std::string::npos) << m;
  m = refusal(with(R"("seconds":"fast")"));  // stod itself refuses
  EXPECT_NE(m.find("cannot read audit results from"), std::string::npos) << m;
  const std::string axis = R"({"label":"n","unit":"","log":false,"categories":[]})";
  m = refusal(with(R"("seconds":1,"plots":[{"title":"p","x":)" + axis + R"(,"y":)" + axis +
                   R"(,"series":[{"name":"k","points":[[1,2,3]]}],"bounds":[]}])"));
  EXPECT_NE(m.find("a point needs 2 numbers"), std::string::npos) << m;
  m = refusal(R"([{"claim":"","title":"t","pass":true,"summary":"s","seconds":1,"figures":{}}])");
  EXPECT_NE(m.find("a result without a claim ID"), std::string::npos) << m;
  m = refusal("[]");
  EXPECT_NE(m.find("no audit results in"), std::string::npos) << m;
  EXPECT_NE(m.find("bad.json"), std::string::npos) << m;
  m = refusal(R"([{"claim":"A","title":"t","pass":"perhaps","summary":"s","seconds":1,"figures":{}}])");
  EXPECT_NE(m.find("cannot read audit results from"), std::string::npos) << m;
  m = refusal(std::string("[{\"claim\":\"A\"\0, ", 16));  // NUL byte, truncated
  EXPECT_NE(m.find("cannot read audit results from"), std::string::npos) << m;
  m = refusal(with(R"("figures_missing_seconds":1)"));  // "seconds" is required
  EXPECT_NE(m.find("seconds"), std::string::npos) << m;
}

// Non-finite measurements (a timing that overflowed, a plot point with no value) are written as
// JSON null, never as "inf"/"nan" (which JSON has not), and read back as NaN.
TEST_F(ResultsFile, NonFiniteNumbersAreWrittenAsNullAndReadBackAsNaN) {
  Result r;
  r.claim = "N";
  r.title = "t";
  r.verdict.pass = true;
  r.seconds = std::numeric_limits<double>::infinity();
  kmr::svg::Plot p;
  p.title = "p";
  p.series = {{"s", {{std::numeric_limits<double>::quiet_NaN(), 2.0}, {3.0, -std::numeric_limits<double>::infinity()}}}};
  r.verdict.plot(p);
  std::ostringstream out;
  write_json({r}, out);
  std::string text = out.str();
  EXPECT_NE(text.find("\"seconds\":null"), std::string::npos) << text;
  EXPECT_NE(text.find("\"points\":[[null,2],[3,null]]"), std::string::npos) << text;
  EXPECT_EQ(text.find("inf"), std::string::npos) << text;
  EXPECT_EQ(text.find("nan"), std::string::npos) << text;
  auto back = read_json(file("nonfinite.json", text));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_TRUE(std::isnan(back[0].seconds));
  const auto& pts = back[0].verdict.plots.at(0).series.at(0).points;
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_TRUE(std::isnan(pts[0].x));
  EXPECT_EQ(pts[0].y, 2.0);
  EXPECT_EQ(pts[1].x, 3.0);
  EXPECT_TRUE(std::isnan(pts[1].y));
}

}  // namespace
