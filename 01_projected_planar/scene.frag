#version 330 core
// Every surface fully lit (shade = 1). Planar shadows are not looked up here: they are
// blended onto the receiver afterwards, as dark copies of the casters.
#include "lighting.glsl"

in vec3 vWorld;
in vec3 vNormal;
uniform vec3 uColor;
uniform int uMode;  // 0 shaded, 1 visibility (white until a shadow darkens it), 2 overdraw
out vec4 outColor;

void main() {
  if (uMode == 1) {
    outColor = vec4(1.0);
    return;
  }
  vec3 lit = shadeSurface(uColor, vWorld, normalize(vNormal), 1.0);
  outColor = vec4(uMode == 2 ? 0.3 * lit : lit, 1.0);  // overdraw: dim, so layers stand out
}
