// Cascaded shadow maps' arithmetic, in plain GLM so the tests can check it (the shader gets
// its results as uniforms): where the eye's frustum is cut, and the box each slice's map
// covers.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace shadows::cascade {

enum class Split { Uniform, Logarithmic, Practical };

// Where slice i of n ends, i = 0..n (0: near, n: far), as Zhang et al.'s parallel-split maps
// and GPU Gems 3, ch. 10 write it:
//   uniform      C_i = n + (f - n) i / N        (as many map texels per metre everywhere)
//   logarithmic  C_i = n (f / n)^(i / N)        (texels per metre falling as 1/z: the ideal)
//   practical    C_i = λ log + (1 - λ) uniform  (the log one gives the nearest slice too little)
inline float splitDistance(Split split, int i, int n, float near, float far, float lambda) {
  const float t = static_cast<float>(i) / static_cast<float>(n);
  const float uniform = near + (far - near) * t;
  const float logarithmic = near * std::pow(far / near, t);
  switch (split) {
    case Split::Uniform:
      return uniform;
    case Split::Logarithmic:
      return logarithmic;
    case Split::Practical:
      break;
  }
  return lambda * logarithmic + (1.0f - lambda) * uniform;
}

// The eight corners, in world space, of the eye's frustum between view depths d0 and d1.
inline std::array<glm::vec3, 8> sliceCorners(const glm::mat4& view, float fovYRadians, float aspect,
                                             float d0, float d1) {
  const glm::mat4 to_world = glm::inverse(view);
  const float ty = std::tan(0.5f * fovYRadians), tx = ty * aspect;
  std::array<glm::vec3, 8> c;
  size_t k = 0;
  for (const float d : {d0, d1}) {
    for (const float sy : {-1.0f, 1.0f}) {
      for (const float sx : {-1.0f, 1.0f}) {
        c[k++] = glm::vec3(to_world * glm::vec4(sx * tx * d, sy * ty * d, -d, 1.0f));
      }
    }
  }
  return c;
}

// The light's own frame, fixed for a sun: it turns with the sun, never with the eye, so a map
// box that moves by whole texels in it moves every texel's footprint on the ground by whole
// texels too.
inline glm::mat4 lightRotation(glm::vec3 direction) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::lookAt(glm::vec3(0.0f), d, up);
}

struct Fit {
  glm::mat4 view_projection{1.0f};  // world to the cascade's clip space (orthographic)
  glm::vec2 min{0.0f}, max{0.0f};   // the box in the light's frame (x, y)
  float texel_world = 0.0f;         // one texel's side on a surface facing the sun
  float depth_range = 1.0f;         // world units from the map's near plane to its far
};

// The box one cascade's map covers. `sphere`: a square around the slice's bounding sphere
// (the same size whichever way the eye turns); otherwise the slice's own extent in the
// light's frame (tighter, but it changes size as the eye turns). `snap`: the box moves by
// whole texels. Depth spans the scene (`sceneCenter`, `sceneRadius`), so every caster is in
// and a point's depth does not change when the eye moves.
inline Fit fitCascade(const std::array<glm::vec3, 8>& corners, const glm::mat4& light, int size,
                      bool sphere, bool snap, glm::vec3 sceneCenter, float sceneRadius) {
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  if (sphere) {
    glm::vec3 center(0.0f);
    for (const glm::vec3& c : corners) center += c / 8.0f;
    float radius = 0.0f;
    for (const glm::vec3& c : corners) radius = std::max(radius, glm::distance(c, center));
    radius = std::ceil(radius * 16.0f) / 16.0f;  // float noise must not change the box's size
    const glm::vec2 at(light * glm::vec4(center, 1.0f));
    lo = at - radius, hi = at + radius;
  } else {
    for (const glm::vec3& c : corners) {
      const glm::vec2 p(light * glm::vec4(c, 1.0f));
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
  }
  const glm::vec2 extent = hi - lo;
  if (snap) {
    const glm::vec2 texel = extent / static_cast<float>(size);
    lo = glm::floor(lo / texel) * texel;
    hi = lo + extent;
  }
  const float z = (light * glm::vec4(sceneCenter, 1.0f)).z;
  Fit fit;
  fit.min = lo, fit.max = hi;
  fit.depth_range = 2.0f * sceneRadius;
  fit.texel_world = std::max(extent.x, extent.y) / static_cast<float>(size);
  // The eye looks down -z in the light's frame: near is the scene's side facing the sun.
  fit.view_projection =
      glm::ortho(lo.x, hi.x, lo.y, hi.y, -(z + sceneRadius), -(z - sceneRadius)) * light;
  return fit;
}

// Texels per pixel as the shimmer pass reads them back in bytes (scene.frag, VIEW_SHIMMER):
// log2 over [-16, 16] in 15 bits, the high 8 in blue, the low 7 in alpha beside the sunlit bit
// (alpha >= 128). Steps of 0.001 in log2 (0.07 %), so a median is its true value to that, not
// the ceiling 8 bits over [-4, 4] made of anything past 16 or under 1/16 texels a pixel.
inline constexpr int kTexelLevels = 32767;
inline constexpr double kTexelLog2Reach = 16.0;
// What the shader writes for `texels` (its level, 0..kTexelLevels).
inline int texelLevelOf(double texels) {
  const double l = (std::log2(std::max(texels, 1e-6)) + kTexelLog2Reach) / (2.0 * kTexelLog2Reach);
  return static_cast<int>(std::floor(std::clamp(l, 0.0, 1.0) * kTexelLevels + 0.5));
}
// The level read back from a pixel's blue and alpha bytes.
inline int texelLevel(unsigned char blue, unsigned char alpha) {
  return static_cast<int>(blue) * 128 + (alpha & 127);
}
inline double texelsFromLevel(int level) {
  return std::exp2(2.0 * kTexelLog2Reach * level / kTexelLevels - kTexelLog2Reach);
}

}  // namespace shadows::cascade
