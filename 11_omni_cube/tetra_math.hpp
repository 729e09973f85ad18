// Tetrahedron maps (as bgfx's shadow-map example offers beside the cube and dual paraboloids):
// four frusta around the light, one a face of a regular tetrahedron, packed as the four tiles
// of one 2D map. In plain GLM so the tests check what scene.frag does with the same numbers.
//
// The faces' directions f_i are the tetrahedron's face normals (f_i . f_j = -1/3). A direction
// belongs to the face whose f_i is nearest: a spherical triangle whose corners are the other
// faces' opposites, 70.5 degrees from f_i. Through a perspective frustum that triangle is a flat
// one (great circles project to straight lines), so an off-centre frustum around its three
// corners holds the whole face and half its texels fall inside it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace shadows::tetra {

inline constexpr int kFaces = 4;
inline constexpr std::array<const char*, kFaces> kFaceNames = {"down", "a", "b", "c"};

// Straight down, then three at 109.47 degrees from it, 120 degrees apart around the vertical.
inline glm::vec3 faceDirection(int face) {
  if (face == 0) return {0.0f, -1.0f, 0.0f};
  const float a = glm::radians(120.0f * static_cast<float>(face - 1));
  const float r = std::sqrt(8.0f / 9.0f);
  return {r * std::cos(a), 1.0f / 3.0f, r * std::sin(a)};
}

// The face a direction from the light reads: the nearest face direction.
inline int faceOf(glm::vec3 v) {
  int best = 0;
  for (int i = 1; i < kFaces; ++i) {
    if (glm::dot(v, faceDirection(i)) > glm::dot(v, faceDirection(best))) best = i;
  }
  return best;
}

inline glm::mat4 faceView(glm::vec3 light, int face) {
  const glm::vec3 up = face == 0 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  return glm::lookAt(light, light + faceDirection(face), up);
}

// The face's triangle on its image plane at distance 1: its corners are the other faces'
// opposites, x / -z and y / -z in the face's view.
inline std::array<glm::vec2, 3> faceCorners(int face) {
  const glm::mat4 view = faceView(glm::vec3(0.0f), face);
  std::array<glm::vec2, 3> c;
  size_t k = 0;
  for (int j = 0; j < kFaces; ++j) {
    if (j == face) continue;
    const glm::vec3 p = glm::vec3(view * glm::vec4(-faceDirection(j), 0.0f));
    c[k++] = glm::vec2(p) / -p.z;
  }
  return c;
}

// The rectangle (left, right, bottom, top) on the image plane the face's tile covers: the
// triangle's bounds, widened by `margin` so that a filtered lookup never reads the next tile.
inline glm::vec4 faceBounds(int face, float margin = 1.02f) {
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec2& c : faceCorners(face)) lo = glm::min(lo, c), hi = glm::max(hi, c);
  const glm::vec2 centre = 0.5f * (lo + hi), half = 0.5f * margin * (hi - lo);
  return {centre.x - half.x, centre.x + half.x, centre.y - half.y, centre.y + half.y};
}

inline glm::mat4 faceProjection(int face, float near, float far) {
  const glm::vec4 b = faceBounds(face) * near;
  return glm::frustum(b.x, b.y, b.z, b.w, near, far);
}

// Where face i's tile sits in the map: 2 x 2, face 0 bottom left.
inline glm::vec2 tileOffset(int face) {
  return {0.5f * static_cast<float>(face % 2), 0.5f * static_cast<float>(face / 2)};
}

// The map's (s, t) of direction v (scene.frag's lookup): its face's projection into its tile.
inline glm::vec2 mapCoord(glm::vec3 v, float near, float far) {
  const int face = faceOf(v);
  const glm::vec4 c =
      faceProjection(face, near, far) * faceView(glm::vec3(0.0f), face) * glm::vec4(v, 1.0f);
  return tileOffset(face) + 0.25f * (glm::vec2(c) / c.w + 1.0f);
}

// The tile's side that holds as many texels as a cube of `cubeSize` faces: 4 t^2 = 6 s^2.
inline int tileSizeFor(int cubeSize) {
  return static_cast<int>(std::lround(static_cast<double>(cubeSize) * std::sqrt(1.5)));
}

// A tile's texel on its face's image plane at distance 1, the wider of its two sides: a texel's
// world size at distance d along the face's axis is d times this (the normal offset's unit).
inline float texelAtUnitDistance(int tile) {
  const glm::vec4 bounds = faceBounds(0);
  return std::max(bounds.y - bounds.x, bounds.w - bounds.z) / static_cast<float>(tile);
}

// How many texels of its tile v lies from the edge of its face's triangle (its seam with the
// next face), measured on the image plane in the tile's texels (the wider of the two axes').
inline float seamDistanceTexels(glm::vec3 v, int tile) {
  const int face = faceOf(v);
  const glm::vec3 p3 = glm::vec3(faceView(glm::vec3(0.0f), face) * glm::vec4(v, 0.0f));
  const glm::vec2 p = glm::vec2(p3) / -p3.z;
  const std::array<glm::vec2, 3> c = faceCorners(face);
  float d = 1e30f;
  for (size_t k = 0; k < 3; ++k) {
    const glm::vec2 a = c[k], b = c[(k + 1) % 3], e = b - a;
    d = std::min(d, std::abs(e.x * (p.y - a.y) - e.y * (p.x - a.x)) / glm::length(e));
  }
  return d / texelAtUnitDistance(tile);
}

}  // namespace shadows::tetra
