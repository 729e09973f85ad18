// Lesson 07 end to end, headless: the 16-bit two-digit compare holds where lesson 06's 8 bits
// break, its three passes split the lit pixels without overlap, pass 3 shades only what pass
// 2 left dark, and every path reads back exactly two bytes a texel.
#include "harness.hpp"

namespace shadows {
namespace {

using testing::label;
using testing::startLesson;

const std::string kLesson = "07_multidigit_16bit";
const std::vector<std::string> kExpanded = {"shadow.fit=false", "light.near=0.1", "light.far=500"};

ErrorMetrics measure(const std::string& lesson, std::vector<std::string> sets,
                     const std::vector<std::string>& more = {}) {
  sets.insert(sets.end(), more.begin(), more.end());
  auto runner = startLesson(lesson, sets);
  runner->renderFrame();
  EXPECT_EQ(runner->glErrors(), 0) << label(sets);
  return runner->measureError().metrics;
}

double wrong(const ErrorMetrics& e) {
  return e.false_shadow_pct + e.false_lit_pct;
}

TEST(Lesson07, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson07, ConfinedFrustumIsAUsableShadowOnEveryPreset) {
  for (const std::string& scene : scenePresets()) {
    const ErrorMetrics e = measure(kLesson, {"scene=" + scene});
    EXPECT_LE(e.false_shadow_pct, 0.5) << scene;
    EXPECT_LE(e.false_lit_pct, 1.0) << scene;
    EXPECT_GT(e.counted_pixels, 5000) << scene;
  }
}

TEST(Lesson07, SixteenBitsHoldWhereLessonSixsEightBitsBreak) {
  // 000, "More Precision Allows Larger Lights Frustums": on the same expanded frustum and
  // map, the two-digit compare has at most a tenth of the 8-bit test's error.
  for (const std::string& scene : scenePresets()) {
    const double eight = wrong(measure("06_dual_texture_8bit", {"scene=" + scene}, kExpanded));
    const double sixteen = wrong(measure(kLesson, {"scene=" + scene}, kExpanded));
    EXPECT_GE(eight, 5.0) << scene;
    EXPECT_LE(sixteen, eight / 10.0) << scene << ": 16-bit " << sixteen << "%, 8-bit " << eight;
    EXPECT_LE(sixteen, 1.5) << scene;
  }
}

TEST(Lesson07, PassesTwoAndThreeNeverLightTheSamePixel) {
  // The "passes" view adds pass 2's green and pass 3's blue: a pixel both lit would be cyan.
  auto runner = startLesson(kLesson, {"view=passes"});
  runner->renderFrame();
  const Image image = runner->readImage();
  int green = 0, blue = 0, both = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    const bool g = image.rgba[i + 1] > 128, b = image.rgba[i + 2] > 128 && image.rgba[i] < 100;
    green += g && !b;
    blue += b && !g;
    both += g && b;
  }
  EXPECT_GT(green, 1000) << "pass 2 decides most lit pixels";
  EXPECT_GT(blue, 100) << "pass 3 decides where the big digits tie";
  EXPECT_EQ(both, 0);
  const auto& counts = runner->measure().lastFrameCounts();
  EXPECT_GT(counts.at("pass2_lit_fragments"), 0);
  EXPECT_GT(counts.at("pass3_lit_fragments"), 0);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson07, EachPassToggleRemovesOnlyItsOwnContribution) {
  auto lit = [](const std::vector<std::string>& sets) {
    auto runner = startLesson(kLesson, sets);
    runner->renderFrame();
    const auto& counts = runner->measure().lastFrameCounts();
    return std::pair{counts.at("pass2_lit_fragments"), counts.at("pass3_lit_fragments")};
  };
  const auto all = lit({});
  // Pass 2 off still marks its pixels in the stencil: pass 3 lights exactly what it did.
  const auto no_big = lit({"pass.big=false"});
  EXPECT_EQ(no_big.second, all.second);
  const auto no_little = lit({"pass.little=false"});
  EXPECT_EQ(no_little.first, all.first);
  EXPECT_EQ(no_little.second, 0);
}

TEST(Lesson07, ReadbackMovesExactlyTwoBytesATexel) {
  auto runner = startLesson(kLesson, {"shadow.size=256", "shadow.height=128"});
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameCounts().at("readback_bytes"), 2 * 256 * 128);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson07, EveryCopyPathSeesTheSameSixteenBitsButForOneUlp) {
  // Unlike lesson 06's 8 bits (exact), 16 bits sit at the edge of float precision: the
  // driver's depth-texture fetch and its glReadPixels turn a 24-bit depth into a float that
  // may differ by one ulp, and 65535 d then lands on the other side of a rounding point for
  // about one pixel in 100,000 (measured: 1 of 76,800 here). Without bias every lit surface
  // is a near-tie, so anything worse than that (a wrong rounding mode, a digit swap) would
  // show in thousands of pixels.
  std::vector<float> reference;
  for (const char* path : {"read_pixels", "copy_texture", "render_to_texture"}) {
    const std::vector<std::string> sets = {std::string("map.path=") + path, "bias.steps=0",
                                           "bias.factor=0"};
    auto runner = startLesson(kLesson, sets);
    runner->renderFrame();
    const std::vector<float> visibility = runner->renderVisibility();
    if (reference.empty()) {
      reference = visibility;
      continue;
    }
    EXPECT_LE(testing::valuesDiffering(visibility, reference), visibility.size() / 20000)
        << label(sets);
  }
}

TEST(Lesson07, EveryInputOfTheMapRendersItAgainAndTheCachedFrameMatchesAnUncachedOne) {
  testing::expectEveryMapInputRendersTheMapAgain(kLesson, testing::readbackMapInputs());
  testing::expectACasterMoveRendersTheMapAgain(kLesson);
}

TEST(Lesson07, EveryViewRendersCleanAndDistinct) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
}

TEST(Lesson07, SliderExtremesStayFiniteAndErrorFree) {
  testing::expectFiniteAndErrorFree(kLesson, testing::readbackMapSliderExtremes());
  testing::expectFiniteAndErrorFree(kLesson, {{"bias.steps=4096", "pass.dimmed=false"}});
}

}  // namespace
}  // namespace shadows
