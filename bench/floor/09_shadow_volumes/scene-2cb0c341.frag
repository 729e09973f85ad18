#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_VOLUMES 2
#define VIEW_COUNT 3
#define VIEW_OVERVIEW 4
#define VIEW_TRUTH 5
#define VIEW_ERROR 6
#define VIEW VIEW_SHADED
#define PASS_DIM 0
#define PASS_LIGHT 1
#define PASS_FULL 2
#define PASS PASS_LIGHT
#line 2 0
// Pass 1 (PASS_DIM): the scene with the light dimmed, which also fills the depth buffer.
// Pass 3 (PASS_LIGHT): what the light adds, blended additively where the count is 0 (seed 002,
// "additive light masking"). PASS_FULL: pass 1 of combine=modulative, fully lit; the shadow is
// then darkened over it, specular highlight included.
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
#line 7 0

in vec3 vWorld;
in vec3 vNormal;
uniform vec3 uColor;
out vec4 outColor;

void main() {
  vec3 n = normalize(vNormal);
#if VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(PASS == PASS_DIM ? 0.0 : 1.0), 1.0);  // the shadow term alone
#elif PASS == PASS_DIM
  outColor = vec4(shadeSurface(uColor, vWorld, n, 0.0), 1.0);
#elif PASS == PASS_LIGHT
  outColor = vec4(shadeSurface(uColor, vWorld, n, 1.0) - shadeSurface(uColor, vWorld, n, 0.0), 1.0);
#else
  outColor = vec4(shadeSurface(uColor, vWorld, n, 1.0), 1.0);
#endif
}
