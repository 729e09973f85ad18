// The arithmetic of an omni light's cube map in plain C++ (no GL), the way cube_lookup.glsl
// computes it, so the unit tests check the formulas the shaders run: the six 90° frusta, which
// face a direction reads, the depth a face stores for a point, and how big a texel is there.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace shadows::cube {

// The faces in GL's order: GL_TEXTURE_CUBE_MAP_POSITIVE_X + i.
inline constexpr std::array<const char*, 6> kFaceNames = {"+x", "-x", "+y", "-y", "+z", "-z"};

// Face i looks down its axis. The up vectors are the cube map's own convention (the GL
// specification's table of major axes): rendered with them, a face's picture lands in the
// texture the way a lookup in that direction reads it.
inline glm::mat4 faceView(glm::vec3 light, int face) {
  static const glm::vec3 kAxis[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  static const glm::vec3 kUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                   {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  return glm::lookAt(light, light + kAxis[face], kUp[face]);
}

// Seed 000: "could use six view frustums for omni-directional light": each 90° wide, square.
inline glm::mat4 faceProjection(float near, float far) {
  return glm::perspective(glm::radians(90.0f), 1.0f, near, far);
}

// The face a direction from the light reads: its largest component (ties go to x, then y,
// the order cube_lookup.glsl tests in).
inline int majorFace(glm::vec3 v) {
  const glm::vec3 a = glm::abs(v);
  if (a.x >= a.y && a.x >= a.z) return v.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return v.y >= 0.0f ? 2 : 3;
  return v.z >= 0.0f ? 4 : 5;
}

// The distance along that face's axis: the eye-space depth the face's projection divides by.
inline float majorDistance(glm::vec3 v) {
  const glm::vec3 a = glm::abs(v);
  return std::max(a.x, std::max(a.y, a.z));
}

// The window depth faceProjection(near, far) gives a point z along the face's axis:
// ndc = (f + n)/(f - n) - 2 f n / ((f - n) z), window = (ndc + 1)/2 = f (z - n) / (z (f - n)).
// The hardware-depth store compares against this; the distance store against |v| / far.
inline float majorDepth(float z, float near, float far) {
  return far * (z - near) / (z * (far - near));
}

// One texel's world size at distance z along a face's axis: the face is 2z wide there.
inline float texelWorldSize(float z, int size) {
  return 2.0f * z / static_cast<float>(size);
}

// How many texels a direction is from its face's nearest edge (0 on a seam): the face's
// coordinates are the two minor components over the major one, in [-1, 1].
inline float seamDistanceTexels(glm::vec3 v, int size) {
  const glm::vec3 a = glm::abs(v);
  const float major = majorDistance(v);
  if (major <= 0.0f) return 0.0f;
  const float minor = (a.x + a.y + a.z - major - std::min(a.x, std::min(a.y, a.z))) / major;
  return (1.0f - minor) * 0.5f * static_cast<float>(size);
}

// Conservative: true only when the two frusta (world to clip) share no point, because all
// eight corners of one lie outside one plane of the other. A face the eye's frustum does not
// reach holds nothing the eye can see shadowed.
inline bool frustaDisjoint(const glm::mat4& a, const glm::mat4& b) {
  const auto outsideOnePlane = [](const glm::mat4& planes_of, const glm::mat4& corners_of) {
    const glm::mat4 inverse = glm::inverse(corners_of);
    std::array<glm::vec4, 8> corners;
    for (int k = 0; k < 8; ++k) {
      const glm::vec4 c =
          inverse * glm::vec4((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1, 1);
      corners[static_cast<size_t>(k)] = c / c.w;
    }
    // Clip-space planes (Gribb and Hartmann): row 3 +- row i, in world space.
    const glm::mat4 m = glm::transpose(planes_of);
    for (int i = 0; i < 3; ++i) {
      for (const float sign : {1.0f, -1.0f}) {
        const glm::vec4 plane = m[3] + sign * m[i];
        const bool all_out = std::all_of(corners.begin(), corners.end(), [&](const glm::vec4& c) {
          return glm::dot(plane, c) < 0.0f;
        });
        if (all_out) return true;
      }
    }
    return false;
  };
  return outsideOnePlane(a, b) || outsideOnePlane(b, a);
}

}  // namespace shadows::cube
