// The error metrics of a rendered shadow term against the truth, and the error picture.
#include <algorithm>
#include <cmath>

#include "truth.hpp"

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

}  // namespace shadows
