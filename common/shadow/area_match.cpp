#include "shadow/area_match.hpp"

#include <algorithm>

#include "math/pcf_math.hpp"

namespace shadows {

AreaLightMatch matchAreaLight(const Frame& f, const ShadowMap& map, float kernelTexels) {
  AreaLightMatch m;
  const Bounds casters = f.scene.bounds(/*castersOnly=*/true);
  const LightFrustum& fr = map.frustum();
  const glm::vec3 light = f.light.position, centre = casters.center();
  const glm::vec3 ray = f.light.directional || glm::distance(centre, light) < 1e-4f
                            ? f.light.direction
                            : glm::normalize(centre - light);
  m.occluder_distance = glm::dot(centre - light, ray);
  const float down = -ray.y;  // how fast the ray descends toward the floor
  const float gap = down > 0.05f ? (centre.y - casters.min.y) / down : casters.radius();
  m.receiver_distance = m.occluder_distance + gap;
  // Depth along the light's axis (a receiver behind a spot light gets no shadow anyway).
  const float axial = std::max(glm::dot(ray * m.receiver_distance, f.light.direction), fr.near);
  m.texel_world = map.texelWorldSize(axial);
  m.radius = pcf::areaLightRadius(kernelTexels, m.texel_world, m.occluder_distance,
                                  m.receiver_distance, fr.directional);
  return m;
}

}  // namespace shadows
