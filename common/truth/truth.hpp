// Ray-traced ground truth (Embree 3) on the very triangles the lessons rasterize, and the
// error metrics that compare a lesson's visibility image against it. No GL in here. The types a
// lesson sees (its surfaces, the light, the metrics) are truth_types.hpp's: a lesson includes
// that, never the tracer.
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
#include "truth/truth_types.hpp"

namespace shadows {

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

// rendered: the lesson's view=visibility (one float per pixel, any value, NaN counted);
// truth: from Truth::visibility; weight: from Truth::facingWeight. All the same size.
ErrorMetrics compareVisibility(const std::vector<float>& rendered, const std::vector<float>& truth,
                               const std::vector<float>& weight);

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
