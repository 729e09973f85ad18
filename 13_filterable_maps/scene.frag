#version 430 core
// Pass 2: the shadow term from a filterable map, or lesson 05's PCF as the reference, into
// seed 000's illumination model with dimming. FILTER_METHOD (compiled per setting, main.cpp):
//   PCF  compare first, then average (05's grid over +-uRadius texels, common/shaders/pcf.glsl);
//   VSM  the blurred moments' mean and variance, and Chebyshev's bound on the lit fraction;
//   ESM  the blurred exp(c (z - 1)) times exp(-c (t - 1));
//   MSM  the blurred four moments, decoded, and the sharpest lower bound on the shadow they
//        allow (Hamburger 4MSM, Peters and Klein 2015; msm_math.hpp mirrors it).
#include "lighting.glsl"
#include "pcf.glsl"
#include "light_depth.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform vec3 uColor;
uniform sampler2D uMoments;  // blurred, LINEAR
uniform float uRadius;       // PCF: the kernel's half-width in texels
uniform float uExponent;     // esm.c
uniform float uMinVariance;  // vsm.min_variance
uniform float uBleeding;     // vsm.bleeding: the lowest bound cut off and the rest rescaled
uniform mat4 uMomentDecode;  // MSM: msm::decodeMatrix()
uniform float uEncodeOffset;
uniform float uMomentBias;   // msm.bias: the moments pulled toward kBiasTarget by this much
out vec4 outColor;

// Chebyshev's one-sided inequality: at most variance / (variance + (t - mean)^2) of the texels
// the filter covered lie at or beyond t. VSM takes that bound as the lit fraction: exact for one
// plane of blockers over one receiver, too light where a second blocker widens the variance
// (light bleeding).
float chebyshev(vec2 moments, float t) {
  if (t <= moments.x) return 1.0;
  float variance = max(moments.y - moments.x * moments.x, uMinVariance);
  float d = t - moments.x;
  float p = variance / (variance + d * d);
#if BLEEDING_REDUCTION
  return clamp((p - uBleeding) / (1.0 - uBleeding), 0.0, 1.0);
#else
  return clamp(p, 0.0, 1.0);  // vsm.bleeding=0: (p - 0) / 1, without the divide
#endif
}

#if FILTER_METHOD == FILTER_METHOD_MSM
// Of every distribution of depths with these four moments, the one with the most mass in front
// of t lies on three depths: t and the two roots of c1 + c2 z + c3 z^2, where B c = (1, t, t^2)
// and B is the moments' Hankel matrix. 1 - that mass: the lit fraction.
float momentLit(vec4 stored, float t) {
  vec4 b = uMomentDecode * (stored - vec4(uEncodeOffset, 0.0, 0.0, 0.0));
  b = mix(b, vec4(0.5), uMomentBias);
  // B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]] = L D L^T
  float d22 = b.y - b.x * b.x;
  float l32 = (b.z - b.x * b.y) / d22;
  float d33 = b.w - b.y * b.y - l32 * l32 * d22;
  float c1 = 1.0, c2 = t - b.x, c3 = t * t - b.y - l32 * c2;
  c2 /= d22;
  c3 /= d33;
  c2 -= l32 * c3;
  c1 -= b.x * c2 + b.y * c3;
  float p = c2 / c3, q = c1 / c3;
  float r = sqrt(max(0.25 * p * p - q, 0.0));
  float z2 = -0.5 * p - r, z3 = -0.5 * p + r;
  float shadow = 0.0;
  if (z3 < t) {
    shadow = 1.0 - (b.y - b.x * (z2 + z3) + z2 * z3) / ((t - z2) * (t - z3));
  } else if (z2 < t) {
    shadow = (b.y - b.x * (t + z3) + t * z3) / ((t - z2) * (z3 - z2));
  }
  return 1.0 - clamp(shadow, 0.0, 1.0);
}
#endif

float shadowTerm(vec3 n, vec3 toLight) {
  // Facing away from the light (the geometric normal, as the truth sees it): in its own
  // shadow, whatever the map says.
  if (dot(n, toLight) <= 0.0) return 0.0;
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum
  vec3 p = c.xyz / c.w;
#if FILTER_METHOD == FILTER_METHOD_PCF
  p.z = min(p.z, 1.0);  // beyond the far plane: every depth format clamps B to 1
#if PCF_KERNEL
  return percentageCloser(p, uRadius);
#else
  return tap(p, vec2(0.0));  // filter.radius=0, nearest: every tap this one's 0 or 1
#endif
#else
  if (outsideTexture(p.xy, vec2(textureSize(uMoments, 0)))) return 1.0;  // the border: lit
  vec4 m = texture(uMoments, p.xy);
  float t = lightDepth01(vWorld);
  if (t >= 1.0) return 1.0;  // beyond the far plane the map holds nothing: lit, as PCF's clamp
  t = max(t, 0.0);
#if FILTER_METHOD == FILTER_METHOD_VSM
  return chebyshev(m.xy, t);
#elif FILTER_METHOD == FILTER_METHOD_MSM
  return momentLit(m, t);
#else
  return clamp(m.x * exp(uExponent * (1.0 - t)), 0.0, 1.0);
#endif
#endif
}

void main() {
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  // The facing test asks only the sign of N.L: the geometric normal (facing the eye) and the
  // way to the light need no normalize.
  float shade = shadowTerm(cross(dFdx(vWorld), dFdy(vWorld)), towardLight(vWorld));
#endif
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#else
  outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), shade), 1.0);
#endif
}
