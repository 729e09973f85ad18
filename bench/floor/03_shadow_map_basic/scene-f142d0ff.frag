#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_LIGHT_VIEW 2
#define VIEW_LIGHT_DEPTH 3
#define VIEW_PROJECTED_DEPTH 4
#define VIEW_LIGHT_DISTANCE 5
#define VIEW_COMPARE 6
#define VIEW_ALIASING 7
#define VIEW_TRUTH 8
#define VIEW_ERROR 9
#define VIEW VIEW_SHADED
#define SHADOW_OFF 0
#line 2 0
// Pass 2: compare the fragment's light depth B = r/q with the map's A at (s/q, t/q).
// sampler2DShadow does the compare in hardware: 1 where B <= A (lit), 0 where B > A.
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
#line 5 0
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
#line 6 0

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform sampler2DShadow uShadowMap;  // compare mode on
uniform sampler2D uShadowDepth;      // the same texture, read raw for the debug views
uniform vec3 uColor;
// Compiled per view (VIEW, from main.cpp) and SHADOW_OFF, so the shaded frame runs only the
// shading: VIEW_PROJECTED_DEPTH shows A, VIEW_LIGHT_DISTANCE B, VIEW_COMPARE both.
uniform float uLightNear;
uniform float uLightFar;
uniform int uLightPerspective;
out vec4 outColor;

float shadowTerm() {
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum, the map says nothing
  // Beyond the far plane: clamp B to 1 so every depth format behaves alike (16/24-bit clamp).
  c.z = min(c.z, c.w);
  if (outsideTexture(c.xy / c.w, vec2(textureSize(uShadowMap, 0)))) return 1.0;  // the border
  return textureProj(uShadowMap, c);
}

// Window depth to 0..1 distance between near and far, so a perspective map is not all white.
float toDistance(float depth) {
  if (uLightPerspective == 0) return depth;
  float z = 2.0 * depth - 1.0;
  float linear = 2.0 * uLightNear * uLightFar / (uLightFar + uLightNear - z * (uLightFar - uLightNear));
  return (linear - uLightNear) / (uLightFar - uLightNear);
}

void main() {
  vec3 n = normalize(vNormal);
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  float shade = shadowTerm();
#endif
#if VIEW == VIEW_SHADED || VIEW == VIEW_LIGHT_VIEW
  outColor = vec4(shadeSurface(uColor, vWorld, n, shade), 1.0);
#elif VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#else
  vec3 c = vShadowCoord.xyz / max(vShadowCoord.w, 1e-6);
  bool inside = vShadowCoord.w > 0.0 && all(greaterThanEqual(c.xy, vec2(0.0))) &&
                all(lessThanEqual(c.xy, vec2(1.0)));
  float a = toDistance(texture(uShadowDepth, c.xy).r);
  float b = toDistance(clamp(c.z, 0.0, 1.0));
  if (!inside) {
    outColor = vec4(vec3(0.25), 1.0);
  } else {
#if VIEW == VIEW_PROJECTED_DEPTH
    outColor = vec4(vec3(a), 1.0);
#elif VIEW == VIEW_LIGHT_DISTANCE
    outColor = vec4(vec3(b), 1.0);
#else
    // Kilgard's comparison: green where A and B agree (lit), the plain surface where B > A.
    float lit = shade;
    vec3 plain = shadeSurface(uColor, vWorld, n, 0.0);
    outColor = vec4(mix(plain, vec3(0.1, 0.9, 0.2) * (0.3 + 0.7 * max(dot(n, directionToLight(vWorld)), 0.0)), lit), 1.0);
#endif
  }
#endif
}
