#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define PASS 2
#define SHADOW_OFF 0
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_BIG_DIGIT 2
#define VIEW_LITTLE_DIGIT 3
#define VIEW_PASSES 4
#define VIEW_ALIASING 5
#define VIEW_TRUTH 6
#define VIEW_ERROR 7
#define VIEW VIEW_SHADED
#line 2 0
// Passes 1 and 2 (pass 2 writes the stencil, so its depth and stencil tests must come after
// the alpha test's discard).
#line 1 1
// The eye passes of McCool's multi-digit comparison (seed 000, "GeForce/Quadro Precision
// Extension"), the register-combiner stages written out, compiled once per pass (PASS 1-3):
//   Tex0  the map's two 8-bit digits at (s/q, t/q) (GL_LUMINANCE8_ALPHA8 then, RG8 now)
//   Tex1  pass 2: a 1D linear ramp at s ("2nd pass just requires a linear 1D texture");
//         pass 3: a 2D ramp, linear along both axes, at (s, 256 s): both digits
//   pass 1  everything dimmed
//   pass 2  lit where bigDigit(map) > bigDigit(fragment); writes stencil 1
//   pass 3  lit where the big digits leave it to the little ones: alpha = littleDigit(map) -
//           littleDigit(fragment) (0 if the fragment's big digit is larger), alpha test
//           GL_GREATER 0, stencil 1 rejected (pass 2 has lit the pixel already)
#line 1 2
// The illumination model every lesson shares (seed 000, "Advice for Shadowed Illumination
// Model"): ambient + diffuse, the diffuse dimmed rather than removed in shadow, specular
// only where lit.
uniform vec3 uLightPos;
uniform vec3 uLightDir;        // from the light into the scene
uniform int uLightDirectional;
uniform vec3 uEye;
uniform float uDimming;        // diffuseShade = dimming + (1 - dimming) * shade

vec3 directionToLight(vec3 p) {
  return uLightDirectional == 1 ? -uLightDir : normalize(uLightPos - p);
}

// The same way, not normalized: enough where only a sign is asked (a facing test).
vec3 towardLight(vec3 p) {
  return uLightDirectional == 1 ? -uLightDir : uLightPos - p;
}

vec3 shadeSurface(vec3 albedo, vec3 p, vec3 n, float shade) {
  vec3 l = directionToLight(p);
  float nl = max(dot(n, l), 0.0);
  vec3 v = normalize(uEye - p);
  vec3 h = normalize(l + v);
  float spec = nl > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) : 0.0;
  float diffuse_shade = uDimming + (1.0 - uDimming) * shade;
  return albedo * (0.12 + 0.88 * nl * diffuse_shade) + vec3(0.35) * spec * shade;
}
#line 12 1
#line 1 3
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
#line 13 1
#line 1 4
// What lessons 06 and 07 share in their eye passes: where a fragment looks in the map, and
// its own light depth in [0, 1] (Tex1's texgen), both as the fixed-function texgen made them.
#line 1 5
// GL_CLAMP_TO_BORDER gives a map's border value (depth 1, "nothing in front"; a spot's black)
// wherever a lookup falls outside it. OpenGL ES 3.0 and WebGL have no border: their textures
// clamp to the edge, and the shaders ask this first, then use the border value themselves.
// True where a NEAREST lookup at `uv` takes a texel outside a texture of `size` texels (a
// LINEAR one there mixes its outer half texel with the edge texel instead of the border).
bool outsideTexture(vec2 uv, vec2 size) {
#if HAS_BORDER_CLAMP
  return false;  // the sampler's border does it
#else
  vec2 texel = floor(uv * size);
  return any(lessThan(texel, vec2(0.0))) || any(greaterThanEqual(texel, size));
#endif
}

// How much of a LINEAR lookup's 2x2 footprint lies inside, along one axis (t: texel space,
// uv * size - 0.5): the rest of its weight is the border's.
float insideWeight(float t, float size) {
  float first = floor(t), f = t - first;
  bool a = first >= 0.0 && first <= size - 1.0, b = first >= -1.0 && first <= size - 2.0;
  return a && b ? 1.0 : a ? 1.0 - f : b ? f : 0.0;  // 1 exactly inside: the picture untouched
}

