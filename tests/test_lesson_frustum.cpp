// Where the error is counted (issue 17, item 16): inside the light frustum the lesson reports,
// near to far as well as side to side. Beyond the far plane a map holds nothing of the scene,
// so no lesson's answer there is measured, and every map lesson counts the same pixels.
#include "harness.hpp"

namespace shadows {
namespace {

using testing::label;
using testing::startLesson;

ErrorMetrics measure(const std::string& lesson, const std::vector<std::string>& sets) {
  auto runner = startLesson(lesson, sets);
  runner->renderFrame();
  EXPECT_EQ(runner->glErrors(), 0) << lesson << " " << label(sets);
  return runner->measureError().metrics;
}

// torus_pyramid with the light's frustum from 2 to 8, which leaves the far part of the floor
// and of the casters beyond the far plane, and the most precise map.
const std::vector<std::string> kShortFrustum = {"scene=torus_pyramid", "shadow.fit=false",
                                                "light.near=2", "light.far=8", "shadow.size=4096"};

TEST(LightFrustum, ReceiversBeyondTheFarPlaneAreNotCountedInAnyMapLesson) {
  // Every map lesson counts exactly the same pixels: the frustum decides, not the technique.
  const std::string lessons[] = {"03_shadow_map_basic",  "04_bias_offset",      "05_pcf_dithered",
                                 "06_dual_texture_8bit", "07_multidigit_16bit", "08_atmospherics"};
  std::vector<long long> counted;
  for (const std::string& lesson : lessons) {
    counted.push_back(measure(lesson, kShortFrustum).counted_pixels);
  }
  for (size_t i = 1; i < counted.size(); ++i) EXPECT_EQ(counted[i], counted[0]) << lessons[i];
  // Far 16 holds the whole floor the spot sees: more of it counts.
  std::vector<std::string> longer = kShortFrustum;
  longer[3] = "light.far=16";
  EXPECT_LT(counted[0], measure(lessons[0], longer).counted_pixels * 9 / 10);
}

TEST(LightFrustum, BackFaceMapsAreAsRightAsTheOthersInAShortFrustum) {
  // 04 and 08 put back faces into the map: a caster whose back lies beyond the far plane is
  // lost, and the floor beyond it was counted lit (2.9 % false lit, against 0.05 % for 07's
  // front faces). Beyond the far plane is not counted, so all of them measure alike.
  for (const std::string lesson : {"04_bias_offset", "07_multidigit_16bit", "08_atmospherics"}) {
    const ErrorMetrics e = measure(lesson, kShortFrustum);
    EXPECT_LT(e.false_lit_pct, 0.1) << lesson;
    EXPECT_LT(e.false_shadow_pct, 0.1) << lesson;
    EXPECT_GT(e.counted_pixels, 10000) << lesson;
  }
}

}  // namespace
}  // namespace shadows
