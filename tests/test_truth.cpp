// Ground truth against closed-form shadows of a sphere over a plane, plus its contracts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

#include "test_meshes.hpp"
#include "truth/truth.hpp"

namespace shadows {
namespace {

using testing::addSphere;
using testing::Mesh;

constexpr double kPi = 3.14159265358979323846;

void addPlane(Mesh& m, float half) {
  const auto base = static_cast<unsigned>(m.positions.size());
  m.positions.insert(m.positions.end(),
                     {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}});
  m.triangles.emplace_back(base, base + 1, base + 2);
  m.triangles.emplace_back(base, base + 2, base + 3);
}

// The scene of most tests: sphere of radius 1 centred 2 above a 20x20 plane.
const glm::vec3 kCentre(0.0f, 2.0f, 0.0f);
constexpr float kRadius = 1.0f;
constexpr float kSceneRadius = 15.0f;

Mesh sphereOverPlane() {
  Mesh m;
  addSphere(m, kCentre, kRadius, 256, 128);
  addPlane(m, 10.0f);
  return m;
}

// Orthographic top view of the plane: pixel (x, y) is the plane point at its centre.
struct Grid {
  int width, height;
  double x0, z0, pixel;
  glm::dvec3 at(int x, int y) const {
    return {x0 + (x + 0.5) * pixel, 0.0, z0 + (y + 0.5) * pixel};
  }
};

SurfaceBuffer planeSurface(const Grid& g) {
  SurfaceBuffer s;
  s.width = g.width;
  s.height = g.height;
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      s.position.emplace_back(glm::vec3(g.at(x, y)), 0.0f);
      s.normal.emplace_back(0.0f, 1.0f, 0.0f, 0.0f);
    }
  }
  return s;
}

// Does the ray p + t*d, t in [0, tmax], meet the sphere? p lies outside it.
bool raySphere(glm::dvec3 p, glm::dvec3 d, double tmax) {
  const glm::dvec3 oc = p - glm::dvec3(kCentre);
  const double a = glm::dot(d, d);
  const double b = 2.0 * glm::dot(d, oc);
  const double c = glm::dot(oc, oc) - double(kRadius) * kRadius;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  const double t = (-b - std::sqrt(disc)) / (2.0 * a);  // nearer root; both share a sign
  return t >= 0.0 && t <= tmax;
}

// Compares a hard-shadow truth with the analytic mask; boundary pixels (whose 8 neighbours
// disagree analytically) may differ. Returns {analytic shadowed, truth shadowed}.
template <typename Shadowed>
std::pair<int, int> checkAgainstAnalytic(const Grid& g, const std::vector<float>& vis,
                                         Shadowed shadowed, bool hard = true) {
  int analyticCount = 0, truthCount = 0, mismatches = 0;
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const float v = vis[static_cast<std::size_t>(y * g.width + x)];
      EXPECT_TRUE(!hard || v == 0.0f || v == 1.0f)
          << "hard light gave " << v << " at " << x << "," << y;
      const bool a = shadowed(g.at(x, y));
      const bool t = v < 0.5f;
      analyticCount += a;
      truthCount += t;
      if (a == t) continue;
      bool boundary = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) boundary |= shadowed(g.at(x + dx, y + dy)) != a;
      }
      if (!boundary && ++mismatches <= 10) {
        ADD_FAILURE() << "pixel " << x << "," << y << " analytic " << a << " truth " << t;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
  return {analyticCount, truthCount};
}

TEST(Truth, PointLightMatchesClosedFormSphereShadow) {
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  TruthLight light;
  light.position = glm::vec3(0.7f, 6.0f, 0.3f);
  // The shadow centre is near (-0.35, 0, -0.15) with semi-axes under 2: a 5x5 window.
  const Grid g{200, 200, -2.85, -2.65, 0.025};
  const std::vector<float> vis = truth.visibility(planeSurface(g), light);
  const glm::dvec3 l(light.position);
  const auto [analytic, traced] =
      checkAgainstAnalytic(g, vis, [&](glm::dvec3 p) { return raySphere(p, l - p, 1.0); });
  EXPECT_GT(analytic, 10000);  // the test is not vacuous: a big shadow, lit pixels around it
  EXPECT_LT(analytic, g.width * g.height / 2);
  EXPECT_GT(traced, 0);
  // The inscribed mesh and the ray offset both shrink the shadow very slightly (observed
  // 0.13% for the point light); a half-pixel shift of the whole edge would be ~1.7%.
  EXPECT_NEAR(traced, analytic, 0.003 * analytic);
}

