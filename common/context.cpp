#include "context.hpp"

// glad's header must come before any system GL header.
#include "gl.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>

#include <vector>

namespace shadows {

namespace {

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
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (context_ == nullptr) throw GlFailure("OSMesa: cannot create a 4.5 core context");
    // The runner renders into its own FBO; OSMesa only needs some buffer to be current.
    buffer_.resize(16 * 16 * 4);
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16)) {
      throw GlFailure("OSMesa: cannot make the context current");
    }
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress)) == 0) {
      throw GlFailure("OSMesa: glad could not load GL");
    }
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

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
                                     EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display_, config_attribs, &config, 1, &count) || count == 0) {
      throw GlFailure("EGL: no OpenGL config");
    }
    eglBindAPI(EGL_OPENGL_API);
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
    if (context_ == EGL_NO_CONTEXT) throw GlFailure("EGL: cannot create a 4.5 core context");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw GlFailure("EGL: cannot make the context current without a surface");
    }
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) == 0) {
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

}  // namespace

std::string HeadlessContext::current() {
  if (eglGetCurrentContext() != EGL_NO_CONTEXT) return "egl";
  if (OSMesaGetCurrentContext() != nullptr) return "osmesa";
  return "none";
}

std::unique_ptr<HeadlessContext> createHeadlessContext(const std::string& backend) {
  if (backend == "egl") return std::make_unique<EglSurfacelessContext>();
  return std::make_unique<OsMesaContext>();
}

}  // namespace shadows
