#version 330 core
// The overview's lines (the eye's frustum, its centre ray, the crossings): world positions.
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
