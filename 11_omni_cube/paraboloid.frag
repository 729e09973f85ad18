#version 330 core
// Pass 1's store for a paraboloid: the fragment's own distance to the light over far, the same
// linear value the cube's distance store writes (the warped depth would be meaningless).
#include "clip_plane_in.glsl"
in vec3 vWorld;
uniform vec3 uLightPos;
uniform float uCubeFar;
void main() {
  clipFragment();
  gl_FragDepth = length(vWorld - uLightPos) / uCubeFar;
}
