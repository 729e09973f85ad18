// Lesson 13's moment shadow maps (13_filterable_maps/msm_math.hpp, mirrored by moments.frag and
// scene.frag): the paper's quantization, and the four-moment bound against distributions of
// depths whose lit fraction is known, beside VSM's two-moment Chebyshev bound.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "../13_filterable_maps/msm_math.hpp"

namespace shadows {
namespace {

struct Depths {
  std::vector<float> z, weight;  // a filter's texels: depths and their shares (sum 1)
  glm::vec4 moments() const {
    glm::vec4 m(0.0f);
    for (size_t i = 0; i < z.size(); ++i) m += weight[i] * msm::powers(z[i]);
    return m;
  }
  float lit(float t) const {  // the truth: the share at or beyond t
    float s = 0.0f;
    for (size_t i = 0; i < z.size(); ++i) s += z[i] >= t ? weight[i] : 0.0f;
    return s;
  }
  // What the map holds after the blur: the average of the stored values, decoded.
  glm::vec4 storedThenDecoded() const {
    glm::vec4 s(0.0f);
    for (size_t i = 0; i < z.size(); ++i) s += weight[i] * msm::encode(z[i]);
    return msm::decode(s, msm::decodeMatrix());
  }
};

// VSM's answer from the same texels (scene.frag's chebyshev, no minimum variance).
float chebyshev(const Depths& d, float t) {
  const glm::vec4 m = d.moments();
  if (t <= m.x) return 1.0f;
  const float variance = m.y - m.x * m.x, gap = t - m.x;
  return variance / (variance + gap * gap);
}

constexpr float kBias = 3e-5f;

TEST(MsmMath, TheQuantizationKeepsEveryDepthInTheUnitRangeAndComesBack) {
  const glm::mat4 decode = msm::decodeMatrix();
  for (int i = 0; i <= 1000; ++i) {
    const float z = static_cast<float>(i) / 1000.0f;
    const glm::vec4 stored = msm::encode(z);
    for (int k = 0; k < 4; ++k) {  // the paper's matrix touches 0 and 1: a float's rounding
      EXPECT_GE(stored[k], -1e-6f) << z << " channel " << k;
      EXPECT_LE(stored[k], 1.0f + 1e-6f) << z << " channel " << k;
    }
    const glm::vec4 back = msm::decode(stored, decode), exact = msm::powers(z);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(back[k], exact[k], 2e-5f) << z << " moment " << k;
  }
}

TEST(MsmMath, AReceiverInFrontOfEveryTexelIsLit) {
  const Depths d{{0.5f, 0.7f}, {0.4f, 0.6f}};
  EXPECT_NEAR(msm::litFraction(d.moments(), 0.3f, kBias), 1.0f, 1e-3f);
  EXPECT_NEAR(msm::litFraction(d.moments(), 0.5f, kBias), 1.0f, 1e-3f);  // its own depth
}

TEST(MsmMath, OneBlockerOverOneReceiverIsExact) {
  for (float share : {0.1f, 0.25f, 0.5f, 0.9f}) {
    const Depths d{{0.3f, 0.6f}, {share, 1.0f - share}};
    EXPECT_NEAR(msm::litFraction(d.storedThenDecoded(), 0.6f, kBias), d.lit(0.6f), 2e-3f) << share;
  }
}

// Seed 002's case against VSM: two blockers at different depths share the filter over a
// receiver behind both. Chebyshev's bound lets light through (bleeding); four moments do not.
TEST(MsmMath, TwoBlockersAtTwoDepthsDoNotBleedAsInVsm) {
  const Depths d{{0.2f, 0.6f}, {0.5f, 0.5f}};
  const float t = 0.7f;
  EXPECT_EQ(d.lit(t), 0.0f);
  EXPECT_GT(chebyshev(d, t), 0.25f) << "VSM bleeds";
  EXPECT_LT(msm::litFraction(d.storedThenDecoded(), t, kBias), 0.01f);
  // Two blockers and the receiver's own texels: three depths, still exact.
  const Depths three{{0.2f, 0.6f, 0.7f}, {0.3f, 0.3f, 0.4f}};
  EXPECT_NEAR(msm::litFraction(three.storedThenDecoded(), t, kBias), 0.4f, 3e-3f);
  EXPECT_GT(chebyshev(three, t), 0.55f) << "VSM bleeds";
}

// Both are upper bounds on the lit share (less the bias's pull); four moments never looser than
// two: the distributions the four allow are among those the two allow.
TEST(MsmMath, TheFourMomentBoundLiesBetweenTheTruthAndChebyshevs) {
  std::mt19937 random(13);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 2000; ++trial) {
    Depths d;
    float sum = 0.0f;
    for (int i = 0; i < 5; ++i) {
      d.z.push_back(0.05f + 0.9f * unit(random));
      d.weight.push_back(unit(random));
      sum += d.weight.back();
    }
    for (float& w : d.weight) w /= sum;
    const float t = 0.05f + 0.9f * unit(random);
    const float truth = d.lit(t), msm = msm::litFraction(d.storedThenDecoded(), t, kBias);
    EXPECT_GE(msm, truth - 0.01f) << trial;
    EXPECT_LE(msm, chebyshev(d, t) + 0.01f) << trial;
  }
}

}  // namespace
}  // namespace shadows
