// The arithmetic of lessons 06 and 07, from the very file their shaders include
// (common/shaders/depth_digits.glsl), against exact integer comparisons.
#include "shadow/depth_digits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace shadows {
namespace {

using namespace digits;

TEST(DualTextureTest, TexenvAndAlphaTestLightExactlyWhereTheMapIsBeyondTheFragment) {
  // alpha = a(Tex0) + (1 - a(Tex1)) - 0.5 > 0.5 for every pair of 8-bit values: lit iff the
  // map's byte is strictly greater (ties shadow: 000's "fragments are likely to shadow
  // themselves", which the polygon offset is there to prevent).
  for (int map = 0; map < 256; ++map) {
    for (int ramp = 0; ramp < 256; ++ramp) {
      const float alpha = texenvAlpha(static_cast<float>(map), static_cast<float>(ramp));
      ASSERT_EQ(alphaTestPasses(alpha), map > ramp) << map << " vs " << ramp;
    }
  }
  // Equal values sit exactly on the alpha test's reference, 0.5.
  EXPECT_EQ(texenvAlpha(100.0f, 100.0f), 0.5f);
}

TEST(DualTextureTest, RampIsTheDepthsEightBitStepStoppingOneShortOfTheClearedMap) {
  for (int i = 0; i <= 4096; ++i) {
    const float s = static_cast<float>(i) / 4096.0f;
    const float expected = std::min(std::floor(s * 256.0f), 254.0f);
    ASSERT_EQ(rampSteps(s), expected) << s;
  }
  EXPECT_EQ(rampSteps(-3.0f), 0.0f);   // in front of the near plane
  EXPECT_EQ(rampSteps(7.0f), 254.0f);  // beyond the far plane
  // So a receiver beyond the far plane with nothing in front of it (map cleared to 255) is lit.
  EXPECT_TRUE(alphaTestPasses(texenvAlpha(255.0f, rampSteps(2.0f))));
}

TEST(DualTextureTest, DepthQuantizationRoundsAsTheDriverSays) {
  for (const int nearest : {0, 1}) {
    EXPECT_EQ(depthToSteps(0.0f, 255.0f, nearest), 0.0f);
    EXPECT_EQ(depthToSteps(1.0f, 255.0f, nearest), 255.0f);
    EXPECT_EQ(depthToSteps(1.5f, 255.0f, nearest), 255.0f);
    EXPECT_EQ(depthToSteps(-0.5f, 255.0f, nearest), 0.0f);
  }
  EXPECT_EQ(depthToSteps(0.7f / 255.0f, 255.0f, 0), 0.0f);  // down (Mesa's bytes)
  EXPECT_EQ(depthToSteps(0.7f / 255.0f, 255.0f, 1), 1.0f);  // to nearest (Mesa's shorts)
  EXPECT_EQ(depthToSteps(40000.4f / 65535.0f, 65535.0f, 1), 40000.0f);
  EXPECT_EQ(depthToSteps(40000.6f / 65535.0f, 65535.0f, 0), 40000.0f);
  // Ties go to the even step, as lrintf does: a product of exactly x.5 in float.
  EXPECT_EQ(depthToSteps(59896.5f / 65535.0f, 65535.0f, 1), 59896.0f);
}

// The values on both sides of every big-digit boundary, and a few inside each digit.
std::vector<int> boundaryValues() {
  std::vector<int> values;
  for (int big = 0; big < 256; ++big) {
    for (int little : {0, 1, 2, 127, 253, 254, 255}) values.push_back(big * 256 + little);
  }
  return values;
}

TEST(MultiDigitTest, DigitsRebuildEverySixteenBitValue) {
  for (int v = 0; v < 65536; ++v) {
    const auto value = static_cast<float>(v);
    ASSERT_EQ(bigDigit(value) * 256.0f + littleDigit(value), value);
    ASSERT_EQ(bigDigit(value), static_cast<float>(v >> 8));
    ASSERT_EQ(littleDigit(value), static_cast<float>(v & 255));
  }
}

TEST(MultiDigitTest, PassTwoOrPassThreeLightExactlyWhereTheSixteenBitMapIsBeyond) {
  // Across every big-digit boundary: pass 2 (big digits) or, on the pixels it leaves,
  // pass 3 (little digit) lights the fragment iff map > fragment as 16-bit numbers.
  const std::vector<int> values = boundaryValues();
  long long relit_without_stencil = 0;
  for (int map : values) {
    for (int fragment : values) {
      const vec2 m(bigDigit(static_cast<float>(map)), littleDigit(static_cast<float>(map)));
      const vec2 f(bigDigit(static_cast<float>(fragment)),
                   littleDigit(static_cast<float>(fragment)));
      const bool pass2 = bigDigitPassLights(m, f);
      const bool pass3 = littleDigitPassAlpha(m, f) > 0.0f;
      ASSERT_EQ(pass2 || (!pass2 && pass3), map > fragment) << map << " vs " << fragment;
      if (pass2 && pass3) ++relit_without_stencil;
    }
  }
  // Pass 3's alpha alone would light many of pass 2's pixels again (the big digits differ,
  // the little ones happen to agree): that is what the stencil's 1 is for.
  EXPECT_GT(relit_without_stencil, 10000);
}

TEST(MultiDigitTest, TwoDimensionalRampGivesTheFragmentsSixteenBitDigits) {
  // Tex1 at (s, t = 256 s), read NEAREST from a 256 x 256 ramp: the digits of floor(65536 s),
  // which stop at (255, 254), one short of the cleared map.
  for (int i = 0; i <= 1 << 18; ++i) {
    const float s = static_cast<float>(i) / static_cast<float>(1 << 18);
    const int v = std::min(static_cast<int>(std::floor(s * 65536.0f)), 65534);
    const vec2 d = rampDigits(s);
    ASSERT_EQ(d.x, static_cast<float>(v >> 8)) << s;
    ASSERT_EQ(d.y, static_cast<float>(v & 255)) << s;
  }
  EXPECT_EQ(rampDigits(3.0f), vec2(255.0f, 254.0f));
  EXPECT_EQ(rampDigits(-1.0f), vec2(0.0f, 0.0f));
}

}  // namespace
}  // namespace shadows
