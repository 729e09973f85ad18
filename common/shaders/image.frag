#version 330 core
// A picture over the target or in a corner, with its border where it has one (border.glsl).
#include "border.glsl"
in vec2 vUv;
uniform sampler2D uImage;
uniform int uHasBorder;
uniform vec4 uBorder;
uniform int uLinear;
// The texture's swizzle where the GL has none (WebGL 2): a channel matrix and constants.
uniform mat4 uSwizzle;
uniform vec4 uSwizzleConstant;
out vec4 outColor;
void main() {
  outColor = uSwizzle * texture(uImage, vUv) + uSwizzleConstant;
  if (uHasBorder == 1) {
    outColor = withBorder(outColor, vUv, vec2(textureSize(uImage, 0)), uBorder, uLinear == 1);
  }
}
