#version 330 core
// The slides' two pictures of a 16-bit map: "most significant 8 bits of the depth map,
// pseudo-color inset magnifies variations" and "least significant 8 bits of the depth map,
// here is where the information is!".
#include "depth_digits.glsl"
in vec2 vUv;
uniform sampler2D uMap;
uniform int uMapIsDepth;
uniform int uReadbackNearest;
uniform int uDigit;  // 0 big, 1 little
out vec4 outColor;

vec3 pseudoColor(float x) {  // blue - cyan - green - yellow - red
  return clamp(vec3(4.0 * x - 2.0, 2.0 - abs(4.0 * x - 2.0), 2.0 - 4.0 * x), 0.0, 1.0);
}

void main() {
  vec4 v = texture(uMap, vUv);
  vec2 digits = floor(v.rg * 255.0 + 0.5);
  if (uMapIsDepth == 1) {
    float steps = depthToSteps(v.r, 65535.0, uReadbackNearest);
    digits = vec2(bigDigit(steps), littleDigit(steps));
  }
  if (uDigit == 1) {
    outColor = vec4(vec3(digits.y / 255.0), 1.0);
    return;
  }
  // A map uses only a few big digits: colours that cycle every 8 values make each step
  // visible. White: 255, nothing in front.
  vec3 c = pseudoColor(mod(digits.x, 8.0) / 7.0);
  outColor = vec4(digits.x >= 255.0 ? vec3(1.0) : c, 1.0);
}
