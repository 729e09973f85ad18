#version 330 core
// Step 2 of the slide, "draw the scene with the shadow map", lit by the projected spotlight.
#include "spot.glsl"
in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
in vec4 vSpotCoord;
uniform vec3 uColor;
uniform vec3 uLightPos;
uniform vec3 uEye;
uniform float uDimming;
// Compiled per VIEW (main.cpp): lit surfaces, the visibility, the spot without shadows, or
// black for the air alone.
out vec4 outColor;

void main() {
#if VIEW == VIEW_AIR
  outColor = vec4(0.0, 0.0, 0.0, 1.0);  // the air alone: surfaces only hide what lies behind
#else
  float shadow = shadowTest(vShadowCoord);
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shadow), 1.0);
#else
#if VIEW == VIEW_SPOT
  float shade = 1.0;
#else
  float shade = uDimming + (1.0 - uDimming) * shadow;
#endif
  float spot = spotLight(vSpotCoord);
  vec3 n = normalize(vNormal);
  vec3 l = normalize(uLightPos - vWorld);
  float nl = max(dot(n, l), 0.0);
  vec3 h = normalize(l + normalize(uEye - vWorld));
  float spec = nl > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) : 0.0;
  vec3 lit = uColor * (0.06 + 0.94 * nl * spot * shade) + vec3(0.3) * spec * spot * shadow;
  outColor = vec4(lit, 1.0);
#endif
#endif
}
