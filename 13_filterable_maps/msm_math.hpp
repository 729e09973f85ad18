// Moment shadow maps (Peters and Klein 2015) in plain C++ (no GL), the way moments.frag stores
// and scene.frag reads them, so the unit tests check the arithmetic the shaders run.
//
// Seed 002 reads VSM as "a particular functional approximation to the transfer function" and
// suggests "improvements via other approximating functional forms". Four moments of the depth
// (z, z^2, z^3, z^4) instead of two: of every distribution of depths with those moments, the
// one that puts the most of its mass in front of the receiver is supported on three depths (the
// receiver's own and the two roots of a quadratic). Its mass strictly in front is the sharpest
// lower bound on the shadow the four moments allow: exact for one blocker over one receiver and
// for two blockers at two depths over one receiver, where VSM's two moments bleed light.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace shadows::msm {

// The paper's quantization: the four moments through a fixed 4 x 4 matrix and an offset on the
// first, which spreads them over [0, 1] so that 16 bits a channel keep what the reconstruction
// needs. Affine, so a blur of the stored values is the stored value of the blurred moments.
// Column k of the glm matrix is the row of moment k in the paper's table.
inline glm::mat4 encodeMatrix() {
  return glm::mat4(-2.07224649f, 13.7948857237f, 0.105877704f, 9.7924062118f,       //
                   32.23703778f, -59.4683975703f, -1.9077466311f, -33.7652110555f,  //
                   -68.571074599f, 82.0359750338f, 9.3496555107f, 47.9456096605f,   //
                   39.3703274134f, -35.364903257f, -6.6543490743f, -23.9728048165f);
}
inline constexpr float kEncodeOffset = 0.035955884801f;

inline glm::vec4 powers(float z) {
  const float z2 = z * z;
  return {z, z2, z2 * z, z2 * z2};
}

// What a texel stores for depth z in [0, 1] (moments.frag).
inline glm::vec4 encode(float z) {
  return encodeMatrix() * powers(z) + glm::vec4(kEncodeOffset, 0.0f, 0.0f, 0.0f);
}

// Back to the (filtered) moments (scene.frag); the inverse is computed in double once.
inline glm::mat4 decodeMatrix() {
  return glm::mat4(glm::inverse(glm::dmat4(encodeMatrix())));
}
inline glm::vec4 decode(const glm::vec4& stored, const glm::mat4& decodeM) {
  return decodeM * (stored - glm::vec4(kEncodeOffset, 0.0f, 0.0f, 0.0f));
}

// The moments every blurred texel is pulled toward by `bias` (the paper's alpha): those of a
// depth half at the near plane and half at the far plane, well inside the set of moments a
// distribution can have, so the Hankel matrix below stays invertible after rounding.
inline constexpr glm::vec4 kBiasTarget{0.5f, 0.5f, 0.5f, 0.5f};

// The lit fraction at receiver depth t from moments b (Hamburger 4MSM): 1 - the largest mass in
// front of t of any distribution with these moments and support {t, z2, z3}.
inline float litFraction(glm::vec4 b, float t, float bias) {
  b = b * (1.0f - bias) + kBiasTarget * bias;
  // B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]] = L D L^T (L unit lower triangular).
  const float d22 = b.y - b.x * b.x;
  const float l32 = (b.z - b.x * b.y) / d22;
  const float d33 = b.w - b.y * b.y - l32 * l32 * d22;
  // B c = (1, t, t^2): forward, scale, back.
  float c1 = 1.0f, c2 = t - b.x, c3 = t * t - b.y - l32 * c2;
  c2 /= d22;
  c3 /= d33;
  c2 -= l32 * c3;
  c1 -= b.x * c2 + b.y * c3;
  // The other two depths: the roots of c1 + c2 z + c3 z^2.
  const float p = c2 / c3, q = c1 / c3;
  const float r = std::sqrt(std::max(0.25f * p * p - q, 0.0f));
  const float z2 = -0.5f * p - r, z3 = -0.5f * p + r;
  float shadow = 0.0f;  // t at or in front of both: nothing lies in front
  if (z3 < t) {
    // Both in front: all but the weight at t, w_t = (b2 - b1 (z2 + z3) + z2 z3) / ((t-z2)(t-z3)).
    shadow = 1.0f - (b.y - b.x * (z2 + z3) + z2 * z3) / ((t - z2) * (t - z3));
  } else if (z2 < t) {
    // z2 in front: its weight, (b2 - b1 (t + z3) + t z3) / ((z2 - t)(z2 - z3)).
    shadow = (b.y - b.x * (t + z3) + t * z3) / ((t - z2) * (z3 - z2));
  }
  return 1.0f - std::clamp(shadow, 0.0f, 1.0f);
}

}  // namespace shadows::msm
