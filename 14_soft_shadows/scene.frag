#version 430 core
// Pass 2: percentage-closer soft shadows (Fernando 2005), the arithmetic of pcss_math.hpp:
//   1. blocker search: which map texels in the cone from this point to the light's disk are
//      nearer the light than this point, and how far they are on average;
//   2. penumbra: its half-width from similar triangles, R (z_r - z_b) / z_b;
//   3. filter: lesson 05's PCF (common/shaders/pcf.glsl) over that half-width.
// The shadow term goes into seed 000's illumination model with dimming. Work is counted per
// fragment into a buffer where the flavour has one (GL 4.3).
#if HAS_EARLY_FRAGMENT_TESTS
layout(early_fragment_tests) in;  // count only fragments that passed the depth test
#endif
#include "lighting.glsl"
#include "pcf.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform vec3 uColor;
// The same map as uShadowMap, through a sampler without compare: the search reads depths.
uniform sampler2D uDepthMap;
uniform mat4 uLightProjection;  // P_light: a stored depth back to a distance from the light
uniform float uLightRadius;     // the disk light's radius, world units (the truth's too)
uniform float uSearchFrom;  // where the search cone is cut: the nearest caster's distance
uniform float uFixedRadius;     // PCSS_MODE_FIXED: lesson 05's one kernel half-width, texels
// Compiled per setting (main.cpp): PCSS_MODE (hard, fixed, pcss), the search's Poisson disk
// (SEARCH_TAP_COUNT points SEARCH_UNIT_TAPS in the unit circle), PCSS_SKIP_UMBRA, the view,
// SHADOW_OFF, PCSS_COUNT, and PCF_KERNEL and PCSS_SEARCH, 0 where their code changes no pixel.
#ifdef SEARCH_TAP_COUNT
const vec2 kSearchTaps[SEARCH_TAP_COUNT] = SEARCH_UNIT_TAPS;
#endif
out vec4 outColor;
#if PCSS_COUNT
layout(std430, binding = 0) buffer Counters {
  uint search_taps;   // depth reads of the blocker search
  uint filter_taps;   // compares of the filter (one in hard mode)
  uint filtered;      // fragments that ran the filter
  uint no_blocker;    // searched, found nothing: lit, no filter
  uint all_blockers;  // searched, every tap a blocker: umbra, no filter (PCSS_SKIP_UMBRA)
  uint facing_away;   // facing away from the light: no search, no filter
};
#endif

// pcss_math.hpp's lightDistance and uvPerWorld.
bool perspectiveLight() {
  return uLightProjection[2][3] != 0.0;
}
float lightDistance(float windowDepth) {
  float ndc = 2.0 * windowDepth - 1.0;
  return perspectiveLight() ? uLightProjection[3][2] / (ndc + uLightProjection[2][2])
                            : (ndc - uLightProjection[3][2]) / -uLightProjection[2][2];
}
vec2 uvPerWorld(float distance) {
  vec2 at_one = 0.5 * vec2(uLightProjection[0][0], uLightProjection[1][1]);
  return perspectiveLight() ? at_one / distance : at_one;
}

// What the debug views show of this fragment.
float gGap = -1.0;     // receiver minus average blocker distance; -1: no blocker found
bool gUmbra = false;   // every search tap found a blocker
float gKernel = -1.0;  // the filter's half-width in texels; -1: no filter ran
int gSearchTaps = 0;

