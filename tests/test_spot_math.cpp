// Lesson 02's spotlight falloff without GL (02_projective_texture/spot_math.hpp: the very
// spot.glsl projector.frag includes), against its formula at hand-worked points, for both
// kinds of projector: smoothstep from the cone's edge to its inner angle (a spot), from the
// beam's edge to its inner radius (a parallel projector), and nothing behind either.
#include "../02_projective_texture/spot_math.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace shadows::spot {
namespace {

constexpr float kPi = 3.14159265358979f;
const vec3 kAxis{0.0f, 0.0f, -1.0f};

// A point `angle` radians off the axis, `distance` from the projector.
vec3 offAxis(float angle, float distance = 5.0f) {
  return distance * vec3(std::sin(angle), 0.0f, -std::cos(angle));
}
// smoothstep's own formula: 3t^2 - 2t^3 on t clamped to [0, 1].
double smooth(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

TEST(SpotFalloff, OffIsOneEverywhereEvenBehind) {
  for (const vec3 d : {offAxis(0.0f), offAxis(1.2f), -offAxis(0.0f)}) {
    EXPECT_EQ(spotFalloff(d, kAxis, 0, 0.0f, kPi / 6, 2.0f), 1.0f);
    EXPECT_EQ(spotFalloff(d, kAxis, 1, 0.0f, kPi / 6, 2.0f), 1.0f);
  }
}

TEST(SpotFalloff, ASpotFadesOnTheCosineFromItsInnerAngleToItsEdge) {
  const float half = kPi / 6, falloff = 0.5f;  // the cone's edge at 30 degrees, inner at 15
  const auto at = [&](float angle) {
    return spotFalloff(offAxis(angle), kAxis, 0, falloff, half, 2.0f);
  };
  EXPECT_FLOAT_EQ(at(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(at(kPi / 12), 1.0f);    // the inner angle: full light
  EXPECT_NEAR(at(kPi / 6), 0.0f, 1e-5f);  // the edge: none
  EXPECT_EQ(at(kPi / 4), 0.0f);           // outside the cone
  // Where the cosine lies halfway between the edges' cosines, smoothstep gives 1/2.
  const double mid = std::acos(0.5 * (std::cos(kPi / 6) + std::cos(kPi / 12)));
  EXPECT_NEAR(at(static_cast<float>(mid)), 0.5f, 1e-4f);
  // At 22.5 degrees, by hand: t = (cos 22.5 - cos 30) / (cos 15 - cos 30) = 0.05785 / 0.09990
  // = 0.5791, and 3t^2 - 2t^3 = 0.6177.
  const double expected = smooth(std::cos(kPi / 6), std::cos(kPi / 12), std::cos(kPi / 8));
  EXPECT_NEAR(expected, 0.6177, 1e-3);
  EXPECT_NEAR(at(kPi / 8), expected, 1e-4);
  // The distance plays no part: only the angle does.
  EXPECT_NEAR(spotFalloff(offAxis(kPi / 8, 50.0f), kAxis, 0, falloff, half, 2.0f), expected, 1e-4);
}

TEST(SpotFalloff, FalloffOneFadesASpotFromItsAxisToItsEdge) {
  const float half = kPi / 4;
  EXPECT_FLOAT_EQ(spotFalloff(offAxis(0.0f), kAxis, 0, 1.0f, half, 2.0f), 1.0f);
  const double expected = smooth(std::cos(kPi / 4), 1.0, std::cos(kPi / 8));
  EXPECT_NEAR(spotFalloff(offAxis(kPi / 8), kAxis, 0, 1.0f, half, 2.0f), expected, 1e-4);
  EXPECT_NEAR(spotFalloff(offAxis(kPi / 4), kAxis, 0, 1.0f, half, 2.0f), 0.0f, 1e-5f);
}

TEST(SpotFalloff, BehindASpotIsDark) {
  // Seed 000's point: the angle to the axis is over 90 degrees behind the projector, so a
  // cone under 180 degrees gives no light there, where (s/q, t/q) would mirror the slide.
  EXPECT_EQ(spotFalloff(-offAxis(0.0f), kAxis, 0, 0.2f, kPi / 3, 2.0f), 0.0f);
  EXPECT_EQ(spotFalloff(offAxis(kPi * 0.6f), kAxis, 0, 0.2f, kPi / 3, 2.0f), 0.0f);
}

TEST(SpotFalloff, AParallelProjectorFadesOnTheDistanceFromItsAxis) {
  const float extent = 2.0f, falloff = 0.25f;  // the beam's edge 2 from the axis, inner 1.5
  const auto at = [&](float radial, float along = 3.0f) {
    return spotFalloff(vec3(radial, 0.0f, -along), kAxis, 1, falloff, kPi / 6, extent);
  };
  EXPECT_FLOAT_EQ(at(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(at(1.5f), 1.0f);                            // the inner radius
  EXPECT_NEAR(at(1.75f), 0.5f, 1e-5f);                        // halfway: smoothstep's 1/2
  EXPECT_NEAR(at(1.6f), 1.0 - smooth(0.75, 1.0, 0.8), 1e-5);  // 1 - 3t^2 + 2t^3, t = 0.2
  EXPECT_FLOAT_EQ(at(2.0f), 0.0f);                            // the beam's edge
  EXPECT_EQ(at(3.0f), 0.0f);
  EXPECT_FLOAT_EQ(at(1.75f, 40.0f), at(1.75f));  // no fading along the beam
  EXPECT_EQ(at(0.0f, -1.0f), 0.0f);              // behind it: none
  EXPECT_EQ(at(0.0f, 0.0f), 0.0f);               // in its own plane: none
}

}  // namespace
}  // namespace shadows::spot
