// The Pareto front that the plots draw and bench/tables.py tabulates (front.hpp), on a
// hand-made CSV whose rows say what they expect (testdata/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "front.hpp"

#ifndef BENCH_TESTDATA
#error "BENCH_TESTDATA (bench/testdata) must be defined by the build"
#endif

namespace shadows::bench {
namespace {

TEST(Front, HandMadeCsv) {
  Table t;
  ASSERT_EQ(readCsv(BENCH_TESTDATA "/front.csv", t), "");
  ASSERT_EQ(t.rows.size(), 15u);
  markFronts(t, "cpu_ms", {"vis_mae", "false_lit_pct"}, {"kernel"});
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string& id = t.cell(r, "id");
    EXPECT_EQ(t.cell(r, "on_front.vis_mae"), t.cell(r, "expect.vis_mae")) << id;
    EXPECT_EQ(t.cell(r, "on_front.false_lit_pct"), t.cell(r, "expect.false_lit_pct")) << id;
    EXPECT_EQ(t.cell(r, "front_group"), t.cell(r, "expect.group")) << id;
    EXPECT_EQ(t.cell(r, "front_time"), t.cell(r, "status") == "ok" ? "cpu_ms" : "") << id;
  }
  // Marking again (a replot of a CSV that has the columns) changes nothing.
  const Table once = t;
  markFronts(t, "cpu_ms", {"vis_mae", "false_lit_pct"}, {"kernel"});
  EXPECT_EQ(t.header, once.header);
  EXPECT_EQ(t.rows, once.rows);
}

TEST(Front, OnePointThatBeatsAllIsTheFront) {
  EXPECT_EQ(paretoFront({{3, 3}, {1, 1}, {2, 1}, {1, 2}}),
            (std::vector<bool>{false, true, false, false}));
}

TEST(Front, TiesStayTogetherAndHalfTiesLose) {
  // Equal in both: neither beats the other. Equal in one, worse in the other: beaten.
  EXPECT_EQ(paretoFront({{1, 2}, {1, 2}, {1, 3}, {2, 2}, {0.5, 4}}),
            (std::vector<bool>{true, true, false, false, true}));
}

TEST(Front, NotANumberIsNeverOnIt) {
  const double nan = std::nan("");
  EXPECT_EQ(paretoFront({{nan, 0}, {1, nan}, {2, 2}}), (std::vector<bool>{false, false, true}));
  EXPECT_TRUE(paretoFront({}).empty());
}

TEST(Front, CsvRoundTrip) {
  Table t;
  t.header = {"a", "b,c"};
  t.numeric = {true, false};
  t.rows = {{"1", "x \"y\", z"}, {"nan", ""}};
  const auto path = std::filesystem::path(testing::TempDir()) / "front_round_trip.csv";
  {
    std::ofstream out(path, std::ios::binary);
    out << toCsv(t);
  }
  Table back;
  ASSERT_EQ(readCsv(path, back), "");
  EXPECT_EQ(back.header, t.header);
  EXPECT_EQ(back.rows, t.rows);
  EXPECT_EQ(back.numeric, t.numeric);
  EXPECT_TRUE(std::isnan(back.value(1, "a")));
  EXPECT_EQ(back.value(0, "a"), 1.0);
}

}  // namespace
}  // namespace shadows::bench