float softShadow(vec3 p) {
#if PCSS_MODE == PCSS_MODE_HARD
  return tap(p, vec2(0.0));  // lesson 04's one compare
#elif PCSS_MODE == PCSS_MODE_FIXED
  gKernel = uFixedRadius;  // lesson 05: one width for every edge
#if PCF_KERNEL
  return percentageCloser(p, uFixedRadius);
#else
  return tap(p, vec2(0.0));  // pcf.radius=0, nearest: every tap this one's 0 or 1
#endif
#elif !PCSS_SEARCH
  // pcss.light_radius=0 (a point light), the umbra skipped, nearest compares: the search region
  // is the pixel's own texel, which is a blocker for every tap or for none, so the answer is
  // the one compare's (Lesson14.APointLightGivesTheHardShadowBitForBit, with the search in).
  return tap(p, vec2(0.0));
#else
  float receiver = lightDistance(p.z);
  // 1. The search region: the cone to the light's disk, cut where the casters begin.
  vec2 search = uvPerWorld(uSearchFrom) *
                (uLightRadius * max(receiver - uSearchFrom, 0.0) / receiver);
  vec2 size = vec2(textureSize(uDepthMap, 0));
  float sum = 0.0;
  int found = 0;
  for (int k = 0; k < SEARCH_TAP_COUNT; ++k) {
    vec2 uv = p.xy + kSearchTaps[k] * search;
    gSearchTaps++;
    if (outsideTexture(uv, size)) continue;  // the border: nothing there
    float d = texture(uDepthMap, uv).r;
    if (d < p.z) {
      sum += lightDistance(d);
      found++;
    }
  }
  if (found == 0) return 1.0;  // nothing between this point and the light: lit
  float blocker = sum / float(found);
  gGap = receiver - blocker;
#if PCSS_SKIP_UMBRA
  if (found == SEARCH_TAP_COUNT) {  // every tap blocked: deep in the umbra
    gUmbra = true;
    return 0.0;
  }
#endif
  // 2. The penumbra's half-width at the receiver (a directional light's cone: / receiver).
  float penumbra = uLightRadius * gGap / (perspectiveLight() ? blocker : receiver);
  // 3. As a kernel radius in texels, and lesson 05's filter over it.
  gKernel = penumbra * uvPerWorld(receiver).x * size.x;
  return percentageCloser(p, gKernel);
#endif
}

float shadowTerm(vec3 n, vec3 toLight) {
  // Facing away from the light (the geometric normal, as the truth sees it): in its own
  // shadow, whatever the map says. No search, no filter.
  if (dot(n, toLight) <= 0.0) {
#if PCSS_COUNT
    atomicAdd(facing_away, 1u);
#endif
    return 0.0;
  }
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum
  vec3 p = c.xyz / c.w;
  p.z = min(p.z, 1.0);  // beyond the far plane: every depth format clamps B to 1
  float shade = softShadow(p);
#if PCSS_COUNT
  atomicAdd(search_taps, uint(gSearchTaps));
  atomicAdd(filter_taps, uint(gTaps));
  if (gTaps > 0) atomicAdd(filtered, 1u);
  if (gSearchTaps > 0 && gGap < 0.0) atomicAdd(no_blocker, 1u);
  if (gUmbra) atomicAdd(all_blockers, 1u);
#endif
  return shade;
}

// Black 0 .. blue .. green .. red at 1.
vec3 heat(float t) {
  return t < 0.5 ? mix(vec3(0.0, 0.1, 0.8), vec3(0.1, 0.8, 0.2), 2.0 * t)
                 : mix(vec3(0.1, 0.8, 0.2), vec3(0.95, 0.1, 0.05), 2.0 * t - 1.0);
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
#elif VIEW == VIEW_BLOCKERS
  {
    // The gap between receiver and average blocker, 0 (touching: blue) to 2 units (red);
    // black where the search found no blocker, grey where it found only blockers.
    vec3 c = gUmbra ? vec3(0.35) : gGap < 0.0 ? vec3(0.0) : heat(clamp(gGap / 2.0, 0.0, 1.0));
    outColor = vec4(c * (0.6 + 0.4 * shade), 1.0);
  }
#else
  {
    // The filter's half-width, log scale: blue 1 texel, green 8, red 64; black: no filter.
    float t = clamp(log2(max(gKernel, 0.0) + 1.0) / log2(65.0), 0.0, 1.0);
    outColor = vec4(gKernel < 0.0 ? vec3(0.0) : heat(t) * (0.6 + 0.4 * shade), 1.0);
  }
#endif
}
