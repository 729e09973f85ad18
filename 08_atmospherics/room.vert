#version 330 core
// The surfaces, with their position in the light's texture space for the spot and the map.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform mat4 uViewProjection;
uniform mat4 uShadowMatrix;  // B * P_map * V_light
uniform mat4 uSpotMatrix;    // B * P_cone * V_light
out vec3 vWorld;
out vec3 vNormal;
out vec4 vShadowCoord;
out vec4 vSpotCoord;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  vShadowCoord = uShadowMatrix * world;
  vSpotCoord = uSpotMatrix * world;
  gl_Position = uViewProjection * world;
}
