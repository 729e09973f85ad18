// Shadow-volume geometry: welding, edge adjacency, the extrudable vertex buffer.
#include "math/shadow_volume.hpp"

#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

namespace shadows {
namespace {

// Position -> welded index: a hash grid of cells the size of the tolerance, searched in the
// 27 cells around a point, so two points closer than it always meet.
class Welder {
 public:
  explicit Welder(float tolerance) : cell_(tolerance) {}
  std::uint32_t index(const glm::vec3& p) {
    const glm::ivec3 c = cellOf(p);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = grid_.find(key(c + glm::ivec3(dx, dy, dz)));
          if (it == grid_.end()) continue;
          for (const std::uint32_t i : it->second) {
            if (glm::distance(points_[i], p) <= cell_) return i;
          }
        }
      }
    }
    const auto i = static_cast<std::uint32_t>(points_.size());
    points_.push_back(p);
    grid_[key(c)].push_back(i);
    return i;
  }

 private:
  // Clamped to what key() packs (21 bits a coordinate): a far corner of a tiny cell cannot
  // overflow the conversion to int.
  glm::ivec3 cellOf(const glm::vec3& p) const {
    const glm::vec3 c =
        glm::clamp(glm::floor(p / cell_), glm::vec3(-(1 << 20)), glm::vec3((1 << 20) - 1));
    return glm::ivec3(c);
  }
  static std::uint64_t key(const glm::ivec3& c) {
    const auto part = [](int v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff; };
    return part(c.x) | part(c.y) << 21 | part(c.z) << 42;
  }
  float cell_;
  std::vector<glm::vec3> points_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid_;
};

glm::vec4 planeOf(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  return {n, -glm::dot(n, a)};
}

// Pairs each half-edge a -> b with one b -> a; what is left over is open.
void findEdges(EdgeMesh& m, const std::vector<std::uint32_t>& welded) {
  struct Half {
    std::uint32_t t;
    std::uint8_t c;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<std::vector<Half>, 2>> halves;
  const size_t triangles = m.planes.size();
  for (std::uint32_t t = 0; t < triangles; ++t) {
    for (std::uint8_t c = 0; c < 3; ++c) {
      const std::uint32_t a = welded[3 * t + c], b = welded[3 * t + (c + 1) % 3];
      halves[{std::min(a, b), std::max(a, b)}][a < b ? 0 : 1].push_back({t, c});
    }
  }
  m.edges.clear();
  m.open_edges = 0;
  for (const auto& [key, sides] : halves) {
    const size_t pairs = std::min(sides[0].size(), sides[1].size());
    for (size_t i = 0; i < pairs; ++i) {
      m.edges.push_back({sides[0][i].t, sides[1][i].t, sides[0][i].c, sides[1][i].c});
    }
    m.open_edges += static_cast<long long>(sides[0].size() + sides[1].size() - 2 * pairs);
  }
}

}  // namespace

EdgeMesh buildEdgeMesh(const MeshData& mesh) {
  Bounds bounds;
  for (const Vertex& v : mesh.vertices) bounds.add(v.position);
  Welder welder(std::max(1e-5f * bounds.radius(), 1e-7f));
  EdgeMesh m;
  std::vector<std::uint32_t> welded;
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    std::array<glm::vec3, 3> p;
    std::array<std::uint32_t, 3> w;
    for (size_t k = 0; k < 3; ++k) {
      p[k] = mesh.vertices[mesh.indices[i + k]].position;
      w[k] = welder.index(p[k]);
    }
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) {
      ++m.dropped;  // a pole's sliver: no area, and it would make edges look open
      continue;
    }
    m.corners.insert(m.corners.end(), p.begin(), p.end());
    welded.insert(welded.end(), w.begin(), w.end());
    m.planes.push_back(planeOf(p[0], p[1], p[2]));
  }
  findEdges(m, welded);
  if (m.open_edges > 0) {
    // An open surface blocks light from either side: its reversed copy closes it, and its
    // rim is shared by a triangle facing the light and one facing away, a silhouette.
    const long long open = m.open_edges;
    const size_t triangles = m.planes.size();
    for (size_t t = 0; t < triangles; ++t) {
      const glm::vec3 a = m.corners[3 * t], b = m.corners[3 * t + 1], c = m.corners[3 * t + 2];
      m.corners.insert(m.corners.end(), {a, c, b});
      welded.insert(welded.end(), {welded[3 * t], welded[3 * t + 2], welded[3 * t + 1]});
      m.planes.push_back(-m.planes[t]);
    }
    findEdges(m, welded);
    m.open_edges = open;  // what the mesh had: the report names it
    m.two_sided = true;
  }
  return m;
}

