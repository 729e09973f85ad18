#version 430 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define PCF_MODE_NONE 0
#define PCF_MODE_HW2X2 1
#define PCF_MODE_GRID 2
#define PCF_MODE_DITHERED 3
#define PCF_MODE_POISSON 4
#define PCF_MODE PCF_MODE_DITHERED
#define PCF_EARLY_OUT 1
#define PCF_UNIT_TAPS vec2[](vec2(-0.75, 0.75), vec2(-0.75, -0.25), vec2(0.25, 0.75), vec2(0.25, -0.25), vec2(-0.25, 0.75), vec2(-0.25, -0.25), vec2(0.75, 0.75), vec2(0.75, -0.25), vec2(-0.75, 0.25), vec2(-0.75, -0.75), vec2(0.25, 0.25), vec2(0.25, -0.75), vec2(-0.25, 0.25), vec2(-0.25, -0.75), vec2(0.75, 0.25), vec2(0.75, -0.75))
#define PCF_TAP_COUNT 16
#define PCF_LOOKUP_COMPARE 0
#define PCF_LOOKUP_FETCH 1
#define PCF_LOOKUP_GATHER 2
#define PCF_LOOKUP PCF_LOOKUP_COMPARE
#define PCF_COUNT 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_TAPS 2
#define VIEW_LIGHT_DEPTH 3
#define VIEW_ALIASING 4
#define VIEW_TRUTH 5
#define VIEW_ERROR 6
#define VIEW VIEW_SHADED
#define SHADOW_OFF 0
#define PCF_KERNEL 1
#line 2 0
// Pass 2: the shadow term by percentage-closer filtering, into 000's illumination model with
// dimming. Taps are counted per fragment into a buffer: llvmpipe's statistics count fragment
// invocations, not texture lookups. (Buffers and early tests are GL 4.3 and 4.2: without them,
// on GL 4.1 and ES, PCF_COUNT is 0 and the counters are unavailable.)
#if HAS_EARLY_FRAGMENT_TESTS
layout(early_fragment_tests) in;  // count only fragments that passed the depth test
#endif
#line 1 1
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
#line 10 0
#line 1 2
// Percentage-closer filtering (Reeves 1987; seed 000 "Hardware Shadow Map Filtering"): compare
// first, then average the results, never the depths. Every tap is one lookup (PCF_LOOKUP below).
// The tap offsets are not computed here: pcf_math.hpp (unitTapOffsets) computes them on the
// CPU and main.cpp compiles them in, so the unit tests check the very offsets the shader uses.
#line 1 3
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
#line 6 2
// PCF_LOOKUP (lesson 05's pcf.lookup, pcf_math.hpp Lookup; without it, compare): how a tap
// reads the map. COMPARE: the texture unit compares (GL_COMPARE_REF_TO_TEXTURE); FETCH: the
// nearest texel's depth and a compare here, through a sampler without compare (main.cpp);
// GATHER: the grid's adjacent taps four at a time (pcfGatherGrid).
#ifndef PCF_LOOKUP
#define PCF_LOOKUP_COMPARE 0
#define PCF_LOOKUP_FETCH 1
#define PCF_LOOKUP_GATHER 2
#define PCF_LOOKUP PCF_LOOKUP_COMPARE
#endif
#if PCF_LOOKUP == PCF_LOOKUP_FETCH
uniform sampler2D uShadowMap;
#else
uniform sampler2DShadow uShadowMap;
#endif
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
#if PCF_LOOKUP == PCF_LOOKUP_FETCH
  // The depth of the texel a NEAREST lookup takes (the border's 1 outside), compared here as
  // GL_LEQUAL does. A plain texture(), as LearnOpenGL reads it: texelFetch cost llvmpipe more.
  return c.z <= texture(uShadowMap, uv).r ? 1.0 : 0.0;
#else
  return texture(uShadowMap, vec3(uv, c.z));
#endif
}

#if PCF_LOOKUP == PCF_LOOKUP_GATHER
// textureGather with a reference: the compares of the 2 x 2 texels from `first` (texel
// coordinates), as (first + (0,1), + (1,1), + (1,0), + (0,0)). One lookup.
vec4 gatherBlock(vec2 first, float z) {
  gTaps++;
  return textureGather(uShadowMap, (first + 1.0) * uTexel, z);
}

// The compare of texel (i, j), each 0 or 1, of a gathered block.
float blockTexel(vec4 g, int i, int j) {
  return j == 0 ? (i == 0 ? g.w : g.z) : (i == 0 ? g.x : g.y);
}

// The taps of block (bx, by) inside the n x n grid: an odd side's last blocks are half in.
float blockSum(vec4 g, int bx, int by, int n) {
  bool x1 = 2 * bx + 1 < n, y1 = 2 * by + 1 < n;
  return blockTexel(g, 0, 0) + (x1 ? blockTexel(g, 1, 0) : 0.0) +
         (y1 ? blockTexel(g, 0, 1) : 0.0) + (x1 && y1 ? blockTexel(g, 1, 1) : 0.0);
}

