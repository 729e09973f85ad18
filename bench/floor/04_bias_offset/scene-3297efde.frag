#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define BIAS_MODE_NONE 0
#define BIAS_MODE_CONSTANT_ONLY 1
#define BIAS_MODE_POLYGON_OFFSET 2
#define BIAS_MODE_CLIP_TRANSLATE 3
#define BIAS_MODE_GRADIENT 4
#define BIAS_MODE_BACK_FACES 5
#define BIAS_MODE_NORMAL_OFFSET 6
#define BIAS_MODE BIAS_MODE_BACK_FACES
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_BIAS_MARGIN 2
#define VIEW_LIGHT_DEPTH 3
#define VIEW_ALIASING 4
#define VIEW_TRUTH 5
#define VIEW_ERROR 6
#define VIEW VIEW_SHADED
#define SHADOW_OFF 0
#line 2 0
// Pass 2: compare the fragment's light depth B with the map's A, with the receiver's share of
// the bias (seed 002's gradient, or normal offset); the other modes biased A in pass 1.
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
// The receiver's half of the biases of lesson 04 (lesson 05 includes it too). The window-space
// offsets (glPolygonOffset, back faces, the clip-space translate) live in pass 1 instead.
uniform mat4 uShadowMatrix;  // B * P_light * V_light: world to (s, t, r, q)
uniform mat4 uLightView;     // V_light, for the point's distance along the light's axis
uniform vec2 uTexelWorld;    // world size of one map texel at light distance d: x * d + y
uniform vec3 uLightAxis;     // unit, the light's view axis pointing away from it (light-space z)

// The geometric normal of the triangle, facing the eye: the same normal the truth uses.
vec3 geometricNormal(vec3 p) { return normalize(cross(dFdx(p), dFdy(p))); }

// Normal offset (beyond the seeds): look the map up from a point lifted off the surface along
// its normal. A texel of world size h spans depths h/2 * tan(theta) either side of its centre
// (theta between N and L); a point lifted by delta lies delta / cos(theta) in front of the
// surface along the light ray, so delta >= h/2 * sin(theta) clears the texel. `texels` scales h.
vec3 normalOffsetPoint(vec3 p, vec3 n, vec3 toLight, float texels) {
  float d = max(-(uLightView * vec4(p, 1.0)).z, 0.0);
  float h = uTexelWorld.x * d + uTexelWorld.y;
  float cos_theta = clamp(dot(n, toLight), -1.0, 1.0);
  float sin_theta = sqrt(1.0 - cos_theta * cos_theta);
  return p + n * (texels * h * sin_theta);
}

// Seed 002: how much window depth a step of `distance` world units along the light's z axis
// is at p (d u3 / d X3 times the distance): a constant in light space, not in the depth buffer.
float lightSpaceDepthStep(vec3 p, float distance) {
  vec4 a = uShadowMatrix * vec4(p, 1.0);
  vec4 b = uShadowMatrix * vec4(p + uLightAxis * distance, 1.0);
  return b.z / b.w - a.z / a.w;
}

// The stored depth at uv, 1 ("nothing in front") outside the map (border.glsl).
float storedDepth(sampler2D depthMap, vec2 uv) {
  return outsideTexture(uv, vec2(textureSize(depthMap, 0))) ? 1.0 : texture(depthMap, uv).r;
}

