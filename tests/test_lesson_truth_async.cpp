// The window's truth off the frame's critical path (issue 10): what the truth needs is read
// back on the render thread, the rays are traced on a worker while frames go on, and the
// result is the one a blocking measurement gives.
#include "harness.hpp"

namespace shadows {
namespace {

void expectSameMetrics(const ErrorMetrics& a, const ErrorMetrics& b, const std::string& label) {
  EXPECT_EQ(a.truth, b.truth) << label;
  EXPECT_EQ(a.counted_pixels, b.counted_pixels) << label;
  EXPECT_EQ(a.covered_pixels, b.covered_pixels) << label;
  EXPECT_EQ(a.false_shadow_pct, b.false_shadow_pct) << label;
  EXPECT_EQ(a.false_lit_pct, b.false_lit_pct) << label;
  EXPECT_EQ(a.vis_mae, b.vis_mae) << label;
  EXPECT_EQ(a.air.valid, b.air.valid) << label;
  EXPECT_EQ(a.air.mae, b.air.mae) << label;
}

TEST(TruthOffTheRenderThread, FramesGoOnWhileItIsTracedAndTheResultIsTheBlockingOne) {
  for (const std::string lesson : {"03_shadow_map_basic", "05_pcf_dithered", "08_atmospherics"}) {
    auto blocking = testing::startLesson(lesson, {}, 160, 120);
    blocking->renderFrame();
    const ErrorMetrics expected = blocking->measureError().metrics;

    auto runner = testing::startLesson(lesson, {}, 160, 120);
    runner->renderFrame();
    runner->errors().begin();
    EXPECT_TRUE(runner->errors().truth().running());
    runner->errors().begin();  // one job at a time: a second call changes nothing
    while (!runner->errors().poll()) runner->renderFrame();  // frames while it traces
    EXPECT_FALSE(runner->errors().truth().running());
    ASSERT_TRUE(runner->host().lastError().valid) << lesson;
    expectSameMetrics(runner->host().lastError().metrics, expected, lesson);
    EXPECT_EQ(runner->glErrors(), 0) << lesson;
  }
}

TEST(TruthOffTheRenderThread, ASliderMovedDuringTheTraceLeavesItStaleAndTheNextMeasureIsNew) {
  auto runner = testing::startLesson("03_shadow_map_basic", {}, 160, 120);
  runner->renderFrame();
  runner->errors().begin();
  ASSERT_EQ(runner->params().set("light.pos", "2,7,3"), "");  // while the rays are traced
  runner->renderFrame();
  const ErrorMetrics stale = runner->measureError().metrics;  // waits, then measures anew

  auto fresh = testing::startLesson("03_shadow_map_basic", {"light.pos=2,7,3"}, 160, 120);
  fresh->renderFrame();
  expectSameMetrics(stale, fresh->measureError().metrics, "light moved during the trace");
}

TEST(TruthOffTheRenderThread, ATruthBuiltForGeometryThatMovedMeanwhileIsNotKept) {
  // Lesson 01 tilts its receiver: the truth's triangles change. A trace begun before the tilt
  // builds its Truth from the old triangles; it must not be kept for the new ones.
  auto runner = testing::startLesson("01_projected_planar", {}, 160, 120);
  runner->renderFrame();
  runner->errors().begin();
  ASSERT_EQ(runner->params().set("plane.tilt", "20"), "");
  runner->renderFrame();  // moves the receiver: the runner drops its truth
  while (!runner->errors().poll()) runner->renderFrame();
  const ErrorMetrics tilted = runner->measureError().metrics;

  auto fresh = testing::startLesson("01_projected_planar", {"plane.tilt=20"}, 160, 120);
  fresh->renderFrame();
  expectSameMetrics(tilted, fresh->measureError().metrics, "receiver tilted during the trace");
}

}  // namespace
}  // namespace shadows
