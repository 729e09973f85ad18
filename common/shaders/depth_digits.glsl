// The arithmetic of seed 000's shadow maps for hardware without depth textures, written once
// in the subset GLSL and C++ share: the shaders #include this file, and so does
// common/shadow/depth_digits.hpp, which the tests check against exact integer comparisons.
// Values are in map steps: 0..255 for one 8-bit digit, 0..65535 for two.

// What glReadPixels(GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE or GL_UNSIGNED_SHORT) makes of a
// depth in [0, 1] (`top` = 255 or 65535). The GL lets a driver take either neighbouring step,
// so DepthReadback asks the driver (`nearest` = 1: to nearest, ties to even; 0: down). Mesa
// 22 truncates bytes and rounds shorts. The paths that never read back (copy_texture,
// render_to_texture) quantize with this, so every path sees the same bits.
float depthToSteps(float depth, float top, int nearest) {
  float steps = clamp(depth, 0.0f, 1.0f) * top;
  return nearest == 1 ? roundEven(steps) : floor(steps);
}

// Tex1 of the dual-texture slides: a 1D ramp of 256 texels read NEAREST at s, texel i
// holding i, except the last, which holds 254: one step short of a cleared map (255, "no
// caster"), so a receiver at the far plane with nothing in front passes the strict test.
float rampSteps(float s) {
  return min(floor(clamp(s, 0.0f, 1.0f) * 256.0f), 254.0f);
}

// The texenv of "Texture environment (texenv) configuration" (EXT_texture_env_combine,
// GL_ADD_SIGNED): alpha = a(Tex0) + (1 - a(Tex1)) - 0.5, with Tex0 the map and Tex1 the ramp.
float texenvAlpha(float mapSteps, float rampStepsValue) {
  return (mapSteps + (255.0f - rampStepsValue)) / 255.0f - 0.5f;
}
// glAlphaFunc(GL_GREATER, 0.5): lit only where the map lies strictly beyond the fragment.
bool alphaTestPasses(float alpha) {
  return alpha > 0.5f;
}

// McCool's two digits of a 16-bit value.
float bigDigit(float value) {
  return floor(value / 256.0f);
}
float littleDigit(float value) {
  return value - 256.0f * floor(value / 256.0f);
}

// Tex1 of the precision-extension slides: a 2D ramp, linear along both axes, read NEAREST at
// (s, t = 256 s): the column gives the big digit, the row (t wraps) the little one. s stops
// half a step short of 1 and texel (255, 255) holds (255, 254), for the reason of rampSteps.
vec2 rampDigits(float s) {
  float c = clamp(s, 0.0f, 1.0f - 0.5f / 65536.0f);
  float little = floor(fract(256.0f * c) * 256.0f);
  float big = floor(c * 256.0f);
  return vec2(big, big == 255.0f ? min(little, 254.0f) : little);
}

// Pass 2: lit where the map's big digit is beyond the fragment's (000 writes it
// "bigDigit(Tex0) < bigDigit(Tex1)"; with Tex0 the map, as in pass 3, lit needs >).
bool bigDigitPassLights(vec2 mapDigits, vec2 fragmentDigits) {
  return mapDigits.x > fragmentDigits.x;
}
// Pass 3: "if bigDigit(Tex1) > bigDigit(Tex0) then alpha = 0 else alpha = littleDigit(Tex0) -
// littleDigit(Tex1)", alpha test GL_GREATER 0; the stencil keeps it off pass 2's pixels.
float littleDigitPassAlpha(vec2 mapDigits, vec2 fragmentDigits) {
  return fragmentDigits.x > mapDigits.x ? 0.0f : (mapDigits.y - fragmentDigits.y) / 255.0f;
}
