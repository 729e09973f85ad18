#version 330 core
// Every surface fully lit (shade = 1). Planar shadows are not looked up here: they are
// blended onto the receiver afterwards, as dark copies of the casters.
#include "lighting.glsl"

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
