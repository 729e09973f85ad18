#include "shadow_map.hpp"

#include <algorithm>
#include <cmath>

namespace shadows {

void ShadowMap::declare(Params& p) {
  constexpr auto kMap = kDirtyShadowMap | kDirtyResources;
  p.addInt("shadow.size", 1024, 64, 4096, "shadow map width in texels", kMap).logarithmic = true;
  p.addInt("shadow.height", 0, 0, 4096, "shadow map height (0 = square)", kMap);
  p.addChoice("shadow.format", {"16", "24", "32f"}, "24", "depth bits of the map", kMap);
  p.addChoice("shadow.filter", {"nearest", "linear"}, "nearest",
              "linear = the hardware 2x2 compare filter (results averaged, never depths)");
  p.addBool("shadow.fit", false, "fit the light's near/far to the casters' bounds",
            kDirtyShadowMap);
  p.addBool("shadow.cache", true, "re-render the map only when the light or a caster changed",
            kDirtyShadowMap);
  p.addBool("inset", true, "show the depth map in a corner");
}

bool ShadowMap::prepare(Frame& f, std::uint32_t extraDirty) {
  Params& p = f.params;
  const int width = p.at("shadow.size").i();
  const int height = p.at("shadow.height").i() > 0 ? p.at("shadow.height").i() : width;
  const std::string& format = p.at("shadow.format").choice();
  const int bits = format == "16" ? 16 : format == "24" ? 24 : 32;
  bool stale = p.consume(kDirtyShadowMap | extraDirty) || !p.at("shadow.cache").b();
  if (p.consume(kDirtyResources) || width != width_ || height != height_ || bits != bits_) {
    width_ = width, height_ = height, bits_ = bits;
    texture_ = Texture::depth(width, height, bits);
    texture_.setCompare(true);  // sampler2DShadow: the texture unit does the compare
    framebuffer_ = std::make_unique<Framebuffer>();
    framebuffer_->attachDepth(texture_);
    framebuffer_->check();
    stale = true;
  }
  filter_ = p.at("shadow.filter").is("linear") ? GL_LINEAR : GL_NEAREST;
  texture_.setFilter(filter_);
  inset_ = p.at("inset").b();

  frustum_ = f.light.frustum(static_cast<float>(width) / static_cast<float>(height));
  if (p.at("shadow.fit").b()) {
    fitNearFar(f.light.view, f.scene.bounds(/*castersOnly=*/true), frustum_.directional,
               frustum_.near, frustum_.far);
  }
  projection_ = shadows::lightProjection(frustum_);
  view_ = f.light.view;
  f.light_view_projection = lightViewProjection();
  f.measure.count("shadow_map_renders", stale ? 1 : 0);
  return stale;
}

void ShadowMap::beginRender() const {
  framebuffer_->bind();
  glViewport(0, 0, width_, height_);
  glClear(GL_DEPTH_BUFFER_BIT);
}

glm::vec2 ShadowMap::texelFootprint() const {
  const float rows = static_cast<float>(std::max(height_, 1));
  if (frustum_.directional) return {0.0f, 2.0f * frustum_.extent / rows};
  // The same clamp lightProjection applies to the field of view.
  const float fov = glm::radians(std::clamp(frustum_.fov, 1.0f, 170.0f));
  return {2.0f * std::tan(0.5f * fov) / rows, 0.0f};
}

bool ShadowMap::drawDepthView(const Frame& frame) const {
  if (frame.mode != "light_depth") return false;
  frame.clearTarget(glm::vec3(0.0f));
  drawInset(frame, /*fullscreen=*/true);
  return true;
}

void ShadowMap::drawInset(const Frame& frame, bool fullscreen) const {
  if (!inset_ && !fullscreen) return;
  frame.drawDepthInset(texture_, frustum_.near, frustum_.far, !frustum_.directional, fullscreen);
}

}  // namespace shadows
