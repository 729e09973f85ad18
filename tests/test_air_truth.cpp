// The truth for lesson 08's air (common/truth/air_truth.cpp) against closed forms: the chord of an
// eye ray through a spot's frustum, the shadow of a sphere on it, and a quadrature of the
// built-in spot along it.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "core/spotlight.hpp"
#include "math/shadow_math.hpp"
#include "test_meshes.hpp"
#include "truth/truth.hpp"

namespace shadows {
namespace {

using testing::Mesh;

constexpr double kPi = 3.14159265358979323846;
const glm::vec3 kLight(0.0f, 10.0f, 0.0f);  // looking straight down
const glm::vec3 kEye(-10.0f, 5.0f, 0.0f);   // looking along +x, 5 below the light
constexpr float kDensity = 0.1f;

void addFloor(Mesh& m) {  // far below, never on the eye ray
  const auto base = static_cast<unsigned>(m.positions.size());
  m.positions.insert(m.positions.end(),
                     {{-30, -5, -30}, {30, -5, -30}, {30, -5, 30}, {-30, -5, 30}});
  m.triangles.emplace_back(base, base + 1, base + 2);
  m.triangles.emplace_back(base, base + 2, base + 3);
}

void addSphere(Mesh& m, glm::vec3 c, float r) {
  testing::addSphere(m, c, r, 256, 128);
}

// A 60-degree spot frustum, far plane 20.
glm::mat4 spotFrustum() {
  return lightProjection({false, 60.0f, 10.0f, 1.0f, 0.5f, 20.0f}) *
         lookAtSafe(kLight, glm::vec3(0.0f));
}

// One pixel whose centre ray is the eye's axis, seeing no surface, in `medium`.
float airOnTheAxis(const Truth& truth, const AirMedium& medium, double* noise = nullptr,
                   float cameraFar = 100.0f) {
  SurfaceBuffer surface{1, 1, {glm::vec4(0, 0, 0, -1)}, {glm::vec4(0.0f)}};
  const glm::mat4 view = glm::lookAt(kEye, kEye + glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
  const glm::mat4 projection = glm::perspective(glm::radians(10.0f), 1.0f, 0.1f, cameraFar);
  const Truth::AirResult air =
      truth.airLight(surface, kEye, glm::inverse(projection * view), medium);
  if (noise != nullptr) *noise = air.noise;
  return air.light[0];
}

// The same in the 60-degree spot.
float airOnTheAxis(const Truth& truth, const SpotTexture* spot, int samples,
                   double* noise = nullptr) {
  return airOnTheAxis(truth, AirMedium{kDensity, kLight, spotFrustum(), spot, samples}, noise);
}

// A directional light straight down from kLight: a box of half width `extent` from `near` to
// `far` below it.
AirMedium directionalDown(float extent, float near, float far, int samples) {
  AirMedium medium{kDensity, kLight,
                   lightProjection({true, 60.0f, extent, 1.0f, near, far}) *
                       lookAtSafe(kLight, kLight - glm::vec3(0.0f, 1.0f, 0.0f)),
                   nullptr, samples};
  medium.directional = true;
  medium.light_direction = {0.0f, -1.0f, 0.0f};
  return medium;
}

// Half the width of the frustum 5 below the light: 5 tan 30.
const double kHalfChord = 5.0 * std::tan(kPi / 6.0);

TEST(AirTruth, UnshadowedAirIsDensityTimesTheChordThroughTheFrustum) {
  Mesh m;
  addFloor(m);
  const Truth truth(m.positions, m.triangles, 30.0f);
  EXPECT_NEAR(airOnTheAxis(truth, nullptr, 64), kDensity * 2.0 * kHalfChord, 1e-4);
}

TEST(AirTruth, ASphereShadowsItsConeOutOfTheAir) {
  // A sphere of radius 1, 2.5 below the light, hides a cone of half-angle asin(1 / 2.5):
  // on the eye ray, 5 below the light, a stretch of 2 * 5 tan(asin 0.4) goes dark.
  Mesh m;
  addFloor(m);
  addSphere(m, {0.0f, 7.5f, 0.0f}, 1.0f);
  const Truth truth(m.positions, m.triangles, 30.0f);
  const double shadow = 2.0 * 5.0 * std::tan(std::asin(0.4));
  const double expected = kDensity * (2.0 * kHalfChord - shadow);
  double noise = 0.0;
  // Each of the two shadow edges can fall inside one of the 4096 strata.
  EXPECT_NEAR(airOnTheAxis(truth, nullptr, 4096, &noise), expected,
              2.0 * kDensity * 2.0 * kHalfChord / 4096 + 2e-3);
  // At 64 samples the edges are resolved to a 64th of the chord (two strata at most wrong).
  const float coarse = airOnTheAxis(truth, nullptr, 64, &noise);
  EXPECT_NEAR(coarse, expected, 4.0 * noise + 2.0 * kDensity * 2.0 * kHalfChord / 64);
}

TEST(AirTruth, BuiltInSpotIntegratesToItsQuadrature) {
  Mesh m;
  addFloor(m);
  const Truth truth(m.positions, m.triangles, 30.0f);
  const SpotTexture spot = SpotTexture::builtin(0.5f);
  // The integral of the spot along the ray, by a fine midpoint rule over the chord.
  const glm::mat4 frustum = spotFrustum();
  const int steps = 200000;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double x = -kHalfChord + (i + 0.5) * 2.0 * kHalfChord / steps;
    const glm::vec4 c = frustum * glm::vec4(static_cast<float>(x), 5.0f, 0.0f, 1.0f);
    sum += spot.value(glm::vec2(c) / c.w * 0.5f + 0.5f);
  }
  const double expected = kDensity * sum * 2.0 * kHalfChord / steps;
  EXPECT_NEAR(airOnTheAxis(truth, &spot, 1024), expected, 0.01 * expected);
  // Through the spot's centre, the fading outer half takes a quarter off the hard chord.
  EXPECT_LT(expected, kDensity * 2.0 * kHalfChord * 0.8);
}

TEST(AirTruth, DoublingTheSamplesMovesLessThanTheNoiseItReports) {
  Mesh m;
  addFloor(m);
  addSphere(m, {0.3f, 7.5f, 0.2f}, 1.0f);
  const Truth truth(m.positions, m.triangles, 30.0f);
  const SpotTexture spot = SpotTexture::builtin(0.35f);
  double noise = 0.0;
  const float at64 = airOnTheAxis(truth, &spot, 64, &noise);
  const float at128 = airOnTheAxis(truth, &spot, 128);
  EXPECT_LE(std::abs(at128 - at64), 3.0 * noise + 1e-6);
  EXPECT_EQ(airOnTheAxis(truth, &spot, 64), at64) << "deterministic";
}

TEST(AirTruth, NoAirBeforeTheNearPlaneOrBeyondTheFarPlane) {
  // The eye ray runs 5 below the light: a frustum from 6 to 20, or from 0.5 to 4, misses it.
  Mesh m;
  addFloor(m);
  const Truth truth(m.positions, m.triangles, 30.0f);
  for (const glm::vec2 range : {glm::vec2(6.0f, 20.0f), glm::vec2(0.5f, 4.0f)}) {
    const glm::mat4 spot = lightProjection({false, 60.0f, 10.0f, 1.0f, range.x, range.y}) *
                           lookAtSafe(kLight, glm::vec3(0.0f));
    EXPECT_EQ(airOnTheAxis(truth, AirMedium{kDensity, kLight, spot, nullptr, 64}), 0.0f)
        << "spot " << range.x << ".." << range.y;
    EXPECT_EQ(airOnTheAxis(truth, directionalDown(3.0f, range.x, range.y, 64)), 0.0f)
        << "directional " << range.x << ".." << range.y;
  }
  // A directional light pointing away from the ray (its box starts at the light and runs up).
  AirMedium away = directionalDown(3.0f, 0.0f, 20.0f, 64);
  away.light_view_projection = lightProjection({true, 60.0f, 3.0f, 1.0f, 0.0f, 20.0f}) *
                               lookAtSafe(kLight, kLight + glm::vec3(0.0f, 1.0f, 0.0f));
  away.light_direction = {0.0f, 1.0f, 0.0f};
  EXPECT_EQ(airOnTheAxis(truth, away), 0.0f);
}

TEST(AirTruth, ARayThatSeesNoSurfaceEndsAtTheCamerasFarPlane) {
  // The eye pass shows nothing beyond its far plane: 12 from the eye, 2 past the light's axis.
  Mesh m;
  addFloor(m);
  const Truth truth(m.positions, m.triangles, 30.0f);
  const AirMedium medium{kDensity, kLight, spotFrustum(), nullptr, 64};
  EXPECT_NEAR(airOnTheAxis(truth, medium, nullptr, 12.0f), kDensity * (kHalfChord + 2.0), 1e-4);
}

TEST(AirTruth, ADirectionalLightsShadowInTheAirIsACylinder) {
  // A sphere of radius 1, 2.5 below the light and 2 to the side of it: parallel rays darken
  // exactly 2 of the box's 8 on the eye ray (x from 1 to 3). Rays toward the light's position
  // would darken a wider stretch, nearer the axis.
  Mesh m;
  addFloor(m);
  addSphere(m, {2.0f, 7.5f, 0.0f}, 1.0f);
  const Truth truth(m.positions, m.triangles, 30.0f);
  const double expected = kDensity * (8.0 - 2.0);
  EXPECT_NEAR(airOnTheAxis(truth, directionalDown(4.0f, 0.0f, 20.0f, 4096)), expected,
              2.0 * kDensity * 8.0 / 4096 + 2e-3);
}

}  // namespace
}  // namespace shadows
