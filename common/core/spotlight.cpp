#include "core/spotlight.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadows {

SpotTexture SpotTexture::builtin(float falloff, int size) {
  SpotTexture spot;
  spot.image_ = {size, size, std::vector<std::uint8_t>(static_cast<size_t>(size) * size * 4)};
  const float inner = 1.0f - std::clamp(falloff, 0.0f, 1.0f);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      // Texel centre, -1..1 across the frustum: r = 1 on the inscribed circle.
      const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / static_cast<float>(size) * 2.0f - 1.0f;
      const float r = glm::length(p);
      const float v = r >= 1.0f ? 0.0f : r <= inner ? 1.0f : (1.0f - r) / (1.0f - inner);
      const auto byte = static_cast<std::uint8_t>(std::lround(255.0f * v));
      std::uint8_t* px = &spot.image_.rgba[(static_cast<size_t>(y) * size + x) * 4];
      px[0] = px[1] = px[2] = byte;
      px[3] = 255;
    }
  }
  return spot;
}

SpotTexture SpotTexture::fromPng(const std::string& path) {
  SpotTexture spot;
  spot.image_ = readPng(path);
  return spot;
}

SpotTexture SpotTexture::fromImage(Image image) {
  SpotTexture spot;
  spot.image_ = std::move(image);
  return spot;
}

float SpotTexture::value(glm::vec2 st) const {
  if (!(st.x >= 0.0f && st.x <= 1.0f && st.y >= 0.0f && st.y <= 1.0f) || image_.width == 0) {
    return 0.0f;
  }
  const int x =
      std::min(static_cast<int>(st.x * static_cast<float>(image_.width)), image_.width - 1);
  const int y =
      std::min(static_cast<int>(st.y * static_cast<float>(image_.height)), image_.height - 1);
  const std::uint8_t* px = &image_.rgba[(static_cast<size_t>(y) * image_.width + x) * 4];
  // The same weights as spot.glsl's luminance.
  return (0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2]) / 255.0f;
}

}  // namespace shadows
