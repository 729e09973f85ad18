// Percentage-closer filtering (Reeves 1987; seed 000 "Hardware Shadow Map Filtering"): compare
// first, then average the results, never the depths. Every tap is one sampler2DShadow lookup.
// The tap offsets are not computed here: pcf_math.hpp (unitTapOffsets) computes them on the
// CPU and main.cpp compiles them in, so the unit tests check the very offsets the shader uses.
#include "border.glsl"
uniform sampler2DShadow uShadowMap;
// Compiled per setting (main.cpp): PCF_MODE is pcf.mode (PCF_MODE_NONE .. PCF_MODE_POISSON);
// PCF_EARLY_OUT 1: stop after 4 probe taps that agree. The kernel is compiled in too, so its
// loops run to constants over constant offsets and unroll (a loop to a uniform count over a
// uniform array cost the 3x3 grid about twice its lookups): PCF_TAP_COUNT offsets
// PCF_UNIT_TAPS for a radius of one texel, in texels: grid, its four corners then the others
// row by row; dithered, 4 per pixel-parity pattern (pattern = x mod 2 + 2 (y mod 2)); poisson,
// the disk's points in order, the first four on its rim.
#ifdef PCF_TAP_COUNT
const vec2 kUnitTaps[PCF_TAP_COUNT] = PCF_UNIT_TAPS;
#endif
uniform vec2 uTexel;    // 1 / map size

// `precise` keeps offset = unit * radius one rounded multiply, as tapOffsets() computes it,
// instead of letting the compiler fold the radius into uTexel first (OpenGL ES 3.0 has no
// precise; there an offset may round differently in its last bit).
#ifdef GL_ES
#define PRECISE
#else
#define PRECISE precise
#endif

int gTaps = 0;         // taps this fragment took (counted, see scene.frag)
bool gStopped = false;  // the probes agreed and the rest were skipped

float tap(vec3 c, vec2 offsetTexels) {
  gTaps++;
  vec2 uv = c.xy + offsetTexels * uTexel;
  if (outsideTexture(uv, vec2(textureSize(uShadowMap, 0)))) return 1.0;  // the border: lit
  return texture(uShadowMap, vec3(uv, c.z));
}

#ifdef PCF_TAP_COUNT
// A tap of the compiled kernel: a unit offset scaled by the radius (the kernel's half-width in
// texels: lesson 05's uniform, lesson 14's per fragment).
float kernelTap(vec3 c, vec2 unitOffset, float radius) {
  PRECISE vec2 offsetTexels = unitOffset * radius;
  return tap(c, offsetTexels);
}
#endif

// The grid, N x N taps at the midpoints of a box of half-width radius (the box filter's
// midpoint rule), and seed 003 slide 71's Poisson-disk samples (pcf_math.hpp poissonDisk:
// each prefix is spread out): the average of PCF_TAP_COUNT taps. pcf_math.hpp puts the early
// out's probes first in both, the grid's four corners and the disk's four rim points.
#if PCF_MODE == PCF_MODE_GRID || PCF_MODE == PCF_MODE_POISSON
float pcfKernel(vec3 c, float radius) {
  const int n = PCF_TAP_COUNT;
  float sum = 0.0;
#if PCF_EARLY_OUT == 1
  if (n > 4) {
    // The four probes first: if they agree, the neighbourhood is fully lit or fully shadowed
    // (unless something smaller than the kernel hides between them) and the rest is skipped.
    // llvmpipe runs both sides of an if for every pixel of its SIMD vector, so the rest is a
    // loop, which it leaves once no pixel of the vector is still in it; but it runs a loop's
    // body at least once, so the fourth probe is the loop's first turn: where all four agree
    // the vector pays no turn beyond the probes (an empty turn cost about two taps).
    for (int k = 0; k < 3; ++k) sum += kernelTap(c, kUnitTaps[k], radius);
    // Always 3 (a tap is at most 1): a start the compiler cannot know keeps the loop a loop,
    // where one of known length would be unrolled and every turn run.
    int k = sum > 3.0 ? 4 : 3;
    do {
      sum += kernelTap(c, kUnitTaps[k], radius);
      if (k == 3) gStopped = sum == 0.0 || sum == 4.0;
    } while (++k < n && !gStopped);
    return gStopped ? sum * 0.25 : sum / float(n);
  }
#endif
  for (int k = 0; k < n; ++k) sum += kernelTap(c, kUnitTaps[k], radius);
  return sum / float(n);
}
#endif

// Seed 001 "PCF with Dithering": 4 taps whose pattern depends on gl_FragCoord mod 2. The four
// patterns of a 2 x 2 pixel block together are the 4 x 4 grid of the same radius.
#if PCF_MODE == PCF_MODE_DITHERED
float pcfDithered(vec3 c, float radius) {
  bvec2 odd = equal(ivec2(mod(floor(gl_FragCoord.xy), 2.0)), ivec2(1));
  float sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    // Pattern x + 2y picked by selects between constants: indexing the constants by the
    // pixel's parity cost llvmpipe more than the four taps' selects (callgrind, README).
    vec2 even_row = odd.x ? kUnitTaps[4 + k] : kUnitTaps[k];
    vec2 odd_row = odd.x ? kUnitTaps[12 + k] : kUnitTaps[8 + k];
    sum += kernelTap(c, odd.y ? odd_row : even_row, radius);
  }
  return sum * 0.25;
}
#endif

// c: (s, t, r) after the divide by q; radius: the kernel's half-width in texels.
float percentageCloser(vec3 c, float radius) {
#if PCF_MODE == PCF_MODE_GRID || PCF_MODE == PCF_MODE_POISSON
  return pcfKernel(c, radius);
#elif PCF_MODE == PCF_MODE_DITHERED
  return pcfDithered(c, radius);
#else
  return tap(c, vec2(0.0));  // none (nearest) or hw2x2 (the sampler is LINEAR: 4 texels, weighted)
#endif
}
