// Shadow-volume geometry (lesson 09): a caster's triangles welded by position into an edge
// adjacency, and the one vertex buffer per caster that the volume pass extrudes in its vertex
// shader (seed 003 slides 43-49).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "core/scene.hpp"

namespace shadows {

// A caster's triangles and their edges. Welded by position, because the procedural meshes
// close their seams only up to float rounding; each triangle keeps the mesh's own corners, so
// a light cap lands on exactly the depths the eye's pass wrote.
struct EdgeMesh {
  std::vector<glm::vec3> corners;  // 3 per triangle, object space, counter-clockwise outside
  std::vector<glm::vec4> planes;   // per triangle (n, d): n.p + d = 0, n pointing outside
  // Triangle t0 runs a -> b from its corner c0, t1 runs b -> a from its corner c1.
  struct Edge {
    std::uint32_t t0, t1;
    std::uint8_t c0, c1;
  };
  std::vector<Edge> edges;
  long long open_edges = 0;  // after welding: edges one triangle uses (or an odd many)
  long long dropped = 0;     // triangles two of whose corners welded into one (zero area)
  bool two_sided = false;    // it was open, so every triangle was added again reversed
};

// Welds within 1e-5 of the mesh's size. A mesh with open edges (a plane) is closed by adding
// each triangle reversed: a shell of zero thickness, whose rim becomes silhouette edges.
EdgeMesh buildEdgeMesh(const MeshData& mesh);

// Whether a triangle faces the light: the light (position, 1) or (-direction, 0) in the
// mesh's space, on the outside of its plane. The vertex shader makes the same test.
inline bool facesLight(const glm::vec4& plane, const glm::vec4& light) {
  return glm::dot(plane, light) > 0.0f;
}

// One vertex of a volume: where it is, the plane of the triangle it belongs to (it goes to
// infinity, w = 0, where that plane faces away from the light), and for one volume per
// triangle the plane of the triangle that owns the volume (none where it faces away).
struct VolumeVertex {
  glm::vec3 position;
  glm::vec4 plane;
  glm::vec4 owner;
};

enum class VolumeGeometry { Silhouette, PerTriangle };

// Caps first (every triangle: the lit ones are the light cap, the others at infinity the dark
// cap), then sides: one quad per edge whose two triangles' vertices move independently, so it
// has area only at a silhouette (slide 47 "possible silhouette edges"). PerTriangle: each
// triangle is its own closed volume (slide 47 "trivial but bad").
struct VolumeBuffer {
  std::vector<VolumeVertex> vertices;
  std::size_t cap_vertices = 0;
};
VolumeBuffer buildVolumeBuffer(const EdgeMesh& mesh, VolumeGeometry geometry);

// What the volume pass rasterizes for this light (in the mesh's space): silhouette edges, and
// the triangles with area (sides, and caps when `caps`), as the vertex shader will decide.
struct VolumeWork {
  long long silhouette_edges = 0, triangles = 0;
};
VolumeWork volumeWork(const EdgeMesh& mesh, VolumeGeometry geometry, const glm::vec4& light,
                      bool lightCap, bool darkCap);

}  // namespace shadows