// What the border would have made of `clamped` (a lookup at uv with edge clamp): outside, the
// border colour (NEAREST); near the edge, LINEAR's mix of the texels inside with the border.
vec4 withBorder(vec4 clamped, vec2 uv, vec2 size, vec4 border, bool linear) {
#if HAS_BORDER_CLAMP
  return clamped;
#else
  vec2 t = uv * size - 0.5;
  float inside = linear ? insideWeight(t.x, size.x) * insideWeight(t.y, size.y)
                        : (outsideTexture(uv, size) ? 0.0 : 1.0);
  // Only where the border reaches: arithmetic on a filtered texel, even a mix by 1, can round
  // it differently from the texel itself on llvmpipe.
  if (inside < 1.0) clamped = mix(border, clamped, inside);
  return clamped;
#endif
}
#line 4 4
#line 1 6
// Tex1 of seed 000's readback lessons: a ramp of 256 texels read NEAREST, a 1D texture as the
// slides had it. OpenGL ES and WebGL have no 1D textures: there it is a 256x1 2D texture read
// along its one row, the same texels (Texture::table1D makes either).
#if HAS_TEXTURE_1D
#define Ramp sampler1D
float rampTexel(Ramp ramp, float s) {
  return texture(ramp, s).r;
}
#else
#define Ramp sampler2D
float rampTexel(Ramp ramp, float s) {
  return texture(ramp, vec2(s, 0.5)).r;
}
#endif
#line 5 4
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
  return uLinear == 1 ? vLinearS : vShadowCoord.z / vShadowCoord.w;
}
#line 14 1

in vec3 vWorld;
in vec3 vNormal;
uniform sampler2D uMap;       // Tex0: big digit in r, little digit in g
uniform Ramp uRampBig;        // Tex1 of pass 2 (ramp.glsl: 1D, or 256x1)
uniform sampler2D uRamp;      // Tex1 of pass 3
uniform vec3 uColor;
// Compiled per VIEW: the colour, the visibility, or which pass lit (1 grey, 2 green, 3 blue).
out vec4 outColor;

vec2 mapDigits() {
  vec4 v = mapTexel(uMap);
  if (uMapIsDepth == 1) {
    float steps = depthToSteps(v.r, 65535.0, uReadbackNearest);
    return vec2(bigDigit(steps), littleDigit(steps));
  }
  return floor(v.rg * 255.0 + 0.5);
}

// The fragment's light depth, stopping half a 16-bit step short of 1 as rampDigits does.
float rampS() {
  return clamp(fragmentDepth(), 0.0, 1.0 - 0.5 / 65536.0);
}

vec4 passColor(float shade, vec4 passesView) {
#if VIEW == VIEW_VISIBILITY
  return vec4(vec3(shade), 1.0);
#elif VIEW == VIEW_PASSES
  return passesView;
#else
  return vec4(shadeSurface(uColor, vWorld, normalize(vNormal), shade), 1.0);
#endif
}

void main() {
#if PASS == 1 && SHADOW_OFF
  outColor = passColor(1.0, vec4(0.15, 0.15, 0.15, 1.0));  // shadow.off: one pass, lit
#elif PASS == 1
  outColor = passColor(0.0, vec4(0.15, 0.15, 0.15, 1.0));
#elif PASS == 2
  float fragmentBig = floor(rampTexel(uRampBig, rampS()) * 255.0 + 0.5);
  if (!(behindLight() || bigDigitPassLights(mapDigits(), vec2(fragmentBig, 0.0)))) discard;
  outColor = passColor(1.0, vec4(0.0, 0.8, 0.0, 0.0));
#else
  float s = rampS();
  vec2 fragment = floor(texture(uRamp, vec2(s, 256.0 * s)).rg * 255.0 + 0.5);
  if (behindLight() || littleDigitPassAlpha(mapDigits(), fragment) <= 0.0) discard;
  outColor = passColor(1.0, vec4(0.0, 0.0, 0.8, 0.0));
#endif
}
#line 5 0
