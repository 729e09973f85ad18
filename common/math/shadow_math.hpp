// The matrices of the seeds, in pure GLM (no GL), so they can be unit-tested.
#pragma once

#include <glm/glm.hpp>

#include "core/scene.hpp"

namespace shadows {

// B: clip space [-1,1] to texture space [0,1] (scale by 1/2, translate by 1/2).
glm::mat4 biasMatrix();

// A view matrix looking from `eye` to `target` that never degenerates: when the direction
// is parallel to +y it picks another up vector, and eye == target looks down -y.
glm::mat4 lookAtSafe(glm::vec3 eye, glm::vec3 target);

struct LightFrustum {
  bool directional = false;
  float fov = 60.0f;     // spot: vertical angle, degrees
  float extent = 10.0f;  // directional: half width of the box
  float aspect = 1.0f;   // shadow map width / height
  float near = 1.0f, far = 20.0f;
};
// P_light: perspective for a spot light, orthographic for a directional one. Near/far are
// sanitized (near > 0 for spots, far > near) so no slider position makes it singular.
glm::mat4 lightProjection(const LightFrustum& frustum);

// The texture matrix of seeds 000/004: B * P_light * V_light (times M in the shader).
glm::mat4 shadowTextureMatrix(const glm::mat4& lightProjection, const glm::mat4& lightView);

// Blinn's projected shadow (seed 001 "Planar Projected Shadows", seed 003 "Projection
// Matrix"): M = (P.L) I - L P^T flattens any point onto the plane P = (A, B, C, D),
// Ax + By + Cz + D = 0, along the line through the light L: (x, y, z, 1) for a point light,
// (direction toward the light, 0) for a directional one (then M is seed 001's matrix).
// The result is homogeneous: w = P.L - P.v (point light). Orient P so that P.L > 0 and
// every point between the plane and the light gets w > 0, while points above the light
// get w < 0, which the GPU's clipper removes (they cannot cast onto the plane).
glm::mat4 planarShadowMatrix(glm::vec4 plane, glm::vec4 light);

// The nearest and farthest distance along the light's view axis of the corners of `bounds`
// (false when they are empty).
bool depthRange(const glm::mat4& lightView, const Bounds& bounds, float& closest, float& farthest);

// The world size, along the light's axis, of one step of a map holding `levels` + 1 depth
// values, at `distance` from the light: z^2 (f - n) / (f n levels) for a spot's projective
// (window) depth, where near decides and far barely matters once f >> n; (f - n) / levels
// for an orthographic light or a linear depth (06's map.encoding=linear).
float depthStepWorld(const LightFrustum& frustum, float distance, double levels, bool linear);

// Near/far along the light's view axis that just enclose `bounds` (e.g. the casters),
// with a small margin. For a spot light, near stays positive. Returns false (and leaves
// near/far alone) when the bounds are empty or lie entirely behind the light.
bool fitNearFar(const glm::mat4& lightView, const Bounds& bounds, bool directional, float& near,
                float& far);

// True when the sphere lies completely outside the frustum of `viewProjection` (so a pass
// with that frustum can skip it).
bool sphereOutsideFrustum(const glm::mat4& viewProjection, glm::vec3 center, float radius);

}  // namespace shadows
