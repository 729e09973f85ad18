#version 330 core
// Pass 1: depth from the light. uClipOffset is 000's "common mistake": a translate of clip-space
// z before the perspective divide, so the bias that lands in the depth buffer is uClipOffset / 2w
// and shrinks with distance from the light (0 in every other mode).
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProjection;  // P_light * V_light
uniform float uClipOffset;
void main() {
  gl_Position = uLightViewProjection * uModel * vec4(aPosition, 1.0);
  gl_Position.z += uClipOffset;
}
