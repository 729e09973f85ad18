#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_TEXCOORDS 2
#define VIEW_SLIDE 3
#define VIEW_TRUTH 4
#define VIEW_ERROR 5
#define VIEW VIEW_SHADED
#define PASS 1
#define SPOT_FALLOFF 0
#line 2 0
// The slide projector (seed 004 "Projective texturing pixel shader"): the colour at
// (s/q, t/q), fetched by textureProj, lights the surface like a coloured spotlight.
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
#line 1 3
// The fragment side of clip_plane_out.glsl: nothing where the GL clips; on OpenGL ES the
// fragments on the negative side of the plane are discarded.
#if !HAS_CLIP_DISTANCE
in float vClipDistance;
#endif
void clipFragment() {
#if !HAS_CLIP_DISTANCE
  if (vClipDistance < 0.0) discard;
#endif
}
#line 7 0
#line 1 4
// Seed 000's first back-projection fix: a spotlight term with the proper cut-off, 0 behind the
// projector because the angle to its axis is over 90 degrees there. Written once in the subset
// GLSL and C++ share: projector.frag includes this file, and so does spot_math.hpp, which the
// tests check against the formula at hand-worked points.
//
// `d` runs from the projector to the surface point, `axis` is where it points (unit length).
// A spot fades from 1 at `halfAngle * (1 - falloff)` off its axis to 0 at `halfAngle`
// (smoothstep on the cosine); a parallel projector from 1 at `(1 - falloff) * extent` from its
// axis to 0 at `extent`, and gives 0 behind it. falloff 0 is off: 1 everywhere.
float spotFalloff(vec3 d, vec3 axis, int directional, float falloff, float halfAngle,
                  float extent) {
  if (falloff <= 0.0f) return 1.0f;
  float along = dot(d, axis);
  if (directional == 1) {
    if (along <= 0.0f) return 0.0f;
    float radial = length(d - along * axis) / extent;
    return 1.0f - smoothstep(1.0f - falloff, 1.0f, radial);
  }
  float cos_angle = along / max(length(d), 1e-6f);
  return smoothstep(cos(halfAngle), cos(halfAngle * (1.0f - falloff)), cos_angle);
}
#line 8 0

in vec3 vWorld;
in vec3 vNormal;
in vec4 vSlideCoord;
uniform sampler2D uSlide;  // border black: no light outside the slide
uniform vec3 uColor;
// VIEW (shaded, visibility, texcoords) and PASS (0 ambient light on everything, 1 the
// projector's light, added) are variants: llvmpipe would run a uniform's both branches.
uniform int uQTest;         // 1: q <= 0 means behind the projector: no light
uniform float uFalloff;     // 0 off; else the spotlight fades over this part of the cone
uniform float uHalfAngle;   // the cone: half the projector's field of view, radians
uniform float uExtent;      // a parallel projector: the half width of its beam
uniform vec3 uAxis;         // where the projector points
out vec4 outColor;

// The spotlight term of seed 000's first back-projection fix (spot.glsl). At falloff 0 it is
// 1 everywhere (spotFalloff's first line), and left out (SPOT_FALLOFF 0, issue 56).
float spot() {
#if SPOT_FALLOFF
  return spotFalloff(vWorld - uLightPos, uAxis, uLightDirectional, uFalloff, uHalfAngle, uExtent);
#else
  return 1.0;
#endif
}

// Where the projector's light lands at all (the shadow term of this lesson: 1 or 0).
bool reaches() {
  vec4 c = vSlideCoord;
  if (uQTest == 1 && c.q <= 0.0) return false;  // behind: (s/q, t/q) would mirror the slide
  if (abs(c.q) < 1e-6) return false;             // in the projector's own plane
  vec2 st = c.st / c.q;
  return all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0))) &&
         spot() > 0.0;
}

void main() {
  clipFragment();
  vec3 n = normalize(vNormal);
#if VIEW == VIEW_TEXCOORDS  // (s/q, t/q) as red/green, blue where q < 0 (no fix applied)
  vec2 st = vSlideCoord.st / vSlideCoord.q;
  bool inside = all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0)));
  vec3 base = uColor * (0.1 + 0.2 * max(dot(n, vec3(0.0, 1.0, 0.0)), 0.0));
  outColor = vec4(inside ? vec3(st, vSlideCoord.q < 0.0 ? 1.0 : 0.0) : base, 1.0);
#elif PASS == 0
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(0.0), 1.0);
#else
  outColor = vec4(0.15 * uColor, 1.0);
#endif
#else
  if (!reaches()) discard;
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(1.0);
#else
  float nl = max(dot(n, directionToLight(vWorld)), 0.0);
  vec2 st = vSlideCoord.st / vSlideCoord.q;
  vec3 slide = withBorder(textureProj(uSlide, vSlideCoord), st, vec2(textureSize(uSlide, 0)),
                          vec4(0.0, 0.0, 0.0, 1.0), true).rgb;  // at (s/q, t/q), border black
  outColor = vec4(uColor * 0.85 * nl * slide * spot(), 1.0);
#endif
#endif
}
