#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#line 2 0
// The caster once more, flattened onto the receiver plane by the shadow matrix
// M = (P.L) I - L P^T (seed 001 "Planar Projected Shadows", seed 003 "Projection Matrix").
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uShadowMatrix;  // M
uniform mat4 uViewProjection;
uniform vec4 uPlane;         // P = (A, B, C, D), oriented so that P.L > 0
uniform int uClip;           // 1: clip at the receiver plane
uniform int uDivide;         // 1: divide by w here, as slide 15's similar triangles do
#line 1 1
// User clip plane 0 in a vertex shader: gl_ClipDistance[0] where the GL has it (enabled by
// PassState::clip_plane). OpenGL ES 3.0 and WebGL have no clip distances: there the distance
// travels as a varying and clip_plane_in.glsl discards the fragments where it is negative,
// the same pixels the clipper would remove.
#if HAS_CLIP_DISTANCE
out float gl_ClipDistance[1];
void setClipDistance(float distance) {
  gl_ClipDistance[0] = distance;
}
#else
out float vClipDistance;
void setClipDistance(float distance) {
  vClipDistance = distance;
}
#endif
#line 12 0

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  // Only what lies on the light's side of the receiver can shadow it (seed 003: "objects
  // behind receiver"); the rest is clipped away. (llvmpipe was seen to clip by a written
  // distance even with GL_CLIP_DISTANCE0 disabled, so "off" writes a distance that keeps.)
  setClipDistance(uClip == 1 ? dot(uPlane, world) : 1.0);
  // w = P.L - P.v: positive below the light, 0 at its height, negative above it. Left as
  // it is, the clipper cuts each triangle at w = 0 and keeps only what can cast.
  vec4 shadow = uShadowMatrix * world;
  gl_Position = uViewProjection * shadow;
}
