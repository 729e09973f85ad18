// The window's orbit camera in plain GLM: a drag turns the eye around its target, and wherever
// it moves it stays on the side of the scene's walls and floor it started on.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "core/scene.hpp"

namespace shadows::orbit {

// A drag's turn: radians a pixel.
inline constexpr float kRadiansPerPixel = 0.01f;

// The eye turned around `target` by a drag of (dx, dy) pixels, the pitch kept short of
// straight up or down.
inline glm::vec3 turn(glm::vec3 eye, glm::vec3 target, float dx, float dy) {
  const glm::vec3 offset = eye - target;
  const float radius = glm::length(offset);
  const float yaw = std::atan2(offset.x, offset.z) - kRadiansPerPixel * dx;
  float pitch = std::asin(std::clamp(offset.y / std::max(radius, 1e-6f), -1.0f, 1.0f)) +
                kRadiansPerPixel * dy;
  pitch = std::clamp(pitch, -1.5f, 1.5f);
  return target + radius * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                     std::cos(pitch) * std::cos(yaw));
}

// The eye stays on the side of the walls it started on: every one-sided plane of the scene (a
// floor, a wall: SceneObject::caster false) that the preset's eye is in front of keeps the
// moved eye in front of it too, by 1 % of the scene's size. Orbiting lesson 11's open room put
// the eye behind its back wall, which shows nothing from behind ("error: none counted"), with
// no way back; under the floor, every scene is seen from below.
inline glm::vec3 keepInFront(glm::vec3 eye, const Scene& scene, glm::vec3 presetEye) {
  const float margin = 0.01f * std::max(2.0f * scene.bounds().radius(), 1.0f);
  for (int pass = 0; pass < 2; ++pass) {  // twice: a push off one wall may cross another
    for (const SceneObject& object : scene.objects) {
      if (object.caster) continue;
      const glm::vec3 point(object.model[3]);
      const glm::vec3 normal = glm::normalize(glm::vec3(object.model[1]));  // the plane's +y
      if (!(glm::dot(presetEye - point, normal) > 0.0f)) continue;
      const float in_front = glm::dot(eye - point, normal);
      if (in_front < margin) eye += (margin - in_front) * normal;
    }
  }
  return eye;
}

}  // namespace shadows::orbit
