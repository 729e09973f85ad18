#include "gl/caps.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

#include "gl/gl_api.hpp"

namespace shadows {

namespace {

// What the build's API allows at most; loadGl keeps what the context really has.
Caps ceiling() {
  Caps c;
#if SHADOWS_GLES && defined(__EMSCRIPTEN__)
  c.flavour = "webgl2";  // the gles30 flavour in a browser: what a page says is missing
  c.es = true;
  c.glsl_version = 300;
#elif SHADOWS_GLES
  c.flavour = "gles30";
  c.es = true;
  c.glsl_version = 300;
#elif SHADOWS_GL_VERSION == 410
  c.flavour = "gl41";
  c.glsl_version = 410;
#else
  c.flavour = "gl45";
  c.glsl_version = 450;
#endif
  return c;
}

Caps g_caps = ceiling();

// Whether the context lists an extension (glGetStringi: GL 3.0, ES 3.0, WebGL 2).
bool hasGlExtension(const char* name) {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i) {
    const auto* e =
        reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (e != nullptr && std::strcmp(e, name) == 0) return true;
  }
  return false;
}

// The largest anisotropy the context filters with, 1 without the feature.
float maxAnisotropy() {
  if (!hasGlExtension("GL_EXT_texture_filter_anisotropic") &&
      !hasGlExtension("GL_ARB_texture_filter_anisotropic")) {
    return 1.0f;
  }
  constexpr GLenum kMaxMaxAnisotropy = 0x84FF;
  GLfloat most = 1.0f;
  glGetFloatv(kMaxMaxAnisotropy, &most);
  return most;
}

#ifdef __EMSCRIPTEN__
extern "C" void* emscripten_webgl1_get_proc_address(const char* name);
extern "C" void* emscripten_webgl2_get_proc_address(const char* name);
// WebGL 2's entry points before WebGL 1's: emscripten's GetProcAddress (GLFW's) asks WebGL 1
// first, which answers glGenQueries with EXT_disjoint_timer_query's, absent from WebGL 2.
GLADapiproc webgl2First(const char* name) {
  void* f = emscripten_webgl2_get_proc_address(name);
  return reinterpret_cast<GLADapiproc>(f != nullptr ? f : emscripten_webgl1_get_proc_address(name));
}
#endif

}  // namespace

const Caps& caps() {
  return g_caps;
}

bool loadGl(GLADloadfunc load) {
  Caps c = ceiling();
#if SHADOWS_GLES
#ifdef __EMSCRIPTEN__
  load = webgl2First;
#endif
  if (gladLoadGLES2(load) == 0) return false;
  // Nothing optional but what WebGL 2 offers too: errors through KHR_debug where it is there,
  // float colour targets (the truth's read backs) through EXT_color_buffer_float. Border clamp
  // and clip distances, which Mesa's ES has as extensions and WebGL does not, are emulated.
  c.debug_output = GLAD_GL_KHR_debug != 0;
  c.float_color_targets = GLAD_GL_EXT_color_buffer_float != 0;
#ifndef __EMSCRIPTEN__
  c.texture_swizzle = true;  // ES 3.0 has it; WebGL 2 left it out
#else
  c.gpu_timer = hasGlExtension("GL_EXT_disjoint_timer_query_webgl2");
#endif
#else
  if (gladLoadGL(load) == 0) return false;
  c.samples_passed = c.texture_1d = c.border_clamp = c.clip_distance = true;
  c.depth_readback = c.float_color_targets = c.texture_swizzle = true;
  c.depth_clamp = GLAD_GL_VERSION_3_2 != 0;
  c.texture_gather = GLAD_GL_VERSION_4_0 != 0;
  c.seamless_cube_switch = GLAD_GL_VERSION_3_2 != 0;
  c.geometry_shaders = GLAD_GL_VERSION_3_2 != 0;
  c.pipeline_statistics = GLAD_GL_ARB_pipeline_statistics_query != 0;
  c.debug_output = GLAD_GL_KHR_debug != 0;
#if SHADOWS_GL_VERSION >= 430
  c.storage_buffers = GLAD_GL_VERSION_4_3 != 0;
  c.early_fragment_tests = GLAD_GL_VERSION_4_2 != 0;
#endif
#endif
  c.max_anisotropy = maxAnisotropy();
  // 32-bit float textures filter LINEAR on desktop GL; ES 3.0 and WebGL 2 need an extension.
  c.float_linear = !c.es || hasGlExtension("GL_OES_texture_float_linear");
  // Tests switch features off that a software rasterizer always has, to reach the fallbacks
  // a laptop's driver may take (tests/README.md): a comma-separated list of these names.
  if (const char* off = std::getenv("SHADOWS_TEST_CAPS_OFF")) {
    const std::string list = std::string(",") + off + ",";
    const auto named = [&](const char* name) {
      return list.find(std::string(",") + name + ",") != std::string::npos;
    };
    if (named("float_linear")) c.float_linear = false;
    if (named("anisotropy")) c.max_anisotropy = 1.0f;
    if (named("texture_gather")) c.texture_gather = false;
    if (named("geometry_shaders")) c.geometry_shaders = false;
  }
  g_caps = c;
  return true;
}

std::vector<std::string> Caps::shaderDefines() const {
  const auto line = [](const char* name, bool on) {
    return std::string(name) + (on ? " 1" : " 0");
  };
  return {line("SHADOWS_GLES", es),
          line("HAS_TEXTURE_1D", texture_1d),
          line("HAS_BORDER_CLAMP", border_clamp),
          line("HAS_CLIP_DISTANCE", clip_distance),
          line("HAS_EARLY_FRAGMENT_TESTS", early_fragment_tests),
          line("HAS_STORAGE_BUFFERS", storage_buffers)};
}

}  // namespace shadows