TEST(Truth, DirectionalLightMatchesClosedFormSphereShadow) {
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  TruthLight light;
  light.directional = true;
  light.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.25f));
  light.position = kCentre - 10.0f * light.direction;
  // The sphere's shadow is centred at (0.8, 0, -0.5), semi-axes about 1 and 1.2.
  const Grid g{160, 160, -1.2, -2.5, 0.025};
  const std::vector<float> vis = truth.visibility(planeSurface(g), light);
  const glm::dvec3 toLight = -glm::dvec3(light.direction);
  const auto [analytic, traced] =
      checkAgainstAnalytic(g, vis, [&](glm::dvec3 p) { return raySphere(p, toLight, 1e30); });
  EXPECT_GT(analytic, 5000);
  EXPECT_LT(analytic, g.width * g.height / 2);
  EXPECT_GT(traced, 0);
  // Observed: 1 pixel of ~5550. A half-pixel shift of the whole edge would be ~2%.
  EXPECT_NEAR(traced, analytic, 0.003 * analytic);
}

TEST(Truth, DirectionalAreaLightTendsToTheHardShadow) {
  // A tiny directional disk must give the parallel-projection shadow, not a perspective one
  // from `position`: the cone of directions is the same for every pixel.
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  TruthLight light;
  light.directional = true;
  light.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.25f));
  light.position = glm::vec3(-3.0f, 9.0f, 4.0f);  // on no particular axis
  light.radius = 1e-4f;
  light.samples = 4;
  const Grid g{160, 160, -1.2, -2.5, 0.025};
  const std::vector<float> vis = truth.visibility(planeSurface(g), light);
  const glm::dvec3 toLight = -glm::dvec3(light.direction);
  const auto [analytic, traced] = checkAgainstAnalytic(
      g, vis, [&](glm::dvec3 p) { return raySphere(p, toLight, 1e30); }, false);
  EXPECT_NEAR(traced, analytic, 0.003 * analytic);
}

TEST(Truth, PointLightIgnoresOccludersAtAndBeyondTheLight) {
  // Floor at y=0, ceiling at y=6. A point light just under the ceiling, or on it, lights the
  // floor (the ray stops short of the light); a directional light from above is blocked.
  Mesh m;
  addPlane(m, 10.0f);
  const auto base = static_cast<unsigned>(m.positions.size());
  for (const glm::vec3& p : std::vector<glm::vec3>(m.positions)) {
    m.positions.push_back(p + glm::vec3(0.0f, 6.0f, 0.0f));
  }
  m.triangles.emplace_back(base, base + 2, base + 1);
  m.triangles.emplace_back(base, base + 3, base + 2);
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  const Grid g{16, 16, -4.0, -4.0, 0.5};
  const SurfaceBuffer s = planeSurface(g);
  TruthLight light;
  for (float y : {5.0f, 6.0f}) {
    light.position = glm::vec3(0.3f, y, -0.2f);
    EXPECT_EQ(truth.visibility(s, light), std::vector<float>(s.position.size(), 1.0f)) << y;
  }
  light.directional = true;
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.position = glm::vec3(0.0f, 5.0f, 0.0f);  // under the ceiling: direction still wins
  EXPECT_EQ(truth.visibility(s, light), std::vector<float>(s.position.size(), 0.0f));
}

TEST(Truth, LitSideOfTheSphereHasNoSelfShadowAtAnyScale) {
  // Face centroids of a convex mesh with their geometric normals: every face turned to the
  // light must be fully lit, down to the terminator. At a 1e4 scale an absolute epsilon is
  // lost in float rounding; at 1e-2 it would swallow geometry: the offset must be relative.
  for (float scale : {1.0f, 1e4f, 1e-2f}) {
    Mesh m = sphereOverPlane();
    for (glm::vec3& p : m.positions) p = p * scale + glm::vec3(3.0f, 1.0f, -2.0f) * scale;
    const Truth truth(m.positions, m.triangles, kSceneRadius * scale);
    SurfaceBuffer s;
    for (const glm::uvec3& t : m.triangles) {
      const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
      if (a.y < 1.5f * scale) continue;  // sphere only
      s.position.emplace_back((a + b + c) / 3.0f, 0.0f);
      s.normal.emplace_back(glm::normalize(glm::cross(b - a, c - a)), 0.0f);
    }
    s.width = static_cast<int>(s.position.size());
    s.height = 1;
    TruthLight light;
    light.position = (glm::vec3(3.0f, 4.0f, 1.0f) + glm::vec3(3.0f, 1.0f, -2.0f)) * scale;
    const std::vector<float> vis = truth.visibility(s, light);
    int counted = 0, shadowed = 0;
    for (float v : vis) {
      counted += v != kNotCounted;
      shadowed += v != kNotCounted && v != 1.0f;
    }
    EXPECT_EQ(shadowed, 0) << "scale " << scale;
    EXPECT_GT(counted, static_cast<int>(vis.size()) / 4);
    EXPECT_LT(counted, static_cast<int>(vis.size()));
  }
}

