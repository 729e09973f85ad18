// The area light a fixed-width filter imitates (lessons 05 and 13): a kernel of half-width k
// texels blurs an edge as a disk light of some radius would, at one pair of distances. Matched
// where it matters most: the ray from the light through the casters' centre, and the receiver
// the casters rest on (their lowest point) further along it; the texel size is taken at that
// receiver (pcf::areaLightRadius has the similar triangles).
#pragma once

#include "shadow/shadow_map.hpp"

namespace shadows {

struct AreaLightMatch {
  float radius = 0;             // the truth's disk light (0: the kernel has no width)
  float occluder_distance = 0;  // along that ray, from the light
  float receiver_distance = 0;
  float texel_world = 0;  // one map texel, in world units at the receiver
};

AreaLightMatch matchAreaLight(const Frame& frame, const ShadowMap& map, float kernelTexels);

}  // namespace shadows
