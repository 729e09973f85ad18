// Seed 000, "Combine with Projective Texturing for Spotlight Shadows": the spotlight is a
// texture projected through the light's frustum, modulated by the projected shadow map.
// Each at its own B * P * V_light * p (the spot's frustum is the lit cone; the map's may be
// fitted to the casters); surfaces and air slices look up the same two.
#include "border.glsl"
uniform sampler2D uSpot;             // NEAREST, 0 outside: the truth reads the same texels
uniform sampler2DShadow uShadowMap;  // compare mode on

float spotLight(vec4 c) {
  // Behind the light, before its near or beyond its far plane: the frustum the truth clips the
  // air to (B maps clip z from [-w, w] to [0, w]). The border of uSpot clips x and y.
  if (c.w <= 0.0 || c.z < 0.0 || c.z > c.w) return 0.0;
  if (outsideTexture(c.xy / c.w, vec2(textureSize(uSpot, 0)))) return 0.0;  // the border
  return dot(texture(uSpot, c.xy / c.w).rgb, vec3(0.2126, 0.7152, 0.0722));
}

float shadowTest(vec4 c) {
#if SHADOW_OFF
  return 1.0;  // shadow.off, the baseline: no map, no lookup
#endif
  if (c.w <= 0.0) return 1.0;
  c.z = min(c.z, c.w);  // beyond the far plane nothing casts (lesson 03)
  if (outsideTexture(c.xy / c.w, vec2(textureSize(uShadowMap, 0)))) return 1.0;  // the border
  return textureProj(uShadowMap, c);
}
