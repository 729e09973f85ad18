#version 330 core
// The stencil does the counting; colour only for view=volumes (slide 28): front faces warm,
// back faces cold, translucent.
out vec4 outColor;
void main() {
#if VIEW == VIEW_VOLUMES
  outColor = gl_FrontFacing ? vec4(1.0, 0.8, 0.2, 0.18) : vec4(0.2, 0.5, 1.0, 0.18);
#else
  outColor = vec4(0.0);
#endif
}
