#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_ALIASING 2
#define VIEW_LIGHT_VIEW 3
#define VIEW_REGIONS 4
#define VIEW_TRUTH 5
#define VIEW_ERROR 6
#define VIEW VIEW_SHADED
#define DEPTH_REPLACE 1
#define SHADOW_OFF 0
#line 2 0
// Pass 2: the map lookup through the chosen projection, and the lesson's views.
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
#line 4 0
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
#line 5 0

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform sampler2DShadow uShadowMap;
uniform vec3 uColor;
uniform vec4 uDepthPlane;  // the light's linear depth (DEPTH_REPLACE)
// Region I (seed 002): on a ray from the light to a point of the plane of interest in view.
uniform vec4 uLight;  // position (w 1) or direction towards the light (w 0)
uniform vec4 uPlane;  // n . p + d = 0, n towards the lit, seen side
uniform int uHasPlane;
uniform int uObject;
uniform int uPlaneObject;
uniform mat4 uPlaneInverse;  // world to the plane object's own space
uniform vec2 uPlaneHalf;
uniform mat4 uCamera;
out vec4 outColor;

float shadowTerm() {
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;  // behind the projection's centre: the map says nothing
  vec2 uv = c.xy / c.w;
  if (outsideTexture(uv, vec2(textureSize(uShadowMap, 0)))) return 1.0;
#if DEPTH_REPLACE
  float depth = clamp(dot(uDepthPlane.xyz, vWorld) + uDepthPlane.w, 0.0, 1.0);
  return texture(uShadowMap, vec3(uv, depth));
#else
  c.z = min(c.z, c.w);  // beyond the far plane: as lessons 03-08
  return textureProj(uShadowMap, c);
#endif
}

// The same test as inRegionOne() in common/math/warped_projection.cpp.
bool inRegionOne(vec3 p) {
  vec3 dir = uLight.w == 0.0 ? -uLight.xyz : p - uLight.xyz;
  float denom = dot(uPlane.xyz, dir);
  if (abs(denom) < 1e-8) return false;
  float s = -(dot(uPlane.xyz, p) + uPlane.w) / denom;
  if (s < -1e-4) return false;
  vec3 q = p + s * dir;
  vec3 local = (uPlaneInverse * vec4(q, 1.0)).xyz;
  if (abs(local.x) > uPlaneHalf.x || abs(local.z) > uPlaneHalf.y) return false;
  vec4 c = uCamera * vec4(q, 1.0);
  return c.w > 0.0 && abs(c.x) <= c.w && abs(c.y) <= c.w;
}

void main() {
  vec3 n = normalize(vNormal);
#if SHADOW_OFF
  float shade = 1.0;
#else
  float shade = shadowTerm();
#endif
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#elif VIEW == VIEW_REGIONS
  // The plane of interest blue, region I green, region II red, over the shaded picture.
  vec3 shaded = shadeSurface(uColor, vWorld, n, shade);
  vec3 tint = vec3(0.5);
  if (uHasPlane == 1) {
    if (uObject == uPlaneObject) {
      tint = vec3(0.2, 0.45, 1.0);
    } else {
      tint = inRegionOne(vWorld) ? vec3(0.2, 0.9, 0.3) : vec3(1.0, 0.2, 0.15);
    }
  }
  outColor = vec4(mix(shaded, tint, 0.45), 1.0);
#else
  outColor = vec4(shadeSurface(uColor, vWorld, n, shade), 1.0);
#endif
}
