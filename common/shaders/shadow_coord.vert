#version 330 core
// Pass 2 of a shadow map (lessons 03, 04, 05): the eye's view. Each vertex also gets its
// position in the light's texture space, (s, t, r, q) = B * P_light * V_light * M * p, for
// textureProj to divide by q.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform mat4 uViewProjection;
uniform mat4 uShadowMatrix;  // B * P_light * V_light
out vec3 vWorld;
out vec3 vNormal;
out vec4 vShadowCoord;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  vShadowCoord = uShadowMatrix * world;
  gl_Position = uViewProjection * world;
}
