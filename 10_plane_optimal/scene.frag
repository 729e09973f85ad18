#version 330 core
// Pass 2: the map lookup through the chosen projection, and the lesson's views.
#include "lighting.glsl"
#include "border.glsl"

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
