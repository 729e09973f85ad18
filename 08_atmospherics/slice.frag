#version 420 core
// Steps 3 and 4 of the slide: each slice fragment adds the light the dust there scatters
// toward the eye: density x spotlight texture x shadow-map test x the length of eye ray the
// slice stands for. Additive blending: the air adds light and absorbs none.
#if AIR_EARLY_REJECT && HAS_EARLY_FRAGMENT_TESTS
// Fragments behind the scene's surfaces fail the depth test before they are shaded (the
// shader writes no depth). GL 4.2: elsewhere the driver decides.
layout(early_fragment_tests) in;
#endif
#include "spot.glsl"

in vec2 vNdc;
flat in float vDepth;
flat in int vSlice;
uniform mat4 uInverseView;
uniform vec2 uTanHalfFov;    // x, y extent of the view frustum at depth 1
uniform mat4 uShadowMatrix;  // B * P_map * V_light
uniform mat4 uSpotMatrix;    // B * P_cone * V_light
uniform float uStep;         // view depth between slices
uniform float uDensity;
uniform vec3 uAirColor;
uniform int uPixelScale;     // k: low-res pixel (x, y) is the ray of pixel (k x, k y)
out vec4 outColor;

uint hash(uint x) {  // lowbias32, as the truth's sampling
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

void main() {
#if !AIR_EARLY_REJECT
  gl_FragDepth = gl_FragCoord.z;  // the tests wait for the shader: every fragment is shaded
#endif
  // The point of the eye ray at this slice's depth, in view space, and the length of ray one
  // slice stands for (longer toward the screen's edges).
  vec3 ray = vec3(vNdc * uTanHalfFov, -1.0);
  float depth = vDepth;
#if AIR_JITTER
  // A different depth inside the slice's interval for every pixel: noise instead of bands.
  // The full picture's pixel, so the low-res air has the same jitter as the full-res air there.
  uvec2 pixel = uvec2(gl_FragCoord.xy) * uint(uPixelScale);
  uint h = hash(pixel.x * 73856093u ^ pixel.y * 19349663u ^
                uint(vSlice) * 83492791u);
  depth += (float(h >> 8) * (1.0 / 16777216.0) - 0.5) * uStep;
#endif
  vec3 world = (uInverseView * vec4(ray * depth, 1.0)).xyz;
  float light = uDensity * uStep * length(ray) * spotLight(uSpotMatrix * vec4(world, 1.0)) *
                shadowTest(uShadowMatrix * vec4(world, 1.0));
#if VIEW == VIEW_AIR
  outColor = vec4(vec3(light), 0.0);  // the air light alone, grey (red: what the truth compares)
#else
  outColor = vec4(uAirColor * light, 0.0);
#endif
}
