// Lesson 14 end to end, headless: percentage-closer soft shadows against the area light's
// truth. The golden and every view; PCSS nearer the truth in the penumbra than lesson 05's best
// single width and than a hard shadow, on the contact and overlap presets; every fragment's
// work accounted for by the counters, and the umbra skip exactly what it says; a light of
// radius 0 giving lesson 04's hard shadow bit for bit.
#include "harness.hpp"

namespace shadows {
namespace {

using testing::reportNumber;
using testing::startLesson;

const std::string kLesson = "14_soft_shadows";

long long counter(Runner& runner, const std::string& name) {
  const auto& counts = runner.measure().lastFrameCounts();
  const auto it = counts.find(name);
  EXPECT_NE(it, counts.end()) << name;
  return it == counts.end() ? -1 : it->second;
}

TEST(Lesson14, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson14, EveryViewIsCleanAndDistinct) {
  for (const char* scene : {"contact", "overlap"}) {
    auto runner = startLesson(kLesson, {std::string("scene=") + scene});
    testing::expectEveryViewCleanAndDistinct(*runner, scene);
  }
}

// The penumbra's vis_mae (the truth strictly between 0 and 1) of one mode.
double penumbraError(const std::string& scene, const std::string& mode) {
  auto runner = startLesson(kLesson, {"scene=" + scene, "pcss.mode=" + mode}, 640, 480);
  runner->renderFrame();
  runner->measureError();
  EXPECT_GT(reportNumber(*runner, "/error/penumbra/counted_pixels"), 2000) << scene;
  return reportNumber(*runner, "/error/penumbra/vis_mae");
}

TEST(Lesson14, TheBlockerSearchBeatsOneWidthAndAHardEdgeInThePenumbra) {
  // Measured at 640x480 (README): contact 0.045 / 0.095 / 0.227, overlap 0.049 / 0.173 /
  // 0.229 for pcss / fixed at its best width (6 texels) / hard.
  for (const char* scene : {"contact", "overlap"}) {
    const double pcss = penumbraError(scene, "pcss");
    const double fixed = penumbraError(scene, "fixed");
    const double hard = penumbraError(scene, "hard");
    EXPECT_LT(pcss, 0.6 * fixed) << scene;
    EXPECT_LT(fixed, 0.8 * hard) << scene;
  }
}

TEST(Lesson14, EveryFragmentIsSearchedAndThenFilteredOrSkippedOnce) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  const long long fragments =
      static_cast<long long>(reportNumber(*runner, "/counters/eye/fragments_passed"));
  const long long filtered = counter(*runner, "pcf_filtered_fragments");
  const long long none = counter(*runner, "pcss_no_blocker");
  const long long umbra = counter(*runner, "pcss_all_blockers");
  const long long away = counter(*runner, "pcss_skipped_facing_away");
  const long long search = counter(*runner, "pcss_search_taps");
  EXPECT_GT(filtered, 1000);
  EXPECT_GT(none, 1000);
  EXPECT_GT(umbra, 100);
  EXPECT_EQ(filtered + none + umbra + away, fragments);
  // 16 search taps for every fragment that faces the light, none for the others.
  EXPECT_EQ(search, 16 * (filtered + none + umbra));
  EXPECT_EQ(counter(*runner, "pcf_taps"), 16 * filtered);  // a 16-point Poisson filter

  // Without the umbra skip those fragments run the filter: the same search, the same count.
  ASSERT_EQ(runner->params().assign("pcss.skip_umbra=false"), "");
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "pcss_all_blockers"), 0);
  EXPECT_EQ(counter(*runner, "pcf_filtered_fragments"), filtered + umbra);
  EXPECT_EQ(counter(*runner, "pcss_search_taps"), search);
}

TEST(Lesson14, SearchTapsAreTheSetting) {
  for (int taps : {1, 4, 32}) {
    auto runner = startLesson(kLesson, {"pcss.search_taps=" + std::to_string(taps)});
    runner->renderFrame();
    EXPECT_DOUBLE_EQ(reportNumber(*runner, "/search_taps_per_fragment"), taps);
  }
}

Image visibility(const std::vector<std::string>& sets) {
  auto runner = startLesson(kLesson, sets);
  EXPECT_EQ(runner->params().assign("view=visibility"), "");
  runner->renderFrame();
  return runner->readImage();
}

TEST(Lesson14, APointLightGivesTheHardShadowBitForBit) {
  // Radius 0: the search region shrinks to the pixel's own texel, found is 0 or all, and the
  // answer is the one compare lesson 04 makes.
  const Image hard = visibility({"pcss.light_radius=0", "pcss.mode=hard"});
  EXPECT_EQ(testing::pixelsDiffering(visibility({"pcss.light_radius=0"}), hard, 0), 0u);
  // With the umbra skip off too: the filter then runs with a kernel of radius 0.
  EXPECT_EQ(testing::pixelsDiffering(visibility({"pcss.light_radius=0", "pcss.skip_umbra=false"}),
                                     hard, 0),
            0u);
  // And with a radius the picture is softer: many pixels strictly between black and white.
  EXPECT_GT(testing::pixelsDiffering(visibility({}), hard, 8), 1000u);
}

}  // namespace
}  // namespace shadows
