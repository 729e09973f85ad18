#version 330 core
// Pass 1 in one layered draw: world positions only; the geometry shader projects them
// through each face's frustum.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
out vec3 vWorldIn;
void main() {
  vWorldIn = (uModel * vec4(aPosition, 1.0)).xyz;
  gl_Position = vec4(vWorldIn, 1.0);
}
