// shadow.off, the unshadowed baseline every shadowing lesson offers (issue 10): the same frame
// with no shadow work at all, so reports and the benchmark can say what the shadow costs.
#include "harness.hpp"

namespace shadows {
namespace {

std::vector<std::string> lessonsWithABaseline() {
  std::vector<std::string> names;
  for (const std::string& lesson : registeredLessons()) {
    auto runner = std::make_unique<Runner>(lesson, makeLesson(lesson), RunOptions{});
    if (runner->params().find("shadow.off") != nullptr) names.push_back(lesson);
  }
  return names;
}

class Baseline : public ::testing::TestWithParam<std::string> {};

TEST_P(Baseline, RendersNoMapAndLightsEverything) {
  // A lesson without a map (09's volumes) has no cache and no map renders to count. Lesson 15's
  // default (baked) reads no map and renders none: its map mode is lesson 03's.
  const std::vector<std::string> sets = GetParam() == "15_light_maps"
                                            ? std::vector<std::string>{"lightmap.mode=map"}
                                            : std::vector<std::string>{};
  auto runner = testing::startLesson(GetParam(), sets, 160, 120);
  const bool map = runner->params().find("shadow.cache") != nullptr;
  const auto map_renders = [&] {
    return map ? runner->measure().lastFrameCounts().at("shadow_map_renders") : 0;
  };
  if (map) {
    ASSERT_EQ(runner->params().set("shadow.cache", "false"), "");
  }
  runner->renderFrame();
  if (map) {
    EXPECT_EQ(map_renders(), 1);
  }
  ASSERT_EQ(runner->params().set("shadow.off", "true"), "");
  runner->renderFrame();
  const auto& work = runner->measure().lastFrameWork();
  EXPECT_EQ(map_renders(), 0);
  EXPECT_EQ(work.count("shadow"), 0u) << "no map pass";
  EXPECT_EQ(work.count("readback"), 0u);
  EXPECT_EQ(work.count("volumes"), 0u) << "no volume pass";
  // Everything lit: nothing the truth calls lit is drawn shadowed, and every shadow is missed.
  const ErrorMetrics& e = runner->measureError().metrics;
  EXPECT_EQ(e.false_shadow_pct, 0.0);
  EXPECT_GT(e.false_lit_pct, 1.0);
  EXPECT_EQ(runner->glErrors(), 0);
  // Back on: the map is rendered again.
  ASSERT_EQ(runner->params().set("shadow.off", "false"), "");
  if (map) {
    ASSERT_EQ(runner->params().set("shadow.cache", "true"), "");
  }
  runner->renderFrame();
  if (map) {
    EXPECT_EQ(map_renders(), 1);
  }
}

INSTANTIATE_TEST_SUITE_P(Lessons, Baseline, ::testing::ValuesIn(lessonsWithABaseline()),
                         [](const ::testing::TestParamInfo<std::string>& lesson) {
                           return lesson.param;
                         });

}  // namespace
}  // namespace shadows
