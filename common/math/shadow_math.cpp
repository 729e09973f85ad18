#include "math/shadow_math.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace shadows {

glm::mat4 biasMatrix() {
  // Column-major: the last column is the translation.
  return glm::mat4(0.5f, 0.0f, 0.0f, 0.0f,  //
                   0.0f, 0.5f, 0.0f, 0.0f,  //
                   0.0f, 0.0f, 0.5f, 0.0f,  //
                   0.5f, 0.5f, 0.5f, 1.0f);
}

glm::mat4 lookAtSafe(glm::vec3 eye, glm::vec3 target) {
  glm::vec3 dir = target - eye;
  if (glm::dot(dir, dir) < 1e-12f) dir = {0.0f, -1.0f, 0.0f};
  dir = glm::normalize(dir);
  const glm::vec3 up = std::abs(dir.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  return glm::lookAt(eye, eye + dir, up);
}

glm::mat4 lightProjection(const LightFrustum& f) {
  const float near = f.directional ? f.near : std::max(f.near, 1e-3f);
  const float far = std::max(f.far, near * 1.0001f + 1e-4f);
  const float aspect = std::clamp(f.aspect, 1e-3f, 1e3f);
  if (f.directional) {
    const float e = std::max(f.extent, 1e-3f);
    return glm::ortho(-e * aspect, e * aspect, -e, e, near, far);
  }
  const float fov = glm::radians(std::clamp(f.fov, 1.0f, 170.0f));
  return glm::perspective(fov, aspect, near, far);
}

glm::mat4 shadowTextureMatrix(const glm::mat4& lightProjection, const glm::mat4& lightView) {
  return biasMatrix() * lightProjection * lightView;
}

glm::mat4 planarShadowMatrix(glm::vec4 plane, glm::vec4 light) {
  // glm::outerProduct(c, r) is the column vector c times the row vector r: here L P^T.
  return glm::dot(plane, light) * glm::mat4(1.0f) - glm::outerProduct(light, plane);
}

bool depthRange(const glm::mat4& lightView, const Bounds& bounds, float& closest, float& farthest) {
  if (bounds.empty()) return false;
  closest = 1e30f, farthest = -1e30f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? bounds.max.x : bounds.min.x,
                      (corner & 2) ? bounds.max.y : bounds.min.y,
                      (corner & 4) ? bounds.max.z : bounds.min.z};
    const float depth = -(lightView * glm::vec4(p, 1.0f)).z;  // distance along the view axis
    closest = std::min(closest, depth);
    farthest = std::max(farthest, depth);
  }
  return true;
}

float depthStepWorld(const LightFrustum& frustum, float distance, double levels, bool linear) {
  const double n = frustum.near, f = frustum.far, range = f - n;
  if (linear || frustum.directional || !(n > 0.0) || !(range > 0.0)) {
    return static_cast<float>(range / levels);
  }
  // Window depth d(z) = f (z - n) / (z (f - n)), so dz/dd = z^2 (f - n) / (f n).
  const double z = distance;
  return static_cast<float>(z * z * range / (f * n * levels));
}

bool fitNearFar(const glm::mat4& lightView, const Bounds& bounds, bool directional, float& near,
                float& far) {
  float closest = 0.0f, farthest = 0.0f;
  if (!depthRange(lightView, bounds, closest, farthest)) return false;
  const float margin = 0.01f * std::max(farthest - closest, 1e-3f);
  float fitted_near = closest - margin;
  const float fitted_far = farthest + margin;
  if (!directional) {
    if (fitted_far <= 0.0f) return false;  // everything is behind the light
    // A spot light cannot see behind itself; keep near a small fraction of far.
    fitted_near = std::max(fitted_near, fitted_far * 1e-3f);
  }
  near = fitted_near;
  far = fitted_far;
  return true;
}

bool sphereOutsideFrustum(const glm::mat4& m, glm::vec3 c, float radius) {
  // Gribb-Hartmann planes from the rows of the view-projection matrix.
  const glm::vec4 row0{m[0][0], m[1][0], m[2][0], m[3][0]};
  const glm::vec4 row1{m[0][1], m[1][1], m[2][1], m[3][1]};
  const glm::vec4 row2{m[0][2], m[1][2], m[2][2], m[3][2]};
  const glm::vec4 row3{m[0][3], m[1][3], m[2][3], m[3][3]};
  const glm::vec4 planes[6] = {row3 + row0, row3 - row0, row3 + row1,
                               row3 - row1, row3 + row2, row3 - row2};
  for (const glm::vec4& plane : planes) {
    const float len = glm::length(glm::vec3(plane));
    if (len < 1e-12f) continue;
    if ((glm::dot(glm::vec3(plane), c) + plane.w) / len < -radius) return true;
  }
  return false;
}

}  // namespace shadows
