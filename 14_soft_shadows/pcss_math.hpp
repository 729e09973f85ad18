// The arithmetic of percentage-closer soft shadows (Fernando 2005) in plain C++ (no GL), the
// way scene.frag computes it, so the unit tests check the formulas the shader runs. Distances
// are along the light's axis from the light (a spot's eye space -z; a directional light's
// from the plane through its position), in world units.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace shadows::pcss {

// A depth as the map stores it (window depth in [0, 1]) back to the distance from the light,
// from the light's own projection matrix (a glm::perspective or glm::ortho, fitted or not):
// perspective, ndc = -P22 - P32 / z_eye; orthographic, ndc = P22 z_eye + P32.
inline bool isPerspective(const glm::mat4& P) {
  return P[2][3] != 0.0f;
}
inline float lightDistance(const glm::mat4& P, float windowDepth) {
  const float ndc = 2.0f * windowDepth - 1.0f;
  return isPerspective(P) ? P[3][2] / (ndc + P[2][2]) : (ndc - P[3][2]) / -P[2][2];
}

// How far a world-sized step at `distance` from the light moves in the map's (s, t): a spot's
// frustum widens with the distance, a directional light's box does not.
inline glm::vec2 uvPerWorld(const glm::mat4& P, float distance) {
  const glm::vec2 at_one = 0.5f * glm::vec2(P[0][0], P[1][1]);
  return isPerspective(P) ? at_one / distance : at_one;
}

// Step 1, the blocker search: only what lies inside the cone from the receiver to the light's
// disk (radius R) can block it. That cone is widest where it is nearest the light, at the
// near plane (no caster is nearer; lesson 14 cuts it at the nearest caster): there its
// radius is R (z_r - n) / z_r, in world units.
inline float searchRadiusWorld(float lightRadius, float receiver, float nearPlane) {
  if (!(receiver > 0.0f) || !(lightRadius > 0.0f)) return 0.0f;
  return lightRadius * std::max(receiver - nearPlane, 0.0f) / receiver;
}

// Step 3, the penumbra from similar triangles: a blocker edge at distance z_b from a disk light
// of radius R casts, on a receiver at z_r, a penumbra of half-width R (z_r - z_b) / z_b
// (Fernando's w_penumbra = (d_receiver - d_blocker) w_light / d_blocker). A directional light's
// disk is a cone of directions set at the receiver (truth.cpp): half-width R (z_r - z_b) / z_r.
inline float penumbraWorld(float lightRadius, float receiver, float blocker, bool directional) {
  if (!(blocker > 0.0f) || !(receiver > blocker)) return 0.0f;
  return lightRadius * (receiver - blocker) / (directional ? receiver : blocker);
}

// Step 4, the filter: that half-width as a PCF kernel radius in map texels, at the receiver.
inline float kernelRadiusTexels(float penumbraWorld, const glm::mat4& P, float receiver,
                                float mapWidth) {
  return penumbraWorld * uvPerWorld(P, receiver).x * mapWidth;
}

}  // namespace shadows::pcss
