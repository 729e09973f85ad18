#include "core/scene.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

namespace shadows {

namespace {

constexpr float kPi = glm::pi<float>();

void addQuad(MeshData& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (glm::vec3 p : {a, b, c, d}) m.vertices.push_back({p, n});
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
  const auto row = static_cast<std::uint32_t>(uSegments + 1);
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

const std::vector<std::string>& scenePresets() {
  static const std::vector<std::string> names = {"torus_pyramid", "grazing", "dueling", "cubes"};
  return names;
}

namespace {

glm::mat4 translate(glm::vec3 t) {
  return glm::translate(glm::mat4(1.0f), t);
}

// A floor that receives but casts nothing (nothing lies below it), so the shadow pass can
// skip it.
SceneObject floorObject(float half, float y) {
  return {"floor", makePlane(half, half), translate({0, y, 0}), {0.75f, 0.75f, 0.72f}, false, true};
}

Scene torusPyramid() {
  Scene s;
  s.objects.push_back(floorObject(8.0f, 0.0f));
  // A torus tilted 60 degrees, resting on the floor: its lowest point is R sin(a) + r down.
  const float ring = 1.0f, tube = 0.35f, tilt = glm::radians(60.0f);
  const glm::mat4 torus = translate({-0.9f, ring * std::sin(tilt) + tube, 0.2f}) *
                          glm::rotate(glm::mat4(1.0f), tilt, {1, 0, 0});
  s.objects.push_back({"torus", makeTorus(ring, tube, 96, 48), torus, {0.85f, 0.45f, 0.25f}});
  s.objects.push_back(
      {"pyramid",
       makePyramid(0.8f, 1.6f),
       translate({1.6f, 0, -0.4f}) * glm::rotate(glm::mat4(1.0f), glm::radians(20.0f), {0, 1, 0}),
       {0.3f, 0.55f, 0.85f}});
  s.objects.push_back(
      {"sphere", makeSphere(0.45f, 48, 24), translate({0.6f, 0.45f, 1.6f}), {0.5f, 0.8f, 0.4f}});
  s.light = {false, {3.5f, 6.0f, 4.0f}, {0.0f, 0.5f, 0.0f}, 55.0f, 10.0f, 2.0f, 16.0f};
  s.camera = {{0.0f, 4.0f, 7.5f}, {0.2f, 0.6f, 0.0f}, 45.0f, 0.1f, 100.0f};
  return s;
}

// Lesson 08's dusty room (seed 000, "Combining Shadows with Atmospherics"): a floor and two
// walls, a spotlight high in a corner shining down past a pillar, a floating sphere and a
// torus, so the light shafts in the air are visibly cut by them.
Scene room() {
  Scene s;
  const glm::mat4 one(1.0f);
  const glm::vec3 plaster{0.72f, 0.7f, 0.66f};
  s.objects.push_back(floorObject(6.0f, 0.0f));
  // Walls receive but cast nothing: the light is inside the room, they bound what it sees.
  s.objects.push_back({"back_wall", makePlane(6.0f, 3.0f),
                       translate({0, 3, -5}) * glm::rotate(one, glm::radians(90.0f), {1, 0, 0}),
                       plaster, false, true});
  s.objects.push_back({"left_wall", makePlane(3.0f, 5.0f),
                       translate({-6, 3, 0}) * glm::rotate(one, glm::radians(-90.0f), {0, 0, 1}),
                       plaster, false, true});
  s.objects.push_back({"pillar",
                       makeBox({0.35f, 1.6f, 0.35f}),
                       translate({-0.6f, 1.6f, -1.0f}),
                       {0.55f, 0.45f, 0.4f}});
  s.objects.push_back(
      {"sphere", makeSphere(0.55f, 48, 24), translate({1.2f, 2.9f, -0.6f}), {0.5f, 0.8f, 0.4f}});
  s.objects.push_back(
      {"torus",
       makeTorus(0.7f, 0.22f, 96, 48),
       translate({0.9f, 0.92f, 1.4f}) * glm::rotate(one, glm::radians(80.0f), {1, 0, 0}),
       {0.85f, 0.45f, 0.25f}});
  s.light = {false, {3.6f, 5.6f, -2.4f}, {-0.8f, 0.0f, 0.6f}, 42.0f, 10.0f, 0.5f, 12.0f};
  s.camera = {{-1.2f, 2.6f, 8.8f}, {0.2f, 1.8f, -1.0f}, 50.0f, 0.1f, 100.0f};
  return s;
}

// Lesson 10's planes of interest beside the floor (seed 002, "Playing with Projection
// Matrices": "ground plane, wall, table top"): receivers that cast nothing, so a map never
// holds them and only the projection decides how well they are shadowed.
void addWallAndTable(Scene& s, const glm::mat4& wall, glm::vec3 tableAt, float tilt) {
  const glm::mat4 one(1.0f);
  s.objects.push_back({"wall", makePlane(8.0f, 3.0f), wall, {0.72f, 0.7f, 0.66f}, false, true});
  const glm::mat4 table = translate(tableAt) * glm::rotate(one, glm::radians(tilt), {1, 0, 0});
  s.objects.push_back({"table", makePlane(1.4f, 0.9f), table, {0.62f, 0.5f, 0.38f}, false, true});
  // The board under the top casts its shadow (the plane alone casts nothing); a little wider,
  // so that its shadow covers the top's, which the ray-traced truth also sees.
  s.objects.push_back({"board",
                       makeBox({1.46f, 0.04f, 0.96f}),
                       table * translate({0.0f, -0.05f, 0.0f}),
                       {0.5f, 0.4f, 0.3f}});
  // Its legs cast; something stands on it (a caster above the plane: region I).
  for (const glm::vec2 leg : {glm::vec2(-1.2f, -0.7f), glm::vec2(1.2f, -0.7f),
                              glm::vec2(-1.2f, 0.7f), glm::vec2(1.2f, 0.7f)}) {
    const glm::vec3 top = glm::vec3(table * glm::vec4(leg.x, 0.0f, leg.y, 1.0f));
    const float h = 0.5f * top.y;
    s.objects.push_back(
        {"leg", makeBox({0.06f, h, 0.06f}), translate({top.x, h, top.z}), {0.4f, 0.3f, 0.22f}});
  }
  s.objects.push_back({"cup",
                       makeBox({0.25f, 0.3f, 0.25f}),
                       table * translate({0.3f, 0.3f, 0.0f}),
                       {0.85f, 0.45f, 0.25f}});
}

// Lesson 10: an RTS-style camera high above the ground looking down at units and buildings
// (seed 002: "most useful for games where the view is top-down or isometric").
Scene strategy() {
  Scene s;
  const glm::mat4 one(1.0f);
  // The floor ends at the wall: the wall, a receiver, casts nothing onto a floor behind it.
  s.objects.push_back(
      {"floor", makePlane(12.0f, 10.0f), translate({0, 0, 3}), {0.75f, 0.75f, 0.72f}, false, true});
  addWallAndTable(s, translate({0, 3, -7}) * glm::rotate(one, glm::radians(90.0f), {1, 0, 0}),
                  {3.0f, 0.9f, 1.5f}, 18.0f);
  for (int i = 0; i < 6; ++i) {
    const float x = -5.0f + 1.6f * static_cast<float>(i), z = (i % 2 == 0) ? -2.0f : 0.5f;
    const float h = 0.4f + 0.25f * static_cast<float>(i % 3);
    s.objects.push_back({"unit_" + std::to_string(i),
                         makeBox({0.35f, h, 0.35f}),
                         translate({x, h, z}),
                         {0.3f + 0.1f * static_cast<float>(i % 3), 0.55f, 0.85f}});
  }
  s.objects.push_back({"building",
                       makeBox({1.2f, 1.5f, 1.0f}),
                       translate({-3.5f, 1.5f, -4.5f}),
                       {0.7f, 0.62f, 0.5f}});
  s.objects.push_back(
      {"sphere", makeSphere(0.6f, 48, 24), translate({0.5f, 0.6f, 3.5f}), {0.5f, 0.8f, 0.4f}});
  s.light = {false, {6.0f, 11.0f, 6.0f}, {-1.0f, 0.0f, -1.5f}, 105.0f, 10.0f, 3.0f, 35.0f};
  s.camera = {{0.0f, 13.0f, 7.0f}, {0.0f, 0.0f, -0.5f}, 45.0f, 0.1f, 100.0f};
  return s;
}

// Lesson 10: a long floor that recedes from a low eye, posts along it (perspective aliasing:
// a uniform map spends as many texels far away as near).
Scene receding() {
  Scene s;
  const glm::mat4 one(1.0f);
  s.objects.push_back({"floor",
                       makePlane(8.25f, 40.0f),
                       translate({3.75f, 0, -30}),
                       {0.75f, 0.75f, 0.72f},
                       false,
                       true});  // it ends at the wall, x = -4.5
  addWallAndTable(s,
                  translate({-4.5f, 3, -6}) * glm::rotate(one, glm::radians(-90.0f), {0, 0, 1}) *
                      glm::rotate(one, glm::radians(90.0f), {0, 1, 0}),
                  {1.8f, 0.8f, 3.0f}, -15.0f);
  for (int i = 0; i < 12; ++i) {
    const float z = 4.0f - 3.5f * static_cast<float>(i);
    s.objects.push_back({"post_" + std::to_string(i),
                         makeBox({0.15f, 1.2f, 0.15f}),
                         translate({(i % 2 == 0) ? -1.5f : 1.5f, 1.2f, z}),
                         {0.3f, 0.55f, 0.85f}});
  }
  s.objects.push_back(
      {"sphere", makeSphere(0.5f, 48, 24), translate({0.0f, 0.5f, -2.0f}), {0.5f, 0.8f, 0.4f}});
  s.light = {true, {12.0f, 20.0f, -8.0f}, {0.0f, 0.0f, -14.0f}, 60.0f, 30.0f, 1.0f, 60.0f};
  s.camera = {{0.0f, 1.7f, 7.0f}, {0.0f, 0.6f, -10.0f}, 50.0f, 0.1f, 100.0f};
  return s;
}

}  // namespace

Scene makeScene(const std::string& preset) {
  Scene s;
  if (preset == "torus_pyramid") {
    s = torusPyramid();
  } else if (preset == "grazing") {
    // The same objects under a light barely above the horizon: long shadows, steep slopes
    // in light space, the hardest case for a fixed bias.
    s = torusPyramid();
    s.light = {false, {-9.0f, 1.6f, 2.0f}, {1.0f, 0.2f, 0.0f}, 50.0f, 10.0f, 4.0f, 20.0f};
  } else if (preset == "dueling") {
    // Light and eye face each other: shadow-map texels near the eye are magnified most.
    s = torusPyramid();
    s.light = {false, {0.6f, 3.5f, -7.5f}, {0.0f, 0.3f, 0.5f}, 60.0f, 10.0f, 3.0f, 16.0f};
  } else if (preset == "cubes") {
    // LearnOpenGL's shadow-mapping scene, so the two can be compared on the same work.
    s.objects.push_back(floorObject(25.0f, -0.5f));
    const MeshData cube = makeBox(glm::vec3(1.0f));  // edge 2
    const glm::mat4 one(1.0f);
    s.objects.push_back({"cube_floating",
                         cube,
                         translate({0, 1.5f, 0}) * glm::scale(one, glm::vec3(0.5f)),
                         {0.8f, 0.8f, 0.8f}});
    s.objects.push_back({"cube_right",
                         cube,
                         translate({2, 0, 1}) * glm::scale(one, glm::vec3(0.5f)),
                         {0.8f, 0.8f, 0.8f}});
    s.objects.push_back(
        {"cube_tilted",
         cube,
         translate({-1, 0, 2}) *
             glm::rotate(one, glm::radians(60.0f), glm::normalize(glm::vec3(1, 0, 1))) *
             glm::scale(one, glm::vec3(0.25f)),
         {0.8f, 0.8f, 0.8f}});
    s.light = {true, {-2.0f, 4.0f, -1.0f}, {0.0f, 0.0f, 0.0f}, 60.0f, 10.0f, 1.0f, 7.5f};
    s.camera = {{0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}, 45.0f, 0.1f, 100.0f};
  } else if (preset == "eye_in_shadow") {
    // Lesson 09: the eye in the torus's shadow, behind it, looking along its shadow on the
    // floor (seed 003 slide 38, the z-pass near plane problem).
    s = torusPyramid();
    s.camera = {{-3.0f, 0.8f, -1.0f}, {-1.0f, 0.0f, 4.0f}, 45.0f, 0.1f, 100.0f};
  } else if (preset == "fence") {
    // Lesson 09: 500 slats in a row under a light, their shadows merged into one strip; an
    // eye below them looking along the row sees the floor through hundreds of volumes, more
    // than an 8-bit stencil counts (seed 003 slide 50).
    s.objects.push_back(floorObject(12.0f, 0.0f));
    const MeshData slat = makeBox({1.5f, 0.01f, 0.025f});
    for (int i = 0; i < 500; ++i) {
      s.objects.push_back({"slat_" + std::to_string(i),
                           slat,
                           translate({0.0f, 2.5f, 8.0f - 0.032f * static_cast<float>(i)}),
                           {0.7f, 0.55f, 0.4f}});
    }
    s.light = {false, {0.0f, 10.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 90.0f, 10.0f, 1.0f, 30.0f};
    s.camera = {{0.0f, 1.5f, 9.5f}, {0.0f, 0.0f, -4.0f}, 45.0f, 0.1f, 100.0f};
  } else if (preset == "contact") {
    // Lesson 14: casters that touch the floor, where a real penumbra is zero at the contact
    // and widens with the distance from it: a tall post, a plank leaning from the floor up
    // away from the light, a ball resting on the floor. The light is low, the shadows long.
    s.objects.push_back(floorObject(8.0f, 0.0f));
    s.objects.push_back({"post",
                         makeBox({0.08f, 1.1f, 0.08f}),
                         translate({-2.0f, 1.1f, -1.3f}),
                         {0.55f, 0.42f, 0.3f}});
    const float lean = glm::radians(30.0f), half_length = 1.2f, half_thickness = 0.03f;
    s.objects.push_back(
        {"plank",
         makeBox({half_length, half_thickness, 0.3f}),
         translate({-0.6f, half_length * std::sin(lean) + half_thickness * std::cos(lean), 0.9f}) *
             glm::rotate(glm::mat4(1.0f), lean, {0, 0, 1}),
         {0.75f, 0.6f, 0.4f}});
    s.objects.push_back(
        {"ball", makeSphere(0.4f, 48, 24), translate({0.6f, 0.4f, -1.4f}), {0.5f, 0.8f, 0.4f}});
    s.light = {false, {-4.5f, 4.5f, 2.2f}, {0.3f, 0.2f, -0.2f}, 75.0f, 10.0f, 2.0f, 16.0f};
    s.camera = {{0.4f, 3.4f, 6.4f}, {0.4f, 0.4f, -0.1f}, 45.0f, 0.1f, 100.0f};
  } else if (preset == "overlap") {
    // Lesson 14: depth complexity two from the light. A high slat crosses over a low shelf,
    // so a floor pixel's blocker search finds both, the slat 3 units up (a wide penumbra)
    // and the shelf 0.6 up (a narrow one), and their average is neither.
    s.objects.push_back(floorObject(8.0f, 0.0f));
    s.objects.push_back({"shelf",
                         makeBox({1.2f, 0.03f, 0.7f}),
                         translate({0.0f, 0.6f, 0.3f}),
                         {0.62f, 0.5f, 0.38f}});
    s.objects.push_back({"slat",
                         makeBox({0.12f, 0.03f, 2.2f}),
                         translate({0.1f, 3.0f, 0.3f}),
                         {0.75f, 0.6f, 0.4f}});
    s.light = {false, {0.6f, 7.0f, 1.2f}, {0.0f, 0.3f, 0.2f}, 60.0f, 10.0f, 2.0f, 16.0f};
    s.camera = {{3.8f, 5.2f, 4.6f}, {0.0f, 0.2f, 0.1f}, 45.0f, 0.1f, 100.0f};
  } else if (preset == "stacked") {
    // Lesson 13: a brick on the floor inside the shadow of a board high above it. A filter over
    // the brick's edge averages the board's depth with the brick's: the variance of two blockers
    // at different depths, where variance shadow maps let light bleed into the board's umbra.
    s.objects.push_back(floorObject(8.0f, 0.0f));
    s.objects.push_back({"board",
                         makeBox({1.3f, 0.03f, 1.3f}),
                         translate({-0.7f, 2.4f, 0.5f}),
                         {0.62f, 0.5f, 0.38f}});
    s.objects.push_back({"brick",
                         makeBox({0.35f, 0.2f, 0.25f}),
                         translate({2.5f, 0.2f, -0.4f}),
                         {0.7f, 0.35f, 0.3f}});
    s.light = {false, {-3.0f, 6.5f, 2.0f}, {0.3f, 0.0f, -0.3f}, 60.0f, 10.0f, 2.0f, 16.0f};
    s.camera = {{4.6f, 2.4f, 2.6f}, {1.9f, 0.1f, -0.5f}, 45.0f, 0.1f, 100.0f};
  } else if (preset == "room") {
    s = room();
  } else if (preset == "strategy") {
    s = strategy();
  } else if (preset == "receding") {
    s = receding();
  } else {
    throw std::invalid_argument("unknown scene '" + preset + "'");
  }
  s.name = preset;
  return s;
}

}  // namespace shadows
