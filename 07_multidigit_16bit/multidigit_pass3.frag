#version 420 core
// Pass 3 writes neither depth nor stencil, so its tests may run before the shader: pixels
// pass 2 took (stencil 1) and hidden surfaces are rejected without being shaded.
layout(early_fragment_tests) in;
#include "multidigit.glsl"
