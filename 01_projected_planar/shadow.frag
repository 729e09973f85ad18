#version 330 core
// A shadow polygon is one flat colour; the blend function decides what it does.
#include "clip_plane_in.glsl"
uniform vec4 uShadowColor;
out vec4 outColor;
void main() {
  clipFragment();
  outColor = uShadowColor;
}
