// Lesson 10's projections (common/math/warped_projection.hpp) as matrices: plane_optimal is the
// camera on its plane and a projection through the light; every projection keeps a light ray
// on one texel; the fallbacks say why.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "math/shadow_math.hpp"
#include "math/warped_projection.hpp"

namespace shadows {
namespace {

glm::vec3 ndc(const glm::mat4& m, glm::vec3 p) {
  const glm::vec4 c = m * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

struct Duel {
  glm::mat4 camera;
  glm::vec3 eye{0.0f, 4.0f, 8.0f};
  glm::vec3 light{0.6f, 3.5f, -7.5f};  // the dueling frusta: light and eye face each other
  HalfSpace floor{{0.0f, 1.0f, 0.0f}, 0.0f};
  Duel() {
    camera = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 100.0f) *
             glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
  }
  PlaneOptimalInput input() const {
    PlaneOptimalInput in;
    in.camera = camera;
    in.eye = eye;
    in.light = glm::vec4(light, 1.0f);
    in.plane = floor;
    std::vector<HalfSpace> poly = frustumHalfSpaces(camera);
    poly.push_back({floor.n, 1e-4f});
    poly.push_back({-floor.n, 1e-4f});
    poly.push_back({{1, 0, 0}, 8.0f});
    poly.push_back({{-1, 0, 0}, 8.0f});
    poly.push_back({{0, 0, 1}, 8.0f});
    poly.push_back({{0, 0, -1}, 8.0f});
    in.plane_in_view = convexVertices(poly);
    for (const glm::vec3 p : {glm::vec3(-2, 0, -2), glm::vec3(2, 2, 2), glm::vec3(0, 1, 0)}) {
      in.depth_points.push_back(p);
    }
    return in;
  }
};

TEST(WarpedProjection, PlaneOptimalIsTheCameraOnThePlaneAndProjectsThroughTheLight) {
  const Duel s;
  const Warp w = planeOptimalProjection(s.input());
  ASSERT_EQ(w.fallback, "");
  for (const glm::vec3 p : {glm::vec3(0.5f, 0, 1.0f), glm::vec3(-2, 0, 3), glm::vec3(1, 0, -1)}) {
    const glm::vec3 a = ndc(w.view_projection, p), b = ndc(s.camera, p);
    EXPECT_NEAR(a.x, b.x, 1e-4f);
    EXPECT_NEAR(a.y, b.y, 1e-4f);
    // Every point between the light and p lands on p's texel, nearer the light in depth.
    float last = -1e30f;  // depth outside -1..1 nearer the light than any depth point
    for (const float t : {0.3f, 0.6f, 0.9f, 1.0f}) {
      const glm::vec3 q = ndc(w.view_projection, s.light + t * (p - s.light));
      EXPECT_NEAR(q.x, a.x, 1e-4f);
      EXPECT_NEAR(q.y, a.y, 1e-4f);
      EXPECT_GT(q.z, last) << "depth grows away from the light";
      last = q.z;
    }
    EXPECT_GE(a.z, -1.0f);
    EXPECT_LE(a.z, 1.0f);
  }
}

TEST(WarpedProjection, PlaneOptimalFallsBackWithAReason) {
  const Duel s;
  auto in = s.input();
  in.light = glm::vec4(1, 0, 2, 1);
  EXPECT_EQ(planeOptimalProjection(in).fallback, "the light lies in the plane");
  in.light = glm::vec4(1, -3, 2, 1);
  EXPECT_EQ(planeOptimalProjection(in).fallback, "the light is behind the plane");
  in = s.input();
  in.eye = glm::vec3(0, 0, 8);
  EXPECT_EQ(planeOptimalProjection(in).fallback, "the eye lies in the plane");
  in.eye = glm::vec3(0, -2, 8);
  EXPECT_EQ(planeOptimalProjection(in).fallback, "the eye is behind the plane");
  in = s.input();
  in.plane_in_view.clear();
  EXPECT_EQ(planeOptimalProjection(in).fallback, "the plane is not in view");
}

TEST(WarpedProjection, ConvexVerticesOfABoxCutByAPlane) {
  Bounds box;
  box.add(glm::vec3(-1.0f));
  box.add(glm::vec3(1.0f));
  auto h = boxHalfSpaces(box);
  EXPECT_EQ(convexVertices(h).size(), 8u);
  h.push_back({{0, -1, 0}, 0.0f});  // y <= 0: the lower half
  for (const glm::vec3& p : convexVertices(h)) EXPECT_LE(p.y, 1e-4f);
  h.push_back({{0, 1, 0}, -2.0f});  // and y >= 2: nothing
  EXPECT_TRUE(convexVertices(h).empty());
}

TEST(WarpedProjection, FocusedAndLispsmKeepTheBodyInTheMapAndLightRaysOnATexel) {
  const Duel s;
  LightFrustum frustum{false, 60.0f, 10.0f, 1.0f, 1.0f, 20.0f};
  const glm::mat4 uniform =
      lightProjection(frustum) * glm::lookAt(s.light, glm::vec3(0, 0.3f, 0.5f), {0, 1, 0});
  std::vector<HalfSpace> h = frustumHalfSpaces(s.camera);
  const auto l = frustumHalfSpaces(uniform);
  h.insert(h.end(), l.begin(), l.end());
  Bounds scene;
  scene.add(glm::vec3(-8, 0, -8));
  scene.add(glm::vec3(8, 2.5f, 8));
  const auto b = boxHalfSpaces(scene);
  h.insert(h.end(), b.begin(), b.end());
  const std::vector<glm::vec3> body = convexVertices(h);
  ASSERT_GE(body.size(), 4u);
  const Warp focused = focusedProjection(uniform, body);
  ASSERT_EQ(focused.fallback, "");
  float n = 0.0f;
  const Warp lispsm = lispsmProjection({uniform, s.eye, glm::normalize(-s.eye), body, 1.0f}, &n);
  ASSERT_EQ(lispsm.fallback, "");
  EXPECT_GT(n, 0.0f);
  for (const Warp* w : {&focused, &lispsm}) {
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : body) {
      const glm::vec3 q = ndc(w->view_projection, p);
      lo = glm::min(lo, glm::vec2(q)), hi = glm::max(hi, glm::vec2(q));
      EXPECT_LE(std::abs(q.x), 1.0f + 1e-3f);
      EXPECT_LE(std::abs(q.y), 1.0f + 1e-3f);
      // Halfway to the light: the same texel.
      const glm::vec3 r = ndc(w->view_projection, 0.5f * (p + s.light));
      EXPECT_NEAR(r.x, q.x, 2e-3f);
      EXPECT_NEAR(r.y, q.y, 2e-3f);
    }
    // The body fills the map (fitted), unlike the uniform frustum.
    EXPECT_NEAR(hi.x - lo.x, 2.0f, 1e-2f);
    EXPECT_NEAR(hi.y - lo.y, 2.0f, 1e-2f);
  }
  // The eye on the light's axis, looking along it: nothing to warp.
  const glm::vec3 axis = glm::normalize(glm::vec3(0, 0.3f, 0.5f) - s.light);
  EXPECT_EQ(lispsmProjection({uniform, s.light + 2.0f * axis, axis, body, 1.0f}).fallback,
            "the eye looks along the light: no direction to warp");
  // The eye behind the spot light: its post-projective position would flip.
  EXPECT_EQ(lispsmProjection({uniform, s.light - 2.0f * axis, axis, body, 1.0f}).fallback,
            "the eye is behind the light: the warp would invert");
  EXPECT_EQ(focusedProjection(uniform, {}).fallback,
            "nothing the eye sees lies in the light's frustum");
}

TEST(WarpedProjection, LispsmsParameterIsWimmersFormulaOnHandWorkedCases) {
  // With the uniform light the identity, its post-projective space is the world: the light
  // directional along +z. The body, the cube [-0.5, 0.5]^3; the eye at (0, -2, 0). Then the
  // warp axis is +y, the body spans depth 1 along it from 1.5 ahead of the eye, and (as the
  // code does) z_n = 1.5 + 0.01 * depth = 1.51, z_f = z_n + depth / sin(gamma),
  // n_opt = (z_n + sqrt(z_n z_f)) / sin(gamma) (Wimmer, Scherzer, Purgathofer 2004).
  std::vector<glm::vec3> cube;
  for (int i = 0; i < 8; ++i) {
    cube.push_back({(i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f});
  }
  const glm::vec3 eye(0.0f, -2.0f, 0.0f);
  struct Case {
    glm::vec3 forward;
    float factor, n;  // worked by hand
  };
  const float s60 = std::sqrt(3.0f) / 2.0f;
  const std::vector<Case> cases = {
      // Across the light (gamma 90 degrees): z_f = 2.51, n = 1.51 + sqrt(3.7901).
      {{0, 1, 0}, 1.0f, 1.51f + std::sqrt(1.51f * 2.51f)},
      // 60 degrees from the light: sin(gamma) 0.5, z_f = 3.51, n = (1.51 + sqrt(5.3001)) / 0.5.
      {{0, 0.5f, s60}, 1.0f, (1.51f + std::sqrt(1.51f * 3.51f)) / 0.5f},
      // lispsm.n scales n_opt: the slider's 2 and 0.5.
      {{0, 1, 0}, 2.0f, 2.0f * (1.51f + std::sqrt(1.51f * 2.51f))},
      {{0, 0.5f, s60}, 0.5f, 0.5f * (1.51f + std::sqrt(1.51f * 3.51f)) / 0.5f},
  };
  for (const Case& c : cases) {
    float n = 0.0f;
    const Warp w = lispsmProjection({glm::mat4(1.0f), eye, c.forward, cube, c.factor}, &n);
    ASSERT_EQ(w.fallback, "");
    EXPECT_NEAR(n, c.n, 1e-4f * c.n) << c.forward.y << " " << c.factor;
  }
}

TEST(WarpedProjection, LispsmGivesTheSliceNearTheEyeMoreOfTheMap) {
  // The warp's direction: equal slices of the body along the view, near the eye and far from
  // it, in the map. Perspective aliasing is undone when the near slice gets more, the more so
  // the smaller lispsm.n (the warp's centre closer to the body); a large n is nearly uniform.
  std::vector<glm::vec3> cube;
  for (int i = 0; i < 8; ++i) {
    cube.push_back({(i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f});
  }
  const auto ratio = [&](float factor) {
    const Warp w = lispsmProjection({glm::mat4(1.0f), {0, -2, 0}, {0, 1, 0}, cube, factor});
    EXPECT_EQ(w.fallback, "");
    const auto map = [&](glm::vec3 p) { return glm::vec2(ndc(w.view_projection, p)); };
    // A light ray (along +z here) stays on one texel.
    EXPECT_NEAR(glm::distance(map({0.1f, 0.0f, 0.2f}), map({0.1f, 0.0f, -0.4f})), 0.0f, 1e-4f);
    const float near_slice = glm::length(map({0.1f, -0.3f, 0.2f}) - map({0.1f, -0.4f, 0.2f}));
    const float far_slice = glm::length(map({0.1f, 0.4f, 0.2f}) - map({0.1f, 0.3f, 0.2f}));
    return near_slice / far_slice;
  };
  const float strong = ratio(0.1f), optimal = ratio(1.0f), weak = ratio(10.0f);
  EXPECT_GT(optimal, 1.2f) << "the near slice gets more of the map";
  EXPECT_GT(strong, optimal);
  EXPECT_GT(optimal, weak);
  EXPECT_GT(weak, 1.0f);
  EXPECT_LT(weak, 1.1f) << "n far from the body: nearly uniform";
}

}  // namespace
}  // namespace shadows
