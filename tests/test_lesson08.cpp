// Lesson 08 end to end, headless: the air light against the ray-marched truth, what more
// slices buy, the work the cone bounds and the early depth test skip, and the extremes.
#include "harness.hpp"

namespace shadows {
namespace {

using testing::label;
using testing::startLesson;

const std::string kLesson = "08_atmospherics";

ErrorMetrics measure(const std::vector<std::string>& sets) {
  auto runner = startLesson(kLesson, sets);
  runner->renderFrame();
  EXPECT_EQ(runner->glErrors(), 0) << label(sets);
  return runner->measureError().metrics;
}

TEST(Lesson08, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson08, DefaultAirLightIsCloseToTheTruthAndTheTruthIsConverged) {
  const ErrorMetrics e = measure({});
  ASSERT_TRUE(e.air.valid);
  EXPECT_GT(e.air.pixels, 5000) << "the shafts cover a good part of the frame";
  EXPECT_GT(e.air.truth_mean, 0.02) << "and they are bright enough to see";
  EXPECT_LT(e.air.rel_rmse, 0.15);
  // The truth's own error is well below the picture's: the figures measure the slices.
  EXPECT_LT(e.air.truth_noise, 0.5 * e.air.mae);
  // The surfaces keep lesson 04's quality.
  EXPECT_LE(e.false_shadow_pct, 0.5);
  EXPECT_LE(e.false_lit_pct, 1.0);
  EXPECT_EQ(e.nonfinite_pixels, 0);
}

TEST(Lesson08, MoreSlicesConvergeOnTheTruth) {
  const double few = measure({"air.slices=6"}).air.rel_rmse;
  const double many = measure({"air.slices=128"}).air.rel_rmse;
  EXPECT_GT(few, 2.0 * many) << "6 slices " << few << ", 128 slices " << many;
}

TEST(Lesson08, ShaftsAreCutByTheCasters) {
  // Without the shadow-map test in the slices (no casters in the room but the walls), the air
  // behind the sphere and the pillar would glow: the truth has dark shafts there.
  auto with = measure({"air.slices=96"});
  auto runner = startLesson(kLesson, {"air.slices=96"});
  runner->renderFrame();
  // Remove every caster from the map: aim the spot's map at nothing by shrinking its far
  // plane below the casters, with the fit off. The medium (the spot's whole frustum) stays.
  const ErrorMetrics uncut =
      measure({"air.slices=96", "shadow.fit=false", "light.near=0.5", "light.far=0.6"});
  EXPECT_GT(uncut.air.rel_rmse, 3.0 * with.air.rel_rmse);
}

TEST(Lesson08, ConeBoundedSlicesShadeFewerFragmentsForTheSameError) {
  auto work = [](bool bound) {
    auto runner = startLesson(kLesson, {std::string("air.bound=") + (bound ? "true" : "false")});
    runner->renderFrame();
    const long long rasterized =
        runner->measure().lastFrameWork().at("air").fragment_invocations.value_or(-1);
    const long long passed = runner->measure().lastFrameCounts().at("air_fragments_passed");
    const double error = runner->measureError().metrics.air.rel_rmse;
    return std::tuple{rasterized, passed, error};
  };
  const auto [bounded_raster, bounded_passed, bounded_error] = work(true);
  const auto [full_raster, full_passed, full_error] = work(false);
  EXPECT_GE(full_raster, 2 * bounded_raster);
  EXPECT_GE(full_passed, 2 * bounded_passed);
  EXPECT_LE(bounded_error, full_error + 0.01);
}

TEST(Lesson08, EarlyRejectionChangesTheCostNotThePicture) {
  auto picture = [](const std::string& early) {
    auto runner = startLesson(kLesson, {"air.early_reject=" + early});
    runner->renderFrame();
    EXPECT_EQ(runner->glErrors(), 0);
    return runner->readImage().rgba;
  };
  EXPECT_EQ(picture("true"), picture("false"));
}

TEST(Lesson08, ABadSpotImageIsRefusedByName) {
  auto runner = startLesson(kLesson, {});
  const std::string error = runner->params().set("spot.image", "/nonexistent/spot.png");
  EXPECT_NE(error.find("/nonexistent/spot.png"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line";
}

TEST(Lesson08, EveryInputOfTheMapRendersItAgainAndTheCachedFrameMatchesAnUncachedOne) {
  testing::expectEveryMapInputRendersTheMapAgain(kLesson, testing::shadowMapInputs());
  testing::expectACasterMoveRendersTheMapAgain(kLesson);
}

TEST(Lesson08, EveryViewRendersCleanAndDistinct) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
}

TEST(Lesson08, SliderExtremesStayFiniteAndErrorFree) {
  testing::expectFiniteAndErrorFree(
      kLesson, {{"air.slices=1"},
                {"air.slices=256", "air.jitter=false"},
                {"air.density=0"},
                {"air.density=1", "spot.falloff=0"},
                {"spot.falloff=1", "air.bound=false", "air.early_reject=false"},
                {"camera.pos=2.5,4.2,-1.6", "camera.target=-0.8,0,0.6"},  // inside the cone
                {"light.pos=1.2,2.9,-0.6"},                               // inside the sphere
                {"scene=torus_pyramid"},
                {"light.fov=5"},
                {"light.fov=160", "shadow.size=64"}});
}

}  // namespace
}  // namespace shadows