// The grid of PCF_GATHER_SIDE^2 taps on adjacent texels (pcf_math.hpp gatherGridSide), block by
// block: ceil(N/2)^2 lookups for N^2 taps. Its first texel is the first tap's, found as tap()
// finds it; the others follow one texel apart. The corner blocks come first: the early out
// decides on the same four corner taps as pcfKernel, so the picture is the compare path's.
float pcfGatherGrid(vec3 c, float radius) {
  const int n = PCF_GATHER_SIDE, m = (n + 1) / 2, last = m - 1;
  const int far = 1 - n % 2;  // the far corner's place in the last block
  PRECISE vec2 offsetTexels = kUnitTaps[0] * radius;  // the (-, -) corner
  vec2 first = floor((c.xy + offsetTexels * uTexel) * vec2(textureSize(uShadowMap, 0)));
  vec4 c00 = gatherBlock(first, c.z);
  if (m == 1) return (c00.x + c00.y + c00.z + c00.w) * 0.25;  // 2 x 2: one lookup
  vec4 c10 = gatherBlock(first + vec2(float(2 * last), 0.0), c.z);
  vec4 c01 = gatherBlock(first + vec2(0.0, float(2 * last)), c.z);
  vec4 c11 = gatherBlock(first + vec2(float(2 * last)), c.z);
  float sum = blockSum(c00, 0, 0, n) + blockSum(c10, last, 0, n) + blockSum(c01, 0, last, n) +
              blockSum(c11, last, last, n);
#if PCF_EARLY_OUT == 1
  float corners = c00.w + blockTexel(c10, far, 0) + blockTexel(c01, 0, far) +
                  blockTexel(c11, far, far);
  gStopped = corners == 0.0 || corners == 4.0;
  if (m > 2) {
    // The blocks between the corners, in a loop llvmpipe leaves once no pixel of its vector is
    // still in it (pcfKernel's early out); its start is one the compiler cannot know (always
    // 0), so that it stays a loop: unrolled, every pixel would run every turn.
    // Block k: the first and last rows' middle blocks, then the rows between, whole.
    const int edge = m - 2;
    int k = sum > float(n * n) ? 1 : 0;
    while (k < m * m - 4 && !gStopped) {
      int j = k - 2 * edge;
      int bx = k < 2 * edge ? 1 + k % edge : j % m;
      int by = k < edge ? 0 : k < 2 * edge ? last : 1 + j / m;
      sum += blockSum(gatherBlock(first + 2.0 * vec2(float(bx), float(by)), c.z), bx, by, n);
      ++k;
    }
  }
  if (gStopped) return corners * 0.25;
#else
  // Every block: unrolled, cheaper than the loop (64 taps: 68 against 85 M instructions).
  for (int by = 0; by < m; ++by) {
    for (int bx = 0; bx < m; ++bx) {
      if ((bx == 0 || bx == last) && (by == 0 || by == last)) continue;  // a corner block
      sum += blockSum(gatherBlock(first + 2.0 * vec2(float(bx), float(by)), c.z), bx, by, n);
    }
  }
#endif
  return sum / float(n * n);
}
#endif

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
#if PCF_LOOKUP == PCF_LOOKUP_GATHER
  return pcfGatherGrid(c, radius);
#elif PCF_MODE == PCF_MODE_GRID || PCF_MODE == PCF_MODE_POISSON
  return pcfKernel(c, radius);
#elif PCF_MODE == PCF_MODE_DITHERED
  return pcfDithered(c, radius);
#else
  return tap(c, vec2(0.0));  // none (nearest) or hw2x2 (the sampler is LINEAR: 4 texels, weighted)
#endif
}
#line 11 0

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform vec3 uColor;
uniform float uRadius;  // kernel half-width in texels: the one setting of the kernel not compiled
// Compiled per setting (main.cpp): VIEW (shaded, visibility, taps per fragment), SHADOW_OFF,
// and PCF_COUNT 1 that adds this fragment's work to the counters (atomics cost; compiled out
// when off).
out vec4 outColor;
#if PCF_COUNT
layout(std430, binding = 0) buffer Counters {
  uint taps;         // shadow-map lookups
  uint filtered;     // fragments that ran the filter
  uint stopped;      // ... of which stopped after the probes
  uint facing_away;  // fragments that skipped it: facing away from the light
};
#endif

float shadowTerm(vec3 n, vec3 toLight) {
  // Facing away from the light (the geometric normal, as the truth sees it): in its own
  // shadow, whatever the map says. No taps.
  if (dot(n, toLight) <= 0.0) {
#if PCF_COUNT
    atomicAdd(facing_away, 1u);
#endif
    return 0.0;
  }
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum
  vec3 p = c.xyz / c.w;
  p.z = min(p.z, 1.0);  // beyond the far plane: every depth format clamps B to 1
#if PCF_KERNEL
  float shade = percentageCloser(p, uRadius);
#else
  // pcf.radius=0 with taps of 0 or 1: each tap reads this texel, their average its answer.
  float shade = tap(p, vec2(0.0));
#endif
#if PCF_COUNT
  atomicAdd(taps, uint(gTaps));
  atomicAdd(filtered, 1u);
  if (gStopped) atomicAdd(stopped, 1u);
#endif
  return shade;
}

void main() {
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  // The facing test asks only the sign of N.L: the geometric normal (facing the eye) and the
  // way to the light need no normalize.
  float shade = shadowTerm(cross(dFdx(vWorld), dFdy(vWorld)), towardLight(vWorld));
#endif
#if VIEW == VIEW_SHADED
  {
    outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), shade), 1.0);
  }
#elif VIEW == VIEW_VISIBILITY
  {
    outColor = vec4(vec3(shade), 1.0);
  }
#else
  {
    // Taps per fragment: black 0, blue 4, through green, to red at 64.
    float t = clamp(log2(float(gTaps) + 1.0) / log2(65.0), 0.0, 1.0);
    vec3 heat = t < 0.5 ? mix(vec3(0.0, 0.1, 0.8), vec3(0.1, 0.8, 0.2), 2.0 * t)
                        : mix(vec3(0.1, 0.8, 0.2), vec3(0.95, 0.1, 0.05), 2.0 * t - 1.0);
    outColor = vec4(gTaps == 0 ? vec3(0.0) : heat * (0.5 + 0.5 * shade), 1.0);
  }
#endif
}
