#version 330 core
// Pass 1 (PASS_DIM): the scene with the light dimmed, which also fills the depth buffer.
// Pass 3 (PASS_LIGHT): what the light adds, blended additively where the count is 0 (seed 002,
// "additive light masking"). PASS_FULL: pass 1 of combine=modulative, fully lit; the shadow is
// then darkened over it, specular highlight included.
#include "lighting.glsl"

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
