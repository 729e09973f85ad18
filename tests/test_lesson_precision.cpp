// Seed 000: a light "too close throws away valuable depth map precision when using a
// projective frustum". The near plane decides 8-bit projective precision, far barely matters;
// a linear (eye-planar) depth does not care about near at all. Pinned on lesson 06 with the
// frustum set by hand, a 1024² map, torus_pyramid (the table in its README).
#include "harness.hpp"
#include "math/shadow_math.hpp"

namespace shadows {
namespace {

using testing::startLesson;

struct Precision {
  double false_lit_pct, step_at_nearest, step_at_farthest;
};

Precision measure06(float near, float far, const std::string& encoding) {
  auto runner =
      startLesson("06_dual_texture_8bit",
                  {"shadow.fit=false", "shadow.size=1024", "map.encoding=" + encoding,
                   "light.near=" + std::to_string(near), "light.far=" + std::to_string(far)},
                  320, 240);
  runner->renderFrame();
  const double lit = runner->measureError().metrics.false_lit_pct;
  EXPECT_EQ(runner->glErrors(), 0);
  return {lit, testing::reportNumber(*runner, "step_world_at_nearest_caster"),
          testing::reportNumber(*runner, "step_world_at_farthest_caster")};
}

TEST(Precision, TheNearPlaneDecidesEightBitProjectiveDepthNotFarOverNear) {
  // far/near 500, near 2: clean. far/near 60, near 0.2: broken.
  const Precision wide = measure06(2.0f, 1000.0f, "projective");
  const Precision close = measure06(0.2f, 12.0f, "projective");
  EXPECT_LE(wide.false_lit_pct, 0.1);
  EXPECT_GE(close.false_lit_pct, 2.0);
  // And the report says why: the step at the casters is ten times coarser with near 0.2.
  EXPECT_GT(close.step_at_nearest, 5.0 * wide.step_at_nearest);
  EXPECT_GT(close.step_at_farthest, 5.0 * wide.step_at_farthest);
  EXPECT_GT(wide.step_at_farthest, wide.step_at_nearest) << "steps grow with distance";
}

TEST(Precision, LinearDepthIsIndifferentToNear) {
  const Precision near_02 = measure06(0.2f, 12.0f, "linear");
  const Precision near_2 = measure06(2.0f, 12.0f, "linear");
  EXPECT_NEAR(near_02.false_lit_pct, near_2.false_lit_pct, 0.1);
  EXPECT_LE(near_02.false_lit_pct, 0.2);
  // One step is (far - near) / 255 everywhere in the map.
  EXPECT_NEAR(near_02.step_at_nearest, (12.0 - 0.2) / 255.0, 1e-5);
  EXPECT_NEAR(near_02.step_at_farthest, near_02.step_at_nearest, 1e-7);
}

// The step formula against the projection it describes: two window depths one step apart,
// computed from lightProjection, are the formula's distance apart in the world.
TEST(Precision, DepthStepMatchesTheLightProjection) {
  for (const auto& [near, far] : {std::pair{0.2f, 12.0f}, {2.0f, 1000.0f}, {1.0f, 100.0f}}) {
    LightFrustum fr;
    fr.near = near, fr.far = far;
    const glm::mat4 p = lightProjection(fr);
    const auto window = [&](double z) {
      const glm::dvec4 c = glm::dmat4(p) * glm::dvec4(0.0, 0.0, -z, 1.0);
      return 0.5 * c.z / c.w + 0.5;
    };
    for (const float z : {near * 1.5f, 0.5f * (near + far), far * 0.9f}) {
      const double dz = 1e-4 * z;
      const double slope = (window(z + dz) - window(z - dz)) / (2.0 * dz);  // depth per unit
      EXPECT_NEAR(depthStepWorld(fr, z, 255.0, false), 1.0 / (255.0 * slope),
                  1e-3 / (255.0 * slope))
          << near << " " << far << " at " << z;
    }
    EXPECT_FLOAT_EQ(depthStepWorld(fr, 5.0f, 255.0, true), (far - near) / 255.0f);
    fr.directional = true;
    EXPECT_FLOAT_EQ(depthStepWorld(fr, 5.0f, 65535.0, false), (far - near) / 65535.0f);
  }
}

}  // namespace
}  // namespace shadows
