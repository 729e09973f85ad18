// Procedural meshes and the named scene presets. One world-space triangle list feeds both
// the rasterizer and the ray-traced truth, so both see exactly the same geometry.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace shadows {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  // Per vertex, where it lies when the surface is laid out flat (object units along the
  // surface): a face's own plane, a grid's (u, v) scaled by its lengths. Lesson 15's light
  // map cuts charts along it (math/light_map_atlas.hpp); beside Vertex, so no vertex buffer
  // grows.
  std::vector<glm::vec2> unwrap;
};

MeshData makePlane(float halfX, float halfZ);  // in y = 0, normal +y
MeshData makeBox(glm::vec3 halfExtent);
MeshData makeSphere(float radius, int slices, int stacks);
MeshData makeTorus(float ringRadius, float tubeRadius, int ringSegments, int tubeSegments);
MeshData makePyramid(float halfBase, float height);  // base on y = 0, apex up

struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  bool empty() const { return min.x > max.x; }
  void add(glm::vec3 p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void add(const Bounds& b) {
    if (!b.empty()) add(b.min), add(b.max);
  }
  glm::vec3 center() const { return 0.5f * (min + max); }
  float radius() const { return empty() ? 0.0f : 0.5f * glm::length(max - min); }
};

struct SceneObject {
  std::string name;
  MeshData mesh;
  glm::mat4 model{1.0f};
  glm::vec3 color{0.8f};
  // Drawn into shadow maps. false marks a one-sided plane (a floor, a wall) that cannot
  // shadow anything on its front side, so a map may skip it while the light is in front of
  // it; from behind it hides everything in front (castsFrom).
  bool caster = true;
  bool receiver = true;  // shows shadows
  Bounds worldBounds() const;
  // Whether the object can cast a shadow lit from this light: casters always, a receiver-only
  // plane when the light is behind it (or in its plane). Skipping work must never change the
  // answer: this decides per frame.
  bool castsFrom(glm::vec3 lightPosition, bool directional, glm::vec3 lightDirection) const;
};

struct LightSetup {
  bool directional = false;
  glm::vec3 position{0.0f, 5.0f, 0.0f};
  glm::vec3 target{0.0f};
  float fov = 60.0f;     // spot: full vertical angle in degrees
  float extent = 10.0f;  // directional: half width of the orthographic box
  float near = 1.0f, far = 20.0f;
};

struct CameraSetup {
  glm::vec3 position{0.0f, 3.0f, 8.0f};
  glm::vec3 target{0.0f};
  float fov = 45.0f;  // vertical, degrees
  float near = 0.1f, far = 100.0f;
};

struct Scene {
  std::string name;
  std::vector<SceneObject> objects;
  LightSetup light;
  CameraSetup camera;
  Bounds bounds(bool castersOnly = false) const;
  // The eye's far plane from `eye`: camera.far, or further where the whole scene would not
  // fit (camera.pos reaches 100 along each axis, so 173 from the centre).
  float eyeFar(glm::vec3 eye) const;
  // The object whose surface passes within `tolerance` of `p` ("" for none): a point light
  // there lies in the plane of the faces around it, and no technique's answer is defined.
  std::string surfaceAt(glm::vec3 p, float tolerance) const;
  // The bounds of what casts a shadow from this light (SceneObject::castsFrom).
  Bounds casterBounds(glm::vec3 lightPosition, bool directional, glm::vec3 lightDirection) const;
  // All triangles in world space, in object order (the truth's input).
  void worldTriangles(std::vector<glm::vec3>& positions, std::vector<glm::uvec3>& triangles) const;
  // The object a `move.object` of `asked` moves (lessons 15 and 16): that index (-1: the last
  // object), or the last caster where that one casts nothing (a floor that moved would take
  // every baked shadow with it).
  size_t movingObject(int asked) const;
};

const std::vector<std::string>& scenePresets();
Scene makeScene(const std::string& preset);  // throws std::invalid_argument for unknown names

}  // namespace shadows
