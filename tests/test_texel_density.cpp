// The arithmetic of texels per pixel (common/math/texel_density.hpp): singular values of the
// screen-to-map Jacobian and the report's percentiles.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "math/texel_density.hpp"

namespace shadows {
namespace {

// J = R(a) * diag(s1, s2) * R(b): its singular values are s1 and s2 whatever the rotations.
TEST(TexelDensity, SingularValuesOfRotatedScalings) {
  for (const float a : {0.0f, 0.3f, 1.7f}) {
    for (const float b : {0.0f, -0.8f, 2.9f}) {
      const glm::mat2 ra(std::cos(a), std::sin(a), -std::sin(a), std::cos(a));
      const glm::mat2 rb(std::cos(b), std::sin(b), -std::sin(b), std::cos(b));
      const glm::mat2 j = ra * glm::mat2(3.0f, 0.0f, 0.0f, 0.25f) * rb;
      const glm::vec2 s = singularValues(j[0], j[1]);
      EXPECT_NEAR(s.x, 3.0f, 1e-5f) << a << " " << b;
      EXPECT_NEAR(s.y, 0.25f, 1e-5f) << a << " " << b;
    }
  }
  // A shear: not the column lengths (1 and sqrt 2) but the golden ratio and its inverse.
  const glm::vec2 shear = singularValues({1.0f, 0.0f}, {1.0f, 1.0f});
  EXPECT_NEAR(shear.x, 1.6180340f, 1e-5f);
  EXPECT_NEAR(shear.y, 0.6180340f, 1e-5f);
  // Rank one (a surface seen edge-on) and zero.
  EXPECT_NEAR(singularValues({2.0f, 0.0f}, {4.0f, 0.0f}).y, 0.0f, 1e-6f);
  EXPECT_EQ(singularValues({0.0f, 0.0f}, {0.0f, 0.0f}), glm::vec2(0.0f));
}

TEST(TexelDensity, PercentilesInterpolateBetweenRanks) {
  std::vector<float> v{4.0f, 1.0f, 3.0f, 2.0f};
  EXPECT_FLOAT_EQ(percentile(v, 50), 2.5f);  // the mean of the middle two, as medians are
  EXPECT_FLOAT_EQ(percentile(v, 0), 1.0f);
  EXPECT_FLOAT_EQ(percentile(v, 100), 4.0f);
  EXPECT_FLOAT_EQ(percentile(v, 5), 1.15f);  // rank 0.15
  std::vector<float> none;
  EXPECT_EQ(percentile(none, 50), 0.0f);
}

TEST(TexelDensity, StatsCountOnlyCountedPixelsAndUndersampledByTheLeastAxis) {
  // x least, y most, z counted, w object.
  const std::vector<TexelPixel> pixels{
      {0.5f, 2.0f, 1.0f, 0.0f},    // under-sampled along one axis, over along the other
      {0.995f, 1.0f, 1.0f, 0.0f},  // within the tolerance of one: not under-sampled
      {2.0f, 4.0f, 1.0f, 1.0f},    // over-sampled, another object
      {0.1f, 0.1f, 0.0f, 0.0f},    // not counted
      {NAN, 1.0f, 1.0f, 0.0f},     // not finite: not counted
  };
  const TexelStats all = texelStats(pixels);
  EXPECT_EQ(all.pixels, 3);
  EXPECT_NEAR(all.undersampled_pct, 100.0 / 3.0, 1e-9);
  EXPECT_FLOAT_EQ(all.min_axis.median, 0.995f);
  EXPECT_FLOAT_EQ(all.max_axis.median, 2.0f);
  const TexelStats floor = texelStats(pixels, 0);
  EXPECT_EQ(floor.pixels, 2);
  EXPECT_DOUBLE_EQ(floor.undersampled_pct, 50.0);
  EXPECT_EQ(texelStats(pixels, 7).pixels, 0);
}

}  // namespace
}  // namespace shadows
