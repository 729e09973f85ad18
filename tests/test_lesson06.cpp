// Lesson 06 end to end, headless: usable on a frustum confined to the casters, broken on an
// expanded one (the lesson's point), every copy path seeing the same bits, and the slides'
// mistakes measurably worse than what they recommend.
#include "harness.hpp"

namespace shadows {
namespace {

using testing::label;
using testing::startLesson;

const std::string kLesson = "06_dual_texture_8bit";
const std::vector<std::string> kExpanded = {"shadow.fit=false", "light.near=0.1", "light.far=500"};

std::vector<std::string> with(std::vector<std::string> sets, const std::vector<std::string>& more) {
  sets.insert(sets.end(), more.begin(), more.end());
  return sets;
}

ErrorMetrics measure(const std::vector<std::string>& sets) {
  return testing::measureOnce(kLesson, sets);
}

TEST(Lesson06, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson06, ConfinedFrustumIsAUsableShadowOnEveryPreset) {
  // 000: "yes, for some simple scenes ... relatively close together". The defaults fit the
  // frustum to the casters; at 1024² the bar is <= 0.5% false shadow, <= 1% false lit.
  for (const std::string& scene : scenePresets()) {
    const std::vector<std::string> sets = {"scene=" + scene, "shadow.size=1024"};
    const ErrorMetrics e = measure(sets);
    EXPECT_LE(e.false_shadow_pct, 0.5) << label(sets);
    EXPECT_LE(e.false_lit_pct, 1.0) << label(sets);
    EXPECT_GT(e.counted_pixels, 5000) << label(sets);
    EXPECT_EQ(e.nonfinite_pixels, 0) << label(sets);
  }
}

TEST(Lesson06, ExpandedFrustumBreaksTheEightBitShadow) {
  // 000: "Frustum expanded out considerably breaks down the shadows". Near 0.1, far 500: the
  // whole scene falls into a few 8-bit steps of projective depth.
  for (const std::string& scene : scenePresets()) {
    const std::vector<std::string> sets = with({"scene=" + scene}, kExpanded);
    const ErrorMetrics e = measure(sets);
    EXPECT_GE(e.false_shadow_pct + e.false_lit_pct, 5.0) << label(sets);
  }
}

TEST(Lesson06, LinearDepthDoesNotCareAboutTheNearPlane) {
  // 000, "Improving Depth Map Precision": projective depth spends its 256 steps by the ratio
  // far/near, crowding them at the far plane; Heidrich's linear depth spreads them over
  // far - near. Keep far, pull near in to a ratio of 1000: projective breaks, linear holds.
  const std::vector<std::string> near_in = {"shadow.fit=false", "light.near=0.016", "light.far=16"};
  const ErrorMetrics projective = measure(near_in);
  const ErrorMetrics linear = measure(with(near_in, {"map.encoding=linear"}));
  EXPECT_GT(projective.false_shadow_pct + projective.false_lit_pct, 5.0);
  EXPECT_LT(linear.false_shadow_pct + linear.false_lit_pct, 0.5);
}

TEST(Lesson06, EveryCopyPathSeesTheSameEightBits) {
  // read_pixels quantizes in the driver, the two depth-texture paths in the shader
  // (depthToSteps): the visibility must be identical, bit for bit. Without bias every lit
  // surface is a near-tie with its own texel, so one step off anywhere would show.
  const std::pair<const char*, const char*> maps[] = {
      {"projective", "24"}, {"linear", "24"}, {"projective", "16"}};
  for (const auto& [encoding, bits] : maps) {
    std::vector<float> reference;
    for (const char* path : {"read_pixels", "copy_texture", "render_to_texture"}) {
      const std::vector<std::string> sets = {
          std::string("map.encoding=") + encoding, std::string("map.path=") + path,
          std::string("map.depth_bits=") + bits, "bias.steps=0", "bias.factor=0"};
      auto runner = startLesson(kLesson, sets);
      runner->renderFrame();
      const std::vector<float> visibility = runner->renderVisibility();
      EXPECT_EQ(runner->glErrors(), 0) << label(sets);
      if (reference.empty()) {
        reference = visibility;
        continue;
      }
      EXPECT_EQ(testing::valuesDiffering(visibility, reference), 0u) << label(sets);
    }
  }
}

TEST(Lesson06, ReadbackMovesExactlyOneByteATexelAndTheOtherPathsNone) {
  auto runner = startLesson(kLesson, {"shadow.size=512", "shadow.height=256"});
  runner->renderFrame();
  const auto& counts = runner->measure().lastFrameCounts();
  EXPECT_EQ(counts.at("readback_bytes"), 512 * 256);
  EXPECT_EQ(runner->measure().lastFrameWork().count("readback"), 1u);
  ASSERT_EQ(runner->params().set("map.path", "copy_texture"), "");
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameCounts().count("readback_bytes"), 0u);
  EXPECT_EQ(runner->measure().lastFrameCounts().at("copied_texels"), 512 * 256);
  ASSERT_EQ(runner->params().set("map.path", "render_to_texture"), "");
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameWork().count("readback"), 0u) << "no copy at all";
  // A static frame renders no map and moves nothing.
  ASSERT_EQ(runner->params().set("map.path", "read_pixels"), "");
  runner->renderFrame();
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameCounts().at("shadow_map_renders"), 0);
  EXPECT_EQ(runner->measure().lastFrameCounts().count("readback_bytes"), 0u);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson06, TexgenBiasLacksTheSlopeTheOffsetHas) {
  // 000: "biases in the texgen transform do not work ... polygon offset scale keeps edge-on
  // polygons from self-shadowing". At the same two steps the texgen bias leaves several
  // times the acne of the offset; without the offset's slope term the two are alike.
  const ErrorMetrics offset = measure({"bias.steps=2"});
  const ErrorMetrics texgen = measure({"bias.steps=2", "bias.mode=texgen"});
  EXPECT_GT(texgen.false_shadow_pct, 0.2);
  EXPECT_GT(texgen.false_shadow_pct, 4.0 * offset.false_shadow_pct);
  const ErrorMetrics flat_offset = measure({"bias.steps=2", "bias.factor=0"});
  const ErrorMetrics flat_texgen = measure({"bias.steps=2", "bias.factor=0", "bias.mode=texgen"});
  EXPECT_NEAR(flat_offset.false_shadow_pct, flat_texgen.false_shadow_pct, 0.15);
}

