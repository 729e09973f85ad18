// What lessons 06 and 07 share in their eye passes: where a fragment looks in the map, and
// its own light depth in [0, 1] (Tex1's texgen), both as the fixed-function texgen made them.
#include "border.glsl"
#include "ramp.glsl"
uniform int uMapIsDepth;    // copy_texture / render_to_texture: a depth texture to quantize
uniform int uReadbackNearest;  // how this driver's glReadPixels rounds (depthToSteps)
uniform int uLinear;        // Heidrich's linear depth: S from the eye-planar texgen
uniform float uTexgenBias;  // bias.mode=texgen: subtracted from r before the divide by q

in vec4 vShadowCoord;
in float vLinearS;

// Behind a spot light the map says nothing (lesson 03): such fragments are lit.
bool behindLight() {
  return vShadowCoord.w <= 0.0;
}
vec2 mapCoord() {
  return vShadowCoord.xy / vShadowCoord.w;
}
// Tex0: the map at (s/q, t/q); outside it the border, all ones ("nothing in front": step 255,
// digits 255 and 255, depth 1).
vec4 mapTexel(sampler2D map) {
  vec2 uv = mapCoord();
  return outsideTexture(uv, vec2(textureSize(map, 0))) ? vec4(1.0) : texture(map, uv);
}
float fragmentDepth() {
  return uLinear == 1 ? vLinearS - uTexgenBias : (vShadowCoord.z - uTexgenBias) / vShadowCoord.w;
}
