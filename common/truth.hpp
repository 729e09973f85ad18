// Ray-traced ground truth (Embree 3) on the very triangles the lessons rasterize, and the
// error metrics that compare a lesson's visibility image against it. No GL in here.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

namespace shadows {

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
};

// Value meaning "not counted" (no surface, or facing away from the light) in visibility images.
inline constexpr float kNotCounted = -1.0f;

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
  std::vector<float> visibility(const SurfaceBuffer& surface, const TruthLight& light) const;

  // N.L per pixel (0 where not counted); the weight of shade_mae.
  static std::vector<float> facingWeight(const SurfaceBuffer& surface, const TruthLight& light);

  float rayOffset() const { return ray_offset_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  float ray_offset_;
};

struct ErrorMetrics {
  std::string truth;               // which truth: "point" or "area r=<radius> n=<samples>"
  double false_shadow_pct = 0.0;   // truth lit (>= 0.5), rendered < 0.5, % of counted pixels
  double false_lit_pct = 0.0;      // truth shadowed (< 0.5), rendered >= 0.5
  double vis_mae = 0.0;            // mean |rendered - truth| over counted pixels
  double shade_mae = 0.0;          // the same weighted by N.L
  long long nonfinite_pixels = 0;  // NaN or Inf in rendered, over all pixels
  long long counted_pixels = 0;
};

// rendered: the lesson's view=visibility (one float per pixel, any value, NaN counted);
// truth: from Truth::visibility; weight: from Truth::facingWeight. All the same size.
ErrorMetrics compareVisibility(const std::vector<float>& rendered, const std::vector<float>& truth,
                               const std::vector<float>& weight);

// The `error` view: the shaded image dimmed, false shadow painted magenta, false lit cyan.
// shadedRgba: 4 bytes per pixel, same size and row order as the other buffers.
std::vector<std::uint8_t> errorImage(const std::vector<std::uint8_t>& shadedRgba,
                                     const std::vector<float>& rendered,
                                     const std::vector<float>& truth);

}  // namespace shadows
