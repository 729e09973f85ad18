#include "context.hpp"

// glad's header (through gl.hpp) must come before any system GL header.
#include "gl.hpp"

#if SHADOWS_HAVE_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif
#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES  // OSMesa makes desktop contexts only
#include <GL/osmesa.h>
#endif
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <vector>

namespace shadows {

namespace {

// The context version this build's API asks for.
#if SHADOWS_GLES
constexpr int kMajor = 3, kMinor = 0;
#elif SHADOWS_GL_VERSION == 410
constexpr int kMajor = 4, kMinor = 1;
#else
constexpr int kMajor = 4, kMinor = 5;
#endif

#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES
class OsMesaContext final : public HeadlessContext {
 public:
  OsMesaContext() {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           kMajor,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           kMinor,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (context_ == nullptr) {
      throw GlFailure(std::string("OSMesa: cannot create ") + contextName());
    }
    // The runner renders into its own FBO; OSMesa only needs some buffer to be current.
    buffer_.resize(16 * 16 * 4);
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16)) {
      throw GlFailure("OSMesa: cannot make the context current");
    }
    if (!loadGl(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress))) {
      throw GlFailure("OSMesa: glad could not load GL");
    }
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};
#endif

#if SHADOWS_HAVE_EGL
class EglSurfacelessContext final : public HeadlessContext {
 public:
  EglSurfacelessContext() {
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay == nullptr) throw GlFailure("EGL: no eglGetPlatformDisplayEXT");
    display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) {
      throw GlFailure("EGL: the surfaceless platform is not available");
    }
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                     SHADOWS_GLES ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display_, config_attribs, &config, 1, &count) || count == 0) {
      throw GlFailure(SHADOWS_GLES ? "EGL: no OpenGL ES 3 config" : "EGL: no OpenGL config");
    }
    eglBindAPI(SHADOWS_GLES ? EGL_OPENGL_ES_API : EGL_OPENGL_API);
#if SHADOWS_GLES
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, kMajor, EGL_CONTEXT_MINOR_VERSION,
                                      kMinor, EGL_NONE};
#else
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      kMajor,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      kMinor,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
#endif
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
    if (context_ == EGL_NO_CONTEXT) {
      throw GlFailure(std::string("EGL: cannot create ") + contextName());
    }
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw GlFailure("EGL: cannot make the context current without a surface");
    }
    if (!loadGl(reinterpret_cast<GLADloadfunc>(eglGetProcAddress))) {
      throw GlFailure("EGL: glad could not load GL");
    }
  }
  ~EglSurfacelessContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};
#endif

// macOS has neither OSMesa nor EGL: a window that is never shown holds the context there.
class HiddenWindowContext final : public HeadlessContext {
 public:
  HiddenWindowContext() {
    if (!glfwInit()) throw GlFailure("GLFW: cannot initialize (a hidden window needs a display)");
    glfwDefaultWindowHints();
    setGlfwContextHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    window_ = glfwCreateWindow(16, 16, "headless", nullptr, nullptr);
    if (window_ == nullptr) {
      glfwTerminate();
      throw GlFailure(std::string("GLFW: cannot create ") + contextName() + " in a hidden window");
    }
    glfwMakeContextCurrent(window_);
    if (!loadGl(glfwGetProcAddress)) throw GlFailure("GLFW: glad could not load GL");
    current_ = true;
  }
  ~HiddenWindowContext() override {
    current_ = false;
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  static bool isCurrent() { return current_; }

 private:
  GLFWwindow* window_ = nullptr;
  static inline bool current_ = false;
};

}  // namespace

const char* contextName() {
#if SHADOWS_GLES
  return "an OpenGL ES 3.0 context";
#elif SHADOWS_GL_VERSION == 410
  return "a 4.1 core context";
#else
  return "a 4.5 core context";
#endif
}

void setGlfwContextHints() {
#if SHADOWS_GLES
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
#else
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
#endif
#if SHADOWS_GL_VERSION == 410
  // macOS gives a core context only to a forward-compatible request.
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#endif
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, kMajor);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, kMinor);
  glfwWindowHint(GLFW_STENCIL_BITS, 8);
}

std::string HeadlessContext::current() {
  if (HiddenWindowContext::isCurrent()) return "glfw";
#if SHADOWS_HAVE_EGL
  if (eglGetCurrentContext() != EGL_NO_CONTEXT) return "egl";
#endif
#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES
  if (OSMesaGetCurrentContext() != nullptr) return "osmesa";
#endif
  return "none";
}

std::vector<std::string> headlessBackends() {
  std::vector<std::string> backends;
#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES
  backends.push_back("osmesa");
#endif
#if SHADOWS_HAVE_EGL
  backends.push_back("egl");
#endif
  backends.push_back("glfw");
  return backends;
}

std::unique_ptr<HeadlessContext> createHeadlessContext(const std::string& backend) {
#if SHADOWS_HAVE_EGL
  if (backend == "egl") return std::make_unique<EglSurfacelessContext>();
#endif
#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES
  if (backend == "osmesa") return std::make_unique<OsMesaContext>();
#endif
  if (backend == "glfw") return std::make_unique<HiddenWindowContext>();
  throw GlFailure("no headless backend '" + backend + "' in this build");
}

}  // namespace shadows
