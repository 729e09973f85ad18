#version 330 core
// The eye passes of Heidrich's dual-texture shadow test (seed 000, "Dual-texture Shadow
// Mapping Approach"), the fixed-function stages written out:
//   Tex0  the 8-bit map at (s/q, t/q)                      (texgen 1, "intensity texture")
//   Tex1  a 1D linear ramp at the fragment's light depth    (texgen 2, "Z planar distance in S")
//   texenv  alpha = a(Tex0) + (1 - a(Tex1)) - 0.5            (EXT_texture_env_combine)
//   alpha test  glAlphaFunc(GL_GREATER, 0.5), as a discard
// Compiled once per pass (PASS 1, 2, or 0 for the one-value views), so each pass runs only
// its own stages: pass 1 looks nothing up, pass 2 tests, the views show a value untested.
#include "lighting.glsl"
#include "depth_digits.glsl"
#include "readback_lookup.glsl"

in vec3 vWorld;
in vec3 vNormal;
uniform sampler2D uMap;   // Tex0
uniform Ramp uRamp;       // Tex1 (ramp.glsl: 1D, or 256x1 where there are no 1D textures)
uniform vec3 uColor;
// Also compiled per VIEW (colour, visibility; the views ramp: Tex1, difference: texenv alpha
// - 0.5) and RAMP_LOOKUP (0: compare with the exact fragment depth instead of Tex1).
out vec4 outColor;

float mapSteps() {
  float v = mapTexel(uMap).r;
  return uMapIsDepth == 1 ? depthToSteps(v, 255.0, uReadbackNearest) : floor(v * 255.0 + 0.5);
}

float fragmentSteps() {
  float s = fragmentDepth();
#if RAMP_LOOKUP
  return floor(rampTexel(uRamp, s) * 255.0 + 0.5);
#else
  return min(clamp(s, 0.0, 1.0) * 255.0, 254.5);  // exact, below the cleared map as the ramp is
#endif
}

float alpha() {
  return behindLight() ? 1.0 : texenvAlpha(mapSteps(), fragmentSteps());
}

void main() {
#if PASS == 1
  // "Render scene with light disabled -or- dimmed substantially and specular light color of
  // zero": no texture at all.
#if SHADOW_OFF
  float lit = 1.0;  // shadow.off, the baseline: this one pass, lit, no texture
#else
  float lit = 0.0;
#endif
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(lit), 1.0);
#else
  outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), lit), 1.0);
#endif
#elif PASS == 2
  // "Enable the light source, un-rejected pixels = unshadowed".
  if (!alphaTestPasses(alpha())) discard;
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(1.0);
#else
  outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), 1.0), 1.0);
#endif
#else
#if VIEW == VIEW_RAMP
  outColor = vec4(vec3(fragmentSteps() / 255.0), 1.0);
#else
  {
    // Signed and magnified 64x (one 8-bit step = a quarter of full): green where the map
    // lies beyond the fragment (lit), red where it does not (shadowed, ties included: the
    // self-shadowing 000 warns about).
    float d = 64.0 * (alpha() - 0.5);
    outColor = d > 0.0 ? vec4(0.0, min(d, 1.0), 0.0, 1.0) : vec4(max(0.25, min(-d, 1.0)), 0.0, 0.0, 1.0);
  }
#endif
#endif
}
