#include "core/scene.hpp"

#include <algorithm>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <stdexcept>

namespace shadows {

namespace {

constexpr float kPi = glm::pi<float>();

// A flat face's unwrap: its points in the face's own plane, a at the origin, u along a->b.
void unwrapFlat(MeshData& m, std::initializer_list<glm::vec3> points) {
  const glm::vec3 a = *points.begin();
  const glm::vec3 u = glm::normalize(*(points.begin() + 1) - a);
  glm::vec3 n(0.0f);
  for (auto p = points.begin() + 2; p != points.end() && glm::length(n) == 0.0f; ++p) {
    n = glm::cross(u, *p - a);
  }
  const glm::vec3 v = glm::normalize(glm::cross(glm::normalize(n), u));
  for (glm::vec3 p : points) m.unwrap.push_back({glm::dot(p - a, u), glm::dot(p - a, v)});
}

void addQuad(MeshData& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (glm::vec3 p : {a, b, c, d}) m.vertices.push_back({p, n});
  unwrapFlat(m, {a, b, c, d});
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

// A (u, v) grid of vertices from a parametric surface, wrapped into triangles.
template <typename Surface>
MeshData makeGrid(int uSegments, int vSegments, Surface surface) {
  MeshData m;
  for (int j = 0; j <= vSegments; ++j) {
    for (int i = 0; i <= uSegments; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(uSegments);
      const float v = static_cast<float>(j) / static_cast<float>(vSegments);
      m.vertices.push_back(surface(u, v));
    }
  }
  // The unwrap: (u, v) times the longest line of the grid along each (the equator, say).
  const auto row = static_cast<std::uint32_t>(uSegments + 1);
  float length_u = 0.0f, length_v = 0.0f;
  for (int j = 0; j <= vSegments; ++j) {
    float along = 0.0f;
    for (int i = 0; i < uSegments; ++i) {
      along +=
          glm::distance(m.vertices[j * row + i].position, m.vertices[j * row + i + 1].position);
    }
    length_u = std::max(length_u, along);
  }
  for (int i = 0; i <= uSegments; ++i) {
    float along = 0.0f;
    for (int j = 0; j < vSegments; ++j) {
      along +=
          glm::distance(m.vertices[j * row + i].position, m.vertices[(j + 1) * row + i].position);
    }
    length_v = std::max(length_v, along);
  }
  for (int j = 0; j <= vSegments; ++j) {
    for (int i = 0; i <= uSegments; ++i) {
      m.unwrap.push_back({length_u * static_cast<float>(i) / static_cast<float>(uSegments),
                          length_v * static_cast<float>(j) / static_cast<float>(vSegments)});
    }
  }
  for (int j = 0; j < vSegments; ++j) {
    for (int i = 0; i < uSegments; ++i) {
      const auto a = static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      // Counter-clockwise seen from outside (the side the normals point to), so culling
      // front faces leaves the back faces (lesson 04's back_faces mode).
      for (std::uint32_t k : {a, a + 1, a + row, a + 1, a + row + 1, a + row}) {
        m.indices.push_back(k);
      }
    }
  }
  return m;
}

}  // namespace

MeshData makePlane(float halfX, float halfZ) {
  MeshData m;
  addQuad(m, {-halfX, 0, halfZ}, {halfX, 0, halfZ}, {halfX, 0, -halfZ}, {-halfX, 0, -halfZ},
          {0, 1, 0});
  return m;
}

MeshData makeBox(glm::vec3 h) {
  MeshData m;
  // Each face counter-clockwise seen from outside.
  addQuad(m, {h.x, -h.y, h.z}, {h.x, -h.y, -h.z}, {h.x, h.y, -h.z}, {h.x, h.y, h.z}, {1, 0, 0});
  addQuad(m, {-h.x, -h.y, -h.z}, {-h.x, -h.y, h.z}, {-h.x, h.y, h.z}, {-h.x, h.y, -h.z},
          {-1, 0, 0});
  addQuad(m, {-h.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, -h.z}, {-h.x, h.y, -h.z}, {0, 1, 0});
  addQuad(m, {-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z}, {-h.x, -h.y, h.z},
          {0, -1, 0});
  addQuad(m, {-h.x, -h.y, h.z}, {h.x, -h.y, h.z}, {h.x, h.y, h.z}, {-h.x, h.y, h.z}, {0, 0, 1});
  addQuad(m, {h.x, -h.y, -h.z}, {-h.x, -h.y, -h.z}, {-h.x, h.y, -h.z}, {h.x, h.y, -h.z},
          {0, 0, -1});
  return m;
}

MeshData makeSphere(float radius, int slices, int stacks) {
  return makeGrid(slices, stacks, [radius](float u, float v) {
    const float phi = u * 2.0f * kPi, theta = v * kPi;
    const glm::vec3 n{std::sin(theta) * std::cos(phi), -std::cos(theta),
                      -std::sin(theta) * std::sin(phi)};
    return Vertex{radius * n, n};
  });
}

MeshData makeTorus(float ringRadius, float tubeRadius, int ringSegments, int tubeSegments) {
  return makeGrid(ringSegments, tubeSegments, [=](float u, float v) {
    const float a = u * 2.0f * kPi, b = v * 2.0f * kPi;
    const glm::vec3 ring{std::cos(a), 0.0f, -std::sin(a)};
    const glm::vec3 n = std::cos(b) * ring + glm::vec3(0.0f, std::sin(b), 0.0f);
    return Vertex{ringRadius * ring + tubeRadius * n, n};
  });
}

MeshData makePyramid(float halfBase, float height) {
  MeshData m;
  const glm::vec3 apex{0, height, 0};
  const glm::vec3 corners[4] = {{-halfBase, 0, halfBase},
                                {halfBase, 0, halfBase},
                                {halfBase, 0, -halfBase},
                                {-halfBase, 0, -halfBase}};
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 a = corners[i], b = corners[(i + 1) % 4];
    const glm::vec3 n = glm::normalize(glm::cross(b - a, apex - a));
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (glm::vec3 p : {a, b, apex}) m.vertices.push_back({p, n});
    unwrapFlat(m, {a, b, apex});
    for (std::uint32_t k : {0u, 1u, 2u}) m.indices.push_back(base + k);
  }
  addQuad(m, corners[3], corners[2], corners[1], corners[0], {0, -1, 0});
  return m;
}

Bounds SceneObject::worldBounds() const {
  Bounds b;
  for (const auto& v : mesh.vertices) b.add(glm::vec3(model * glm::vec4(v.position, 1.0f)));
  return b;
}

bool SceneObject::castsFrom(glm::vec3 lightPosition, bool directional,
                            glm::vec3 lightDirection) const {
  if (caster) return true;
  if (mesh.vertices.empty()) return false;
  const glm::vec3 point = glm::vec3(model * glm::vec4(mesh.vertices[0].position, 1.0f));
  const glm::vec3 normal = glm::mat3(glm::transpose(glm::inverse(model))) * mesh.vertices[0].normal;
  const glm::vec3 to_light = directional ? -lightDirection : lightPosition - point;
  return glm::dot(normal, to_light) <= 0.0f;
}

Bounds Scene::casterBounds(glm::vec3 lightPosition, bool directional,
                           glm::vec3 lightDirection) const {
  Bounds b;
  for (const auto& o : objects) {
    if (o.castsFrom(lightPosition, directional, lightDirection)) b.add(o.worldBounds());
  }
  return b;
}

Bounds Scene::bounds(bool castersOnly) const {
  Bounds b;
  for (const auto& o : objects) {
    if (!castersOnly || o.caster) b.add(o.worldBounds());
  }
  return b;
}

float Scene::eyeFar(glm::vec3 eye) const {
  const Bounds b = bounds();
  if (b.empty()) return camera.far;
  return std::max(camera.far, 1.01f * (glm::distance(eye, b.center()) + b.radius()));
}

namespace {

// The distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
float distanceToTriangle(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return glm::distance(p, a);
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return glm::distance(p, b);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return glm::distance(p, a + ab * (d1 / (d1 - d3)));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return glm::distance(p, c);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return glm::distance(p, a + ac * (d2 / (d2 - d6)));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f) {
    return glm::distance(p, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  }
  const float denom = va + vb + vc;
  if (!(denom > 0.0f)) return glm::distance(p, a);  // a sliver: its corner will do
  return glm::distance(p, a + ab * (vb / denom) + ac * (vc / denom));
}

}  // namespace

std::string Scene::surfaceAt(glm::vec3 p, float tolerance) const {
  for (const SceneObject& o : objects) {
    const Bounds b = o.worldBounds();
    if (glm::any(glm::lessThan(p, b.min - tolerance)) ||
        glm::any(glm::greaterThan(p, b.max + tolerance))) {
      continue;
    }
    const auto world = [&](std::uint32_t i) {
      return glm::vec3(o.model * glm::vec4(o.mesh.vertices[i].position, 1.0f));
    };
    for (size_t t = 0; t + 2 < o.mesh.indices.size(); t += 3) {
      const glm::vec3 a = world(o.mesh.indices[t]), bb = world(o.mesh.indices[t + 1]),
                      c = world(o.mesh.indices[t + 2]);
      if (distanceToTriangle(p, a, bb, c) <= tolerance) return o.name;
    }
  }
  return {};
}

void Scene::worldTriangles(std::vector<glm::vec3>& positions,
                           std::vector<glm::uvec3>& triangles) const {
  positions.clear();
  triangles.clear();
  for (const auto& o : objects) {
    const auto base = static_cast<std::uint32_t>(positions.size());
    for (const auto& v : o.mesh.vertices) {
      positions.push_back(glm::vec3(o.model * glm::vec4(v.position, 1.0f)));
    }
    for (size_t i = 0; i + 2 < o.mesh.indices.size(); i += 3) {
      triangles.push_back(
          glm::uvec3(o.mesh.indices[i], o.mesh.indices[i + 1], o.mesh.indices[i + 2]) + base);
    }
  }
}

size_t Scene::movingObject(int asked) const {
  const int last = static_cast<int>(objects.size()) - 1;
  const auto chosen = static_cast<size_t>(asked < 0 ? last : std::min(asked, last));
  if (objects[chosen].caster) return chosen;
  for (size_t k = objects.size(); k-- > 0;) {
    if (objects[k].caster) return k;
  }
  return chosen;
}

}  // namespace shadows
