// The truth for lesson 08's air: single scattering along each eye ray, with Embree shadow rays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "core/spotlight.hpp"
#include "truth/sample_hash.hpp"
#include "truth/truth.hpp"

namespace shadows {

namespace {

// The part [t0, t1] of the ray o + t d (0 <= t <= tmax) inside the light's frustum, from its
// near to its far plane: every plane of clip space is linear in t. False when the ray misses
// it. The render's spotLight() clips to the same six planes.
bool clipToFrustum(const glm::mat4& lightViewProjection, const glm::vec3& o, const glm::vec3& d,
                   float tmax, float& t0, float& t1) {
  const glm::vec4 c0 = lightViewProjection * glm::vec4(o, 1.0f);
  const glm::vec4 c1 = lightViewProjection * glm::vec4(d, 0.0f);
  // a + b t >= 0 for w ± x, w ± y, w + z (near), w - z (far) and w (in front of the light).
  const glm::vec2 planes[] = {{c0.w + c0.x, c1.w + c1.x},
                              {c0.w - c0.x, c1.w - c1.x},
                              {c0.w + c0.y, c1.w + c1.y},
                              {c0.w - c0.y, c1.w - c1.y},
                              {c0.w + c0.z, c1.w + c1.z},
                              {c0.w - c0.z, c1.w - c1.z},
                              {c0.w, c1.w}};
  t0 = 0.0f;
  t1 = tmax;
  for (const glm::vec2& p : planes) {
    if (p.y > 0.0f) {
      t0 = std::max(t0, -p.x / p.y);
    } else if (p.y < 0.0f) {
      t1 = std::min(t1, -p.x / p.y);
    } else if (p.x < 0.0f) {
      return false;
    }
  }
  return t1 > t0;
}

}  // namespace

Truth::AirResult Truth::airLight(const SurfaceBuffer& surface, const glm::vec3& eye,
                                 const glm::mat4& inverseViewProjection,
                                 const AirMedium& medium) const {
  const int w = surface.width, h = surface.height;
  if (surface.position.size() != static_cast<size_t>(w) * static_cast<size_t>(h)) {
    throw std::invalid_argument("airLight: surface buffer does not match its size");
  }
  const int n = std::max(2, medium.samples / 2 * 2);  // even: two interleaved halves
  AirResult result;
  result.light.assign(surface.position.size(), 0.0f);
  std::vector<float> half_difference(surface.position.size(), -1.0f);

  auto pixel = [&](int x, int y) {
    const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
    // The eye ray through the pixel centre (rows bottom-up, as glReadPixels gives them).
    const glm::vec2 ndc((static_cast<float>(x) + 0.5f) / static_cast<float>(w) * 2.0f - 1.0f,
                        (static_cast<float>(y) + 0.5f) / static_cast<float>(h) * 2.0f - 1.0f);
    const glm::vec4 far_clip = inverseViewProjection * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 far_point = glm::vec3(far_clip) / far_clip.w;
    const glm::vec3 d = glm::normalize(far_point - eye);
    // What the eye pass shows along the ray: up to the first surface, or where the pixel sees
    // none (its geometric normal was cleared to 0) up to the camera's far plane.
    const bool hit = surface.normal[i] != glm::vec4(0.0f);
    const float tmax = glm::distance(eye, hit ? glm::vec3(surface.position[i]) : far_point);
    float t0 = 0.0f, t1 = 0.0f;
    if (!clipToFrustum(medium.light_view_projection, eye, d, tmax, t0, t1)) return;
    const std::uint32_t seed = hash32(static_cast<std::uint32_t>(i) * 0x9E3779B9u + 0x1234567u);
    double half[2] = {0.0, 0.0};
    for (int k = 0; k < n; ++k) {
      const float u = (static_cast<float>(k) + unitFloat(hash32(seed + static_cast<uint32_t>(k)))) /
                      static_cast<float>(n);
      const glm::vec3 p = eye + d * (t0 + u * (t1 - t0));
      const glm::vec4 c = medium.light_view_projection * glm::vec4(p, 1.0f);
      const glm::vec2 st = glm::vec2(c) / c.w * 0.5f + 0.5f;
      const float spot = medium.spot != nullptr ? medium.spot->value(st) : 1.0f;
      if (spot <= 0.0f) continue;
      if (medium.directional) {
        if (!unoccluded(p, -medium.light_direction, std::numeric_limits<float>::infinity())) {
          continue;
        }
      } else {
        const glm::vec3 to_light = medium.light_position - p;
        const float dist = glm::length(to_light);
        // Stop just short of the light, as the surface truth does.
        if (dist > 0.0f && !unoccluded(p, to_light / dist, dist * (1.0f - 1e-4f))) continue;
      }
      half[k % 2] += spot;
    }
    // Each half is a stratified estimate of its own (every other stratum): their spread is
    // the estimate's error, and their mean the estimate.
    const double scale = static_cast<double>(medium.density) * (t1 - t0) * 2.0 / n;
    result.light[i] = static_cast<float>(0.5 * scale * (half[0] + half[1]));
    half_difference[i] = static_cast<float>(0.5 * scale * std::abs(half[0] - half[1]));
  };

  const int threads =
      std::max(1, std::min(static_cast<int>(std::thread::hardware_concurrency()), h));
  auto work = [&](int first) {
    for (int y = first; y < h; y += threads) {
      for (int x = 0; x < w; ++x) pixel(x, y);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& th : pool) th.join();

  double sum = 0.0;
  long long lit = 0;
  for (float v : half_difference) {
    if (v < 0.0f) continue;
    sum += v;
    ++lit;
  }
  result.noise = lit > 0 ? sum / static_cast<double>(lit) : 0.0;
  return result;
}

}  // namespace shadows
