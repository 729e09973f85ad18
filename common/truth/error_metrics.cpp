// The error metrics of a rendered shadow term (and lesson 08's air) against the truth, and
// the error pictures. No Embree: a browser's build computes them from its own trace.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "truth/truth.hpp"

namespace shadows {

ErrorMetrics compareVisibility(const std::vector<float>& rendered, const std::vector<float>& truth,
                               const std::vector<float>& weight) {
  if (rendered.size() != truth.size() || weight.size() != truth.size()) {
    throw std::invalid_argument("compareVisibility: buffers differ in size");
  }
  ErrorMetrics m;
  long long falseShadow = 0, falseLit = 0;
  double absSum = 0.0, weightedSum = 0.0, weightSum = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const float r = rendered[i];
    const bool finite = std::isfinite(r);
    if (!finite) ++m.nonfinite_pixels;
    const float t = truth[i];
    const float wt = weight[i];
    if (!(t >= 0.0f) || !(wt > 0.0f)) continue;
    ++m.counted_pixels;
    const bool truthLit = t >= 0.5f;
    double err;
    if (!finite) {
      // A NaN/Inf visibility is wrong whatever the truth: maximal error, on the wrong side.
      err = 1.0;
      ++(truthLit ? falseShadow : falseLit);
    } else {
      err = std::abs(static_cast<double>(r) - static_cast<double>(t));
      if (truthLit && r < 0.5f) ++falseShadow;
      if (!truthLit && r >= 0.5f) ++falseLit;
    }
    absSum += err;
    weightedSum += static_cast<double>(wt) * err;
    weightSum += static_cast<double>(wt);
  }
  if (m.counted_pixels > 0) {
    const double counted = static_cast<double>(m.counted_pixels);
    m.false_shadow_pct = 100.0 * static_cast<double>(falseShadow) / counted;
    m.false_lit_pct = 100.0 * static_cast<double>(falseLit) / counted;
    m.vis_mae = absSum / counted;
  }
  if (weightSum > 0.0) m.shade_mae = weightedSum / weightSum;
  return m;
}

std::string notCountedReason(const ErrorMetrics& m) {
  return m.covered_pixels == 0 ? "no pixel shows a surface: the eye sees only sky"
                               : "no surface seen faces the light inside its frustum";
}

ErrorMetrics compareVisibilityIn(
    const ErrorPixels& pixels, const std::function<bool(glm::vec4 position)>& inside,
    const std::function<bool(float truth, float rendered)>& pixelInside) {
  if (pixels.position.size() != pixels.truth.size()) {
    throw std::invalid_argument("compareVisibilityIn: positions and pixels differ in size");
  }
  // Outside the region a pixel weighs nothing, which compareVisibility does not count.
  std::vector<float> weight = pixels.weight;
  for (std::size_t i = 0; i < weight.size() && i < pixels.position.size(); ++i) {
    const glm::vec4 p = pixels.position[i];
    if (p.w < 0.0f || !inside(p) ||
        (pixelInside && !pixelInside(pixels.truth[i], pixels.rendered[i]))) {
      weight[i] = 0.0f;
    }
  }
  ErrorMetrics m = compareVisibility(pixels.rendered, pixels.truth, weight);
  m.nonfinite_pixels = 0;  // compareVisibility counts them in every pixel, not the region's
  return m;
}

std::vector<std::uint8_t> errorImage(const std::vector<std::uint8_t>& shadedRgba,
                                     const std::vector<float>& rendered,
                                     const std::vector<float>& truth) {
  if (rendered.size() != truth.size() || shadedRgba.size() != 4 * truth.size()) {
    throw std::invalid_argument("errorImage: buffers differ in size");
  }
  std::vector<std::uint8_t> out(shadedRgba.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    std::uint8_t* px = &out[4 * i];
    // Dimmed to 35% (integer rounding, so the image is exact and portable).
    for (std::size_t c = 0; c < 3; ++c) {
      px[c] = static_cast<std::uint8_t>((shadedRgba[4 * i + c] * 35 + 50) / 100);
    }
    px[3] = 255;
    const float t = truth[i];
    const float r = rendered[i];
    if (!(t >= 0.0f)) continue;
    const bool truthLit = t >= 0.5f;
    // Same classification as compareVisibility: non-finite counts as wrong either way.
    const bool wrong = !std::isfinite(r) || (truthLit ? r < 0.5f : r >= 0.5f);
    if (!wrong) continue;
    if (truthLit) {  // false shadow: magenta
      px[0] = 255;
      px[1] = 0;
      px[2] = 255;
    } else {  // false lit: cyan
      px[0] = 0;
      px[1] = 255;
      px[2] = 255;
    }
  }
  return out;
}