TEST(Lesson06, BiasStepsAreMapStepsWhereverTheBiasGoes) {
  // A directional light (q = 1) and the exact fragment depth: the texgen bias is exactly
  // `steps` map steps, and so must the polygon offset be (the driver's unit is measured).
  const std::vector<std::string> flat = {"light.type=directional", "ramp.lookup=false",
                                         "bias.factor=0"};
  for (const char* steps : {"0.5", "1"}) {
    std::vector<std::string> offset = flat, texgen = flat;
    offset.push_back(std::string("bias.steps=") + steps);
    texgen.push_back(std::string("bias.steps=") + steps);
    texgen.push_back("bias.mode=texgen");
    EXPECT_NEAR(measure(offset).false_shadow_pct, measure(texgen).false_shadow_pct, 0.2) << steps;
  }
}

TEST(Lesson06, WithoutBiasNearEqualityShadowsTheLitSurfaces) {
  // 000: "fragments are likely to shadow themselves"; the strict alpha test turns every tie
  // into shadow.
  const ErrorMetrics none = measure({"bias.steps=0", "bias.factor=0"});
  EXPECT_GT(none.false_shadow_pct, 5.0);
}

TEST(Lesson06, TheRampsQuantizationCostsAboutAStepOfBias) {
  // Tex1 rounds the fragment's depth to the ramp's 256 texels, the map to 255 steps: the two
  // grids disagree by up to a step, so one step of bias leaves acne with the ramp and none
  // with the exact fragment depth.
  const ErrorMetrics ramp = measure({"bias.steps=1"});
  const ErrorMetrics exact = measure({"bias.steps=1", "ramp.lookup=false"});
  EXPECT_GT(ramp.false_shadow_pct, 3.0);
  EXPECT_LT(exact.false_shadow_pct, 0.2);
}

