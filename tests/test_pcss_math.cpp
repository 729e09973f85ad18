// Lesson 14's arithmetic without GL (14_soft_shadows/pcss_math.hpp, which scene.frag mirrors):
// depths back to distances through real light projections, and Fernando's search region and
// penumbra on cases worked by hand.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "../14_soft_shadows/pcss_math.hpp"

namespace shadows {
namespace {

// The window depth a point at `distance` along the light's axis gets through P.
float windowDepth(const glm::mat4& P, float distance) {
  const glm::vec4 clip = P * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
  return 0.5f * clip.z / clip.w + 0.5f;
}

TEST(PcssMath, StoredDepthsGoBackToTheirDistanceForSpotAndDirectionalLights) {
  const glm::mat4 spot = glm::perspective(glm::radians(60.0f), 1.0f, 2.0f, 16.0f);
  const glm::mat4 sun = glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 60.0f);
  EXPECT_TRUE(pcss::isPerspective(spot));
  EXPECT_FALSE(pcss::isPerspective(sun));
  for (float d : {2.0f, 3.0f, 7.5f, 16.0f}) {
    EXPECT_NEAR(pcss::lightDistance(spot, windowDepth(spot, d)), d, 1e-3f * d) << d;
  }
  for (float d : {1.0f, 20.0f, 60.0f}) {
    EXPECT_NEAR(pcss::lightDistance(sun, windowDepth(sun, d)), d, 1e-3f * d) << d;
  }
  // The near plane is depth 0 (the shader's uNear), the far plane depth 1.
  EXPECT_NEAR(pcss::lightDistance(spot, 0.0f), 2.0f, 1e-4f);
  EXPECT_NEAR(pcss::lightDistance(spot, 1.0f), 16.0f, 1e-3f);
  EXPECT_NEAR(pcss::lightDistance(sun, 0.0f), 1.0f, 1e-4f);
}

TEST(PcssMath, AWorldStepIsTheMapStepTheProjectionMakes) {
  // A spot of 90 degrees: at distance 4 its frustum is 8 wide, so 1 world unit is 1/8 of the
  // map's width; a directional box 20 wide, 1/20 at any distance.
  const glm::mat4 spot = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 20.0f);
  EXPECT_NEAR(pcss::uvPerWorld(spot, 4.0f).x, 1.0f / 8.0f, 1e-6f);
  EXPECT_NEAR(pcss::uvPerWorld(spot, 4.0f).y, 1.0f / 8.0f, 1e-6f);
  const glm::mat4 sun = glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 60.0f);
  EXPECT_NEAR(pcss::uvPerWorld(sun, 4.0f).x, 1.0f / 20.0f, 1e-6f);
  EXPECT_NEAR(pcss::uvPerWorld(sun, 40.0f).x, 1.0f / 20.0f, 1e-6f);
  // As a kernel radius: half a unit at distance 4 on a 1024 map is 1024 / 16 = 64 texels.
  EXPECT_NEAR(pcss::kernelRadiusTexels(0.5f, spot, 4.0f, 1024.0f), 64.0f, 1e-3f);
}

TEST(PcssMath, SearchRegionIsTheConeToTheLightCutAtTheNearPlane) {
  // Light radius 0.4, receiver 8 from the light, near plane at 2: the cone from the receiver
  // to the disk is 0.4 * (8 - 2) / 8 = 0.3 wide there.
  EXPECT_FLOAT_EQ(pcss::searchRadiusWorld(0.4f, 8.0f, 2.0f), 0.3f);
  EXPECT_FLOAT_EQ(pcss::searchRadiusWorld(0.4f, 2.0f, 2.0f), 0.0f);  // on the near plane
  EXPECT_FLOAT_EQ(pcss::searchRadiusWorld(0.4f, 1.0f, 2.0f), 0.0f);  // before it: nothing
  EXPECT_FLOAT_EQ(pcss::searchRadiusWorld(0.0f, 8.0f, 2.0f), 0.0f);  // a point light
}

TEST(PcssMath, PenumbraFromSimilarTriangles) {
  // Fernando's w = (d_receiver - d_blocker) w_light / d_blocker: a blocker halfway between a
  // light of radius 0.5 and the receiver casts a penumbra as wide as the light.
  EXPECT_FLOAT_EQ(pcss::penumbraWorld(0.5f, 8.0f, 4.0f, false), 0.5f);
  EXPECT_FLOAT_EQ(pcss::penumbraWorld(0.5f, 8.0f, 6.0f, false), 0.5f * 2.0f / 6.0f);
  // Touching: no penumbra (contact hardening), and nothing nearer than the receiver, none.
  EXPECT_FLOAT_EQ(pcss::penumbraWorld(0.5f, 8.0f, 8.0f, false), 0.0f);
  EXPECT_FLOAT_EQ(pcss::penumbraWorld(0.5f, 8.0f, 9.0f, false), 0.0f);
  // A directional light's cone is set at the receiver (truth.cpp): gap * R / receiver.
  EXPECT_FLOAT_EQ(pcss::penumbraWorld(0.5f, 8.0f, 4.0f, true), 0.25f);
  // The penumbra grows with the gap, linearly for the directional light.
  EXPECT_LT(pcss::penumbraWorld(0.5f, 8.0f, 7.0f, false),
            pcss::penumbraWorld(0.5f, 8.0f, 5.0f, false));
}

}  // namespace
}  // namespace shadows
