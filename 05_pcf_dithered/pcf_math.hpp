// The arithmetic of lesson 05 in plain C++ (no GL), mirrored from pcf.glsl so unit tests can
// check it: why depths are never averaged, the kernels' tap offsets, and the radius of the
// area light a kernel imitates.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

namespace shadows::pcf {

// Seed 000 "Depth Values are not Blend-able": filter the depths, then compare once.
// 1 = lit (the receiver depth is not behind the filtered depth), 0 = shadowed.
inline float compareAveragedDepth(const std::vector<float>& depths, float receiver) {
  float sum = 0.0f;
  for (float d : depths) sum += d;
  return receiver <= sum / static_cast<float>(depths.size()) ? 1.0f : 0.0f;
}

// Seed 000 "Percentage Closer Filtering": compare each depth, then average the results.
inline float percentageCloser(const std::vector<float>& depths, float receiver) {
  float lit = 0.0f;
  for (float d : depths) lit += receiver <= d ? 1.0f : 0.0f;
  return lit / static_cast<float>(depths.size());
}

// What GL_LINEAR does with a depth-compare texture: the four comparisons of the 2x2 block,
// weighted bilinearly by (fx, fy), the position between the texel centres.
// depths: {bottom-left, bottom-right, top-left, top-right}.
inline float bilinearPercentageCloser(const std::array<float, 4>& depths, float receiver, float fx,
                                      float fy) {
  std::array<float, 4> lit{};
  for (size_t i = 0; i < 4; ++i) lit[i] = receiver <= depths[i] ? 1.0f : 0.0f;
  const float bottom = lit[0] + fx * (lit[1] - lit[0]);
  const float top = lit[2] + fx * (lit[3] - lit[2]);
  return bottom + fy * (top - bottom);
}

// pcf.glsl gridOffset: N taps per axis at the midpoints of a box of half-width `radius` texels.
inline std::vector<glm::vec2> gridOffsets(int n, float radius) {
  std::vector<glm::vec2> taps;
  auto at = [&](int i) {
    return (-1.0f + (2.0f * static_cast<float>(i) + 1.0f) / static_cast<float>(n)) * radius;
  };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) taps.emplace_back(at(i), at(j));
  }
  return taps;
}

// pcf.glsl pcfDithered: seed 001's four taps for the pixel at (x, y) (gl_FragCoord, floored).
inline std::array<glm::vec2, 4> ditheredOffsets(int x, int y, float radius) {
  const float swidth = 0.5f * radius;
  const glm::vec2 o = glm::vec2(static_cast<float>(x % 2), static_cast<float>(y % 2)) * swidth;
  return {glm::vec2(-1.5f * swidth + o.x, 1.5f * swidth - o.y),
          glm::vec2(-1.5f * swidth + o.x, -0.5f * swidth - o.y),
          glm::vec2(0.5f * swidth + o.x, 1.5f * swidth - o.y),
          glm::vec2(0.5f * swidth + o.x, -0.5f * swidth - o.y)};
}

// The side N of the grid for a tap budget: the largest N x N that fits, 1 to 8 (64 taps).
inline int gridSide(int taps) {
  int n = 1;
  while ((n + 1) * (n + 1) <= taps && n < 8) ++n;
  return n;
}

// The radius of the disk light whose penumbra a kernel of `kernelTexels` half-width imitates.
// A kernel blurs every receiver over the same number of texels: half-width kernelTexels * h,
// h the world size of a texel at the receiver. A disk light of radius a gives an occluder edge
// at distance dOccluder from the light a penumbra of half-width a (dReceiver - dOccluder) /
// dOccluder on a receiver at dReceiver (similar triangles through the edge). Equal when
//   a = kernelTexels * h * dOccluder / (dReceiver - dOccluder).
// The directional truth (common/truth.cpp) is a cone of half-angle atan(a / dReceiver)
// around each receiver point's own ray, so its penumbra is a (dReceiver - dOccluder) /
// dReceiver, and then a = kernelTexels * h * dReceiver / (dReceiver - dOccluder).
// It can match at one occluder-receiver gap only: nearer contacts get too much blur from the
// kernel, taller casters too little. 0 when there is no kernel or no gap.
inline float areaLightRadius(float kernelTexels, float texelAtReceiver, float dOccluder,
                             float dReceiver, bool directional = false) {
  if (!(kernelTexels > 0.0f) || !(texelAtReceiver > 0.0f) || !(dOccluder > 0.0f) ||
      !(dReceiver > dOccluder)) {
    return 0.0f;
  }
  const float near_side = directional ? dReceiver : dOccluder;
  const float a = kernelTexels * texelAtReceiver * near_side / (dReceiver - dOccluder);
  return std::isfinite(a) ? a : 0.0f;
}

}  // namespace shadows::pcf
