#version 420 core
// Pass 3 writes neither depth nor stencil, so its tests may run before the shader: pixels
// pass 2 took (stencil 1) and hidden surfaces are rejected without being shaded.
#if HAS_EARLY_FRAGMENT_TESTS  // GL 4.2: elsewhere the driver decides when the tests run
layout(early_fragment_tests) in;
#endif
#include "multidigit.glsl"
