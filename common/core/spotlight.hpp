// A spotlight's projected texture (seed 000, "Combine with Projective Texturing for Spotlight
// Shadows"; seed 004's spotlight falloff): an image thrown through the light's frustum. The
// raster path samples it as a texture, the ray-traced truth samples the same pixels on the
// CPU (nearest, luminance), so both see one light.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "core/image.hpp"

namespace shadows {

class SpotTexture {
 public:
  // The built-in spot: 1 inside the circle inscribed in the frustum, fading linearly to 0 at
  // its edge over the outer `falloff` (0..1) of the radius; 0 outside the circle.
  static SpotTexture builtin(float falloff, int size = 256);
  // A PNG (rows bottom-up); throws std::runtime_error naming the file.
  static SpotTexture fromPng(const std::string& path);
  // Any image (a truth job's copy).
  static SpotTexture fromImage(Image image);
  static bool isBuiltin(const std::string& path) { return path == "builtin"; }

  // The light at texture coordinates (s, t) in [0, 1]² (0 outside), as the GPU's NEAREST
  // lookup of the same image gives it: luminance of the texel, in [0, 1].
  float value(glm::vec2 st) const;
  const Image& image() const { return image_; }

 private:
  Image image_;
};

}  // namespace shadows
