#version 330 core
// The stencil does the counting; colour only for view=volumes (slide 29): front faces warm,
// back faces cold, translucent (uAlpha: strong in front of the surfaces, faint behind); the
// same for view=overview, the volumes seen from outside.
out vec4 outColor;
#if VIEW == VIEW_VOLUMES || VIEW == VIEW_OVERVIEW
uniform float uAlpha;
#endif
void main() {
#if VIEW == VIEW_VOLUMES || VIEW == VIEW_OVERVIEW
  outColor = gl_FrontFacing ? vec4(1.0, 0.8, 0.2, uAlpha) : vec4(0.2, 0.5, 1.0, uAlpha);
#else
  outColor = vec4(0.0);
#endif
}
