// Lesson 10's light projections (seed 002, "Playing with Projection Matrices"): where a map's
// texels land is decided by the matrix that takes the world to the map. Each function returns
// a light view-projection (world to clip, the map's x and y from its x/w and y/w) or says why
// it cannot, in which case the lesson falls back to the uniform one. No GL here: the tests
// check the matrices themselves.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/scene.hpp"

namespace shadows {

// n . p + d >= 0 on the side that counts.
struct HalfSpace {
  glm::vec3 n{0.0f, 1.0f, 0.0f};
  float d = 0.0f;
  float at(glm::vec3 p) const { return glm::dot(n, p) + d; }
};

// The six half-spaces inside a view-projection's clip volume (Gribb and Hartmann).
std::vector<HalfSpace> frustumHalfSpaces(const glm::mat4& viewProjection);
std::vector<HalfSpace> boxHalfSpaces(const Bounds& box);
// The vertices of the convex body inside every half-space (empty if there is none): every
// three planes' intersection that lies inside all the others.
std::vector<glm::vec3> convexVertices(const std::vector<HalfSpace>& halfSpaces);

struct Warp {
  glm::mat4 view_projection{1.0f};
  std::string fallback;  // empty: the projection is used; else why it fell back to uniform
};

// focused: the uniform frustum cropped (in its own x and y) to what the eye can see, the view
// frustum intersected with the scene's bounds and the light's frustum.
Warp focusedProjection(const glm::mat4& uniform, const std::vector<glm::vec3>& body);

// lispsm (Wimmer, Scherzer, Purgathofer 2004): in the uniform light's post-projective space,
// where the light is directional along +z, a perspective warp whose axis is the view
// direction projected perpendicular to the light, with its centre n before the body;
// n = nFactor * n_opt, n_opt = (z_n + sqrt(z_n z_f)) / sin(gamma).
struct LispsmInput {
  glm::mat4 uniform{1.0f};
  glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};
  std::vector<glm::vec3> body;
  float n_factor = 1.0f;
};
Warp lispsmProjection(const LispsmInput& in, float* nUsed = nullptr);

// plane_optimal (Chong and Gortler): on the plane of interest the light image is the camera
// image. With C the camera's clip matrix and L the light (w = 0 for a directional light), the
// rows x, y, w of P = C - (C L) pi^T / (pi^T L) vanish at L (a projection through the light)
// and equal C's on the plane pi. Depth: z/w = A + B / w over the scene's casters.
struct PlaneOptimalInput {
  glm::mat4 camera{1.0f};  // P_camera * V_camera
  glm::vec3 eye{0.0f};
  glm::vec4 light{0.0f};                 // (position, 1) or (direction towards the light, 0)
  HalfSpace plane;                       // its normal faces the side that is lit and seen
  std::vector<glm::vec3> plane_in_view;  // the plane's polygon inside the view (convexVertices)
  std::vector<glm::vec3> depth_points;   // what the depth must hold (casters' bounds corners)
};
Warp planeOptimalProjection(const PlaneOptimalInput& in);

// Region I (seed 002): points on rays between the light and a point of the plane's polygon
// in the camera's view. `inPolygon` says whether a point of the plane lies on its polygon.
bool inRegionOne(glm::vec3 p, glm::vec4 light, const HalfSpace& plane, const glm::mat4& camera,
                 const glm::mat4& planeModelInverse, glm::vec2 planeHalf);

}  // namespace shadows
