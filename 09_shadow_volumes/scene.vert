#version 330 core
// The eye's passes 1 and 3 (and the volumes' light caps) must put every surface at exactly
// the same depth, or the light pass's depth test EQUAL and the caps would flicker: invariant.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform mat4 uViewProjection;
out vec3 vWorld;
out vec3 vNormal;
invariant gl_Position;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  gl_Position = uViewProjection * world;
}
