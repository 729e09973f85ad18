// Ray-traced ground truth (Embree 3) on the very triangles the lessons rasterize, and the
// error metrics that compare a lesson's visibility image against it. No GL in here.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
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

// The single definition of a counted pixel (truth_job.cpp), shared by every tracer and by
// facingWeight() so their masks agree exactly: a surface (position.w >= 0: the geometry pass
// already left out what lies outside the light's frustum), finite, whose normal faces the
// light by more than a graze (N.L >= kGrazingNdotL). Outputs the surface point, unit normal
// and N.L.
//
// Below that N.L (the light within 0.06 degrees of the surface's plane: a directional light
// level with the floor, a point light in a face's plane) lit or not is decided by the rounding
// of the light's direction, not by any technique (docs/CONTRACTS.md). Steeper grazes stay
// counted: lesson 04's acne lives there.
inline constexpr float kGrazingNdotL = 0.001f;
bool countedPixel(const SurfaceBuffer& s, std::size_t i, const TruthLight& light, glm::vec3& p,
                  glm::vec3& n, float& ndotl);

// Value meaning "not counted" (no surface, or facing away from the light) in visibility images.
inline constexpr float kNotCounted = -1.0f;

// A long trace (lesson 15's bake) watched and stopped from another thread: rows finished so
// far, and a flag that makes the trace return at the next row (its image then incomplete).
struct TraceControl {
  std::atomic<long long> rows_done{0};
  std::atomic<bool> cancel{false};
};

class Truth {
 public:
  // World-space triangle soup; sceneRadius sets the ray offset (relative, not absolute).
  Truth(const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles,
        float sceneRadius);
  ~Truth();
  Truth(const Truth&) = delete;
  Truth& operator=(const Truth&) = delete;

  // Fraction of the light seen from each pixel's surface, in [0,1]; kNotCounted where the
  // pixel has no surface or its normal does not face the light (N.L <= 0).
  // Deterministic: the same inputs give bit-identical output, whatever the thread count.
  std::vector<float> visibility(const SurfaceBuffer& surface, const TruthLight& light,
                                TraceControl* control = nullptr) const;

  // N.L per pixel (0 where not counted); the weight of shade_mae (error_metrics.cpp: no
  // Embree, a browser's build has it too). `grazing`, if given, gets the pixels that face the
  // light only at a graze (0 < N.L < kGrazingNdotL): shown, not counted.
  static std::vector<float> facingWeight(const SurfaceBuffer& surface, const TruthLight& light,
                                         long long* grazing = nullptr);

  float rayOffset() const { return ray_offset_; }
  // Relative, not absolute: an absolute epsilon is wrong for either tiny or huge scenes.
  static float rayOffsetFor(float sceneRadius) { return 1e-4f * std::max(sceneRadius, 1e-3f); }

  // True when nothing blocks the ray from `origin` along the unit `direction` up to `tfar`.
  bool unoccluded(const glm::vec3& origin, const glm::vec3& direction, float tfar) const;

  // Single scattering in a medium (lesson 08), integrated along every eye ray up to its first
  // surface, or the camera's far plane (inverseViewProjection's) where it sees none; see
  // AirMedium. Deterministic like visibility().
  struct AirResult {
    std::vector<float> light;  // in-scattered light per pixel (0 where the ray misses the cone)
    double noise = 0.0;        // mean over lit pixels of |half A - half B| / 2 (see air_truth.cpp)
  };
  AirResult airLight(const SurfaceBuffer& surface, const glm::vec3& eye,
                     const glm::mat4& inverseViewProjection, const AirMedium& medium) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  float ray_offset_;
};

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

// rendered: the lesson's view=visibility (one float per pixel, any value, NaN counted);
// truth: from Truth::visibility; weight: from Truth::facingWeight. All the same size.
ErrorMetrics compareVisibility(const std::vector<float>& rendered, const std::vector<float>& truth,
                               const std::vector<float>& weight);

// Per pixel, what the last error measure compared, kept so that a lesson can break the error
// down by the regions it knows (lesson 10: the plane of interest, region II).
struct ErrorPixels {
  std::vector<float> rendered, truth, weight;  // compareVisibility's inputs
  std::vector<glm::vec4> position;             // world xyz, w the object (-1: no surface)
};
// compareVisibility over the counted pixels that show a surface `inside` says is in the region
// (given the pixel's ErrorPixels::position) and, where given, whose truth and rendered
// visibility `pixelInside` takes (lesson 14: the penumbra, 0 < truth < 1), the same
// definitions as the whole frame's.
ErrorMetrics compareVisibilityIn(
    const ErrorPixels& pixels, const std::function<bool(glm::vec4 position)>& inside,
    const std::function<bool(float truth, float rendered)>& pixelInside = {});

AirMetrics compareAir(const std::vector<float>& rendered, const Truth::AirResult& truth);
// The error view for air: red where the picture has too much air light, blue too little,
// brightness the size of the error relative to `scale` (the truth's largest value).
std::vector<std::uint8_t> airErrorImage(const std::vector<float>& rendered,
                                        const std::vector<float>& truth);

// The `error` view: the shaded image dimmed, false shadow painted magenta, false lit cyan.
// shadedRgba: 4 bytes per pixel, same size and row order as the other buffers.
std::vector<std::uint8_t> errorImage(const std::vector<std::uint8_t>& shadedRgba,
                                     const std::vector<float>& rendered,
                                     const std::vector<float>& truth);

}  // namespace shadows
