#version 330 core
// Depth only: the depth buffer is the shadow map; no colour is written.
void main() {}
