#version 430 core
// Pass 2: the shadow term by percentage-closer filtering, into 000's illumination model with
// dimming. Taps are counted per fragment into a buffer: llvmpipe's statistics count fragment
// invocations, not texture lookups. (Buffers and early tests are GL 4.3 and 4.2: without them,
// on GL 4.1 and ES, PCF_COUNT is 0 and the counters are unavailable.)
#if HAS_EARLY_FRAGMENT_TESTS
layout(early_fragment_tests) in;  // count only fragments that passed the depth test
#endif
#include "lighting.glsl"
#include "pcf.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform vec3 uColor;
uniform float uRadius;  // kernel half-width in texels: the one setting of the kernel not compiled
// Compiled per setting (main.cpp): VIEW (shaded, visibility, taps per fragment), SHADOW_OFF,
// and PCF_COUNT 1 that adds this fragment's work to the counters (atomics cost; compiled out
// when off).
out vec4 outColor;
#if PCF_COUNT
layout(std430, binding = 0) buffer Counters {
  uint taps;         // shadow-map lookups
  uint filtered;     // fragments that ran the filter
  uint stopped;      // ... of which stopped after the probes
  uint facing_away;  // fragments that skipped it: facing away from the light
};
#endif

float shadowTerm(vec3 n, vec3 toLight) {
  // Facing away from the light (the geometric normal, as the truth sees it): in its own
  // shadow, whatever the map says. No taps.
  if (dot(n, toLight) <= 0.0) {
#if PCF_COUNT
    atomicAdd(facing_away, 1u);
#endif
    return 0.0;
  }
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum
  vec3 p = c.xyz / c.w;
  p.z = min(p.z, 1.0);  // beyond the far plane: every depth format clamps B to 1
#if PCF_KERNEL
  float shade = percentageCloser(p, uRadius);
#else
  // pcf.radius=0 with taps of 0 or 1: each tap reads this texel, their average its answer.
  float shade = tap(p, vec2(0.0));
#endif
#if PCF_COUNT
  atomicAdd(taps, uint(gTaps));
  atomicAdd(filtered, 1u);
  if (gStopped) atomicAdd(stopped, 1u);
#endif
  return shade;
}

void main() {
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  // The facing test asks only the sign of N.L: the geometric normal (facing the eye) and the
  // way to the light need no normalize.
  float shade = shadowTerm(cross(dFdx(vWorld), dFdy(vWorld)), towardLight(vWorld));
#endif
#if VIEW == VIEW_SHADED
  {
    outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), shade), 1.0);
  }
#elif VIEW == VIEW_VISIBILITY
  {
    outColor = vec4(vec3(shade), 1.0);
  }
#else
  {
    // Taps per fragment: black 0, blue 4, through green, to red at 64.
    float t = clamp(log2(float(gTaps) + 1.0) / log2(65.0), 0.0, 1.0);
    vec3 heat = t < 0.5 ? mix(vec3(0.0, 0.1, 0.8), vec3(0.1, 0.8, 0.2), 2.0 * t)
                        : mix(vec3(0.1, 0.8, 0.2), vec3(0.95, 0.1, 0.05), 2.0 * t - 1.0);
    outColor = vec4(gTaps == 0 ? vec3(0.0) : heat * (0.5 + 0.5 * shade), 1.0);
  }
#endif
}
