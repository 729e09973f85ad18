// The matrices of the seeds, checked against numbers worked out by hand.
#include "shadow_math.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace shadows {
namespace {

constexpr float kEps = 1e-5f;

TEST(BiasMatrix, MapsClipCubeCornersToUnitCube) {
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 clip{(corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f,
                         (corner & 4) ? 1.0f : -1.0f, 1.0f};
    const glm::vec4 tex = biasMatrix() * clip;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(tex[k], clip[k] > 0 ? 1.0f : 0.0f, kEps);
    EXPECT_NEAR(tex.w, 1.0f, kEps);
  }
  // The centre of clip space lands in the middle of the texture.
  const glm::vec4 centre = biasMatrix() * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(centre.x, 0.5f, kEps);
  EXPECT_NEAR(centre.z, 0.5f, kEps);
}

TEST(BiasMatrix, CommutesWithTheHomogeneousDivide) {
  // B works on (x, y, z, w) before the divide: (B c)/w == B (c/w) for any w > 0.
  const glm::vec4 clip{0.6f, -1.2f, 1.5f, 2.0f};
  const glm::vec4 tex = biasMatrix() * clip;
  const glm::vec3 after = glm::vec3(tex) / tex.w;
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  EXPECT_NEAR(after.x, 0.5f * ndc.x + 0.5f, kEps);
  EXPECT_NEAR(after.y, 0.5f * ndc.y + 0.5f, kEps);
  EXPECT_NEAR(after.z, 0.5f * ndc.z + 0.5f, kEps);
}

TEST(ShadowTextureMatrix, OrthographicLightSendsAWorldPointToTheTexelAndDepthByHand) {
  // A directional light at (0, 10, 0) looking straight down, box +-5, near 1, far 21.
  // The world point (2.5, 0, -1) is 10 units below the light: depth (10 - 1) / 20 = 0.45.
  // lookAtSafe picks up = -z when looking along -y, so light x = world x and light y = -z:
  // s = 0.5 + 2.5 / 10 = 0.75, t = 0.5 + 1 / 10 = 0.6.
  const glm::mat4 view = lookAtSafe({0, 10, 0}, {0, 0, 0});
  const glm::mat4 projection = lightProjection({true, 60, 5.0f, 1.0f, 1.0f, 21.0f});
  const glm::vec4 stpq = shadowTextureMatrix(projection, view) * glm::vec4(2.5f, 0, -1, 1);
  EXPECT_NEAR(stpq.x / stpq.w, 0.75f, kEps);
  EXPECT_NEAR(stpq.y / stpq.w, 0.6f, kEps);
  EXPECT_NEAR(stpq.z / stpq.w, 0.45f, kEps);
  // In a 1024-wide map that is texel (768, 614).
  EXPECT_EQ(static_cast<int>(stpq.x / stpq.w * 1024), 768);
  EXPECT_EQ(static_cast<int>(stpq.y / stpq.w * 1024), 614);
}

TEST(ShadowTextureMatrix, PerspectiveLightDepthFollowsTheWindowDepthFormula) {
  // A spot light at the origin looking down -z, 90 degrees, near 1, far 10. A point at
  // distance d on the axis has window depth (f + n)/(2(f - n)) - f n/((f - n) d) + 1/2.
  const glm::mat4 view = lookAtSafe({0, 0, 0}, {0, 0, -1});
  const glm::mat4 projection = lightProjection({false, 90, 10, 1.0f, 1.0f, 10.0f});
  const glm::mat4 texture = shadowTextureMatrix(projection, view);
  for (float d : {1.0f, 2.0f, 5.0f, 10.0f}) {
    const glm::vec4 stpq = texture * glm::vec4(0, 0, -d, 1);
    const float n = 1, f = 10;
    const float expected = (f + n) / (2 * (f - n)) - f * n / ((f - n) * d) + 0.5f;
    EXPECT_NEAR(stpq.z / stpq.w, expected, kEps) << "distance " << d;
    EXPECT_NEAR(stpq.x / stpq.w, 0.5f, kEps);
    EXPECT_NEAR(stpq.w, d, kEps);  // q is the distance along the axis
  }
  // A point at 45 degrees to the right sits on the right edge of a 90-degree frustum.
  const glm::vec4 edge = texture * glm::vec4(3, 0, -3, 1);
  EXPECT_NEAR(edge.x / edge.w, 1.0f, kEps);
}

TEST(LookAtSafe, NeverProducesNonFiniteMatrices) {
  const glm::vec3 cases[][2] = {{{0, 5, 0}, {0, 0, 0}},   // straight down (parallel to up)
                                {{0, -5, 0}, {0, 0, 0}},  // straight up
                                {{1, 1, 1}, {1, 1, 1}}};  // eye == target
  for (const auto& c : cases) {
    const glm::mat4 m = lookAtSafe(c[0], c[1]);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(m[i][j]));
    }
    EXPECT_NEAR(std::abs(glm::determinant(m)), 1.0f, 1e-4f);
  }
}

