#version 330 core
// Depth read back where the GL cannot read depth (OpenGL ES: no glReadPixels of depth, no
// copies from a depth buffer): the light pass's depth texture, quantized as glReadPixels does
// (depth_digits.glsl), written as 8-bit digits into a colour target that can be read and
// copied. One digit: the steps in r; two: the big digit in r, the little one in g.
#include "depth_digits.glsl"
uniform sampler2D uDepth;
uniform int uDigits;          // 1 or 2
uniform int uReadbackNearest;  // the rounding of depthToSteps
out vec4 outColor;
void main() {
  float depth = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r;
  float steps = depthToSteps(depth, uDigits == 1 ? 255.0 : 65535.0, uReadbackNearest);
  vec2 digits = uDigits == 1 ? vec2(steps, 0.0) : vec2(bigDigit(steps), littleDigit(steps));
  outColor = vec4(digits / 255.0, 0.0, 1.0);
}
