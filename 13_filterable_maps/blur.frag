#version 330 core
// One axis of the separable box blur of the moments: BLUR_TAPS taps at the midpoints of a box
// of half-width uRadius texels (lesson 05's grid, one row of it), through the texture's
// LINEAR filter. Two passes (x, then y) give lesson 05's N x N grid for 2N lookups.
#include "border.glsl"
in vec2 vUv;
uniform sampler2D uSource;
uniform vec2 uAxis;    // one texel along the blurred axis, in (s, t)
uniform float uRadius;  // texels
const vec2 kUnitTaps[BLUR_TAPS] = BLUR_UNIT_TAPS;  // .x: the offset for a radius of 1
out vec4 outColor;
// Outside the map, nothing in front: what a texel at z = 1 stores (the textures' border; ES has
// none, so the taps that reach past the edge mix it in here, as LINEAR with a border would).
uniform vec4 uNothing;
void main() {
  vec2 size = vec2(textureSize(uSource, 0));
  vec4 sum = vec4(0.0);
  for (int k = 0; k < BLUR_TAPS; ++k) {
    vec2 uv = vUv + kUnitTaps[k].x * uRadius * uAxis;
    sum += withBorder(texture(uSource, uv), uv, size, uNothing, true);
  }
  outColor = sum / float(BLUR_TAPS);
}
