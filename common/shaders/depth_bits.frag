#version 330 core
// A depth texture's value, read where the GL cannot read depth back (OpenGL ES): its float's
// 32 bits as four 8-bit channels (least significant in r), exactly, for the offset-unit probe.
uniform sampler2D uDepth;
out vec4 outColor;
void main() {
  uint bits = floatBitsToUint(texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r);
  uvec4 bytes = (uvec4(bits) >> uvec4(0u, 8u, 16u, 24u)) & 255u;
  outColor = vec4(bytes) / 255.0;
}
