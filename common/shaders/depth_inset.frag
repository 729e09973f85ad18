#version 330 core
// A depth map shown as grey, linearized for a perspective light so it is not all white.
in vec2 vUv;
uniform sampler2D uDepth;
uniform float uNear;
uniform float uFar;
uniform int uPerspective;
out vec4 outColor;
void main() {
  float d = texture(uDepth, vUv).r;
  if (uPerspective == 1) {
    float z = 2.0 * d - 1.0;
    float linear = 2.0 * uNear * uFar / (uFar + uNear - z * (uFar - uNear));
    d = (linear - uNear) / (uFar - uNear);
  }
  outColor = vec4(vec3(d), 1.0);
}
