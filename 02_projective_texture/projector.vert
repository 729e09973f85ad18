#version 330 core
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
#include "clip_plane_out.glsl"

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  vSlideCoord = uTextureMatrix * world;
  // Seed 000: "use a clip plane positioned at the plane defined by the light position and
  // spotlight direction". (llvmpipe was seen to clip by a written distance even with
  // GL_CLIP_DISTANCE0 disabled, so "off" writes a distance that keeps everything.)
  setClipDistance(uClip == 1 ? dot(uProjectorPlane, world) : 1.0);
  gl_Position = uViewProjection * world;
}
