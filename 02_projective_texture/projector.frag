#version 330 core
// The slide projector (seed 004 "Projective texturing pixel shader"): the colour at
// (s/q, t/q), fetched by textureProj, lights the surface like a coloured spotlight.
#include "lighting.glsl"
#include "border.glsl"
#include "clip_plane_in.glsl"
#include "spot.glsl"

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
