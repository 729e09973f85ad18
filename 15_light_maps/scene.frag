#version 330 core
// The frame: the shadow is a texture lookup. The light map holds, per texel, the fraction of
// the area light its surface point saw when it was baked (seed 003: "bake soft shadows in
// light maps ... sample area light sources"); what it cost was paid once, before the first
// frame.
//   LIGHTMAP_MODE_BAKED:  the light map alone;
//   LIGHTMAP_MODE_HYBRID: the light map of the static casters times lesson 03's map of the one
//                         that moves (the moving object itself takes the map alone);
//   LIGHTMAP_MODE_MAP:    lesson 03's map for everything, the comparison.
#include "lighting.glsl"
#include "border.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
in vec2 vLightMapUv;
uniform vec3 uColor;
uniform sampler2D uLightMap;         // R16F, its filter bilinear or nearest (lightmap.filter)
uniform sampler2DShadow uShadowMap;  // lesson 03's map (compare on)
uniform int uObject;
uniform int uMovingObject;
uniform float uSamples;  // samples a texel, for the noise view
out vec4 outColor;

float baked() {
  if (vLightMapUv.x < 0.0) return 1.0;  // an object without a chart: nothing baked
  return texture(uLightMap, vLightMapUv).r;
}

float mapped() {
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;
  c.z = min(c.z, c.w);
  if (outsideTexture(c.xy / c.w, vec2(textureSize(uShadowMap, 0)))) return 1.0;
  return textureProj(uShadowMap, c);
}

float shadowTerm() {
#if SHADOW_OFF
  return 1.0;  // shadow.off: the baseline, no lookup
#elif LIGHTMAP_MODE == LIGHTMAP_MODE_BAKED
  return baked();
#elif LIGHTMAP_MODE == LIGHTMAP_MODE_HYBRID
  return uObject == uMovingObject ? mapped() : baked() * mapped();
#else
  return mapped();
#endif
}

void main() {
  vec3 n = normalize(vNormal);
  float shade = shadowTerm();
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#elif VIEW == VIEW_TEXEL_GRID
  // The texel grid on the scene: where one light map texel ends and the next begins (texel
  // edges at whole texel coordinates; a chart's border runs through its outer texels' centres).
  vec2 texel = vLightMapUv * vec2(textureSize(uLightMap, 0));
  vec2 edge = abs(fract(texel + 0.5) - 0.5) / max(fwidth(texel), vec2(1e-6));
  float line = vLightMapUv.x < 0.0 ? 0.0 : 1.0 - clamp(min(edge.x, edge.y), 0.0, 1.0);
  vec3 lit = shadeSurface(uColor, vWorld, n, shade);
  outColor = vec4(mix(lit, vec3(1.0, 0.85, 0.2), 0.8 * line), 1.0);
#elif VIEW == VIEW_NOISE
  // What n samples a texel leave uncertain: the standard error of a fraction v seen with n
  // independent samples, sqrt(v (1 - v) / n) (stratified samples do better): red at 0.1.
  float v = baked();
  float error = sqrt(max(v * (1.0 - v), 0.0) / max(uSamples, 1.0));
  outColor = vec4(mix(shadeSurface(vec3(0.5), vWorld, n, 1.0) * 0.6, vec3(1.0, 0.1, 0.05),
                      clamp(error / 0.1, 0.0, 1.0)), 1.0);
#else
  outColor = vec4(shadeSurface(uColor, vWorld, n, shade), 1.0);
#endif
}
