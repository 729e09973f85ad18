// Lesson 11's tetrahedron map (11_omni_cube/tetra_math.hpp, the numbers scene.frag and the map
// pass use): four faces that cover every direction once, each inside its own tile.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../11_omni_cube/tetra_math.hpp"

namespace shadows {
namespace {

TEST(TetraMath, TheFacesAreATetrahedronsAndTheirCornersLie70DegreesOut) {
  for (int i = 0; i < tetra::kFaces; ++i) {
    EXPECT_NEAR(glm::length(tetra::faceDirection(i)), 1.0f, 1e-6f) << i;
    for (int j = i + 1; j < tetra::kFaces; ++j) {
      EXPECT_NEAR(glm::dot(tetra::faceDirection(i), tetra::faceDirection(j)), -1.0f / 3.0f, 1e-6f);
    }
    // A corner is 70.53 degrees from the face's centre: tan = 2 sqrt(2) on the image plane.
    for (const glm::vec2& c : tetra::faceCorners(i)) {
      EXPECT_NEAR(glm::length(c), 2.0f * std::sqrt(2.0f), 1e-4f) << i;
    }
  }
}

TEST(TetraMath, EveryDirectionLandsInsideItsOwnFacesTile) {
  std::mt19937 random(11);
  std::normal_distribution<float> gauss;
  const float near = 0.1f, far = 20.0f;
  for (int n = 0; n < 20000; ++n) {
    const glm::vec3 v = glm::normalize(glm::vec3(gauss(random), gauss(random), gauss(random)));
    const int face = tetra::faceOf(v);
    const glm::vec2 local = 2.0f * (tetra::mapCoord(v, near, far) - tetra::tileOffset(face));
    // The 2 % margin keeps a linear lookup a hundredth of the tile from the next one.
    EXPECT_GE(std::min(local.x, local.y), 0.009f) << n;
    EXPECT_LE(std::max(local.x, local.y), 0.991f) << n;
  }
}

TEST(TetraMath, TheSeamIsWhereTwoFacesMeet) {
  const int tile = 627;
  // Between two faces: on the seam.
  const glm::vec3 between = glm::normalize(tetra::faceDirection(0) + tetra::faceDirection(1));
  EXPECT_LT(tetra::seamDistanceTexels(between, tile), 0.01f);
  // The face's centre: the triangle's inradius, sqrt(2) on the image plane, in texels of the
  // tile's wider side, the triangle's edge 2 sqrt(6) x 1.02: tile / (2 sqrt(3) x 1.02).
  EXPECT_NEAR(tetra::seamDistanceTexels(tetra::faceDirection(2), tile),
              static_cast<float>(tile) / (2.0f * std::sqrt(3.0f) * 1.02f), 0.5f);
  // As many texels as the cube of 512: 4 x 627^2 against 6 x 512^2.
  EXPECT_EQ(tetra::tileSizeFor(512), 627);
}

}  // namespace
}  // namespace shadows
