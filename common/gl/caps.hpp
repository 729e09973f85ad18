// What the current context can do, asked once when it is made (loadGl) and read by the code
// that needs it: the flavour's API sets the ceiling (a gl41 build never uses what 4.2 added),
// the context's extensions what is there below it. Where a feature is missing the code
// emulates it (see README, "One source, three APIs") or reports the number as unavailable.
#pragma once

#include <string>
#include <vector>

namespace shadows {

struct Caps {
  std::string flavour;     // the build's API: "gl45", "gl41" or "gles30"
  bool es = false;         // OpenGL ES: `#version 300 es` shaders with precision lines
  int glsl_version = 330;  // what Program writes where a file asks for more (410, 300 es)

  // Counters. Without them the report says null, "unavailable on <flavour>".
  bool pipeline_statistics = false;  // fragment_invocations (ARB_pipeline_statistics_query)
  bool samples_passed = false;       // counting occlusion queries (ES has only boolean ones)
  bool storage_buffers = false;      // SSBOs and atomics (05's tap counters): GL 4.3
  bool debug_output = false;         // KHR_debug; else GL errors come from glGetError only

  // Features with an emulation where they are missing.
  bool texture_1d = false;            // else ramps are 256x1 2D textures
  bool border_clamp = false;          // else edge clamp, the shader tests the lookup
  bool clip_distance = false;         // else a varying and discard
  bool depth_readback = false;        // glReadPixels and copies of depth; else via colour
  bool early_fragment_tests = false;  // layout(early_fragment_tests): GL 4.2; else the driver's
  bool float_color_targets = false;   // RGBA32F colour attachments (the truth's read backs)
  bool depth_clamp = false;           // GL_DEPTH_CLAMP (GL 3.2; not in ES 3.0 nor WebGL 2)
  bool texture_swizzle = false;       // GL_TEXTURE_SWIZZLE_* (GL 3.3, ES 3.0; not WebGL 2):
                                      // else the image shader swizzles what it shows
  bool float_linear = false;          // 32-bit float textures filter LINEAR (ES: an extension)
  bool texture_gather = false;        // textureGather with a depth reference: GL 4.0, ES 3.1
  bool geometry_shaders = false;      // GL 3.2; ES 3.2 only, so never in ES 3.0 or WebGL 2
  // A page's frame timed on the GPU: WebGL 2's EXT_disjoint_timer_query_webgl2 (a browser's
  // glFinish returns before its GPU process has drawn, so wall time counts only the calls).
  bool gpu_timer = false;
  bool seamless_cube_switch = false;  // GL_TEXTURE_CUBE_MAP_SEAMLESS can be switched (GL 3.2);
                                      // ES 3.0 and WebGL 2 always filter across cube faces
  float max_anisotropy = 1.0f;        // anisotropic filtering (GL 4.6, EXT/ARB extensions):
                                      // 1 = none, lookups are trilinear at best

  // "unavailable on gles30": what a report or panel says for a number this context lacks.
  std::string unavailable() const { return "unavailable on " + flavour; }
  // The shader #defines Program adds to every stage: HAS_TEXTURE_1D 1, ...
  std::vector<std::string> shaderDefines() const;
};

// The caps of the current context (loadGl fills them; before that, the build's ceiling).
const Caps& caps();

}  // namespace shadows
