#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define SHADOW_OFF 0
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_AIR 2
#define VIEW_SURFACES 3
#define VIEW_SPOT 4
#define VIEW_LIGHT_DEPTH 5
#define VIEW_ALIASING 6
#define VIEW_TRUTH 7
#define VIEW_ERROR 8
#define VIEW VIEW_SHADED
#line 2 0
// Step 2 of the slide, "draw the scene with the shadow map", lit by the projected spotlight.
#line 1 1
// Seed 000, "Combine with Projective Texturing for Spotlight Shadows": the spotlight is a
// texture projected through the light's frustum, modulated by the projected shadow map.
// Each at its own B * P * V_light * p (the spot's frustum is the lit cone; the map's may be
// fitted to the casters); surfaces and air slices look up the same two.
#line 1 2
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
#line 6 1
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
#line 4 0
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
