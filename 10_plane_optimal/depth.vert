#version 330 core
// Pass 1 through the chosen projection; the world position for depth replacement.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProjection;  // uniform, focused, lispsm or plane_optimal
out vec3 vWorld;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  gl_Position = uLightViewProjection * world;
}
