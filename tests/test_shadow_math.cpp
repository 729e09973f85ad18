// The matrices of the seeds, checked against numbers worked out by hand.
#include "math/shadow_math.hpp"

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

// ---------------------------------------------------------------- planar projected shadows

// The plane through `point` with unit normal `normal`, as (A, B, C, D).
glm::vec4 planeThrough(glm::vec3 point, glm::vec3 normal) {
  const glm::vec3 n = glm::normalize(normal);
  return {n, -glm::dot(n, point)};
}

TEST(PlanarShadowMatrix, PointLightSendsPointsOntoThePlaneAlongTheLightRay) {
  // A tilted plane and a light on its positive side; points between them project onto the
  // plane, on the ray from the light through the point, beyond the point.
  const glm::vec4 plane = planeThrough({0.5f, -0.3f, 0.2f}, {0.3f, 1.0f, -0.2f});
  const glm::vec3 light{1.5f, 6.0f, 2.0f};
  const glm::mat4 m = planarShadowMatrix(plane, glm::vec4(light, 1.0f));
  const glm::vec3 points[] = {{0, 1, 0}, {-1.2f, 0.5f, 0.7f}, {2, 3, -1}, {1.4f, 5.5f, 1.9f}};
  for (const glm::vec3& v : points) {
    ASSERT_GT(glm::dot(plane, glm::vec4(v, 1)), 0.0f) << "test point on the light's side";
    const glm::vec4 h = m * glm::vec4(v, 1.0f);
    ASSERT_GT(h.w, 0.0f) << "between the plane and the light: w > 0, kept by the clipper";
    const glm::vec3 p = glm::vec3(h) / h.w;
    EXPECT_NEAR(glm::dot(plane, glm::vec4(p, 1)), 0.0f, 1e-4f) << "on the plane";
    const glm::vec3 to_point = v - light, to_shadow = p - light;
    EXPECT_NEAR(glm::length(glm::cross(to_point, to_shadow)) / glm::length(to_shadow), 0.0f, 1e-4f)
        << "on the line from the light through the point";
    EXPECT_GE(glm::dot(to_shadow, to_point), glm::dot(to_point, to_point) - 1e-4f)
        << "beyond the point, not between the light and it";
  }
}

TEST(PlanarShadowMatrix, DirectionalLightSendsPointsAlongTheDirection) {
  const glm::vec4 plane = planeThrough({0, -0.5f, 0}, {0, 1, 0.4f});
  const glm::vec3 toward_light = glm::normalize(glm::vec3(-2, 4, -1));
  const glm::mat4 m = planarShadowMatrix(plane, glm::vec4(toward_light, 0.0f));
  for (const glm::vec3& v : {glm::vec3(0, 1, 0), glm::vec3(1.5f, 2, -3), glm::vec3(-4, 0.2f, 2)}) {
    const glm::vec4 h = m * glm::vec4(v, 1.0f);
    EXPECT_NEAR(h.w, glm::dot(plane, glm::vec4(toward_light, 0)), kEps) << "w = P.L for all";
    const glm::vec3 p = glm::vec3(h) / h.w;
    EXPECT_NEAR(glm::dot(plane, glm::vec4(p, 1)), 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(glm::cross(v - p, toward_light)), 0.0f, 1e-4f) << "parallel rays";
    EXPECT_GT(glm::dot(v - p, toward_light), 0.0f) << "the point lies toward the light";
  }
}

TEST(PlanarShadowMatrix, MatchesSeed001ForADirectionAndTheGroundFormulaForAPoint) {
  // Seed 001 writes the matrix for (x, y, z), the vector to the light, row by row:
  // [By+Cz, -Bx, -Cx, -Dx; -Ay, Ax+Cz, -Cy, -Dy; -Az, -Bz, Ax+By, -Dz; 0, 0, 0, Ax+By+Cz].
  const float a = 0.2f, b = 0.9f, c = -0.3f, d = 0.7f, x = 1.5f, y = 4.0f, z = -2.0f;
  const float rows[4][4] = {{b * y + c * z, -b * x, -c * x, -d * x},
                            {-a * y, a * x + c * z, -c * y, -d * y},
                            {-a * z, -b * z, a * x + b * y, -d * z},
                            {0, 0, 0, a * x + b * y + c * z}};
  const glm::mat4 m = planarShadowMatrix({a, b, c, d}, {x, y, z, 0});
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) EXPECT_NEAR(m[col][row], rows[row][col], kEps);
  }
  // Seed 001 "Computing Shadow Vertex" (and 003's similar triangles) for the ground y = 0:
  // x_p = x_l - y_l (x - x_l) / (y - y_l), and the same for z.
  const glm::vec3 light{1, 5, 2}, v{-0.5f, 1.5f, 0.5f};
  const glm::vec4 h = planarShadowMatrix({0, 1, 0, 0}, glm::vec4(light, 1)) * glm::vec4(v, 1);
  EXPECT_NEAR(h.x / h.w, light.x - light.y * (v.x - light.x) / (v.y - light.y), kEps);
  EXPECT_NEAR(h.y / h.w, 0.0f, kEps);
  EXPECT_NEAR(h.z / h.w, light.z - light.y * (v.z - light.z) / (v.y - light.y), kEps);
}

TEST(PlanarShadowMatrix, WSeparatesWhatCanCastFromWhatCannot) {
  // Ground plane, light at height 4: w = 4 - y. Points on the plane stay put (w = 4),
  // points at the light's height go to infinity (w = 0), points above it get w < 0 and
  // are removed by the clipper instead of becoming an inverted "anti-shadow".
  const glm::mat4 m = planarShadowMatrix({0, 1, 0, 0}, {1, 4, -1, 1});
  const glm::vec4 on_plane = m * glm::vec4(2, 0, 3, 1);
  EXPECT_NEAR(on_plane.w, 4.0f, kEps);
  EXPECT_NEAR(on_plane.x / on_plane.w, 2.0f, kEps);
  EXPECT_NEAR(on_plane.z / on_plane.w, 3.0f, kEps);
  EXPECT_NEAR((m * glm::vec4(0, 4, 0, 1)).w, 0.0f, kEps);
  EXPECT_LT((m * glm::vec4(0, 5, 0, 1)).w, 0.0f);
  // The same plane written with the opposite sign is the same plane, but every w flips:
  // the real shadow would be clipped away and only the parts above the light kept.
  const glm::mat4 flipped = planarShadowMatrix({0, -1, 0, 0}, {1, 4, -1, 1});
  EXPECT_LT((flipped * glm::vec4(0, 1, 0, 1)).w, 0.0f);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isfinite(m[k][k]));
}

}  // namespace
}  // namespace shadows
