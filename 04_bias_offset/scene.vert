#version 330 core
// Pass 2: the eye's view. The light-space coordinates are computed per fragment (scene.frag),
// since normal offset moves the point before projecting it.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform mat4 uViewProjection;
out vec3 vWorld;
out vec3 vNormal;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = mat3(uNormalMatrix) * aNormal;
  gl_Position = uViewProjection * world;
}
