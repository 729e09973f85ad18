#version 330 core
// The scene as usual: world position and normal for the lighting of lighting.glsl.
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
