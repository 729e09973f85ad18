// No overdraw shaded twice (issue 10): the eye's view draws solids front to back and the
// planes behind them last, with back faces culled, so the depth test rejects hidden fragments
// before they are shaded. llvmpipe's fragment_invocations counts every rasterized fragment,
// early test or not; fragments_passed (GL_SAMPLES_PASSED) counts those that passed the depth
// test, the only ones shaded. Measured against the pixels that show a surface at all.
#include "harness.hpp"

namespace shadows {
namespace {

// Each lesson's pass that draws the scene from the eye, opaque.
const std::pair<const char*, const char*> kEyePasses[] = {{"02_projective_texture", "ambient"},
                                                          {"03_shadow_map_basic", "eye"},
                                                          {"04_bias_offset", "eye"},
                                                          {"05_pcf_dithered", "eye"},
                                                          {"06_dual_texture_8bit", "pass1"},
                                                          {"07_multidigit_16bit", "pass1"},
                                                          {"08_atmospherics", "surfaces"}};

TEST(Overdraw, EyePassesShadeAtMostOneAndAHalfTenthsMoreThanTheCoveredPixels) {
  for (const auto& [lesson, pass] : kEyePasses) {
    auto probe = std::make_unique<Runner>(lesson, makeLesson(lesson), RunOptions{});
    for (const std::string& scene : probe->params().at("scene").choices) {
      auto runner = testing::startLesson(lesson, {"scene=" + scene, "inset=false"}, 320, 240);
      runner->renderFrame();
      const PassWork& work = runner->measure().lastFrameWork().at(pass);
      const ErrorMetrics& e = runner->measureError().metrics;
      ASSERT_GT(e.covered_pixels, 0) << lesson << " " << scene;
      const double passed = static_cast<double>(work.fragments_passed.value_or(-1));
      EXPECT_LE(passed, 1.15 * static_cast<double>(e.covered_pixels)) << lesson << " " << scene;
      // Every covered pixel is shaded at least once.
      EXPECT_GE(passed, static_cast<double>(e.covered_pixels)) << lesson << " " << scene;
    }
  }
}

}  // namespace
}  // namespace shadows
