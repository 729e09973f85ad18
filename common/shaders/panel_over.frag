#version 330 core
// The window's panel, drawn by ImGui into its own texture (colour already multiplied by its
// alpha), laid over the frame pixel for pixel.
uniform sampler2D uPanel;
out vec4 outColor;
void main() { outColor = texelFetch(uPanel, ivec2(gl_FragCoord.xy), 0); }
