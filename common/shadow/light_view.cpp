#include "shadow/light_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace shadows {

void LightView::declareSize(Params& p) {
  const Params::SharedScope shared(p);
  constexpr auto kMap = kDirtyShadowMap | kDirtyResources;
  size_param_ =
      p.addInt("shadow.size", 1024, 64, 4096, "shadow map width in texels", kMap).logScale();
  // 0 (square) or the same range as the width: a 64x1 map would "match" absurd area lights.
  height_ =
      p.addInt("shadow.height", 0, 0, 4096, "shadow map height (0 = square, else 64..4096)", kMap)
          .checkedBy([](const std::string& text) -> std::string {
            const double rows = std::strtod(text.c_str(), nullptr);
            return rows == 0.0 || rows >= 64.0 ? ""
                                               : "expected 0 (square) or 64..4096, got " + text;
          });
}

void LightView::declareFit(Params& p) {
  const Params::SharedScope shared(p);
  fit_ = p.addBool("shadow.fit", false, "fit the light's near/far to the casters' bounds",
                   kDirtyShadowMap);
  cache_ = p.addBool("shadow.cache", true,
                     "re-render the map only when the light or a caster changed", kDirtyShadowMap);
  off_param_ =
      p.addBool("shadow.off", false,
                "baseline: the same frame with no shadow work (no map, no lookup), for what a "
                "shadow costs",
                kDirtyShadowMap);
}

bool LightView::update(Frame& f, glm::ivec2 size, bool recreated, std::uint32_t extraDirty) {
  off_ = off_param_();
  const bool stale =
      (f.params.consume(kDirtyShadowMap | extraDirty) || !cache_() || recreated) && !off_;
  size_ = size;
  frustum_ = f.light.frustum(static_cast<float>(size.x) / static_cast<float>(size.y));
  fitted_ = fit_();
  if (fitted_ || track_caster_distances_) {
    const Light& l = f.light;
    const Bounds casters = f.scene.casterBounds(l.position, l.directional, l.direction);
    if (!depthRange(l.view, casters, caster_distances_.x, caster_distances_.y)) {
      caster_distances_ = glm::vec2(0.0f);
    }
    if (fitted_) fitNearFar(l.view, casters, frustum_.directional, frustum_.near, frustum_.far);
  }
  projection_ = lightProjection(frustum_);
  view_ = f.light.view;
  warped_.reset();
  f.measure.count("shadow_map_renders", 0);  // in every report of a map lesson, cached or not
  return stale;
}

std::optional<ShadowSampling> LightView::sampling() const {
  if (off_) return std::nullopt;
  return ShadowSampling{textureMatrix(), size_};
}

void LightView::sampledBy(Frame& f) const {
  f.light_view_projection = projection_ * view_;  // the light's own frustum, warped or not (10)
  f.shadow_sampling = sampling();
}

bool LightView::warp(const glm::mat4& viewProjection) {
  warped_ = viewProjection;
  const bool changed = last_warp_ != warped_;
  last_warp_ = warped_;
  return changed;
}

glm::vec2 LightView::texelFootprint() const {
  const float rows = static_cast<float>(std::max(size_.y, 1));
  if (frustum_.directional) return {0.0f, 2.0f * frustum_.extent / rows};
  // The same clamp lightProjection applies to the field of view.
  const float fov = glm::radians(std::clamp(frustum_.fov, 1.0f, 170.0f));
  return {2.0f * std::tan(0.5f * fov) / rows, 0.0f};
}

}  // namespace shadows
