#version 330 core
// Passes 1 and 2 (pass 2 writes the stencil, so its depth and stencil tests must come after
// the alpha test's discard).
#include "multidigit.glsl"
