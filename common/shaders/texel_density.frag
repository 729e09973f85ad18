#version 330 core
// The runner's texel pass (common/math/texel_density.hpp): per pixel, the map's texels one screen
// pixel spans, from the screen-space derivatives of the map coordinates times the map's size:
// the singular values of that 2x2 Jacobian, along the least and the most sampled direction.
// TEXEL_HEATMAP 1: the `aliasing` view (red under-sampled, blue over-sampled, green one texel
// per pixel along both axes, white near one); 0: the raw numbers the runner reads back.
#include "lighting.glsl"
#include "texel_density.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform vec2 uMapSize;
uniform int uObject;
uniform float uTolerance;  // kTexelTolerance
out vec4 outColor;


void main() {
  vec4 c = vShadowCoord;
  // Derivatives in uniform control flow, before anything branches on this pixel.
  vec2 uv = c.xy / (abs(c.w) > 1e-30 ? c.w : 1e-30) * uMapSize;
  vec2 s = singularValues(dFdx(uv), dFdy(uv));
  vec3 n = normalize(vNormal);
  float nl = dot(n, directionToLight(vWorld));
  // What the error counts: a surface seen from the front that faces the light, inside the
  // map side to side and near to far.
  bool inside = c.w > 0.0 && all(greaterThanEqual(c.xyz, vec3(0.0))) &&
                all(lessThanEqual(c.xyz, vec3(c.w)));
  bool counted = inside && gl_FrontFacing && nl > 0.0 && s.y > 0.0;
#if TEXEL_HEATMAP
  float light = 0.55 + 0.45 * max(nl, 0.0);  // enough shading to read the shapes
  if (!counted) {
    outColor = vec4(vec3(0.3 * light), 1.0);
    return;
  }
  float e = log2(s.y);  // the least sampled axis decides blockiness
  vec3 color;
  if (abs(s.y - 1.0) <= uTolerance && abs(s.x - 1.0) <= uTolerance) {
    color = vec3(0.15, 0.8, 0.25);  // one texel per pixel along both axes
  } else if (s.y < 1.0 - uTolerance) {
    color = mix(vec3(1.0, 0.85, 0.8), vec3(0.85, 0.05, 0.05), clamp(-e / 3.0, 0.0, 1.0));
  } else {
    color = mix(vec3(0.8, 0.85, 1.0), vec3(0.05, 0.2, 0.9), clamp(e / 3.0, 0.0, 1.0));
  }
  outColor = vec4(color * light, 1.0);
#else
  outColor = vec4(s.y, s.x, counted ? 1.0 : 0.0, float(uObject));
#endif
}
