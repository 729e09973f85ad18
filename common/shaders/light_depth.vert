#version 330 core
// A shadow map's pass: depth from the light, nothing but the position needed.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProjection;  // P_light * V_light
void main() { gl_Position = uLightViewProjection * uModel * vec4(aPosition, 1.0); }
