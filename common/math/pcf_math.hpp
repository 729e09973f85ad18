// The arithmetic of lesson 05 in plain C++ (no GL): why depths are never averaged, the
// kernels' tap offsets, and the radius of the area light a kernel imitates. The offsets are
// not a mirror: main.cpp compiles unitTapOffsets() into pcf.glsl as a constant array, which the
// shader scales by the radius as tapOffsets() does, so what the unit tests check is what the
// shader uses.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <glm/glm.hpp>
#include <string>
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

// N taps per axis at the midpoints of a box of half-width `radius` texels.
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

// Seed 001's four dithered taps for the pixel at (x, y) (gl_FragCoord, floored). The seed
// writes them with swidth = radius / 2: (-1.5, 1.5), (-1.5, -0.5), (0.5, 1.5), (0.5, -0.5)
// times swidth, shifted by (x mod 2, -(y mod 2)) swidth. Here as a unit pattern (exact in
// float) times the radius, the one rounding the shader's unit offset times radius makes too.
inline std::array<glm::vec2, 4> ditheredOffsets(int x, int y, float radius) {
  const glm::vec2 o = 0.5f * glm::vec2(static_cast<float>(x % 2), -static_cast<float>(y % 2));
  return {(glm::vec2(-0.75f, 0.75f) + o) * radius, (glm::vec2(-0.75f, -0.25f) + o) * radius,
          (glm::vec2(0.25f, 0.75f) + o) * radius, (glm::vec2(0.25f, -0.25f) + o) * radius};
}

// Seed 003 slide 71: a progressive Poisson disk in the unit circle (each prefix is spread
// out), the first four on the rim so they double as the early-out probes.
inline const std::array<glm::vec2, 64>& poissonDisk() {
  static const std::array<glm::vec2, 64> points = {{
      {0.6364f, 0.6364f},   {-0.6364f, 0.6364f},  {-0.6364f, -0.6364f}, {0.6364f, -0.6364f},
      {-0.0213f, 0.0144f},  {0.9892f, -0.0104f},  {-0.9460f, -0.0379f}, {0.0371f, -0.9720f},
      {0.0072f, 0.9425f},   {0.4781f, 0.1453f},   {-0.1561f, -0.5123f}, {-0.4557f, 0.1950f},
      {0.0282f, 0.4832f},   {0.2798f, -0.2901f},  {-0.5320f, -0.1895f}, {0.2223f, -0.6549f},
      {-0.9015f, 0.3348f},  {-0.3560f, -0.9296f}, {0.6528f, -0.2006f},  {-0.3868f, 0.9175f},
      {0.8903f, 0.3451f},   {0.3506f, 0.9340f},   {-0.8607f, -0.3669f}, {0.3473f, 0.4409f},
      {-0.2947f, 0.5928f},  {0.9379f, -0.3368f},  {0.3576f, -0.9327f},  {-0.2312f, -0.1876f},
      {0.2048f, 0.1853f},   {-0.7193f, 0.1017f},  {-0.1647f, 0.2537f},  {-0.4166f, -0.4569f},
      {0.7434f, 0.1104f},   {0.1696f, 0.7117f},   {0.0159f, -0.2977f},  {0.6284f, 0.3764f},
      {-0.6299f, 0.3801f},  {-0.0287f, -0.7276f}, {0.4193f, -0.5094f},  {0.3624f, -0.0640f},
      {-0.3406f, -0.6830f}, {-0.0786f, 0.7117f},  {0.3967f, 0.6555f},   {0.7440f, -0.4383f},
      {-0.2929f, 0.0279f},  {-0.7658f, -0.1645f}, {-0.6443f, -0.4155f}, {-0.3949f, 0.4047f},
      {0.5397f, 0.8280f},   {0.1522f, -0.1113f},  {0.4496f, -0.7390f},  {-0.8304f, 0.5428f},
      {-0.5391f, -0.8307f}, {0.0667f, -0.5224f},  {0.4880f, -0.3198f},  {0.8279f, 0.5451f},
      {-0.1904f, 0.9690f},  {-0.1662f, -0.8729f}, {0.8374f, -0.1358f},  {-0.5392f, 0.0182f},
      {-0.9821f, 0.1516f},  {-0.4525f, 0.7069f},  {-0.2659f, 0.7764f},  {0.0470f, 0.2986f},
  }};
  return points;
}

// pcf.mode's choices, in this order (main.cpp declares them from kModeNames; the shader sees
// PCF_MODE_NONE .. PCF_MODE_POISSON).
enum class Mode { None, Hw2x2, Grid, Dithered, Poisson };
inline const std::vector<std::string> kModeNames = {"none", "hw2x2", "grid", "dithered", "poisson"};

