#version 330 core
// The caster once more, flattened onto the receiver plane by the shadow matrix
// M = (P.L) I - L P^T (seed 001 "Planar Projected Shadows", seed 003 "Projection Matrix").
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uShadowMatrix;  // M
uniform mat4 uViewProjection;
uniform vec4 uPlane;         // P = (A, B, C, D), oriented so that P.L > 0
uniform int uClip;           // 1: clip at the receiver plane
uniform int uDivide;         // 1: divide by w here, as slide 15's similar triangles do
#include "clip_plane_out.glsl"

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  // Only what lies on the light's side of the receiver can shadow it (seed 003: "objects
  // behind receiver"); the rest is clipped away. (llvmpipe was seen to clip by a written
  // distance even with GL_CLIP_DISTANCE0 disabled, so "off" writes a distance that keeps.)
  setClipDistance(uClip == 1 ? dot(uPlane, world) : 1.0);
  // w = P.L - P.v: positive below the light, 0 at its height, negative above it. Left as
  // it is, the clipper cuts each triangle at w = 0 and keeps only what can cast.
  vec4 shadow = uShadowMatrix * world;
  if (uDivide == 1) {
    // The failure mode: dividing before clipping sends w -> 0 toward infinity and flips
    // everything above the light to the other side of it (the anti-shadow). The clamp
    // only keeps the numbers finite.
    float w = abs(shadow.w) < 1e-6 ? (shadow.w < 0.0 ? -1e-6 : 1e-6) : shadow.w;
    shadow = vec4(shadow.xyz / w, 1.0);
  }
  gl_Position = uViewProjection * shadow;
}