TEST(Truth, Deterministic) {
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  const Truth rebuilt(m.positions, m.triangles, kSceneRadius);
  const Grid g{96, 96, -2.85, -2.65, 5.0 / 96};
  const SurfaceBuffer s = planeSurface(g);
  TruthLight point;
  point.position = glm::vec3(0.7f, 6.0f, 0.3f);
  TruthLight area = point;
  area.radius = 0.5f;
  area.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  area.samples = 16;
  for (const TruthLight& light : {point, area}) {
    const std::vector<float> a = truth.visibility(s, light);
    const std::vector<float> b = truth.visibility(s, light);
    const std::vector<float> c = rebuilt.visibility(s, light);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), c.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(a.data(), c.data(), a.size() * sizeof(float)), 0);
  }
}

// Umbra, penumbra and lit surroundings of an area light; values are multiples of 1/n.
void checkSoftShadow(const std::vector<float>& vis, const Grid& g, int umbraX, int umbraY, int n) {
  int penumbra = 0;
  for (float v : vis) {
    ASSERT_GE(v, 0.0f);
    ASSERT_LE(v, 1.0f);
    const float scaled = v * static_cast<float>(n);
    EXPECT_NEAR(scaled, std::round(scaled), 1e-4) << v << " is not a multiple of 1/" << n;
    penumbra += v > 0.0f && v < 1.0f;
  }
  EXPECT_GT(penumbra, 500);
  EXPECT_EQ(vis[static_cast<std::size_t>(umbraY * g.width + umbraX)], 0.0f);
  for (int i = 0; i < g.width; ++i) {  // the window's border lies outside the penumbra
    EXPECT_EQ(vis[static_cast<std::size_t>(i)], 1.0f);
    EXPECT_EQ(vis[static_cast<std::size_t>((g.height - 1) * g.width + i)], 1.0f);
    EXPECT_EQ(vis[static_cast<std::size_t>(i * g.width)], 1.0f);
    EXPECT_EQ(vis[static_cast<std::size_t>(i * g.width + g.width - 1)], 1.0f);
  }
}

TEST(Truth, AreaLightHasUmbraPenumbraAndLitSurroundings) {
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  TruthLight light;
  light.position = glm::vec3(0.7f, 6.0f, 0.3f);
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.radius = 0.5f;
  light.samples = 64;
  const Grid g{120, 120, -3.35, -3.15, 0.05};  // shadow centre (-0.35, -0.15) at pixel 60,60
  const std::vector<float> vis = truth.visibility(planeSurface(g), light);
  checkSoftShadow(vis, g, 60, 60, 64);

  // The disk contains the point light, so the umbra lies inside the point light's shadow.
  TruthLight hard = light;
  hard.radius = 0.0f;
  const std::vector<float> hardVis = truth.visibility(planeSurface(g), hard);
  for (std::size_t i = 0; i < vis.size(); ++i) {
    if (vis[i] == 0.0f) {
      EXPECT_EQ(hardVis[i], 0.0f) << i;
    }
  }
}

TEST(Truth, DirectionalAreaLightHasUmbraPenumbraAndLitSurroundings) {
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  TruthLight light;
  light.directional = true;
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.position = glm::vec3(0.0f, 8.0f, 0.0f);
  light.radius = 0.6f;
  light.samples = 49;
  const Grid g{100, 100, -2.5, -2.5, 0.05};  // shadow centred under the sphere, at pixel 50,50
  const std::vector<float> vis = truth.visibility(planeSurface(g), light);
  checkSoftShadow(vis, g, 50, 50, 49);
}

// A disk light over the straight edge of a half-plane: the part of the disk a floor point sees
// is a circular segment, so its visibility has a closed form across the whole penumbra. Light
// disk of radius R at height H, the occluder's edge x = 0 at height h: the ray to the disk
// point q passes the occluder's height at x0 + (q.x - x0) h / H, so q is hidden when
// q.x < c = x0 (1 - H / h), and the visible fraction is the segment x >= c of the disk.
TEST(Truth, DiskLightOverAnEdgeGivesTheCircularSegmentProfile) {
  constexpr float kH = 4.0f, kEdgeHeight = 2.0f, kR = 0.5f;
  Mesh m;
  addPlane(m, 10.0f);
  const auto base = static_cast<unsigned>(m.positions.size());
  m.positions.insert(m.positions.end(), {{-20.0f, kEdgeHeight, -20.0f},
                                         {0.0f, kEdgeHeight, -20.0f},
                                         {0.0f, kEdgeHeight, 20.0f},
                                         {-20.0f, kEdgeHeight, 20.0f}});
  m.triangles.emplace_back(base, base + 1, base + 2);
  m.triangles.emplace_back(base, base + 2, base + 3);
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  TruthLight light;
  light.position = glm::vec3(0.0f, kH, 0.0f);
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.radius = kR;
  light.samples = 256;
  // Across the penumbra (x0 in [-R, R] here, as 1 - H/h = -1), several rows in z.
  const Grid g{64, 8, -0.64, -0.4, 0.02};
  const std::vector<float> vis = truth.visibility(planeSurface(g), light);
  double squared = 0.0, worst = 0.0;
  int penumbra = 0;
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const double c = g.at(x, y).x * (1.0 - double(kH) / kEdgeHeight);
      const double r = kR, cc = std::clamp(c, -r, r);
      const double visible =
          (r * r * std::acos(cc / r) - cc * std::sqrt(r * r - cc * cc)) / (kPi * r * r);
      const double error = vis[static_cast<size_t>(y * g.width + x)] - visible;
      squared += error * error;
      worst = std::max(worst, std::abs(error));
      penumbra += visible > 0.0 && visible < 1.0;
    }
  }
  ASSERT_GT(penumbra, 300);
  // Stratified 16 x 16 samples: only the strata the segment's chord crosses are uncertain,
  // about 2/16 of the disk at most; independent samples would be off by ~0.03 (RMS).
  EXPECT_LT(std::sqrt(squared / (g.width * g.height)), 0.012);
  EXPECT_LT(worst, 0.06);
}