VolumeBuffer buildVolumeBuffer(const EdgeMesh& m, VolumeGeometry geometry) {
  VolumeBuffer out;
  auto& v = out.vertices;
  const glm::vec4 none{0.0f};
  const auto corner = [&](std::uint32_t t, int c) { return m.corners[3 * t + (c % 3)]; };
  // The quad (b0, a0, a1, b1): with t0 lit and t1 extruded it is (b, a, a_inf, b_inf), facing
  // out of the volume; with t1 lit it is the same cycle from the other side. Its diagonal
  // starts at the lesser corner, so two volumes sharing an edge rasterize it alike and cancel.
  const auto less = [](glm::vec3 x, glm::vec3 y) {
    return x.x != y.x ? x.x < y.x : x.y != y.y ? x.y < y.y : x.z < y.z;
  };
  const auto quad = [&](glm::vec3 a0, glm::vec3 b0, glm::vec4 p0, glm::vec3 a1, glm::vec3 b1,
                        glm::vec4 p1, glm::vec4 owner) {
    if (less(b0, a0)) {
      v.insert(v.end(), {{b0, p0, owner}, {a0, p0, owner}, {a1, p1, owner}});
      v.insert(v.end(), {{b0, p0, owner}, {a1, p1, owner}, {b1, p1, owner}});
    } else {
      v.insert(v.end(), {{a0, p0, owner}, {a1, p1, owner}, {b1, p1, owner}});
      v.insert(v.end(), {{a0, p0, owner}, {b1, p1, owner}, {b0, p0, owner}});
    }
  };
  const size_t triangles = m.planes.size();
  if (geometry == VolumeGeometry::Silhouette) {
    for (std::uint32_t t = 0; t < triangles; ++t) {
      for (int c = 0; c < 3; ++c) v.push_back({corner(t, c), m.planes[t], none});
    }
    out.cap_vertices = v.size();
    for (const EdgeMesh::Edge& e : m.edges) {
      quad(corner(e.t0, e.c0), corner(e.t0, e.c0 + 1), m.planes[e.t0], corner(e.t1, e.c1 + 1),
           corner(e.t1, e.c1), m.planes[e.t1], none);
    }
    return out;
  }
  // One closed volume per triangle: itself, itself reversed, and its three edges between them.
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const glm::vec4 p = m.planes[t];
    for (int c = 0; c < 3; ++c) v.push_back({corner(t, c), p, p});
    for (int c = 3; c > 0; --c) v.push_back({corner(t, c), -p, p});
  }
  out.cap_vertices = v.size();
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const glm::vec4 p = m.planes[t];
    for (int c = 0; c < 3; ++c) {
      const glm::vec3 a = corner(t, c), b = corner(t, c + 1);
      quad(a, b, p, a, b, -p, p);
    }
  }
  return out;
}

VolumeWork volumeWork(const EdgeMesh& m, VolumeGeometry geometry, const glm::vec4& light,
                      bool lightCap, bool darkCap) {
  VolumeWork work;
  const auto caps = static_cast<long long>(lightCap) + static_cast<long long>(darkCap);
  if (geometry == VolumeGeometry::PerTriangle) {
    for (const glm::vec4& p : m.planes) {
      if (facesLight(p, light)) work.silhouette_edges += 3, work.triangles += 6 + caps;
    }
    return work;
  }
  for (const EdgeMesh::Edge& e : m.edges) {
    if (facesLight(m.planes[e.t0], light) != facesLight(m.planes[e.t1], light)) {
      ++work.silhouette_edges;
    }
  }
  work.triangles = 2 * work.silhouette_edges;
  for (const glm::vec4& p : m.planes) {
    work.triangles += facesLight(p, light) ? lightCap : darkCap;
  }
  return work;
}

}  // namespace shadows
