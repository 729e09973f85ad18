#version 330 core
// Depth only: the depth buffer is the shadow map (glPolygonOffset, if on, is applied to it).
void main() {}
