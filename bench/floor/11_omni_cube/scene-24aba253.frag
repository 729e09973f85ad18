#version 330 core
#define SHADOWS_GLES 0
#define HAS_TEXTURE_1D 1
#define HAS_BORDER_CLAMP 1
#define HAS_CLIP_DISTANCE 1
#define HAS_EARLY_FRAGMENT_TESTS 1
#define HAS_STORAGE_BUFFERS 1
#define OMNI_METHOD_CUBE 0
#define OMNI_METHOD_PARABOLOID 1
#define OMNI_METHOD_TETRAHEDRON 2
#define OMNI_METHOD OMNI_METHOD_CUBE
#define CUBE_STORE_DISTANCE 0
#define CUBE_STORE_DEPTH 1
#define CUBE_STORE CUBE_STORE_DISTANCE
#define VIEW_SHADED 0
#define VIEW_VISIBILITY 1
#define VIEW_CUBE_CROSS 2
#define VIEW_FACE 3
#define VIEW_FACE_TEXELS 4
#define VIEW_DISTANCE 5
#define VIEW_TRUTH 6
#define VIEW_ERROR 7
#define VIEW_TEXEL_STATS 8
#define VIEW VIEW_SHADED
#define SHADOW_OFF 0
#define NORMAL_OFFSET 1
#line 2 0
// Pass 2 from the eye: the direction from the light to the fragment picks the cube face and
// the texel (the hardware does it: samplerCubeShadow), and the reference it is compared with
// is the fragment's own value in the map's store, less the bias:
//   distance: (|p - light| - bias) / far                 against the distance written
//   depth:    majorDepth(max(|v.x|, |v.y|, |v.z|) - bias)  against the face's hardware depth
// with p moved along its normal by bias.normal texels first (a texel is 2 z / size wide).
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
#line 9 0
#line 1 2
// The cube map's arithmetic, as cube_math.hpp has it in C++ (tested there): which face a
// direction from the light reads, the distance along that face's axis, and the reference a
// fragment compares with the stored value, in either store.
uniform float uCubeNear;
uniform float uCubeFar;
uniform float uCubeSize;  // texels along a face's side

int majorFace(vec3 v) {
  vec3 a = abs(v);
  if (a.x >= a.y && a.x >= a.z) return v.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return v.y >= 0.0 ? 2 : 3;
  return v.z >= 0.0 ? 4 : 5;
}

float majorDistance(vec3 v) {
  vec3 a = abs(v);
  return max(a.x, max(a.y, a.z));
}

// faceProjection's window depth for a point z along the face's axis.
float majorDepth(float z) {
  return uCubeFar * (z - uCubeNear) / (z * (uCubeFar - uCubeNear));
}

// One texel's world size at distance z along a face's axis.
float texelWorldSize(float z) {
  return 2.0 * z / uCubeSize;
}
#line 10 0
#line 1 3
// The singular values of the 2x2 Jacobian of a pixel's map texel coordinates (the texels one
// screen pixel spans along its most and its least sampled direction), largest first, as
// singularValues() in common/math/texel_density.cpp: s1^2 + s2^2 = |J|^2, s1 s2 = |det J|.
// The runner's texel pass (texel_density.frag) and lesson 11's faces, which are no one 2D map.
vec2 singularValues(vec2 ddx, vec2 ddy) {
  float frob = dot(ddx, ddx) + dot(ddy, ddy);
  float det = abs(ddx.x * ddy.y - ddy.x * ddx.y);
  float big = sqrt(0.5 * (frob + sqrt(max(frob * frob - 4.0 * det * det, 0.0))));
  return vec2(big, big > 0.0 ? det / big : 0.0);
}
#line 11 0

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;  // unused: shadow_coord.vert's 2D lookup, not a cube's
uniform samplerCubeShadow uCube;  // compare mode on (a sampler object)
uniform sampler2DShadow uParaboloidUp;    // omni.method=paraboloid: the two hemispheres
uniform sampler2DShadow uParaboloidDown;
uniform sampler2D uParaboloidUpRaw;       // the same two, read raw for the views
uniform sampler2D uParaboloidDownRaw;
uniform samplerCube uCubeRaw;     // the same texture read raw, for the views
uniform sampler2DShadow uTetra;   // omni.method=tetrahedron: four faces' tiles in one map
uniform sampler2D uTetraRaw;
uniform mat4 uTetraFace[4];       // each face's P * V (tetra_math.hpp)
uniform vec3 uTetraDir[4];        // each face's direction
uniform float uTetraTexel;        // a tile's texel on its image plane at distance 1 (the wider side)
uniform float uBiasWorld;         // world units, along the ray (distance) or the axis (depth)
uniform float uBiasNormal;        // texels, along the normal
uniform vec3 uColor;
out vec4 outColor;

