#version 330 core
// Pass 1 of a filterable map: the casters from the light, each fragment's world position on to
// moments.frag, which stores what the filter may average.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProjection;
out vec3 vWorld;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  gl_Position = uLightViewProjection * world;
}
