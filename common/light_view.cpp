#include "light_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace shadows {

void LightView::declareSize(Params& p) {
  constexpr auto kMap = kDirtyShadowMap | kDirtyResources;
  p.addInt("shadow.size", 1024, 64, 4096, "shadow map width in texels", kMap).logarithmic = true;
  // 0 (square) or the same range as the width: a 64x1 map would "match" absurd area lights.
  p.addInt("shadow.height", 0, 0, 4096, "shadow map height (0 = square, else 64..4096)", kMap)
      .check = [](const std::string& text) -> std::string {
    const double rows = std::strtod(text.c_str(), nullptr);
    return rows == 0.0 || rows >= 64.0 ? "" : "expected 0 (square) or 64..4096, got " + text;
  };
}

void LightView::declareFit(Params& p) {
  p.addBool("shadow.fit", false, "fit the light's near/far to the casters' bounds",
            kDirtyShadowMap);
  p.addBool("shadow.cache", true, "re-render the map only when the light or a caster changed",
            kDirtyShadowMap);
  p.addBool("shadow.off", false,
            "baseline: the same frame with no shadow work (no map, no lookup), for what a "
            "shadow costs",
            kDirtyShadowMap);
}

glm::ivec2 LightView::mapSize(const Params& p) {
  const int width = p.at("shadow.size").i();
  const int height = p.at("shadow.height").i();
  return {width, height > 0 ? height : width};
}

bool LightView::update(Frame& f, glm::ivec2 size, bool recreated, std::uint32_t extraDirty) {
  Params& p = f.params;
  off_ = p.at("shadow.off").b();
  const bool stale =
      (p.consume(kDirtyShadowMap | extraDirty) || !p.at("shadow.cache").b() || recreated) && !off_;
  size_ = size;
  frustum_ = f.light.frustum(static_cast<float>(size.x) / static_cast<float>(size.y));
  if (p.at("shadow.fit").b()) {
    const Light& l = f.light;
    fitNearFar(f.light.view, f.scene.casterBounds(l.position, l.directional, l.direction),
               frustum_.directional, frustum_.near, frustum_.far);
  }
  projection_ = lightProjection(frustum_);
  view_ = f.light.view;
  f.light_view_projection = viewProjection();
  f.measure.count("shadow_map_renders", stale ? 1 : 0);
  return stale;
}

glm::vec2 LightView::texelFootprint() const {
  const float rows = static_cast<float>(std::max(size_.y, 1));
  if (frustum_.directional) return {0.0f, 2.0f * frustum_.extent / rows};
  // The same clamp lightProjection applies to the field of view.
  const float fov = glm::radians(std::clamp(frustum_.fov, 1.0f, 170.0f));
  return {2.0f * std::tan(0.5f * fov) / rows, 0.0f};
}

}  // namespace shadows
