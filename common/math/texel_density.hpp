// Texels per pixel (seed 002, "Playing with Projection Matrices"; seed 003, "Problem:
// Aliasing Artifacts"): how many of the map's texels one screen pixel spans, per visible
// pixel. The map coordinates (s/q, t/q) times the map's size, differentiated across the
// screen, form a 2x2 Jacobian; its singular values are the texels per pixel along the
// pixel's most and least sampled directions. Below 1 along some axis, several pixels share a
// texel there (under-sampled: blocky); above 1 along both, texels are wasted (over-sampled).
// The GPU computes J per pixel (shaders/texel_density.frag); this file does the arithmetic a
// test can check and the statistics the report gives.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace shadows {

// What a map lesson tells the runner about its map (Frame::shadow_sampling): world to
// (s, t, r, q), and the map's texels.
struct ShadowSampling {
  glm::mat4 texture_matrix{1.0f};
  glm::ivec2 map_size{0};
};

// A pixel is under-sampled where its least sampled axis gets fewer than 1 - kTexelTolerance
// texels: float rounding of an exact 1 must not count.
inline constexpr float kTexelTolerance = 0.01f;

// The singular values (largest first) of the 2x2 matrix whose columns are d(uv)/dx and
// d(uv)/dy; shaders/texel_density.frag does the same in GLSL.
glm::vec2 singularValues(glm::vec2 ddx, glm::vec2 ddy);

// One pixel of the runner's texel pass: x the least, y the most texels per pixel, z 1 where
// counted (a visible surface the map covers, facing the light), w the scene object's index.
using TexelPixel = glm::vec4;

struct TexelAxisStats {
  float p5 = 0.0f, median = 0.0f, p95 = 0.0f;
};
struct TexelStats {
  long long pixels = 0;  // counted pixels
  TexelAxisStats min_axis, max_axis;
  double undersampled_pct = 0.0;  // of counted pixels, least axis below 1 - kTexelTolerance
};

// Statistics over the counted pixels (optionally only those of one object).
TexelStats texelStats(const std::vector<TexelPixel>& pixels, std::optional<int> object = {});

class JsonWriter;
// The report's "texels_per_pixel" object: pixels, then min_axis and max_axis (median, p5, p95).
void writeTexelsPerPixel(JsonWriter& json, const TexelStats& stats);

// The p-th percentile (0..100) by linear interpolation between ranks (p50 of an even count is
// the mean of the middle two, as the report's medians are); sorts `values`. 0 for none.
float percentile(std::vector<float>& values, double p);

}  // namespace shadows
