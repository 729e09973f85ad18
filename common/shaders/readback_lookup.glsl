// What lessons 06 and 07 share in their eye passes: where a fragment looks in the map, and
// its own light depth in [0, 1] (Tex1's texgen), both as the fixed-function texgen made them.
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
float fragmentDepth() {
  return uLinear == 1 ? vLinearS - uTexgenBias : (vShadowCoord.z - uTexgenBias) / vShadowCoord.w;
}
