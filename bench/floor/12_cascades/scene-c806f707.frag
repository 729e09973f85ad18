#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_CASCADES 2
#define VIEW_MAPS 3
#define VIEW_TEXEL_GRID 4
#define VIEW_TRUTH 5
#define VIEW_ERROR 6
#define VIEW VIEW_SHADED
#define SHADOW_OFF 0
#define KEPT_CASCADES 0
#define CASCADE_BLEND 1
#define NORMAL_OFFSET 1
#line 2 0
// Pass 2 from the eye, with cascades: the fragment's depth along the eye's view picks the
// slice, and the slice's map answers as lesson 03's does:
//   i = the first cascade with  depth <= split_far[i]
//   s = B * P_i * V_sun * (p + n * bias.normal * texel_i)     (its tile of the atlas)
//   shade = s.z - bias.depth * texel_i / depth_range_i  <=  map_i(s.xy)
// In the last `blend` share of a slice the next cascade's answer is mixed in, so the seam
// where the texels change size does not show as a line.
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

#define MAX_CASCADES 4
in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;  // unused: shadow_coord.vert's one-map lookup
uniform sampler2DShadow uAtlas;  // every cascade's tile; compare mode on (a sampler object)
uniform int uCount;              // cascades in use (0: shadow.off)
uniform mat4 uCascadeView;       // the eye whose slices the cascades are (shimmer: a step's)
uniform mat4 uCascade[MAX_CASCADES];     // world to the cascade's clip space (orthographic)
uniform vec2 uTileOffset[MAX_CASCADES];  // the tile's corner in the atlas
uniform vec4 uTile[MAX_CASCADES];        // the tile less half a texel each side (a clamp)
uniform float uTexelWorld[MAX_CASCADES]; // a texel's side in world units
uniform float uDepthRange[MAX_CASCADES]; // world units from the map's near to its far
uniform float uSplitNear[MAX_CASCADES];
uniform float uSplitFar[MAX_CASCADES];
uniform vec3 uCascadeColor[MAX_CASCADES];
uniform vec2 uTileScale;
uniform float uSize;        // texels along a cascade's side
uniform float uBiasNormal;  // texels of the cascade
uniform float uBiasDepth;   // texels of the cascade
uniform float uBlend;       // share of a slice blended with the next
uniform vec3 uColor;
out vec4 outColor;

// Where cascade i sees the point (x, y in [0, 1] inside its box; z its depth there).
vec3 cascadeCoord(int i, vec3 p) {
  return 0.5 * (uCascade[i] * vec4(p, 1.0)).xyz + 0.5;
}

float lookup(int i, vec3 n) {
#if NORMAL_OFFSET
  // Toward the sun's side of the surface, by a texel of this cascade.
  float side = dot(n, uLightDir) > 0.0 ? -1.0 : 1.0;
  vec3 s = cascadeCoord(i, vWorld + side * n * uBiasNormal * uTexelWorld[i]);
#else
  vec3 s = cascadeCoord(i, vWorld);  // bias.normal=0: the same point
#endif
  // Outside its box (a kept cascade's box the eye has moved past, or a slice's corner past the
  // box's float edge): no answer here, the caller asks the next cascade.
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return -1.0;
  vec2 uv = clamp(uTileOffset[i] + s.xy * uTileScale, uTile[i].xy, uTile[i].zw);
  float reference = s.z - uBiasDepth * uTexelWorld[i] / uDepthRange[i];
  return texture(uAtlas, vec3(uv, reference));
}

float viewDepth() {
  return -(uCascadeView * vec4(vWorld, 1.0)).z;
}

// The cascade a depth falls in, or uCount beyond the shadow distance.
int cascadeOf(float depth) {
  for (int i = 0; i < MAX_CASCADES; ++i) {
    if (i < uCount && depth <= uSplitFar[i]) return i;
  }
  return uCount;
}

