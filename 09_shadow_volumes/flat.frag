#version 330 core
// One colour over the pixels the stencil test lets through (count view, modulative shadow).
uniform vec4 uColor;
out vec4 outColor;
void main() {
  outColor = uColor;
}
