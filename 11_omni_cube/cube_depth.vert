#version 330 core
// Pass 1, once per cube face: the casters through that face's 90° frustum.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProjection;  // the face's P * V
out vec3 vWorld;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  gl_Position = uLightViewProjection * world;
}