// Seed 002 (Ogre): the stored depth A plus a bias from the map itself: the depth gradient over
// the neighbouring texels (clamped, since across a silhouette it jumps to another surface)
// times `scale`. Returns A + that; scene.frag adds the constant, expressed in light space
// (lightSpaceDepthStep), where bias.units is not 0.
float gradientBiasedDepth(sampler2D depthMap, vec2 uv, vec3 p, float scale, float clampDistance) {
  vec2 texel = 1.0 / vec2(textureSize(depthMap, 0));
  float centre = storedDepth(depthMap, uv);
  vec4 depths = vec4(storedDepth(depthMap, uv - vec2(texel.x, 0.0)),
                     storedDepth(depthMap, uv + vec2(texel.x, 0.0)),
                     storedDepth(depthMap, uv - vec2(0.0, texel.y)),
                     storedDepth(depthMap, uv + vec2(0.0, texel.y)));
  vec2 differences = abs(depths.yw - depths.xz);
  float gradient = min(lightSpaceDepthStep(p, clampDistance), max(differences.x, differences.y));
  return centre + gradient * scale;
}
#line 7 0

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;  // B * P_light * V_light * world, per vertex (shadow_coord.vert)
uniform sampler2DShadow uShadowMap;  // compare mode on: 1 where B <= A
uniform sampler2D uShadowDepth;      // the same texture read raw, for the gradient and the views
uniform vec3 uColor;
// Compiled per BIAS_MODE, VIEW and SHADOW_OFF (main.cpp), so a frame runs only its own bias
// and view. Only gradient (002) and normal offset bias the receiver here; the other modes
// biased the map in pass 1.
uniform float uFactor;     // bias.factor: gradient scale, or normal offset in texels
uniform float uUnits;      // bias.units: the gradient's light-space constant (world units)
uniform float uClamp;      // bias.clamp: the gradient's clamp (world units along the light z)
uniform float uDepthStep;  // one step of the map's depth format (the "units" of glPolygonOffset)
out vec4 outColor;

// The shadow term and the margin A - B the compare saw (negative: shadowed).
float shadowTerm(vec3 n, out float margin) {
  vec3 p = vWorld;
#if BIAS_MODE == BIAS_MODE_NORMAL_OFFSET
  // Normal offset moves the point before projecting it: only this mode projects per fragment.
#if NORMAL_OFFSET
  p = normalOffsetPoint(p, n, directionToLight(vWorld), uFactor);
#endif
  vec4 c = uShadowMatrix * vec4(p, 1.0);  // bias.factor=0: vWorld, projected all the same
#else
  vec4 c = vShadowCoord;  // projected per vertex and interpolated, as in lesson 03
#endif
  margin = 1.0;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum
  c.xyz /= c.w;
  c.z = min(c.z, 1.0);  // beyond the far plane: every depth format clamps B to 1
#if BIAS_MODE == BIAS_MODE_GRADIENT
#if GRADIENT_TERM
  float a = gradientBiasedDepth(uShadowDepth, c.xy, p, uFactor, uClamp);
#else  // bias.factor or bias.clamp 0: no slope term, so no neighbours read
  float a = storedDepth(uShadowDepth, c.xy);
#endif
#if CONSTANT_TERM
  a += lightSpaceDepthStep(p, uUnits);  // bias.units=0: a step of 0, not computed
#endif
  margin = a - c.z;
  return c.z <= a ? 1.0 : 0.0;
#else
  if (outsideTexture(c.xy, vec2(textureSize(uShadowMap, 0)))) {  // the border: depth 1
    margin = 1.0 - c.z;
    return 1.0;
  }
#if VIEW == VIEW_BIAS_MARGIN
  margin = texture(uShadowDepth, c.xy).r - c.z;
#endif
  return texture(uShadowMap, c.xyz);
#endif
}

void main() {
  vec3 n = geometricNormal(vWorld);
  float margin = 0.0;
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  float shade = shadowTerm(n, margin);
#endif
#if VIEW == VIEW_SHADED
  outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), shade), 1.0);
#elif VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#else
  {
    // The margin in depth steps, one brightness band per decade: green lit with room to
    // spare, red where B > A (acne on a lit surface, true shadow elsewhere).
    float decades = clamp(log2(abs(margin) / uDepthStep + 1.0) / log2(10.0) / 7.0, 0.0, 1.0);
    vec3 tone = margin >= 0.0 ? vec3(0.1, 0.9, 0.2) : vec3(0.95, 0.1, 0.1);
    float facing = max(dot(n, directionToLight(vWorld)), 0.0);
    outColor = vec4(tone * (0.15 + 0.85 * decades) * (0.4 + 0.6 * facing), 1.0);
  }
#endif
}
