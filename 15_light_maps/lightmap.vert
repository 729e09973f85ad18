#version 330 core
// The eye's pass: each vertex also carries its light map coordinate, where its chart put it
// in the atlas. The coordinates live in a float texture, one row block per object, read by
// the vertex's index (gl_VertexID is the index an indexed draw fetched), so the scene's
// vertex buffers stay as every lesson has them.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform mat4 uViewProjection;
uniform mat4 uShadowMatrix;  // B * P_light * V_light: the hybrid's map of the moving caster
uniform highp sampler2D uUv; // RG32F: per vertex its atlas (u, v); (-1, -1) for none
uniform int uObject;
uniform int uUvRowsPerObject;
out vec3 vWorld;
out vec3 vNormal;
out vec4 vShadowCoord;
out vec2 vLightMapUv;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  vShadowCoord = uShadowMatrix * world;
  int width = textureSize(uUv, 0).x;
  ivec2 at = ivec2(gl_VertexID % width, uObject * uUvRowsPerObject + gl_VertexID / width);
  vLightMapUv = texelFetch(uUv, at, 0).xy;
  gl_Position = uViewProjection * world;
}
