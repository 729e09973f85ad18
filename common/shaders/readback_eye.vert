#version 330 core
// The eye passes of lessons 06 and 07. Every pass draws the same triangles through this one
// shader, and gl_Position is invariant, so glDepthFunc(GL_EQUAL) meets pass 1's depths exactly.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform mat4 uViewProjection;
uniform mat4 uShadowMatrix;  // Tex0's texgen: B * P_light * V_light
uniform vec4 uLinearPlane;   // Tex1's texgen for linear depth: eye-planar S
out vec3 vWorld;
out vec3 vNormal;
out vec4 vShadowCoord;
out float vLinearS;
invariant gl_Position;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  vShadowCoord = uShadowMatrix * world;
  vLinearS = dot(uLinearPlane, world);
  gl_Position = uViewProjection * world;
}
