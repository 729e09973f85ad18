#version 330 core
// The six faces unfolded as a cross (4 x 3 squares: +x, +z, -x, -z across the middle, +y
// above +z, -y below it), each texel's stored value as a grey: near the light dark, far light.
// Faces skipped (no caster in them, or none the eye can see) are tinted blue.
#include "cube_lookup.glsl"

in vec2 vUv;
uniform samplerCube uCubeRaw;
uniform float uAspect;       // the target's width over height
uniform int uFacesRendered;  // bit i: face i holds casters rendered since the map changed
out vec4 outColor;

uniform sampler2D uParaboloidUpRaw;    // omni.method=paraboloid: the two disks instead
uniform sampler2D uParaboloidDownRaw;

void main() {
#if OMNI_METHOD == OMNI_METHOD_PARABOLOID
  // The two hemispheres side by side, upper left, lower right, each a disk of radius 1.
  vec2 half_ = vec2(fract(vUv.x * 2.0), vUv.y);
  vec2 q2 = 2.0 * half_ - 1.0;
  q2.y *= 2.0 / uAspect;  // each half is aspect/2 as wide as it is high
  if (dot(q2, q2) > 1.0) {
    outColor = vec4(0.08, 0.08, 0.1, 1.0);
    return;
  }
  vec2 uv = 0.5 * q2 + 0.5;
  float d = vUv.x < 0.5 ? texture(uParaboloidUpRaw, uv).r : texture(uParaboloidDownRaw, uv).r;
  outColor = vec4(vec3(sqrt(clamp(d, 0.0, 1.0))), 1.0);
  return;
#endif
  // A 4:3 cross centred in the target.
  vec2 p = vUv;
  if (uAspect > 4.0 / 3.0) {
    p.x = (p.x - 0.5) * uAspect / (4.0 / 3.0) + 0.5;
  } else {
    p.y = (p.y - 0.5) * (4.0 / 3.0) / uAspect + 0.5;
  }
  vec2 cell = p * vec2(4.0, 3.0);
  ivec2 c = ivec2(floor(cell));
  vec2 q = 2.0 * fract(cell) - 1.0;  // [-1, 1] inside the cell, y up
  vec3 dir;
  int face = -1;
  if (c.y == 1 && c.x >= 0 && c.x < 4) {
    // The middle row, as if standing at the light turning right: +x, +z, -x, -z.
    if (c.x == 0) { dir = vec3(1.0, q.y, q.x); face = 0; }
    if (c.x == 1) { dir = vec3(-q.x, q.y, 1.0); face = 4; }
    if (c.x == 2) { dir = vec3(-1.0, q.y, -q.x); face = 1; }
    if (c.x == 3) { dir = vec3(q.x, q.y, -1.0); face = 5; }
  } else if (c.x == 1 && c.y == 2) {
    dir = vec3(-q.x, 1.0, -q.y); face = 2;
  } else if (c.x == 1 && c.y == 0) {
    dir = vec3(-q.x, -1.0, q.y); face = 3;
  }
  if (face < 0 || any(lessThan(p, vec2(0.0))) || any(greaterThan(p, vec2(1.0)))) {
    outColor = vec4(0.08, 0.08, 0.1, 1.0);
    return;
  }
  float stored = texture(uCubeRaw, dir).r;
#if CUBE_STORE == CUBE_STORE_DEPTH
  float z = 2.0 * stored - 1.0;
  stored = 2.0 * uCubeNear * uCubeFar / (uCubeFar + uCubeNear - z * (uCubeFar - uCubeNear)) / uCubeFar;
#endif
  vec3 grey = vec3(sqrt(clamp(stored, 0.0, 1.0)));
  if (((uFacesRendered >> face) & 1) == 0) grey = mix(grey, vec3(0.2, 0.35, 0.8), 0.5);
  // A thin frame around each face.
  float edge = max(abs(q.x), abs(q.y));
  if (edge > 0.985) grey = vec3(0.9, 0.75, 0.2);
  outColor = vec4(grey, 1.0);
}
