// The plumbing lessons 03-05 share: a depth texture and its framebuffer (re-created when
// size or format change) over the light's view (LightView: frustum, fit, matrices, the
// re-render decision). The passes themselves stay in the lessons.
#pragma once

#include <array>
#include <string>

#include "shadow/light_view.hpp"

namespace shadows {

class ShadowMap {
 public:
  // shadow.size, shadow.height, shadow.format, shadow.filter, shadow.fit, shadow.cache, inset.
  void declare(Params& params);

  // Creates or re-creates the map, computes the light's matrices, and says whether the map
  // must be rendered this frame. Any `extraDirty` bits a lesson's own parameters set (bias,
  // say) also force a render. renderCasters and renderObject count shadow_map_renders.
  bool prepare(Frame& frame, std::uint32_t extraDirty = kDirtyNothing);
  // The eye pass reads this map: the frustum the truth counts in, texels per pixel
  // (LightView::sampledBy).
  void sampledBy(Frame& frame) const { light_.sampledBy(frame); }
  // Lesson 04's default bias, which 05 and 08 use too: only back faces into the map (seed 003,
  // slide 70), plus glPolygonOffset(factor, units).
  static PassState backFacesBias(float factor, float units) {
    PassState state;
    state.cull = true;
    state.cull_face = GL_FRONT;
    state.polygon_offset = true;
    state.offset_factor = factor;
    state.offset_units = units;
    return state;
  }
  // Pass 1, timed as "shadow": beginRender, then `state` (a bias), then the casters inside the
  // light frustum (the others are culled and counted) with `depthProgram`, whose
  // uLightViewProjection = P_light * V_light is set here; leaves the default state behind.
  // Without a program: common/shaders/light_depth.vert + depth_only.frag, position only.
  // `which`: Objects::Occluders puts every object in (lesson 08: the air behind any surface).
  void renderCasters(Frame& frame, const Program& depthProgram, const PassState& state = {},
                     Objects which = Objects::Casters) const;
  void renderCasters(Frame& frame, const PassState& state = {}, Objects which = Objects::Casters);
  // Pass 1 with one object alone (lesson 15's hybrid: the caster that moves, while the bake
  // holds the others), timed as "shadow", with renderCasters' own program.
  void renderObject(Frame& frame, size_t index, const PassState& state = {});
  // Kilgard's "depth buffer from the light's point of view": when the frame shows
  // views::kLightDepth, draws the map over the whole target and returns true.
  bool drawDepthView(const Frame& frame) const;
  // The depth map inset in a corner (or over the whole target), when `inset` is on.
  void drawInset(const Frame& frame, bool fullscreen = false) const;

  // Lesson 10: the map through a focused or warped projection (LightView::warp).
  bool warp(const glm::mat4& viewProjection) { return light_.warp(viewProjection); }
  const Texture& texture() const { return texture_; }
  bool off() const { return light_.off(); }
  bool fitted() const { return light_.fitted(); }
  int width() const { return light_.size().x; }
  int height() const { return light_.size().y; }
  const LightView& light() const { return light_; }
  const LightFrustum& frustum() const { return light_.frustum(); }
  const glm::mat4& lightProjection() const { return light_.projection(); }
  const glm::mat4& lightView() const { return light_.view(); }
  glm::mat4 lightViewProjection() const { return light_.viewProjection(); }
  glm::mat4 textureMatrix() const { return light_.textureMatrix(); }
  GLenum filter() const { return filter_; }
  int depthBits() const { return bits_; }  // shadow.format: 16, 24 or 32 (float)
  glm::vec2 texelFootprint() const { return light_.texelFootprint(); }
  float texelWorldSize(float distance) const { return light_.texelWorldSize(distance); }

 private:
  // Binds the map's framebuffer, sets the viewport and clears the depth.
  void beginRender() const;
  const Program& depthOnly();  // renderCasters' program, compiled on first use
  LightView light_;
  Texture texture_;
  std::unique_ptr<Framebuffer> framebuffer_;
  glm::ivec2 size_{0};
  int bits_ = 0;
  GLenum filter_ = GL_NEAREST;
  Program depth_only_;  // renderCasters' own, compiled on first use
  ChoiceParam<> format_, filter_param_;
  BoolParam inset_;
};

// Lesson 04's default bias as the sliders 05, 13, 14 and 15 offer: back faces into the map,
// plus glPolygonOffset(bias.factor, bias.units) (ShadowMap::backFacesBias).
class BackFaceBias {
 public:
  // bias.factor and bias.units, each help line after `helpPrefix` (13: "PCF: ").
  void declare(Params& params, const std::string& helpPrefix = "");
  PassState state() const { return ShadowMap::backFacesBias(factor_(), units_()); }
  std::array<Param*, 2> params() { return {&factor_.param(), &units_.param()}; }

 private:
  FloatParam factor_, units_;
};

}  // namespace shadows