// pcf.lookup's choices (lesson 05): how a tap reads the map. compare: a sampler2DShadow, the
// texture unit compares; fetch: the nearest texel's depth through a sampler without compare
// and a compare in the shader (LearnOpenGL's way); gather: textureGather with a reference, the four
// compares of a 2 x 2 block in one call (GL 4.0, ES 3.1).
enum class Lookup { Compare, Fetch, Gather };
inline const std::vector<std::string> kLookupNames = {"compare", "fetch", "gather"};

// The side N of a grid whose taps fall on N x N adjacent texels, so that 2 x 2 gathers can take
// them (ceil(N/2)^2 calls instead of N^2 taps), or 0. Adjacent means one texel apart: the grid's
// midpoints 2 radius / N apart, radius = N / 2 exactly (3 x 3 at radius 1.5, LearnOpenGL's).
inline int gatherGridSide(Mode mode, int side, float radius) {
  if (mode != Mode::Grid || side < 2) return 0;
  return 2.0f * radius == static_cast<float>(side) ? side : 0;
}

// The side N of the grid for a tap budget: the largest N x N that fits, 1 to 8 (64 taps).
inline int gridSide(int taps) {
  int n = 1;
  while ((n + 1) * (n + 1) <= taps && n < 8) ++n;
  return n;
}

// A grid's taps with its four corners first (the early out's probes, as the Poisson disk's
// first four are on its rim), then the others row by row: the shader probes with the first
// four of either kernel. A 2 x 2 grid is all corners, in its own order.
inline std::vector<glm::vec2> cornersFirst(const std::vector<glm::vec2>& grid, int n) {
  if (n <= 2) return grid;
  const int last = n - 1;
  const std::array<int, 4> corners = {0, last, last * n, last * n + last};
  std::vector<glm::vec2> taps;
  for (int k : corners) taps.push_back(grid[static_cast<size_t>(k)]);
  for (int k = 0; k < n * n; ++k) {
    if (std::find(corners.begin(), corners.end(), k) == corners.end()) {
      taps.push_back(grid[static_cast<size_t>(k)]);
    }
  }
  return taps;
}

// The kernel's offsets for a radius of one texel, which main.cpp compiles into pcf.glsl (as
// PCF_UNIT_TAPS): grid, the N x N of gridOffsets (N = gridSide(taps)) corners first;
// dithered, the four patterns of ditheredOffsets one after another, pattern x + 2y for the
// pixel parity (x, y); poisson, the first `taps` disk points (at least 4); none and hw2x2,
// the one tap at the centre.
inline std::vector<glm::vec2> unitTapOffsets(Mode mode, int taps) {
  switch (mode) {
    case Mode::Grid:
      return cornersFirst(gridOffsets(gridSide(taps), 1.0f), gridSide(taps));
    case Mode::Dithered: {
      std::vector<glm::vec2> offsets;
      for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 2; ++x) {
          for (const glm::vec2& o : ditheredOffsets(x, y, 1.0f)) offsets.push_back(o);
        }
      }
      return offsets;
    }
    case Mode::Poisson: {
      // Fewer than 4 points all sit off centre and would shift the shadow sideways.
      const auto n = static_cast<size_t>(std::clamp(taps, 4, 64));
      return {poissonDisk().begin(), poissonDisk().begin() + static_cast<std::ptrdiff_t>(n)};
    }
    default:
      return {glm::vec2(0.0f)};
  }
}

// The offsets in texels a fragment's taps take: unitTapOffsets times the radius, one float
// multiply each, as pcf.glsl computes them (for the grid and the disk the same floats as
// gridOffsets(n, radius), corners first, and poissonDisk() * radius).
inline std::vector<glm::vec2> tapOffsets(Mode mode, int taps, float radius) {
  std::vector<glm::vec2> offsets = unitTapOffsets(mode, taps);
  for (glm::vec2& o : offsets) o *= radius;
  return offsets;
}

// The radius of the disk light whose penumbra a kernel of `kernelTexels` half-width imitates.
// A kernel blurs every receiver over the same number of texels: half-width kernelTexels * h,
// h the world size of a texel at the receiver. A disk light of radius a gives an occluder edge
// at distance dOccluder from the light a penumbra of half-width a (dReceiver - dOccluder) /
// dOccluder on a receiver at dReceiver (similar triangles through the edge). Equal when
//   a = kernelTexels * h * dOccluder / (dReceiver - dOccluder).
// The directional truth (common/truth/truth.cpp) is a cone of half-angle atan(a / dReceiver)
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
