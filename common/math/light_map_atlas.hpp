// Lesson 15's light map: every surface cut into charts along its unwrap (MeshData::unwrap),
// each chart sized by its world area at so many texels per unit, packed on shelves into one
// atlas with padding between charts, and every texel's surface point (the bake's input: a
// point on the surface and its normal per texel, as the truth's G-buffer has per pixel).
// Seed 003: "incorporate shadows into light maps. For each texel, cast ray to each light
// source." No GL here: the texture is the lesson's, the rays the truth's.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace shadows {

struct LightMapChart {
  size_t object = 0;
  glm::ivec2 origin{0}, size{0};  // its texels in the atlas (padding around them)
  glm::vec2 unwrap_min{0.0f};     // the unwrap point at texel (0, 0)'s centre
  glm::vec2 texels_per_unwrap{1.0f};
  std::vector<std::uint32_t> triangles;  // into the mesh's indices / 3
};

struct LightMapAtlas {
  int width = 0, height = 0;
  float texels_per_unit = 0.0f;
  int padding = 0;
  bool texel_edges = false;  // charts end on their texels' outer edges, not on their centres
  std::vector<LightMapChart> charts;
  // Per object, per vertex: its atlas coordinate in [0, 1]^2 (texel centres at (i + 0.5) / w),
  // or (-1, -1) for an object without an unwrap, which the atlas leaves out.
  std::vector<std::vector<glm::vec2>> uv;
  // Per texel, rows from the bottom (v = 0), as the truth's SurfaceBuffer: the world point
  // (w = object index, -1 where no triangle covers the texel) and the triangle's unit normal.
  std::vector<glm::vec4> position, normal;
  std::vector<int> chart;  // per texel: its chart, or -1 in the padding between charts
  // Per texel, 1 where a triangle covers it: what dilation keeps (position and normal may be
  // handed on to the bake, this stays).
  std::vector<std::uint8_t> covered;
  long long texels() const { return static_cast<long long>(width) * height; }
  long long coveredTexels() const;
};

// The largest atlas a bake may ask for: 4096 texels a side, 4096 x 4096 in all. A texel costs
// 45 bytes while it bakes: its point and normal (32), its chart (4), its coverage (1), its
// answer and the copy uploaded (8); so 755 MB at the limit.
inline constexpr int kLightMapSideLimit = 4096;
inline constexpr long long kLightMapTexelLimit = 4096LL * 4096LL;
inline constexpr int kLightMapBytesPerTexel = 45;

// Charts and packing only (no texel is filled): cheap, for the limit's check.
// `texelEdges`: a chart's border on its outer texels' edges (a lookup there reads half a
// texel of padding), not on their centres.
LightMapAtlas planLightMap(const std::vector<SceneObject>& objects, float texelsPerUnit,
                           int padding, bool texelEdges = false);
// "" or why this atlas is refused (a side over kLightMapSideLimit, or more texels than
// kLightMapTexelLimit, the limit named).
std::string lightMapRefusal(const LightMapAtlas& plan);
// The plan with every texel's surface point: the objects at `objects`' matrices.
void fillLightMap(const std::vector<SceneObject>& objects, LightMapAtlas& atlas);

// Fills the texels no triangle covers (the padding, a triangle chart's other half) from their
// covered neighbours, ring by ring, `rings` times: bilinear filtering then never blends in a
// value that belongs to nothing. `values`: one per texel, those not `atlas.covered` unfilled.
void dilateLightMap(const LightMapAtlas& atlas, std::vector<float>& values, int rings);

// For the error along seams: per object, the world segments where a chart ends (edges of one
// triangle only), at `objects`' matrices.
struct Segment {
  glm::vec3 a, b;
};
std::vector<std::vector<Segment>> chartBorders(const std::vector<SceneObject>& objects);
float distanceToSegment(glm::vec3 p, const Segment& s);

}  // namespace shadows
