// The shadow's overhead in every report (issue 10): the same frame rendered with shadow.off,
// off-screen and interleaved, timed on its own. Counted, not timed, here: the baseline frame
// renders no map, leaves the cached map and every dirty bit alone, and the picture is the
// lesson's.
#include "harness.hpp"

namespace shadows {
namespace {

TEST(Overhead, TheBaselineFrameRendersNoMapAndLeavesTheLessonsFrameAsItWas) {
  auto runner = testing::startLesson("03_shadow_map_basic", {}, 160, 120);
  runner->renderFrame();
  const Image before = runner->readImage();
  runner->baseline().render();  // the first compiles the unshadowed variant: not timed
  EXPECT_EQ(runner->baseline().measure().timedFrames(), 0u);
  runner->baseline().render();
  EXPECT_EQ(runner->baseline().measure().timedFrames(), 1u);
  EXPECT_EQ(runner->baseline().measure().lastFrameCounts().at("shadow_map_renders"), 0);
  EXPECT_TRUE(runner->baseline().measure().lastFrameWork().count("eye"));
  EXPECT_FALSE(runner->params().at("shadow.off").b());
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameCounts().at("shadow_map_renders"), 0) << "still cached";
  EXPECT_EQ(testing::pixelsDiffering(runner->readImage(), before, 0), 0u);
  EXPECT_GT(runner->baseline().overhead(), 0.0);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Overhead, AChangeMadeBeforeTheBaselineFrameStillRendersTheMap) {
  auto runner = testing::startLesson("03_shadow_map_basic", {}, 160, 120);
  runner->renderFrame();
  ASSERT_EQ(runner->params().set("light.pos", "2,7,3"), "");
  ASSERT_EQ(runner->params().set("shadow.size", "512"), "");
  runner->baseline().render();  // must not swallow the dirty map
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameCounts().at("shadow_map_renders"), 1);
  auto fresh =
      testing::startLesson("03_shadow_map_basic", {"light.pos=2,7,3", "shadow.size=512"}, 160, 120);
  fresh->renderFrame();
  EXPECT_EQ(testing::pixelsDiffering(runner->readImage(), fresh->readImage(), 0), 0u);
}

TEST(Overhead, LessonsWithoutABaselineHaveNone) {
  auto runner = testing::startLesson("01_projected_planar", {}, 160, 120);
  runner->renderFrame();
  runner->baseline().render();
  runner->baseline().render();
  EXPECT_EQ(runner->baseline().measure().timedFrames(), 0u);
  EXPECT_EQ(runner->baseline().overhead(), 0.0);
}

}  // namespace
}  // namespace shadows
