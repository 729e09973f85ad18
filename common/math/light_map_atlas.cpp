#include "math/light_map_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

namespace shadows {

namespace {

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

glm::vec3 world(const SceneObject& o, std::uint32_t vertex) {
  return glm::vec3(o.model * glm::vec4(o.mesh.vertices[vertex].position, 1.0f));
}

bool hasUnwrap(const SceneObject& o) {
  return !o.mesh.vertices.empty() && o.mesh.unwrap.size() == o.mesh.vertices.size();
}

// A chart: the triangles that share vertices (a face of a box, a whole sphere's grid).
std::vector<std::vector<std::uint32_t>> chartsOf(const MeshData& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  const size_t triangles = mesh.indices.size() / 3;
  for (size_t t = 0; t < triangles; ++t) {
    const int a = findRoot(parent, static_cast<int>(mesh.indices[3 * t]));
    for (int k = 1; k < 3; ++k) {
      const int b = findRoot(parent, static_cast<int>(mesh.indices[3 * t + k]));
      if (a != b) parent[b] = a;
    }
  }
  std::map<int, std::vector<std::uint32_t>> by_root;  // ordered: the same charts every run
  for (size_t t = 0; t < triangles; ++t) {
    by_root[findRoot(parent, static_cast<int>(mesh.indices[3 * t]))].push_back(
        static_cast<std::uint32_t>(t));
  }
  std::vector<std::vector<std::uint32_t>> charts;
  for (auto& [root, list] : by_root) charts.push_back(std::move(list));
  return charts;
}

// World length per unwrap unit along u and along v, the largest over the chart's triangles
// (a model matrix may stretch one more than the other).
glm::vec2 worldPerUnwrap(const SceneObject& o, const std::vector<std::uint32_t>& triangles) {
  glm::vec2 scale(0.0f);
  for (const std::uint32_t t : triangles) {
    const std::uint32_t* i = &o.mesh.indices[3 * t];
    const glm::vec2 u0 = o.mesh.unwrap[i[0]], u1 = o.mesh.unwrap[i[1]], u2 = o.mesh.unwrap[i[2]];
    const glm::vec3 p0 = world(o, i[0]), p1 = world(o, i[1]), p2 = world(o, i[2]);
    const glm::vec2 e1 = u1 - u0, e2 = u2 - u0;
    const float det = e1.x * e2.y - e2.x * e1.y;
    if (std::abs(det) < 1e-12f) continue;  // a pole's sliver
    // dP/du and dP/dv from the two edges.
    const glm::vec3 d1 = p1 - p0, d2 = p2 - p0;
    const glm::vec3 dpdu = (d1 * e2.y - d2 * e1.y) / det;
    const glm::vec3 dpdv = (d2 * e1.x - d1 * e2.x) / det;
    scale = glm::max(scale, glm::vec2(glm::length(dpdu), glm::length(dpdv)));
  }
  return scale;
}

}  // namespace

long long LightMapAtlas::coveredTexels() const {
  return std::count(covered.begin(), covered.end(), std::uint8_t{1});
}

LightMapAtlas planLightMap(const std::vector<SceneObject>& objects, float texelsPerUnit,
                           int padding, bool texelEdges) {
  LightMapAtlas atlas;
  atlas.texel_edges = texelEdges;
  atlas.texels_per_unit = texelsPerUnit;
  atlas.padding = std::max(padding, 0);
  atlas.uv.resize(objects.size());
  for (size_t k = 0; k < objects.size(); ++k) {
    const SceneObject& o = objects[k];
    atlas.uv[k].assign(o.mesh.vertices.size(), glm::vec2(-1.0f));
    if (!hasUnwrap(o)) continue;
    for (auto& triangles : chartsOf(o.mesh)) {
      LightMapChart c;
      c.object = k;
      glm::vec2 lo(1e30f), hi(-1e30f);
      for (const std::uint32_t t : triangles) {
        for (int j = 0; j < 3; ++j) {
          lo = glm::min(lo, o.mesh.unwrap[o.mesh.indices[3 * t + j]]);
          hi = glm::max(hi, o.mesh.unwrap[o.mesh.indices[3 * t + j]]);
        }
      }
      const glm::vec2 extent = glm::max(hi - lo, glm::vec2(1e-6f));
      const glm::vec2 world_extent = extent * worldPerUnwrap(o, triangles);
      // Texel centres from one edge of the chart to the other: a vertex on its border lies on
      // a centre, so bilinear filtering inside a chart never reads past its last texel. Or
      // (texelEdges, the usual first try) the chart's border on its texels' outer edges: a
      // lookup there reads half the texel beyond, in the padding.
      const glm::vec2 texels = glm::ceil(world_extent * texelsPerUnit) + (texelEdges ? 0.0f : 1.0f);
      c.size =
          glm::ivec2(glm::clamp(texels, glm::vec2(texelEdges ? 1.0f : 2.0f), glm::vec2(1 << 20)));
      c.unwrap_min = lo;
      c.texels_per_unwrap = glm::vec2(texelEdges ? c.size : c.size - 1) / extent;
      c.triangles = std::move(triangles);
      atlas.charts.push_back(std::move(c));
    }
  }
  // Shelves: the tallest charts first, rows as wide as the square the area needs.
  std::vector<size_t> order(atlas.charts.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return atlas.charts[a].size.y > atlas.charts[b].size.y;
  });
  const int pad = atlas.padding;
  double area = 0.0;
  int widest = 1;
  for (const auto& c : atlas.charts) {
    area += static_cast<double>(c.size.x + 2 * pad) * (c.size.y + 2 * pad);
    widest = std::max(widest, c.size.x + 2 * pad);
  }
  const int width =
      (std::max(widest, static_cast<int>(std::ceil(std::sqrt(area * 1.1)))) + 3) / 4 * 4;
  int x = 0, y = 0, row = 0;
  for (const size_t k : order) {
    LightMapChart& c = atlas.charts[k];
    if (x + c.size.x + 2 * pad > width) x = 0, y += row, row = 0;
    c.origin = glm::ivec2(x + pad, y + pad);
    x += c.size.x + 2 * pad;
    row = std::max(row, c.size.y + 2 * pad);
  }
  atlas.width = atlas.charts.empty() ? 0 : width;
  atlas.height = atlas.charts.empty() ? 0 : y + row;
  for (const auto& c : atlas.charts) {
    const SceneObject& o = objects[c.object];
    for (const std::uint32_t t : c.triangles) {
      for (int j = 0; j < 3; ++j) {
        const std::uint32_t v = o.mesh.indices[3 * t + j];
        const glm::vec2 texel = (o.mesh.unwrap[v] - c.unwrap_min) * c.texels_per_unwrap;
        atlas.uv[c.object][v] = (glm::vec2(c.origin) + texel + (texelEdges ? 0.0f : 0.5f)) /
                                glm::vec2(atlas.width, atlas.height);
      }
    }
  }
  return atlas;
}

