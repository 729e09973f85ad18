// The scene presets: the shared ones every map lesson offers (torus_pyramid, grazing, dueling,
// cubes) and the ones a lesson makes its own case with (room for 08, eye_in_shadow and fence
// for 09, strategy and receding for 10, bulb for 11, street for 12, stacked for 13, contact and
// overlap for 14). The meshes and the scene's queries are in scene.cpp.
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "core/scene.hpp"

namespace shadows {

const std::vector<std::string>& scenePresets() {
  static const std::vector<std::string> names = {"torus_pyramid", "grazing", "dueling", "cubes"};
  return names;
}

namespace {

glm::mat4 translate(glm::vec3 t) {
  return glm::translate(glm::mat4(1.0f), t);
}

// A one-sided plane that receives but casts nothing (a floor, a wall: nothing lies behind
// it), so the shadow pass can skip it while the light is in front of it.
SceneObject receiverPlane(const std::string& name, float halfX, float halfZ, const glm::mat4& model,
                          glm::vec3 color) {
  return {name, makePlane(halfX, halfZ), model, color, false, true};
}

SceneObject floorObject(float half, float y) {
  return receiverPlane("floor", half, half, translate({0, y, 0}), {0.75f, 0.75f, 0.72f});
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

// A room's shell, 08's and 11's: the floor, then plaster walls 3 high that receive but cast
// nothing (the light is inside the room, they bound what it sees): the back wall at
// z = -depth and the left one at x = -6, each as long as the room is deep, and the right one
// at x = 6 where `right`.
void addRoomShell(Scene& s, float depth, bool right) {
  const glm::mat4 one(1.0f);
  const glm::vec3 plaster{0.72f, 0.7f, 0.66f};
  s.objects.push_back(floorObject(6.0f, 0.0f));
  s.objects.push_back(receiverPlane(
      "back_wall", 6.0f, 3.0f,
      translate({0, 3, -depth}) * glm::rotate(one, glm::radians(90.0f), {1, 0, 0}), plaster));
  s.objects.push_back(receiverPlane(
      "left_wall", 3.0f, depth,
      translate({-6, 3, 0}) * glm::rotate(one, glm::radians(-90.0f), {0, 0, 1}), plaster));
  if (right) {
    s.objects.push_back(receiverPlane(
        "right_wall", 3.0f, depth,
        translate({6, 3, 0}) * glm::rotate(one, glm::radians(90.0f), {0, 0, 1}), plaster));
  }
}

// Lesson 08's dusty room (seed 000, "Combining Shadows with Atmospherics"): a floor and two
// walls, a spotlight high in a corner shining down past a pillar, a floating sphere and a
// torus, so the light shafts in the air are visibly cut by them.
Scene room() {
  Scene s;
  const glm::mat4 one(1.0f);
  addRoomShell(s, 5.0f, /*right=*/false);
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

// Lesson 11's bare bulb in a room: a point light with casters on every side of it, so
// every face of its cube map but the one looking up (no ceiling, nothing above) holds a
// shadow somewhere: a table under it, a pillar to its left, a ball to its right, a ring
// behind it and a crate in front, shadowing the floor and three walls.
Scene bulb() {
  Scene s;
  const glm::mat4 one(1.0f);
  addRoomShell(s, 6.0f, /*right=*/true);
  s.objects.push_back({"table_top",
                       makeBox({0.9f, 0.04f, 0.6f}),
                       translate({0.2f, 1.0f, 0.1f}),
                       {0.62f, 0.5f, 0.38f}});
  for (const glm::vec2 leg : {glm::vec2(-0.6f, -0.4f), glm::vec2(1.0f, -0.4f),
                              glm::vec2(-0.6f, 0.6f), glm::vec2(1.0f, 0.6f)}) {
    s.objects.push_back({"table_leg",
                         makeBox({0.05f, 0.48f, 0.05f}),
                         translate({leg.x, 0.48f, leg.y}),
                         {0.45f, 0.35f, 0.25f}});
  }
  s.objects.push_back({"pillar",
                       makeBox({0.3f, 1.6f, 0.3f}),
                       translate({-2.6f, 1.6f, -0.8f}),
                       {0.55f, 0.45f, 0.4f}});
  s.objects.push_back(
      {"ball", makeSphere(0.5f, 48, 24), translate({2.4f, 2.3f, 0.6f}), {0.5f, 0.8f, 0.4f}});
  s.objects.push_back(
      {"ring",
       makeTorus(0.6f, 0.16f, 96, 48),
       translate({-0.4f, 2.5f, -2.4f}) * glm::rotate(one, glm::radians(75.0f), {1, 0, 0}),
       {0.85f, 0.45f, 0.25f}});
  s.objects.push_back(
      {"crate",
       makeBox({0.35f, 0.35f, 0.35f}),
       translate({1.1f, 0.35f, 2.2f}) * glm::rotate(one, glm::radians(25.0f), {0, 1, 0}),
       {0.7f, 0.35f, 0.3f}});
  // An omni light has no target or angle: these only matter to lessons that aim it.
  s.light = {false, {0.0f, 2.3f, 0.2f}, {0.0f, 0.0f, 0.0f}, 90.0f, 10.0f, 0.1f, 20.0f};
  s.camera = {{0.8f, 4.6f, 9.5f}, {0.0f, 1.3f, -0.8f}, 55.0f, 0.1f, 100.0f};
  return s;
}

// The bulb's room with `extra` more casters around it (lesson 11 against 09's volumes as the
// caster count grows): crates on the floor and balls in the air, spread on a golden-angle
// spiral between 1.8 and 5 units from the bulb, clear of the walls.
Scene bulbCrowd(int extra) {
  Scene s = bulb();
  const float golden = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < extra; ++i) {
    const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(extra);
    const float a = golden * static_cast<float>(i), r = 1.8f + 3.2f * t;
    const glm::vec3 at(r * std::cos(a), 0.0f, 0.2f + r * std::sin(a) * 0.9f);
    if (i % 2 == 0) {
      s.objects.push_back({"crate",
                           makeBox(glm::vec3(0.18f)),
                           translate(at + glm::vec3(0, 0.18f, 0)),
                           {0.7f, 0.35f, 0.3f}});
    } else {
      s.objects.push_back({"ball",
                           makeSphere(0.16f, 16, 8),
                           translate(at + glm::vec3(0, 0.9f + 0.6f * t, 0)),
                           {0.5f, 0.8f, 0.4f}});
    }
  }
  return s;
}

// Lesson 10's planes of interest beside the floor (seed 002, "Playing with Projection
// Matrices": "ground plane, wall, table top"): receivers that cast nothing, so a map never
// holds them and only the projection decides how well they are shadowed.
void addWallAndTable(Scene& s, const glm::mat4& wall, glm::vec3 tableAt, float tilt) {
  const glm::mat4 one(1.0f);
  s.objects.push_back(receiverPlane("wall", 8.0f, 3.0f, wall, {0.72f, 0.7f, 0.66f}));
  const glm::mat4 table = translate(tableAt) * glm::rotate(one, glm::radians(tilt), {1, 0, 0});
  s.objects.push_back(receiverPlane("table", 1.4f, 0.9f, table, {0.62f, 0.5f, 0.38f}));
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
      receiverPlane("floor", 12.0f, 10.0f, translate({0, 0, 3}), {0.75f, 0.75f, 0.72f}));
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

// Lesson 12's street (seed 003, perspective aliasing): the sun over a scene 200 units deep,
// the eye at head height looking along it. Posts every 6 units on both kerbs, a low wall
// beside the left one and a few crates on the road: near shadows a step away, far ones
// many pixels thin.
Scene street() {
  Scene s;
  s.objects.push_back(
      receiverPlane("road", 14.0f, 110.0f, translate({0, 0, -96}), {0.62f, 0.62f, 0.6f}));
  for (int i = 0; i < 34; ++i) {
    const float z = 2.0f - 6.0f * static_cast<float>(i);
    for (const float x : {-4.0f, 4.0f}) {
      s.objects.push_back(
          {"post", makeBox({0.15f, 1.5f, 0.15f}), translate({x, 1.5f, z}), {0.3f, 0.55f, 0.85f}});
    }
  }
  for (int i = 0; i < 10; ++i) {
    s.objects.push_back({"wall",
                         makeBox({0.25f, 0.6f, 9.0f}),
                         translate({-7.0f, 0.6f, -6.0f - 20.0f * static_cast<float>(i)}),
                         {0.7f, 0.5f, 0.4f}});
  }
  for (const glm::vec3 at : {glm::vec3(1.2f, 0.5f, -9.0f), glm::vec3(-1.5f, 0.5f, -31.0f),
                             glm::vec3(0.8f, 0.5f, -70.0f)}) {
    s.objects.push_back({"crate", makeBox(glm::vec3(0.5f)), translate(at), {0.8f, 0.62f, 0.3f}});
  }
  // The sun: only its direction matters; extent, near and far are a box around the whole
  // street for the lessons that fit one map to it.
  s.light = {true, {30.0f, 45.0f, -16.5f}, {0.0f, 0.0f, -50.0f}, 60.0f, 120.0f, 1.0f, 300.0f};
  s.camera = {{0.0f, 1.7f, 8.0f}, {0.0f, 1.2f, -30.0f}, 50.0f, 0.1f, 250.0f};
  return s;
}

// LearnOpenGL's shadow-mapping scene, so the two can be compared on the same work.
Scene cubes() {
  Scene s;
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
  return s;
}

// Lesson 09: 500 slats in a row under a light, their shadows merged into one strip; an
// eye below them looking along the row sees the floor through hundreds of volumes, more
// than an 8-bit stencil counts (seed 003 slide 50).
Scene fence() {
  Scene s;
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
  return s;
}

// Lesson 14: casters that touch the floor, where a real penumbra is zero at the contact
// and widens with the distance from it: a tall post, a plank leaning from the floor up
// away from the light, a ball resting on the floor. The light is low, the shadows long.
Scene contact() {
  Scene s;
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
  return s;
}

// Lesson 14: depth complexity two from the light. A high slat crosses over a low shelf,
// so a floor pixel's blocker search finds both, the slat 3 units up (a wide penumbra)
// and the shelf 0.6 up (a narrow one), and their average is neither.
Scene overlap() {
  Scene s;
  s.objects.push_back(floorObject(8.0f, 0.0f));
  s.objects.push_back(
      {"shelf", makeBox({1.2f, 0.03f, 0.7f}), translate({0.0f, 0.6f, 0.3f}), {0.62f, 0.5f, 0.38f}});
  s.objects.push_back(
      {"slat", makeBox({0.12f, 0.03f, 2.2f}), translate({0.1f, 3.0f, 0.3f}), {0.75f, 0.6f, 0.4f}});
  s.light = {false, {0.6f, 7.0f, 1.2f}, {0.0f, 0.3f, 0.2f}, 60.0f, 10.0f, 2.0f, 16.0f};
  s.camera = {{3.8f, 5.2f, 4.6f}, {0.0f, 0.2f, 0.1f}, 45.0f, 0.1f, 100.0f};
  return s;
}

// Lesson 13: a brick on the floor inside the shadow of a board high above it. A filter over
// the brick's edge averages the board's depth with the brick's: the variance of two blockers
// at different depths, where variance shadow maps let light bleed into the board's umbra.
Scene stacked() {
  Scene s;
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
  return s;
}

// Lesson 16: a yard that stands still and one ball, the last caster, a light map cannot follow.
Scene yard() {
  Scene s;
  s.objects.push_back(floorObject(8.0f, 0.0f));
  s.objects.push_back(
      {"wall", makeBox({2.4f, 0.6f, 0.12f}), translate({-0.4f, 0.6f, -2.2f}), {0.7f, 0.6f, 0.5f}});
  for (const float x : {-2.6f, 2.2f}) {
    s.objects.push_back(
        {"post", makeBox({0.1f, 0.9f, 0.1f}), translate({x, 0.9f, -0.6f}), {0.55f, 0.42f, 0.3f}});
  }
  s.objects.push_back(
      {"bench", makeBox({0.9f, 0.05f, 0.3f}), translate({0.3f, 0.5f, 0.9f}), {0.62f, 0.5f, 0.38f}});
  for (const float x : {-0.45f, 1.05f}) {
    s.objects.push_back({"bench_leg",
                         makeBox({0.05f, 0.225f, 0.25f}),
                         translate({x, 0.225f, 0.9f}),
                         {0.45f, 0.36f, 0.28f}});
  }
  s.objects.push_back(
      {"crate", makeBox(glm::vec3(0.35f)), translate({-1.8f, 0.35f, 1.2f}), {0.8f, 0.62f, 0.3f}});
  s.objects.push_back(
      {"ball", makeSphere(0.4f, 48, 24), translate({1.6f, 0.4f, -0.4f}), {0.5f, 0.8f, 0.4f}});
  s.light = {false, {-2.5f, 6.0f, 3.0f}, {0.2f, 0.3f, -0.2f}, 75.0f, 10.0f, 2.0f, 16.0f};
  s.camera = {{0.8f, 3.6f, 7.0f}, {0.0f, 0.4f, -0.2f}, 45.0f, 0.1f, 100.0f};
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
    s = cubes();
  } else if (preset == "eye_in_shadow") {
    // Lesson 09: the eye in the torus's shadow, behind it, looking along its shadow on the
    // floor (seed 003 slide 38, the z-pass near plane problem).
    s = torusPyramid();
    s.camera = {{-3.0f, 0.8f, -1.0f}, {-1.0f, 0.0f, 4.0f}, 45.0f, 0.1f, 100.0f};
  } else if (preset == "fence") {
    s = fence();
  } else if (preset == "yard") {
    s = yard();
  } else if (preset == "contact") {
    s = contact();
  } else if (preset == "overlap") {
    s = overlap();
  } else if (preset == "stacked") {
    s = stacked();
  } else if (preset == "bulb_crowd") {
    s = bulbCrowd(24);
  } else if (preset == "bulb_throng") {
    s = bulbCrowd(96);
  } else if (preset == "bulb") {
    s = bulb();
  } else if (preset == "street") {
    s = street();
  } else if (preset == "street_low_sun") {
    // Late afternoon, the sun 10° high: shadows five times their posts' height.
    s = street();
    s.light.position = {30.0f, 7.9f, -16.5f};
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
