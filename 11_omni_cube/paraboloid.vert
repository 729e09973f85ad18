#version 330 core
// Dual paraboloids (Brabec, Annen and Seidel 2002), pass 1 for one hemisphere: the direction
// v from the light is mapped to (s v.x, v.z) / (|v| + s v.y), s = +1 for the upper hemisphere
// and -1 for the lower, a disk of radius 1. The map is in the vertex shader: the rasterizer
// then joins the warped corners with straight edges, where the true images of the edges are
// curves (the known failure: long triangles bent wrong).
#include "clip_plane_out.glsl"
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform vec3 uLightPos;
uniform float uHemisphere;  // +1 or -1
uniform float uCubeFar;
out vec3 vWorld;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vec3 v = world.xyz - uLightPos;
  float len = max(length(v), 1e-6);
  // The other hemisphere's side is clipped (its vertices have s v.y < 0).
  setClipDistance(uHemisphere * v.y);
  // x mirrored for the lower hemisphere, so that both are seen as a camera sees (triangles
  // keep their winding, and a map pass culls back faces as everywhere).
  vec2 disk = vec2(uHemisphere * v.x, v.z) / (len + uHemisphere * v.y);
  gl_Position = vec4(disk, 2.0 * len / uCubeFar - 1.0, 1.0);
}
