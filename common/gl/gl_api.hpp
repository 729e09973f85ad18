// The GL API this build compiles against (SHADOWS_GL at configure time: gl45, gl41 or gles30),
// through its own glad loader. Everything else includes this, never a glad header itself, and
// asks Caps (caps.hpp) at run time what the context can do.
#pragma once

#if defined(SHADOWS_GL_GLES30)
#include <glad/gles2.h>
#define SHADOWS_GLES 1
#define SHADOWS_GL_VERSION 300
#elif defined(SHADOWS_GL_GL41)
#include <glad/gl.h>
#define SHADOWS_GLES 0
#define SHADOWS_GL_VERSION 410
#else
#include <glad/gl.h>
#define SHADOWS_GLES 0
#define SHADOWS_GL_VERSION 450
#endif

#if SHADOWS_GLES
// Names the shared code passes around but OpenGL ES 3.0 lacks: they are never handed to the
// GL there (Caps says so first), only compared and stored.
#define GL_CLAMP_TO_BORDER 0x812D
#define GL_SAMPLES_PASSED 0x8914
#define GL_DEPTH_CLAMP 0x864F
// KHR_debug, which ES has only as an extension, with suffixed names.
#define GL_DEBUG_OUTPUT GL_DEBUG_OUTPUT_KHR
#define GL_DEBUG_OUTPUT_SYNCHRONOUS GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR
#define GL_DEBUG_SOURCE_SHADER_COMPILER GL_DEBUG_SOURCE_SHADER_COMPILER_KHR
#define GL_DEBUG_TYPE_ERROR GL_DEBUG_TYPE_ERROR_KHR
#define GL_DEBUG_SEVERITY_HIGH GL_DEBUG_SEVERITY_HIGH_KHR
#endif

namespace shadows {

// Loads GL entry points for this build's API through `load` (eglGetProcAddress,
// glfwGetProcAddress, ...), then fills Caps. False when the loader found no context.
bool loadGl(GLADloadfunc load);

}  // namespace shadows
