#version 330 core
// The light pass of lessons 06 and 07: depth from the light and, for Heidrich's linear depth,
// the eye-planar distance S from the light scaled to [0, 1] (000's texgen for S).
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProjection;
uniform vec4 uLinearPlane;
out float vS;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vS = dot(uLinearPlane, world);
  gl_Position = uLightViewProjection * world;
}