// The tetrahedron's face of v (the nearest face direction) and its texel: that face's
// projection into its tile of the 2 x 2 map, as tetra_math.hpp's mapCoord.
int tetraFace(vec3 v) {
  int best = 0;
  for (int i = 1; i < 4; ++i) {
    if (dot(v, uTetraDir[i]) > dot(v, uTetraDir[best])) best = i;
  }
  return best;
}
const int kTetraColour[4] = int[4](3, 0, 2, 4);  // faceColor's: down dark green, the others bright
vec2 tetraTile(int face) { return 0.5 * vec2(face % 2, face / 2); }
vec2 tetraCoord(vec3 v, int face) {
  vec4 c = uTetraFace[face] * vec4(uLightPos + v, 1.0);
  return tetraTile(face) + 0.25 * (c.xy / c.w + 1.0);
}

vec3 offsetPosition(vec3 n) {
#if NORMAL_OFFSET
  vec3 v = vWorld - uLightPos;
  // Toward the light's side of the surface, by a texel's size here.
  float side = dot(n, v) > 0.0 ? -1.0 : 1.0;
#if OMNI_METHOD == OMNI_METHOD_TETRAHEDRON
  // A tile's texel at v: its image plane's width over the tile, at v's distance along the face.
  float texel = uTetraTexel * dot(v, uTetraDir[tetraFace(v)]);
#else
  float texel = texelWorldSize(majorDistance(v));
#endif
  return vWorld + side * n * uBiasNormal * texel;
#else
  return vWorld;  // bias.normal=0: the same point, without the 5 M a frame of finding it
#endif
}

float reference(vec3 v) {
#if CUBE_STORE == CUBE_STORE_DISTANCE
  return (length(v) - uBiasWorld) / uCubeFar;
#else
  return majorDepth(max(majorDistance(v) - uBiasWorld, uCubeNear));
#endif
}

// The paraboloid's lookup, as paraboloid.vert maps: the hemisphere by the sign of v.y, the
// texel at (s v.x, v.z) / (|v| + s v.y), compared with the distance store's reference.
float paraboloidTerm(vec3 v) {
  float len = length(v);
  if (len >= uCubeFar) return 1.0;
  float s = v.y >= 0.0 ? 1.0 : -1.0;
  vec2 uv = 0.5 * vec2(s * v.x, v.z) / (len + s * v.y) + 0.5;
  vec3 c = vec3(uv, (len - uBiasWorld) / uCubeFar);
  return s > 0.0 ? texture(uParaboloidUp, c) : texture(uParaboloidDown, c);
}

float tetraTerm(vec3 v) {
  float len = length(v);
  if (len >= uCubeFar) return 1.0;
  return texture(uTetra, vec3(tetraCoord(v, tetraFace(v)), (len - uBiasWorld) / uCubeFar));
}

float shadowTerm(vec3 n) {
  vec3 v = offsetPosition(n) - uLightPos;
#if OMNI_METHOD == OMNI_METHOD_PARABOLOID
  return paraboloidTerm(v);
#elif OMNI_METHOD == OMNI_METHOD_TETRAHEDRON
  return tetraTerm(v);
#else
  // Beyond far nothing was stored: unshadowed, in each store's own measure of far (a float
  // depth would not clamp a reference past 1 as the fixed-point formats do).
#if CUBE_STORE == CUBE_STORE_DISTANCE
  if (length(v) >= uCubeFar) return 1.0;
#else
  if (majorDistance(v) >= uCubeFar) return 1.0;
#endif
  return texture(uCube, vec4(v, reference(v)));
#endif
}

// The texel coordinates of v on the face (or hemisphere) it reads: the face's -1 .. 1 times
// half its texels.
vec2 faceTexels(vec3 v) {
  vec3 a = abs(v);
#if OMNI_METHOD == OMNI_METHOD_PARABOLOID
  vec2 st = vec2(v.x, v.z) / (length(v) + (v.y >= 0.0 ? v.y : -v.y));
#elif OMNI_METHOD == OMNI_METHOD_TETRAHEDRON
  int tf = tetraFace(v);
  vec2 st = 4.0 * (tetraCoord(v, tf) - tetraTile(tf)) - 1.0;  // -1 .. 1 across the tile
#else
  int f = majorFace(v);
  vec2 st = f < 2 ? v.yz / a.x : (f < 4 ? v.xz / a.y : v.xy / a.z);
#endif
  return 0.5 * uCubeSize * st;
}