TEST(Truth, AreaSampleCountRoundsToASquare) {
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  TruthLight light;
  light.position = glm::vec3(0.7f, 6.0f, 0.3f);
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.radius = 0.5f;
  light.samples = 10;  // -> 3x3
  const Grid g{120, 120, -3.35, -3.15, 0.05};
  checkSoftShadow(truth.visibility(planeSurface(g), light), g, 60, 60, 9);
}

TEST(Truth, FacingAwayAndEmptyPixelsAreNotCounted) {
  const Mesh m = sphereOverPlane();
  const Truth truth(m.positions, m.triangles, kSceneRadius);
  SurfaceBuffer s;
  s.width = 4;
  s.height = 1;
  s.position = {{5, 0, 5, 0}, {5, 0, 5, 1}, {5, 0, 5, -1}, {5, 0, 5, 0}};
  const glm::vec3 tilted = glm::normalize(glm::vec3(1, 1, 0));
  s.normal = {{0, 1, 0, 0}, {0, -1, 0, 0}, {0, 1, 0, 0}, {tilted, 0}};
  TruthLight point;
  point.position = glm::vec3(5.0f, 6.0f, 5.0f);
  TruthLight directional;
  directional.directional = true;
  directional.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  TruthLight area = point;
  area.radius = 0.3f;
  for (const TruthLight& light : {point, directional, area}) {
    const std::vector<float> vis = truth.visibility(s, light);
    EXPECT_EQ(vis, (std::vector<float>{1.0f, kNotCounted, kNotCounted, 1.0f}));
    const std::vector<float> w = Truth::facingWeight(s, light);
    ASSERT_EQ(w.size(), 4u);
    EXPECT_FLOAT_EQ(w[0], 1.0f);
    EXPECT_EQ(w[1], 0.0f);
    EXPECT_EQ(w[2], 0.0f);
    EXPECT_NEAR(w[3], std::sqrt(0.5f), 1e-6f);
  }
}

TEST(Truth, EmptyMeshIsAllLit) {
  const Truth truth({}, {}, 1.0f);
  const Grid g{8, 8, -1.0, -1.0, 0.25};
  SurfaceBuffer s = planeSurface(g);
  s.position[3].w = -1.0f;
  TruthLight light;
  light.position = glm::vec3(0.0f, 3.0f, 0.0f);
  for (float radius : {0.0f, 0.5f}) {
    light.radius = radius;
    const std::vector<float> vis = truth.visibility(s, light);
    for (std::size_t i = 0; i < vis.size(); ++i) EXPECT_EQ(vis[i], i == 3 ? kNotCounted : 1.0f);
  }
}

TEST(Truth, RayOffsetIsRelative) {
  EXPECT_FLOAT_EQ(Truth({}, {}, 100.0f).rayOffset(), 1e-2f);
  EXPECT_FLOAT_EQ(Truth({}, {}, 0.0f).rayOffset(), 1e-7f);
}

TEST(Truth, RejectsBadInput) {
  EXPECT_THROW(Truth({{0, 0, 0}}, {{0, 1, 2}}, 1.0f), std::invalid_argument);
  const Truth truth({}, {}, 1.0f);
  SurfaceBuffer s;
  s.width = 2;
  s.height = 2;
  s.position.resize(4);
  s.normal.resize(3);
  EXPECT_THROW(truth.visibility(s, TruthLight{}), std::invalid_argument);
  s.normal.resize(4);
  TruthLight noDirection;
  noDirection.directional = true;
  EXPECT_THROW(truth.visibility(s, noDirection), std::invalid_argument);
}

}  // namespace
}  // namespace shadows
