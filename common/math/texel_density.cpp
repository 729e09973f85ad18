#include "math/texel_density.hpp"

#include <algorithm>
#include <cmath>

#include "core/json.hpp"

namespace shadows {

glm::vec2 singularValues(glm::vec2 ddx, glm::vec2 ddy) {
  // For J = [ddx ddy]: s1^2 + s2^2 = |J|_F^2 and s1 * s2 = |det J|.
  const double a = ddx.x, b = ddy.x, c = ddx.y, d = ddy.y;
  const double frob = a * a + b * b + c * c + d * d;
  const double det = std::abs(a * d - b * c);
  const double root = std::sqrt(std::max(frob * frob - 4.0 * det * det, 0.0));
  const double big = std::sqrt(0.5 * (frob + root));
  // The small one from the determinant where big > 0: no cancellation in frob - root.
  const double small = big > 0.0 ? det / big : 0.0;
  return {static_cast<float>(big), static_cast<float>(small)};
}

float percentile(std::vector<float>& values, double p) {
  if (values.empty()) return 0.0f;
  std::sort(values.begin(), values.end());
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(values.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(rank));
  const size_t hi = std::min(lo + 1, values.size() - 1);
  const double t = rank - static_cast<double>(lo);
  return static_cast<float>((1.0 - t) * values[lo] + t * values[hi]);
}

TexelStats texelStats(const std::vector<TexelPixel>& pixels, std::optional<int> object) {
  std::vector<float> least, most;
  long long under = 0;
  for (const TexelPixel& p : pixels) {
    if (p.z < 0.5f || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    if (object && static_cast<int>(std::lround(p.w)) != *object) continue;
    least.push_back(p.x);
    most.push_back(p.y);
    if (p.x < 1.0f - kTexelTolerance) ++under;
  }
  TexelStats s;
  s.pixels = static_cast<long long>(least.size());
  if (s.pixels == 0) return s;
  s.min_axis = {percentile(least, 5), percentile(least, 50), percentile(least, 95)};
  s.max_axis = {percentile(most, 5), percentile(most, 50), percentile(most, 95)};
  s.undersampled_pct = 100.0 * static_cast<double>(under) / static_cast<double>(s.pixels);
  return s;
}

void writeTexelsPerPixel(JsonWriter& json, const TexelStats& t) {
  json.beginObject("texels_per_pixel");
  json.value("pixels", t.pixels);
  // Percentiles of no pixel are null (JsonWriter writes NaN so), and the note says why.
  if (t.pixels == 0) json.value("not_counted", "no pixel seen lies in the shadow map");
  const auto figure = [&](float v) { return t.pixels > 0 ? static_cast<double>(v) : kNoFigure; };
  for (const auto& [name, axis] : {std::pair{"min_axis", t.min_axis}, {"max_axis", t.max_axis}}) {
    json.beginObject(name);
    json.value("median", figure(axis.median));
    json.value("p5", figure(axis.p5));
    json.value("p95", figure(axis.p95));
    json.endObject();
  }
  json.endObject();
}

}  // namespace shadows