TEST(Lesson06, PassTwoLightsOnlyWhatTheAlphaTestPasses) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  const long long lit = runner->measure().lastFrameCounts().at("pass2_lit_fragments");
  EXPECT_GT(lit, 10000);
  // Everything lit: no pixel of the visibility is shadowed.
  const std::vector<float> visibility = runner->renderVisibility();
  size_t lit_pixels = 0;
  for (float v : visibility) lit_pixels += v == 1.0f;  // the sky reads 0.55
  EXPECT_EQ(static_cast<long long>(lit_pixels), lit) << "one lit fragment per lit pixel";
  // Pass 2 off: the dimmed pass alone, nothing lit.
  ASSERT_EQ(runner->params().set("pass.lit", "false"), "");
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameWork().count("pass2"), 0u);
}

TEST(Lesson06, PassTwoAloneIsTheFramesLitPixelsOnBlackAndNothingElse) {
  // README: "--set pass.dimmed=false (pass 2 alone: only the lit fragments)". Not only
  // "something changed": where the shadow term is lit the picture is the whole frame's, and
  // everywhere else (shadow, sky) it is black: no dimmed colour, no sky, no hole of another
  // colour.
  auto runner = startLesson(kLesson, {}, 160, 120);
  runner->renderFrame();
  const Image whole = runner->readImage();
  const std::vector<float> visibility = runner->renderVisibility();
  ASSERT_EQ(runner->params().set("pass.dimmed", "false"), "");
  runner->renderFrame();
  const Image alone = runner->readImage();
  ASSERT_EQ(runner->glErrors(), 0);
  size_t lit = 0, lit_differing = 0, dark = 0, dark_not_black = 0;
  for (size_t i = 0; i < visibility.size(); ++i) {
    int worst = 0, brightest = 0;
    for (size_t c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(whole.rgba[4 * i + c] - alone.rgba[4 * i + c]));
      brightest = std::max(brightest, static_cast<int>(alone.rgba[4 * i + c]));
    }
    if (visibility[i] == 1.0f) {
      ++lit, lit_differing += worst > 2;
    } else {
      ++dark, dark_not_black += brightest > 0;
    }
  }
  EXPECT_GT(lit, 3000u);
  EXPECT_GT(dark, 3000u) << "shadow and sky";
  EXPECT_EQ(lit_differing, 0u) << "a lit pixel is the whole frame's";
  EXPECT_EQ(dark_not_black, 0u) << "only the lit fragments are drawn";
}

TEST(Lesson06, EveryInputOfTheMapRendersItAgainAndTheCachedFrameMatchesAnUncachedOne) {
  std::vector<std::string> inputs = testing::readbackMapInputs();
  inputs.push_back("map.encoding=linear");
  testing::expectEveryMapInputRendersTheMapAgain(kLesson, inputs);
  testing::expectACasterMoveRendersTheMapAgain(kLesson);
}

TEST(Lesson06, EveryViewRendersCleanAndDistinct) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
}

TEST(Lesson06, SliderExtremesStayFiniteAndErrorFree) {
  testing::expectFiniteAndErrorFree(kLesson, testing::readbackMapSliderExtremes());
  testing::expectFiniteAndErrorFree(
      kLesson, {{"map.encoding=linear", "map.path=copy_texture", "bias.steps=64"},
                {"map.encoding=linear", "map.path=render_to_texture", "ramp.lookup=false"}});
}

TEST(Lesson06, AnExerciseChosenAfterAnotherSceneStartsFromItsOwnLight) {
  // Picking exercise 1 with the cubes preset showing: the defaults' scene is loaded first, and
  // the exercise's near and far are what the frame draws with, not the preset's.
  auto runner = startLesson(kLesson, {"scene=cubes"}, 320, 240);
  runner->renderFrame();
  ASSERT_EQ(runner->chooseExercise(1), "");
  runner->renderFrame();
  EXPECT_FLOAT_EQ(runner->params().at("light.near").f(), 0.1f);
  EXPECT_FLOAT_EQ(runner->params().at("light.far").f(), 500.0f);
  EXPECT_FALSE(runner->params().at("shadow.fit").b());
  EXPECT_GT(runner->measureError().metrics.false_lit_pct, 3.0) << "the expanded frustum's start";
}

}  // namespace
}  // namespace shadows