// Six colours, one a face, for the face view.
vec3 faceColor(int face) {
  vec3 c[6] = vec3[6](vec3(0.9, 0.3, 0.3), vec3(0.45, 0.12, 0.12), vec3(0.3, 0.85, 0.3),
                      vec3(0.12, 0.4, 0.12), vec3(0.3, 0.45, 0.95), vec3(0.12, 0.18, 0.5));
  return c[face];
}

void main() {
  vec3 n = normalize(vNormal);
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  float shade = shadowTerm(n);
#endif
#if VIEW == VIEW_SHADED
  outColor = vec4(shadeSurface(uColor, vWorld, n, shade), 1.0);
#elif VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#elif VIEW == VIEW_FACE
  // Which face each pixel read, dimmed where it is in shadow.
  vec3 v = vWorld - uLightPos;
#if OMNI_METHOD == OMNI_METHOD_PARABOLOID
  int face = v.y >= 0.0 ? 2 : 3;  // the two hemispheres, coloured as +y and -y
#elif OMNI_METHOD == OMNI_METHOD_TETRAHEDRON
  int face = kTetraColour[tetraFace(v)];
#else
  int face = majorFace(v);
#endif
  outColor = vec4(faceColor(face) * (0.35 + 0.65 * shade), 1.0);
#elif VIEW == VIEW_TEXEL_STATS
  // The runner's texel pass for a map that is no one 2D map (main.cpp reads it back): the
  // least and most texels a pixel spans on the face it reads, and whether the pixel counts
  // (seen from the front, facing the light, within its reach).
  vec3 v = vWorld - uLightPos;
  vec2 t = faceTexels(v);
  vec2 s = singularValues(dFdx(t), dFdy(t));
  bool counted = gl_FrontFacing && dot(n, -v) > 0.0 && length(v) < uCubeFar && s.y > 0.0;
  outColor = vec4(s.y, s.x, counted ? 1.0 : 0.0, 0.0);
#elif VIEW == VIEW_FACE_TEXELS
  // Map texels per pixel on the face read: how far one pixel step moves in the face's texels.
  vec2 texels = faceTexels(vWorld - uLightPos);
  float per_pixel = max(length(dFdx(texels)), length(dFdy(texels)));
  // Green near one texel a pixel, red where a texel covers many pixels (blocky), blue where
  // many texels fall on one pixel (wasted), on a log scale.
  float l = clamp(log2(max(per_pixel, 1e-4)) / 4.0, -1.0, 1.0);
  vec3 heat = l < 0.0 ? mix(vec3(0.2, 0.8, 0.3), vec3(0.9, 0.2, 0.15), -l)
                      : mix(vec3(0.2, 0.8, 0.3), vec3(0.2, 0.35, 0.95), l);
  outColor = vec4(heat * (0.45 + 0.55 * shade), 1.0);
#else  // VIEW_DISTANCE: the stored value and the fragment's own, as Kilgard shows a 2D map's
  vec3 v = vWorld - uLightPos;
#if OMNI_METHOD == OMNI_METHOD_PARABOLOID
  float s = v.y >= 0.0 ? 1.0 : -1.0;
  vec2 uv = 0.5 * vec2(s * v.x, v.z) / (length(v) + s * v.y) + 0.5;
  float stored = s > 0.0 ? texture(uParaboloidUpRaw, uv).r : texture(uParaboloidDownRaw, uv).r;
#elif OMNI_METHOD == OMNI_METHOD_TETRAHEDRON
  float stored = texture(uTetraRaw, tetraCoord(v, tetraFace(v))).r;
#else
  float stored = texture(uCubeRaw, v).r;
#endif
#if CUBE_STORE == CUBE_STORE_DEPTH && OMNI_METHOD == OMNI_METHOD_CUBE
  // Back from hyperbolic depth to the distance along the axis, over far.
  float z = 2.0 * stored - 1.0;
  stored = 2.0 * uCubeNear * uCubeFar / (uCubeFar + uCubeNear - z * (uCubeFar - uCubeNear)) / uCubeFar;
#endif
  outColor = vec4(vec3(stored), 1.0);
#endif
}
