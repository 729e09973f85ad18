#version 330 core
// Pass 2: compare the fragment's light depth B with the map's A, with the receiver's share of
// the bias (seed 002's gradient, or normal offset); the other modes biased A in pass 1.
#include "lighting.glsl"
#include "border.glsl"
#include "receiver_bias.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;  // B * P_light * V_light * world, per vertex (shadow_coord.vert)
uniform sampler2DShadow uShadowMap;  // compare mode on: 1 where B <= A
uniform sampler2D uShadowDepth;      // the same texture read raw, for the gradient and the views
uniform vec3 uColor;
// Compiled per BIAS_MODE, VIEW and SHADOW_OFF (main.cpp), so a frame runs only its own bias
// and view. Only gradient (002) and normal offset bias the receiver here; the other modes
// biased the map in pass 1.
uniform float uFactor;     // bias.factor: gradient scale, or normal offset in texels
uniform float uUnits;      // bias.units: the gradient's light-space constant (world units)
uniform float uClamp;      // bias.clamp: the gradient's clamp (world units along the light z)
uniform float uDepthStep;  // one step of the map's depth format (the "units" of glPolygonOffset)
out vec4 outColor;

// The shadow term and the margin A - B the compare saw (negative: shadowed).
float shadowTerm(vec3 n, out float margin) {
  vec3 p = vWorld;
#if BIAS_MODE == BIAS_MODE_NORMAL_OFFSET
  // Normal offset moves the point before projecting it: only this mode projects per fragment.
#if NORMAL_OFFSET
  p = normalOffsetPoint(p, n, directionToLight(vWorld), uFactor);
#endif
  vec4 c = uShadowMatrix * vec4(p, 1.0);  // bias.factor=0: vWorld, projected all the same
#else
  vec4 c = vShadowCoord;  // projected per vertex and interpolated, as in lesson 03
#endif
  margin = 1.0;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum
  c.xyz /= c.w;
  c.z = min(c.z, 1.0);  // beyond the far plane: every depth format clamps B to 1
#if BIAS_MODE == BIAS_MODE_GRADIENT
#if GRADIENT_TERM
  float a = gradientBiasedDepth(uShadowDepth, c.xy, p, uFactor, uClamp);
#else  // bias.factor or bias.clamp 0: no slope term, so no neighbours read
  float a = storedDepth(uShadowDepth, c.xy);
#endif
#if CONSTANT_TERM
  a += lightSpaceDepthStep(p, uUnits);  // bias.units=0: a step of 0, not computed
#endif
  margin = a - c.z;
  return c.z <= a ? 1.0 : 0.0;
#else
  if (outsideTexture(c.xy, vec2(textureSize(uShadowMap, 0)))) {  // the border: depth 1
    margin = 1.0 - c.z;
    return 1.0;
  }
#if VIEW == VIEW_BIAS_MARGIN
  margin = texture(uShadowDepth, c.xy).r - c.z;
#endif
  return texture(uShadowMap, c.xyz);
#endif
}

void main() {
  vec3 n = geometricNormal(vWorld);
  float margin = 0.0;
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  float shade = shadowTerm(n, margin);
#endif
#if VIEW == VIEW_SHADED
  outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), shade), 1.0);
#elif VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#else
  {
    // The margin in depth steps, one brightness band per decade: green lit with room to
    // spare, red where B > A (acne on a lit surface, true shadow elsewhere).
    float decades = clamp(log2(abs(margin) / uDepthStep + 1.0) / log2(10.0) / 7.0, 0.0, 1.0);
    vec3 tone = margin >= 0.0 ? vec3(0.1, 0.9, 0.2) : vec3(0.95, 0.1, 0.1);
    float facing = max(dot(n, directionToLight(vWorld)), 0.0);
    outColor = vec4(tone * (0.15 + 0.85 * decades) * (0.4 + 0.6 * facing), 1.0);
  }
#endif
}
