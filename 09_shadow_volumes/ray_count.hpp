// One eye ray through the shadow volumes, as slides 24-26 draw it: where it enters (+1) and
// leaves (-1) a volume before it reaches the surface, and how many volumes hold the eye. A
// point is in a caster's volume when its segment to the light crosses the caster (the
// definition the stencil count approximates); the ray is sampled densely between eye and
// surface. Plain GLM, no GL: lesson 09's overview view draws it, the tests check it by hand.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace shadows::volumes {

struct Triangle {
  glm::vec3 a, b, c;
};

// The distance along `dir` (unit) from `origin` to the nearest triangle in (tMin, tMax), if any
// (Moller-Trumbore, both faces).
inline std::optional<float> hit(const std::vector<Triangle>& triangles, glm::vec3 origin,
                                glm::vec3 dir, float tMin, float tMax) {
  std::optional<float> nearest;
  for (const Triangle& t : triangles) {
    const glm::vec3 e1 = t.b - t.a, e2 = t.c - t.a;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) continue;
    const glm::vec3 s = origin - t.a;
    const float u = glm::dot(s, p) / det;
    if (u < 0.0f || u > 1.0f) continue;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) / det;
    if (v < 0.0f || u + v > 1.0f) continue;
    const float d = glm::dot(e2, q) / det;
    if (d > tMin && d < tMax && (!nearest || d < *nearest)) nearest = d;
  }
  return nearest;
}

// A caster's triangles and the sphere around them (a way to the light that misses the sphere
// misses the caster: most of them, most of the time).
struct Caster {
  std::vector<Triangle> triangles;
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
  explicit Caster(std::vector<Triangle> t) : triangles(std::move(t)) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Triangle& tri : triangles) {
      for (const glm::vec3& p : {tri.a, tri.b, tri.c}) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    centre = 0.5f * (lo + hi);
    radius = triangles.empty() ? 0.0f : 0.5f * glm::length(hi - lo);
  }
};

// Whether `point` lies in the volume of `caster`: its way to the light (`light`: (position, 1)
// or (direction toward the light, 0)) crosses the caster.
inline bool inVolume(const Caster& caster, glm::vec4 light, glm::vec3 point) {
  const bool directional = light.w == 0.0f;
  const glm::vec3 to = directional ? glm::vec3(light) : glm::vec3(light) - point;
  const float length = glm::length(to);
  if (length < 1e-6f) return false;
  const glm::vec3 dir = to / length;
  const float far = directional ? 1e30f : length;
  // The nearest point of the way to the sphere's centre: farther than the radius, no hit.
  const float along = std::clamp(glm::dot(caster.centre - point, dir), 0.0f, far);
  if (glm::length(point + along * dir - caster.centre) > caster.radius) return false;
  // A little off the point, so a surface is not its own caster where it faces the light.
  return hit(caster.triangles, point, dir, 1e-4f, far).has_value();
}

struct RayCount {
  int at_eye = 0;      // volumes holding the eye: what z-pass misses (slide 38)
  int enters = 0;      // +1 crossings before the surface
  int leaves = 0;      // -1 crossings before the surface
  int at_surface = 0;  // volumes holding the surface point: the true count
  // Where the count changes along the ray: the distance, and by how much.
  std::vector<std::pair<float, int>> crossings;
  // z-pass counts the crossings only, starting at 0 at the eye.
  int zpassCount() const { return enters - leaves; }
};

// The count along `dir` (unit) from `eye` to the surface at distance `surface`, one list of
// triangles per caster, sampled `samples` times (a crossing between two samples is found; two
// crossings of one volume closer than the step are not).
inline RayCount countAlongRay(const std::vector<Caster>& casters, glm::vec4 light, glm::vec3 eye,
                              glm::vec3 dir, float surface, int samples = 2000) {
  const auto countAt = [&](glm::vec3 p) {
    int n = 0;
    for (const auto& caster : casters) n += inVolume(caster, light, p) ? 1 : 0;
    return n;
  };
  RayCount r;
  r.at_eye = countAt(eye);
  int previous = r.at_eye;
  // The last sample stops just short of the surface, on the eye's side of it.
  const float end = std::max(surface - 1e-3f, 0.0f);
  for (int i = 1; i <= samples; ++i) {
    const float t = end * static_cast<float>(i) / static_cast<float>(samples);
    const int n = countAt(eye + t * dir);
    if (n != previous) {
      r.crossings.push_back({t, n - previous});
      (n > previous ? r.enters : r.leaves) += std::abs(n - previous);
      previous = n;
    }
  }
  r.at_surface = previous;
  return r;
}

}  // namespace shadows::volumes
