// The CSV and JSON table behind every benchmark plot and README table (tables.cpp): each
// column's header against the value it must hold, from a result whose every field differs,
// so a swapped or mislabelled column fails here rather than in a README number.
#include <gtest/gtest.h>

#include "bench.hpp"

namespace shadows::bench {
namespace {

TEST(Table, EveryColumnHoldsTheFieldItsHeaderNames) {
  Config c;
  c.lesson = "05_pcf_dithered";
  c.scene = "cubes";
  c.axis_names = {"shadow.size", "pcf.mode"};
  c.values = {"512", "grid"};
  Result r;
  r.done = true;
  r.rounds = 3;
  r.frame_ms = 11.5, r.frame_min_ms = 10.25, r.cpu_ms = 13.75;
  r.pass_ms = {{"eye", 1.5}, {"shadow", 2.5}};
  r.work["eye"].draw_calls = 7, r.work["eye"].fragment_invocations = 700;
  r.work["shadow"].draw_calls = 8, r.work["shadow"].fragment_invocations = 800;
  r.counts = {{"shadow_map_renders", 9}, {"taps", 90}};
  r.error_valid = true;
  r.error.false_shadow_pct = 0.125, r.error.false_lit_pct = 0.375;
  r.error.vis_mae = 0.0625, r.error.shade_mae = 0.03125;
  r.error.nonfinite_pixels = 2, r.error.counted_pixels = 12345;
  r.error.air.valid = true;
  r.error.air.mae = 0.5, r.error.air.rel_rmse = 0.75, r.error.air.truth_noise = 0.0078125;
  r.error.truth = "area r=0.25 n=64";
  r.undersampled_pct = 66.5;
  r.report_numbers = {{"shimmer_pct", 0.046875}};
  r.gl_errors = 1;
  r.renderer = "llvmpipe";
  Options o;
  o.width = 320, o.height = 240, o.frames = 4;

  const Table t = makeTable({&c}, {&r}, o);
  ASSERT_EQ(t.rows.size(), 1u);
  ASSERT_EQ(t.rows[0].size(), t.header.size());
  ASSERT_EQ(t.numeric.size(), t.header.size());
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"lesson", "05_pcf_dithered"},
      {"scene", "cubes"},
      {"shadow.size", "512"},
      {"pcf.mode", "grid"},
      {"width", "320"},
      {"height", "240"},
      {"frames", "4"},
      {"rounds", "3"},
      {"frame_ms", "11.5"},
      {"frame_min_ms", "10.25"},
      {"cpu_ms", "13.75"},
      {"pass_ms.eye", "1.5"},
      {"pass_ms.shadow", "2.5"},
      {"draw_calls.eye", "7"},
      {"fragment_invocations.eye", "700"},
      {"draw_calls.shadow", "8"},
      {"fragment_invocations.shadow", "800"},
      {"shadow_map_renders", "9"},
      {"taps", "90"},
      {"false_shadow_pct", "0.125"},
      {"false_lit_pct", "0.375"},
      {"vis_mae", "0.0625"},
      {"shade_mae", "0.03125"},
      {"nonfinite_pixels", "2"},
      {"counted_pixels", "12345"},
      {"air_mae", "0.5"},
      {"air_rel_rmse", "0.75"},
      {"air_truth_noise", "0.0078125"},
      {"undersampled_pct", "66.5"},
      {"shimmer_pct", "0.046875"},
      {"truth", "area r=0.25 n=64"},
      {"gl_errors", "1"},
      {"renderer", "llvmpipe"},
      {"status", "ok"},
  };
  for (const auto& [name, value] : expected) {
    const int k = t.column(name);
    ASSERT_GE(k, 0) << "no column " << name;
    EXPECT_EQ(t.rows[0][static_cast<size_t>(k)], value) << name;
  }
  // Every column is one of those, but the machine's name (which varies).
  EXPECT_EQ(t.header.size(), expected.size() + 1);
  EXPECT_GE(t.column("machine"), 0);
  // Text columns are quoted in the JSON, numbers not: pcf.mode's "grid" is text.
  EXPECT_FALSE(t.numeric[static_cast<size_t>(t.column("pcf.mode"))]);
  EXPECT_TRUE(t.numeric[static_cast<size_t>(t.column("shadow.size"))]);
  EXPECT_FALSE(t.numeric[static_cast<size_t>(t.column("truth"))]);
  EXPECT_TRUE(t.numeric[static_cast<size_t>(t.column("vis_mae"))]);
}

TEST(Table, AFieldNotMeasuredIsAnEmptyCellNotAZero) {
  // No truth, no air, no map, a pass with no fragment count: empty cells, never 0.
  Config c;
  c.lesson = "09_shadow_volumes";
  c.scene = "torus_pyramid";
  Result r;
  r.done = false;
  r.failure = "timed out";
  r.work["volumes"].draw_calls = 3;
  Options o;
  const Table t = makeTable({&c}, {&r}, o);
  for (const char* name : {"false_shadow_pct", "vis_mae", "counted_pixels", "air_mae",
                           "undersampled_pct", "fragment_invocations.volumes", "truth"}) {
    EXPECT_EQ(t.cell(0, name), "") << name;
  }
  EXPECT_EQ(t.cell(0, "draw_calls.volumes"), "3");
  EXPECT_EQ(t.cell(0, "status"), "failed: timed out");
}

}  // namespace
}  // namespace shadows::bench