// Cascade i's answer, or (outside its box) the next one's; -1: neither box holds the point.
float lookupOrNext(int i, vec3 n) {
  float shade = lookup(i, n);
#if KEPT_CASCADES
  // llvmpipe pays for this lookup on every fragment (34 M of 66 M instructions a frame): only
  // frames with a kept cascade (cascades.update > 1) have it.
  if (shade < 0.0 && i + 1 < uCount) shade = lookup(i + 1, n);
#endif
  return shade;
}

float shadowTerm(vec3 n, int i, float depth) {
  if (i >= uCount) return 1.0;  // beyond the shadow distance: no map, no shadow
  float shade = lookupOrNext(i, n);
#if CASCADE_BLEND
  // llvmpipe runs this block for every fragment even where no depth is past `start` (30 M of
  // 102 M a frame): at cascades.blend=0, or with one cascade, it is not compiled.
  float start = uSplitFar[i] - uBlend * (uSplitFar[i] - uSplitNear[i]);
  if (i + 1 < uCount && depth > start && shade >= 0.0) {
    float next = lookupOrNext(i + 1, n);
    if (next >= 0.0) {
      shade = mix(shade, next, (depth - start) / max(uSplitFar[i] - start, 1e-6));
    }
  }
#endif
  return shade < 0.0 ? 1.0 : shade;  // in no box at all: unshadowed, not guessed
}

void main() {
  vec3 n = normalize(vNormal);
  float depth = viewDepth();
  int cascade = cascadeOf(depth);
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  float shade = shadowTerm(n, cascade, depth);
#endif
#if VIEW == VIEW_SHADED
  outColor = vec4(shadeSurface(uColor, vWorld, n, shade), 1.0);
#elif VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#elif VIEW == VIEW_CASCADES
  // Each slice its colour, dimmed in shadow; grey beyond the shadow distance.
  vec3 c = cascade < uCount ? uCascadeColor[cascade] : vec3(0.5);
  outColor = vec4(c * (0.35 + 0.65 * shade), 1.0);
#elif VIEW == VIEW_TEXEL_GRID
  // Every map texel a square of the checkerboard, in its cascade's colour: snapped boxes keep
  // the squares still on the ground as the eye moves; free ones make them slide.
  vec3 c = vec3(0.5);
  if (cascade < uCount) {
    vec2 t = cascadeCoord(cascade, vWorld).xy * uSize;
    float odd = mod(floor(t.x) + floor(t.y), 2.0);
    // Where a pixel spans a texel or more the squares cannot be drawn: their average, not a
    // moiré (texels a pixel from the screen-space derivatives).
    float texels = max(length(dFdx(t)), length(dFdy(t)));
    odd = mix(odd, 0.5, clamp(2.0 * texels - 1.0, 0.0, 1.0));
    c = uCascadeColor[cascade] * (0.55 + 0.45 * odd);
  }
  outColor = vec4(c * (0.4 + 0.6 * shade), 1.0);
#else  // VIEW_SHIMMER (never offered), read back as bytes: the state, inside the cascades,
       // the cascade's texels per pixel, facing the sun. Texels per pixel as log2 over
       // [-16, 16] in 15 bits: the high 8 in blue, the low 7 in alpha beside the sunlit bit
       // (cascade_math.hpp, texelLevelOf, mirrors it).
  float sunlit = dot(n, -uLightDir) > 0.0 ? 1.0 : 0.0;
  float texels = 1.0;
  if (cascade < uCount) {
    vec2 t = cascadeCoord(cascade, vWorld).xy * uSize;
    texels = max(length(dFdx(t)), length(dFdy(t)));
  }
  float level = floor(clamp((log2(max(texels, 1e-6)) + 16.0) / 32.0, 0.0, 1.0) * 32767.0 + 0.5);
  float high = floor(level / 128.0);
  outColor = vec4(shade >= 0.5 ? 1.0 : 0.0, cascade < uCount ? float(cascade + 1) / 255.0 : 0.0,
                  high / 255.0, (128.0 * sunlit + level - 128.0 * high) / 255.0);
#endif
}
