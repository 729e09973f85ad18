// The plumbing every shadow-map lesson shares: the shadow.* parameters, the depth texture
// and its framebuffer (re-created when size or format change), the light frustum (fitted
// to the casters on request), and the decision whether the map must be rendered again.
// The passes themselves stay in the lessons.
#pragma once

#include "app.hpp"

namespace shadows {

class ShadowMap {
 public:
  // shadow.size, shadow.height, shadow.format, shadow.filter, shadow.fit, shadow.cache, inset.
  static void declare(Params& params);

  // Creates or re-creates the map, computes the light's matrices, and says whether the map
  // must be rendered this frame (counted as shadow_map_renders). Any `extraDirty` bits a
  // lesson's own parameters set (bias, say) also force a render.
  bool prepare(Frame& frame, std::uint32_t extraDirty = kDirtyNothing);
  // Binds the map's framebuffer, sets the viewport and clears the depth.
  void beginRender() const;
  // Kilgard's "depth buffer from the light's point of view": when frame.mode is
  // "light_depth", draws the map over the whole target and returns true.
  bool drawDepthView(const Frame& frame) const;
  // The depth map inset in a corner (or over the whole target), when `inset` is on.
  void drawInset(const Frame& frame, bool fullscreen = false) const;

  const Texture& texture() const { return texture_; }
  int width() const { return width_; }
  int height() const { return height_; }
  const LightFrustum& frustum() const { return frustum_; }
  const glm::mat4& lightProjection() const { return projection_; }
  const glm::mat4& lightView() const { return view_; }
  glm::mat4 lightViewProjection() const { return projection_ * view_; }
  // B * P_light * V_light: world space to (s, t, r, q).
  glm::mat4 textureMatrix() const { return shadowTextureMatrix(projection_, view_); }
  GLenum filter() const { return filter_; }
  // The world size of one texel (along the map's height) at distance d along the light's
  // axis is x * d + y: a spot's texels grow with distance (x = 2 tan(fov/2) / rows, y = 0),
  // a directional light's do not (x = 0, y = 2 extent / rows).
  glm::vec2 texelFootprint() const;
  float texelWorldSize(float distance) const {
    const glm::vec2 t = texelFootprint();
    return t.x * distance + t.y;
  }

 private:
  Texture texture_;
  std::unique_ptr<Framebuffer> framebuffer_;
  int width_ = 0, height_ = 0, bits_ = 0;
  LightFrustum frustum_;
  glm::mat4 projection_{1.0f}, view_{1.0f};
  GLenum filter_ = GL_NEAREST;
  bool inset_ = true;
};

}  // namespace shadows
