// The light's side of every shadow technique that renders from the light: the map's size
// (shadow.size, shadow.height), the light frustum for that size (fitted to the casters on
// request), P_light and V_light, and the decision whether a map built from it must be
// rendered again. What the map is stored in (a depth texture, 8-bit bytes read back, two
// 8-bit digits) is up to the lesson or to ShadowMap.
#pragma once

#include <optional>

#include "lesson/lesson.hpp"

namespace shadows {

class LightView {
 public:
  // shadow.size and shadow.height: the map's texels.
  void declareSize(Params& params);
  // shadow.fit, shadow.cache and shadow.off (the unshadowed baseline).
  void declareFit(Params& params);
  // The map size the parameters ask for (height 0 = square).
  glm::ivec2 mapSize() const { return {size_param_(), height_() > 0 ? height_() : size_param_()}; }

  // Computes this frame's frustum and matrices for a map of `size` texels, and says whether
  // the map must be rendered: when the light, a caster or any `extraDirty` bit changed, the
  // cache is off, or `recreated` (new storage). It writes nothing of the frame's but a
  // shadow_map_renders of 0: the pass that renders the map counts itself.
  bool update(Frame& frame, glm::ivec2 size, bool recreated,
              std::uint32_t extraDirty = kDirtyNothing);
  // What the lesson tells the frame when its eye pass reads this map: the light frustum the
  // truth counts pixels in (Frame::light_view_projection) and how the map is sampled
  // (Frame::shadow_sampling: texels per pixel, the aliasing view; none with shadow.off).
  void sampledBy(Frame& frame) const;
  std::optional<ShadowSampling> sampling() const;

  // Lesson 10: this frame's map through another world-to-clip matrix than the frustum's (a
  // focused or warped projection), set after update(). The frustum the truth counts in stays
  // the light's own. True when it differs from the matrix of the previous frame, so a map built
  // through it must be rendered again.
  bool warp(const glm::mat4& viewProjection);

  const LightFrustum& frustum() const { return frustum_; }
  const glm::mat4& projection() const { return projection_; }
  const glm::mat4& view() const { return view_; }
  glm::mat4 viewProjection() const { return warped_ ? *warped_ : projection_ * view_; }
  // B * P_light * V_light (or B * the warp): world space to (s, t, r, q).
  glm::mat4 textureMatrix() const {
    return warped_ ? biasMatrix() * *warped_ : shadowTextureMatrix(projection_, view_);
  }
  glm::ivec2 size() const { return size_; }
  // shadow.off: the lesson draws its frame without any shadow work (update() renders no map).
  bool off() const { return off_; }
  bool fitted() const { return fitted_; }  // shadow.fit: near/far fitted to the casters
  // The casters' nearest and farthest distance along the light's axis (their bounds' corners),
  // fitted or not: where a map's depth steps matter. Kept up to date only after
  // trackCasterDistances() (06/07 report them), so other lessons do not walk the casters'
  // vertices every frame for nothing.
  void trackCasterDistances() { track_caster_distances_ = true; }
  glm::vec2 casterDistances() const { return caster_distances_; }
  // The world size of one texel (along the map's height) at distance d along the light's
  // axis is x * d + y: a spot's texels grow with distance (x = 2 tan(fov/2) / rows, y = 0),
  // a directional light's do not (x = 0, y = 2 extent / rows).
  glm::vec2 texelFootprint() const;
  float texelWorldSize(float distance) const {
    const glm::vec2 t = texelFootprint();
    return t.x * distance + t.y;
  }

 private:
  LightFrustum frustum_;
  glm::mat4 projection_{1.0f}, view_{1.0f};
  std::optional<glm::mat4> warped_, last_warp_;
  glm::ivec2 size_{0};
  glm::vec2 caster_distances_{0.0f};
  bool track_caster_distances_ = false;
  bool off_ = false, fitted_ = false;
  IntParam size_param_, height_;
  BoolParam fit_, cache_, off_param_;
};

}  // namespace shadows