std::vector<float> Truth::facingWeight(const SurfaceBuffer& surface, const TruthLight& light,
                                       long long* grazing) {
  if (surface.position.size() != static_cast<std::size_t>(surface.width) * surface.height) {
    throw std::invalid_argument("facingWeight: surface buffer does not match its size");
  }
  std::vector<float> out(surface.position.size(), 0.0f);
  if (grazing != nullptr) *grazing = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    glm::vec3 p, n;
    float ndotl = 0.0f;  // countedPixel sets it only where a surface faces some way
    if (countedPixel(surface, i, light, p, n, ndotl)) {
      out[i] = std::min(ndotl, 1.0f);
    } else if (grazing != nullptr && ndotl > 0.0f) {
      ++*grazing;
    }
  }
  return out;
}

AirMetrics compareAir(const std::vector<float>& rendered, const Truth::AirResult& truth) {
  if (rendered.size() != truth.light.size()) {
    throw std::invalid_argument("compareAir: buffers differ in size");
  }
  AirMetrics m;
  double abs_sum = 0.0, sq_sum = 0.0, truth_sq = 0.0, truth_sum = 0.0;
  for (size_t i = 0; i < rendered.size(); ++i) {
    const double t = truth.light[i];
    double r = rendered[i];
    if (!std::isfinite(r)) {
      ++m.nonfinite;
      r = t + 1.0;  // wrong by a whole unit of light
    }
    if (r == 0.0 && t == 0.0) continue;
    ++m.pixels;
    abs_sum += std::abs(r - t);
    sq_sum += (r - t) * (r - t);
    truth_sq += t * t;
    truth_sum += t;
  }
  m.truth_noise = truth.noise;
  m.valid = true;
  // Both dark everywhere (no dust, or no lit air in view): they agree, nothing to compare.
  if (m.pixels == 0) m.note = "no air light in the picture or the truth";
  if (m.pixels > 0) {
    const double n = static_cast<double>(m.pixels);
    m.mae = abs_sum / n;
    m.truth_mean = truth_sum / n;
    // A truth too dark to see (a light inside a caster, whose map leaks) makes the ratio
    // huge and meaningless (163.7 was reported): no number, and why.
    if (m.truth_mean < kAirRelFloor) {
      m.rel_rmse = std::nan("");
      char buf[160];
      std::snprintf(buf, sizeof buf,
                    "truth's mean air light %.2g is below %.2g (one 8-bit step): a ratio to it "
                    "means nothing; see air_mae",
                    m.truth_mean, kAirRelFloor);
      m.rel_rmse_note = buf;
    } else {
      m.rel_rmse = std::sqrt(sq_sum / truth_sq);
    }
  }
  return m;
}

std::vector<std::uint8_t> airErrorImage(const std::vector<float>& rendered,
                                        const std::vector<float>& truth) {
  float top = 1e-6f;
  for (float t : truth) top = std::max(top, t);
  std::vector<std::uint8_t> out(rendered.size() * 4, 0);
  for (size_t i = 0; i < rendered.size(); ++i) {
    const float r = std::isfinite(rendered[i]) ? rendered[i] : truth[i] + top;
    // Signed error, 4x magnified against the brightest air: red too much, blue too little;
    // a dim grey of the truth underneath so the shafts stay recognizable.
    const float e = std::clamp(4.0f * (r - truth[i]) / top, -1.0f, 1.0f);
    const float base = 0.25f * std::clamp(truth[i] / top, 0.0f, 1.0f);
    out[i * 4 + 0] =
        static_cast<std::uint8_t>(std::lround(255.0f * std::min(1.0f, base + std::max(e, 0.0f))));
    out[i * 4 + 1] = static_cast<std::uint8_t>(std::lround(255.0f * base));
    out[i * 4 + 2] =
        static_cast<std::uint8_t>(std::lround(255.0f * std::min(1.0f, base + std::max(-e, 0.0f))));
    out[i * 4 + 3] = 255;
  }
  return out;
}

}  // namespace shadows
