// The window's orbit camera (math/orbit.hpp): a drag turns the eye around its target at the
// same distance, and the eye stays in front of the walls and floor it started in front of
// (issue 55, 5: lesson 11's eye was dragged behind its room's back wall, and nothing brought
// it back).
#include <gtest/gtest.h>

#include "core/scene.hpp"
#include "math/orbit.hpp"

namespace shadows {
namespace {

TEST(Orbit, ADragTurnsTheEyeAroundItsTargetAtTheSameDistance) {
  const glm::vec3 target(1, 0, -2), eye(1, 3, 2);
  const glm::vec3 turned = orbit::turn(eye, target, 95.0f, 0.0f);
  EXPECT_NEAR(glm::length(turned - target), glm::length(eye - target), 1e-4f);
  EXPECT_NEAR(turned.y, eye.y, 1e-4f);  // a sideways drag keeps the height
  EXPECT_GT(glm::length(turned - eye), 1.0f);
  // Up or down never flips over the top.
  const glm::vec3 up = orbit::turn(eye, target, 0.0f, 1e4f);
  EXPECT_LT(glm::normalize(up - target).y, 1.0f);
  EXPECT_GT(glm::normalize(up - target).y, 0.99f);
}

TEST(Orbit, TheEyeStaysInFrontOfTheRoomsWallsAndFloor) {
  const Scene room = makeScene("bulb");  // lesson 11's: floor, back, left and right walls
  const glm::vec3 preset = room.camera.position, target = room.camera.target;
  // Dragged around and down, the free eye leaves the room (behind the back wall, z < -6, or
  // under the floor); kept, it stays in front of each: z > -6, |x| < 6, y > 0.
  glm::vec3 free = preset, kept = preset;
  bool left_the_room = false;
  for (int i = 0; i < 20; ++i) {
    free = orbit::turn(free, target, 95.0f, 15.0f);
    kept = orbit::keepInFront(orbit::turn(kept, target, 95.0f, 15.0f), room, preset);
    left_the_room = left_the_room || free.z < -6.0f || std::abs(free.x) > 6.0f || free.y < 0.0f;
    EXPECT_GT(kept.z, -6.0f) << i;
    EXPECT_LT(std::abs(kept.x), 6.0f) << i;
    EXPECT_GT(kept.y, 0.0f) << i;
  }
  EXPECT_TRUE(left_the_room) << "the drags never took a free eye out: the test tests nothing";
  // In front of everything already: unchanged.
  EXPECT_EQ(orbit::keepInFront(preset, room, preset), preset);
}

TEST(Orbit, AnOutdoorEyeGoesAnywhereAboveTheFloor) {
  const Scene yard = makeScene("torus_pyramid");
  const glm::vec3 preset = yard.camera.position;
  EXPECT_EQ(orbit::keepInFront({30, 40, 30}, yard, preset), glm::vec3(30, 40, 30));
  EXPECT_GT(orbit::keepInFront({3, -2, 8}, yard, preset).y, 0.0f);  // never under the floor
}

}  // namespace
}  // namespace shadows