std::string lightMapRefusal(const LightMapAtlas& plan) {
  if (plan.texels() <= kLightMapTexelLimit && plan.width <= kLightMapSideLimit &&
      plan.height <= kLightMapSideLimit) {
    return {};
  }
  const auto mb = [](long long texels) {
    // Rounded, not cut: 754,974,720 bytes is 755 MB.
    return std::to_string((texels * kLightMapBytesPerTexel + 500000) / 1000000) + " MB";
  };
  char density[32];
  std::snprintf(density, sizeof density, "%g", plan.texels_per_unit);
  return "the light map would be " + std::to_string(plan.width) + " x " +
         std::to_string(plan.height) + " texels (" + std::to_string(plan.charts.size()) +
         " charts at " + density + " texels a unit), over the limit of 4096 texels a side and " +
         "4096 x 4096 in all (" + mb(kLightMapTexelLimit) + " while it bakes; this one " +
         mb(plan.texels()) + "): lower lightmap.texels_per_unit";
}

void fillLightMap(const std::vector<SceneObject>& objects, LightMapAtlas& atlas) {
  const size_t n = static_cast<size_t>(atlas.texels());
  atlas.position.assign(n, glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
  atlas.normal.assign(n, glm::vec4(0.0f));
  atlas.chart.assign(n, -1);
  atlas.covered.assign(n, 0);
  for (size_t k = 0; k < atlas.charts.size(); ++k) {
    const LightMapChart& c = atlas.charts[k];
    for (int y = 0; y < c.size.y; ++y) {
      for (int x = 0; x < c.size.x; ++x) {
        atlas.chart[static_cast<size_t>(c.origin.y + y) * atlas.width + c.origin.x + x] =
            static_cast<int>(k);
      }
    }
    const SceneObject& o = objects[c.object];
    for (const std::uint32_t t : c.triangles) {
      const std::uint32_t* i = &o.mesh.indices[3 * t];
      glm::vec2 q[3];
      for (int j = 0; j < 3; ++j) q[j] = (o.mesh.unwrap[i[j]] - c.unwrap_min) * c.texels_per_unwrap;
      const float area =
          (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
      if (std::abs(area) < 1e-9f) continue;  // a pole's sliver covers no texel
      const glm::vec3 p[3] = {world(o, i[0]), world(o, i[1]), world(o, i[2])};
      const glm::vec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
      // A sliver at a pole: its two pole corners differ only by sin(pi)'s rounding, and its
      // normal would be noise. Its texels stay uncovered, for dilation to fill.
      const float longest = std::max(
          {glm::distance(p[0], p[1]), glm::distance(p[1], p[2]), glm::distance(p[2], p[0])});
      if (glm::length(cross) <= 1e-4f * longest * longest) continue;
      const glm::vec3 normal = glm::normalize(cross);  // the triangle's, as its winding says
      const glm::ivec2 lo =
          glm::max(glm::ivec2(glm::floor(glm::min(q[0], glm::min(q[1], q[2])))), glm::ivec2(0));
      const glm::ivec2 hi =
          glm::min(glm::ivec2(glm::ceil(glm::max(q[0], glm::max(q[1], q[2])))), c.size - 1);
      for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
          const glm::vec2 s = glm::vec2(static_cast<float>(x), static_cast<float>(y)) +
                              (atlas.texel_edges ? 0.5f : 0.0f);
          // Barycentrics of the texel's centre; a hair of tolerance keeps the centres on a
          // chart's border (where its vertices lie) inside.
          const float b1 =
              ((s.x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (s.y - q[0].y)) / area;
          const float b2 =
              ((q[1].x - q[0].x) * (s.y - q[0].y) - (s.x - q[0].x) * (q[1].y - q[0].y)) / area;
          const float b0 = 1.0f - b1 - b2;
          constexpr float kEdge = -1e-4f;
          if (b0 < kEdge || b1 < kEdge || b2 < kEdge) continue;
          const size_t at = static_cast<size_t>(c.origin.y + y) * atlas.width + c.origin.x + x;
          if (atlas.covered[at] != 0) continue;  // the first triangle keeps a shared centre
          const glm::vec3 point = b0 * p[0] + b1 * p[1] + b2 * p[2];
          atlas.position[at] = glm::vec4(point, static_cast<float>(c.object));
          atlas.normal[at] = glm::vec4(normal, 0.0f);
          atlas.covered[at] = 1;
        }
      }
    }
  }
}

void dilateLightMap(const LightMapAtlas& atlas, std::vector<float>& values, int rings) {
  const int w = atlas.width, h = atlas.height;
  std::vector<char> known(values.size());
  for (size_t i = 0; i < values.size(); ++i) known[i] = atlas.covered[i] != 0 ? 1 : 0;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> next = known;
    bool any = false;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        if (known[i]) continue;
        // Neighbours of the texel's own chart first: across padding, a texel takes nothing of
        // the chart next door while its own chart has a value.
        float sum[2] = {0.0f, 0.0f};
        int count[2] = {0, 0};
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
            const size_t j = static_cast<size_t>(ny) * w + nx;
            if (!known[j]) continue;
            const int same = atlas.chart[j] == atlas.chart[i] ? 0 : 1;
            sum[same] += values[j];
            ++count[same];
          }
        }
        const int use = count[0] > 0 ? 0 : 1;
        if (count[use] == 0) continue;
        values[i] = sum[use] / static_cast<float>(count[use]);
        next[i] = 1;
        any = true;
      }
    }
    known.swap(next);
    if (!any) break;
  }
}

std::vector<std::vector<Segment>> chartBorders(const std::vector<SceneObject>& objects) {
  std::vector<std::vector<Segment>> borders(objects.size());
  for (size_t k = 0; k < objects.size(); ++k) {
    const SceneObject& o = objects[k];
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (size_t t = 0; t + 2 < o.mesh.indices.size(); t += 3) {
      for (int j = 0; j < 3; ++j) {
        std::uint32_t a = o.mesh.indices[t + j], b = o.mesh.indices[t + (j + 1) % 3];
        if (a > b) std::swap(a, b);
        ++uses[{a, b}];
      }
    }
    for (const auto& [edge, count] : uses) {
      if (count != 1) continue;
      const Segment s{world(o, edge.first), world(o, edge.second)};
      if (glm::distance(s.a, s.b) > 0.0f) borders[k].push_back(s);
    }
  }
  return borders;
}

float distanceToSegment(glm::vec3 p, const Segment& s) {
  const glm::vec3 d = s.b - s.a;
  const float len2 = glm::dot(d, d);
  const float t = len2 > 0.0f ? glm::clamp(glm::dot(p - s.a, d) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::distance(p, s.a + t * d);
}

}  // namespace shadows