TEST(LightProjection, DegenerateSlidersGiveInvertibleMatrices) {
  const LightFrustum cases[] = {{false, 60, 10, 1, 5, 5},          // near == far
                                {false, 60, 10, 1, 0, 10},         // near = 0
                                {false, 0, 10, 1, 1, 10},          // fov 0
                                {false, 180, 10, 1, 1, 10},        // fov 180
                                {true, 60, 0, 1, 1, 10},           // empty box
                                {false, 60, 10, 0, 1, 10},         // zero aspect
                                {false, 60, 10, 1, 0.01f, 1e5f}};  // extreme range
  for (const auto& f : cases) {
    const glm::mat4 p = lightProjection(f);
    EXPECT_GT(std::abs(glm::determinant(p)), 0.0f);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(p[i][j]));
    }
  }
}

TEST(FitNearFar, EnclosesTheBoundsTightly) {
  Bounds b;
  b.add({-1, 0, -1});
  b.add({1, 2, 1});
  const glm::mat4 view = lookAtSafe({0, 10, 0}, {0, 0, 0});
  float near = 0.1f, far = 1000.0f;
  ASSERT_TRUE(fitNearFar(view, b, false, near, far));
  // The box spans 8..10 below the light, plus a 1% margin.
  EXPECT_NEAR(near, 8.0f - 0.02f, 1e-4f);
  EXPECT_NEAR(far, 10.0f + 0.02f, 1e-4f);
  // All behind a spot light: nothing to fit, values untouched.
  const glm::mat4 away = lookAtSafe({0, 10, 0}, {0, 20, 0});
  near = 0.5f, far = 7.0f;
  EXPECT_FALSE(fitNearFar(away, b, false, near, far));
  EXPECT_EQ(near, 0.5f);
  EXPECT_FALSE(fitNearFar(view, Bounds{}, false, near, far));
}

TEST(SphereOutsideFrustum, CullsOnlyWhatIsReallyOutside) {
  const glm::mat4 vp =
      glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 10.0f) * lookAtSafe({0, 0, 0}, {0, 0, -1});
  EXPECT_FALSE(sphereOutsideFrustum(vp, {0, 0, -5}, 0.5f));     // inside
  EXPECT_FALSE(sphereOutsideFrustum(vp, {5.2f, 0, -5}, 0.5f));  // straddles the side plane
  EXPECT_TRUE(sphereOutsideFrustum(vp, {8, 0, -5}, 0.5f));      // right of it
  EXPECT_TRUE(sphereOutsideFrustum(vp, {0, 0, 5}, 1.0f));       // behind the eye
  EXPECT_TRUE(sphereOutsideFrustum(vp, {0, 0, -12}, 1.0f));     // beyond far
}

}  // namespace
}  // namespace shadows
