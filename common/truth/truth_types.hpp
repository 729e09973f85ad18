// What a lesson and the runner hand the truth and read back from it: the surfaces a frame
// saw, the light, the medium, and the error metrics. Plain data, no tracer (truth.hpp has it):
// lesson/lesson.hpp includes this, so a lesson cannot call the tracer it is measured by.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

namespace shadows {

class SpotTexture;

// Per-pixel surface the runner's geometry pass saw, rows bottom-up like glReadPixels.
struct SurfaceBuffer {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> position;  // xyz = world position, w = object index, or -1 for no surface
  std::vector<glm::vec4> normal;    // xyz = geometric world normal (unit), w unused
};

struct TruthLight {
  glm::vec3 position{0.0f};   // the light point (spot) or a point on the light's axis
  glm::vec3 direction{0.0f};  // unit, from the light into the scene (used when directional)
  bool directional = false;
  float radius = 0.0f;  // area light: disk radius around position, facing direction; 0 = point
  int samples = 64;     // area light: stratified samples (rounded to a square number)
  // The side of the stratified grid: round(sqrt(samples)), at least 1.
  static int sampleSide(int samples) {
    return std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(samples, 1)))));
  }
  // Rays a surface point casts to this light: one to a point, the grid's k x k to a disk.
  int raysPerPoint() const { return radius > 0.0f ? sampleSide(samples) * sampleSide(samples) : 1; }
};

// A participating medium for the truth (lesson 08, seed 000 "Combining Shadows with
// Atmospherics"): homogeneous density inside a spotlight's frustum, between its near and far
// planes, lit through the spotlight's texture and shadowed by the scene; single scattering,
// no extinction (the air adds light and absorbs none).
struct AirMedium {
  float density = 0.0f;  // light scattered toward the eye per world unit of lit air
  glm::vec3 light_position{0.0f};
  glm::mat4 light_view_projection{1.0f};  // the spot's frustum (orthographic: directional)
  const SpotTexture* spot = nullptr;      // the spot's light at (s, t); null = 1 everywhere
  int samples = 64;                       // stratified samples along each ray
  // A directional light's rays are parallel: shadow rays leave along -light_direction (to
  // infinity, as the surface truth's), not toward light_position.
  bool directional = false;
  glm::vec3 light_direction{0.0f, -1.0f, 0.0f};  // unit, from the light into the scene
};

// Value meaning "not counted" (no surface, or facing away from the light) in visibility images.
inline constexpr float kNotCounted = -1.0f;

// The air light against its truth, over the pixels where either is non-zero.
// Below this mean truth air light (one step of an 8-bit picture) the truth's air is invisible
// and a ratio to it measures nothing: air_rel_rmse is then null with a note; air_mae stays.
inline constexpr double kAirRelFloor = 1.0 / 255.0;
struct AirMetrics {
  bool valid = false;         // measured: the lesson has a medium (every field then reported)
  std::string note;           // why the numbers are 0 when no pixel has air light in either
  double mae = 0.0;           // mean |rendered - truth|
  double rel_rmse = 0.0;      // sqrt(mean (rendered - truth)^2) / sqrt(mean truth^2); NaN
                              // (reported null) when truth_mean < kAirRelFloor
  std::string rel_rmse_note;  // why rel_rmse is NaN
  double truth_mean = 0.0;    // mean truth over the same pixels (the scale of the numbers)
  double truth_noise = 0.0;   // the truth's own error estimate (AirResult::noise)
  long long pixels = 0;
  long long nonfinite = 0;
};
struct ErrorMetrics {
  std::string truth;               // which truth: "point" or "area r=<radius> n=<samples>"
  double false_shadow_pct = 0.0;   // truth lit (>= 0.5), rendered < 0.5, % of counted pixels
  double false_lit_pct = 0.0;      // truth shadowed (< 0.5), rendered >= 0.5
  double vis_mae = 0.0;            // mean |rendered - truth| over counted pixels
  double shade_mae = 0.0;          // the same weighted by N.L
  long long nonfinite_pixels = 0;  // NaN or Inf in rendered, over all pixels
  long long counted_pixels = 0;
  // Pixels that show any surface (the sky excluded), counted or not: what an eye pass with no
  // overdraw would shade (the report's fragments_passed is measured against it).
  long long covered_pixels = 0;
  // Pixels whose surface faces the light only at a graze (0 < N.L < kGrazingNdotL): shown,
  // not counted.
  long long grazing_pixels = 0;
  AirMetrics air;  // lesson 08: the air light against Truth::airLight (valid only there)
};

// Why a frame counted no pixel, for the report's "not_counted" and the printed line.
std::string notCountedReason(const ErrorMetrics& m);

// Per pixel, what the last error measure compared, kept so that a lesson can break the error
// down by the regions it knows (lesson 10: the plane of interest, region II).
struct ErrorPixels {
  std::vector<float> rendered, truth, weight;  // compareVisibility's inputs
  std::vector<glm::vec4> position;             // world xyz, w the object (-1: no surface)
};

}  // namespace shadows
