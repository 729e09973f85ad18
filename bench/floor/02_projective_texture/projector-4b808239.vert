#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_TEXCOORDS 2
#define VIEW_SLIDE 3
#define VIEW_TRUTH 4
#define VIEW_ERROR 5
#define VIEW VIEW_SHADED
#define PASS 0
#define SPOT_FALLOFF 0
#line 2 0
// Each vertex gets (s, t, r, q) = B * P_projector * V_projector * M * p, the texture matrix
// of seed 004 ("Texture matrix"), next to the usual eye-space position.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform mat4 uViewProjection;
uniform mat4 uTextureMatrix;   // B * P_projector * V_projector
uniform vec4 uProjectorPlane;  // the plane through the projector, facing where it points
uniform int uClip;             // 1: clip away what lies behind the projector
out vec3 vWorld;
out vec3 vNormal;
out vec4 vSlideCoord;
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
#line 16 0

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  vSlideCoord = uTextureMatrix * world;
  // Seed 000: "use a clip plane positioned at the plane defined by the light position and
  // spotlight direction". (llvmpipe was seen to clip by a written distance even with
  // GL_CLIP_DISTANCE0 disabled, so "off" writes a distance that keeps everything.)
  setClipDistance(1.0);
  gl_Position = uViewProjection * world;
}
