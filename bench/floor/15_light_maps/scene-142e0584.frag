#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define LIGHTMAP_MODE_BAKED 0
#define LIGHTMAP_MODE_HYBRID 1
#define LIGHTMAP_MODE_MAP 2
#define LIGHTMAP_MODE LIGHTMAP_MODE_BAKED
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_ATLAS 2
#define VIEW_TEXEL_GRID 3
#define VIEW_NOISE 4
#define VIEW_LIGHT_DEPTH 5
#define VIEW_TRUTH 6
#define VIEW_ERROR 7
#define VIEW VIEW_SHADED
#define SHADOW_OFF 0
#line 2 0
// The frame: the shadow is a texture lookup. The light map holds, per texel, the fraction of
// the area light its surface point saw when it was baked (seed 003: "bake soft shadows in
// light maps ... sample area light sources"); what it cost was paid once, before the first
// frame.
//   LIGHTMAP_MODE_BAKED:  the light map alone;
//   LIGHTMAP_MODE_HYBRID: the light map of the static casters times lesson 03's map of the one
//                         that moves (the moving object itself takes the map alone);
//   LIGHTMAP_MODE_MAP:    lesson 03's map for everything, the comparison.
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
#line 11 0
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
#line 12 0

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
in vec2 vLightMapUv;
uniform vec3 uColor;
uniform sampler2D uLightMap;         // R16F, its filter bilinear or nearest (lightmap.filter)
uniform sampler2DShadow uShadowMap;  // lesson 03's map (compare on)
uniform int uObject;
uniform int uMovingObject;
uniform float uSamples;  // samples a texel, for the noise view
out vec4 outColor;

float baked() {
  if (vLightMapUv.x < 0.0) return 1.0;  // an object without a chart: nothing baked
  return texture(uLightMap, vLightMapUv).r;
}

float mapped() {
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;
  c.z = min(c.z, c.w);
  if (outsideTexture(c.xy / c.w, vec2(textureSize(uShadowMap, 0)))) return 1.0;
  return textureProj(uShadowMap, c);
}

float shadowTerm() {
#if SHADOW_OFF
  return 1.0;  // shadow.off: the baseline, no lookup
#elif LIGHTMAP_MODE == LIGHTMAP_MODE_BAKED
  return baked();
#elif LIGHTMAP_MODE == LIGHTMAP_MODE_HYBRID
  return uObject == uMovingObject ? mapped() : baked() * mapped();
#else
  return mapped();
#endif
}

void main() {
  vec3 n = normalize(vNormal);
  float shade = shadowTerm();
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#elif VIEW == VIEW_TEXEL_GRID
  // The texel grid on the scene: where one light map texel ends and the next begins (texel
  // edges at whole texel coordinates; a chart's border runs through its outer texels' centres).
  vec2 texel = vLightMapUv * vec2(textureSize(uLightMap, 0));
  vec2 edge = abs(fract(texel + 0.5) - 0.5) / max(fwidth(texel), vec2(1e-6));
  float line = vLightMapUv.x < 0.0 ? 0.0 : 1.0 - clamp(min(edge.x, edge.y), 0.0, 1.0);
  vec3 lit = shadeSurface(uColor, vWorld, n, shade);
  outColor = vec4(mix(lit, vec3(1.0, 0.85, 0.2), 0.8 * line), 1.0);
#elif VIEW == VIEW_NOISE
  // What n samples a texel leave uncertain: the standard error of a fraction v seen with n
  // independent samples, sqrt(v (1 - v) / n) (stratified samples do better): red at 0.1.
  float v = baked();
  float error = sqrt(max(v * (1.0 - v), 0.0) / max(uSamples, 1.0));
  outColor = vec4(mix(shadeSurface(vec3(0.5), vWorld, n, 1.0) * 0.6, vec3(1.0, 0.1, 0.05),
                      clamp(error / 0.1, 0.0, 1.0)), 1.0);
#else
  outColor = vec4(shadeSurface(uColor, vWorld, n, shade), 1.0);
#endif
}
