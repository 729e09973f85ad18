#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_OVERDRAW 2
#define VIEW_TRUTH 3
#define VIEW_ERROR 4
#define VIEW VIEW_SHADED
#line 2 0
// Every surface fully lit (shade = 1). Planar shadows are not looked up here: they are
// blended onto the receiver afterwards, as dark copies of the casters.
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
  return albedo * (0.12 + 0.88 * nl) + vec3(0.35) * spec * shade;
}
#line 5 0

in vec3 vWorld;
in vec3 vNormal;
uniform vec3 uColor;
out vec4 outColor;

// VIEW is a variant (issue 56): llvmpipe would run every view's branch on a uniform.
void main() {
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(1.0);  // white until a shadow darkens it
#else
  vec3 lit = shadeSurface(uColor, vWorld, normalize(vNormal), 1.0);
#if VIEW == VIEW_OVERDRAW
  lit *= 0.3;  // dim, so layers stand out
#endif
  outColor = vec4(lit, 1.0);
#endif
}
