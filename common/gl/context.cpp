#include "gl/context.hpp"

// glad's header (through gl.hpp) must come before any system GL header.
#include "gl/gl.hpp"

#if SHADOWS_HAVE_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif
#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES  // OSMesa makes desktop contexts only
#include <GL/osmesa.h>
#include <dlfcn.h>
#endif
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <sstream>
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
// OSMesa is loaded when asked for, not linked: it pulls in LLVM (~120 MB), which a machine
// with a GPU (and the bundle, scripts/bundle.sh) has no use for.
struct OsMesaApi {
  decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetCurrentContext) getCurrentContext = nullptr;
  std::string why;  // empty when loaded

  // The library, loaded once per process; `why` says when it cannot be had.
  static const OsMesaApi& get() {
    static const OsMesaApi api = load();
    return api;
  }
  // Only when it is loaded already: asking what is current must not pull in LLVM.
  static const OsMesaApi* ifLoaded() {
    if (dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_NOLOAD) == nullptr) return nullptr;
    return get().why.empty() ? &get() : nullptr;
  }

 private:
  static OsMesaApi load() {
    OsMesaApi api;
    void* handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* error = dlerror();
      api.why = std::string("OSMesa: cannot load libOSMesa.so.8 (") + (error ? error : "?") + ")";
      return api;
    }
    auto symbol = [&](auto& function, const char* name) {
      function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(dlsym(handle, name));
      if (function == nullptr && api.why.empty()) api.why = std::string("OSMesa: no ") + name;
    };
    symbol(api.createContextAttribs, "OSMesaCreateContextAttribs");
    symbol(api.makeCurrent, "OSMesaMakeCurrent");
    symbol(api.getProcAddress, "OSMesaGetProcAddress");
    symbol(api.destroyContext, "OSMesaDestroyContext");
    symbol(api.getCurrentContext, "OSMesaGetCurrentContext");
    return api;
  }
};

class OsMesaContext final : public HeadlessContext {
 public:
  OsMesaContext() {
    api_ = &OsMesaApi::get();
    if (!api_->why.empty()) throw GlFailure(api_->why);
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
    context_ = api_->createContextAttribs(attribs, nullptr);
    if (context_ == nullptr) {
      throw GlFailure(std::string("OSMesa: cannot create ") + contextName());
    }
    // The runner renders into its own FBO; OSMesa only needs some buffer to be current.
    buffer_.resize(16 * 16 * 4);
    if (!api_->makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16)) {
      throw GlFailure("OSMesa: cannot make the context current");
    }
    if (!loadGl(reinterpret_cast<GLADloadfunc>(api_->getProcAddress))) {
      throw GlFailure("OSMesa: glad could not load GL");
    }
  }
  ~OsMesaContext() override { api_->destroyContext(context_); }

 private:
  const OsMesaApi* api_ = nullptr;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};
#endif

#if SHADOWS_HAVE_EGL
PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay() {
  auto get = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get == nullptr) throw GlFailure("EGL: no eglGetPlatformDisplayEXT");
  return get;
}

// Whether a space-separated EGL extension list names `name`.
bool hasExtension(const char* list, const std::string& name) {
  std::istringstream words(list != nullptr ? list : "");
  for (std::string word; words >> word;) {
    if (word == name) return true;
  }
  return false;
}

// EGL_EXT_device_enumeration: the devices, or why there are none to choose from.
struct EglDevices {
  std::string unsupported;
  std::vector<EGLDeviceEXT> devices;
  std::vector<std::string> names;
};

EglDevices enumerateEglDevices() {
  EglDevices out;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  for (const char* needed : {"EGL_EXT_device_enumeration", "EGL_EXT_platform_device"}) {
    if (!hasExtension(client, needed)) {
      out.unsupported = std::string("EGL: this EGL has no ") + needed +
                        " (--backend egl-device needs it; try --backend egl)";
      return out;
    }
  }
  auto query = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      eglGetProcAddress("eglQueryDeviceStringEXT"));
  EGLint count = 0;
  if (query == nullptr || !query(0, nullptr, &count)) {
    out.unsupported = "EGL: eglQueryDevicesEXT failed";
    return out;
  }
  out.devices.resize(static_cast<size_t>(count));
  if (count > 0 && !query(count, out.devices.data(), &count)) count = 0;
  out.devices.resize(static_cast<size_t>(count));
  // A name a person recognizes: the renderer where the driver says it
  // (EGL_EXT_device_query_name: NVIDIA), the DRM node, or Mesa's software device.
  for (EGLDeviceEXT device : out.devices) {
    std::vector<std::string> parts;
    const char* extensions = string != nullptr ? string(device, EGL_EXTENSIONS) : nullptr;
    auto add = [&](const char* extension, EGLint name) {
      if (!hasExtension(extensions, extension)) return;
      if (const char* value = string(device, name); value != nullptr && *value != 0) {
        parts.emplace_back(value);
      }
    };
    add("EGL_EXT_device_query_name", EGL_RENDERER_EXT);
    add("EGL_EXT_device_drm", EGL_DRM_DEVICE_FILE_EXT);
    if (parts.empty()) add("EGL_EXT_device_drm_render_node", EGL_DRM_RENDER_NODE_FILE_EXT);
    if (hasExtension(extensions, "EGL_MESA_device_software")) parts.emplace_back("Mesa software");
    std::string name;
    for (const std::string& part : parts) name += (name.empty() ? "" : ", ") + part;
    out.names.push_back(name.empty() ? "unnamed" : name);
  }
  return out;
}

// An EGL context of this build's API with no surface, on the display a platform gives.
class EglContext : public HeadlessContext {
 protected:
  void init(EGLDisplay display, const std::string& what) {
    display_ = display;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) {
      display_ = EGL_NO_DISPLAY;
      throw GlFailure("EGL: " + what + " is not available");
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

 public:
  EGLDisplay display() const {
    return display_;
  }
  ~EglContext() override {
    if (display_ == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

// Mesa's surfaceless platform (what Mesa offers without a display or a device node).
class EglSurfacelessContext final : public EglContext {
 public:
  EglSurfacelessContext() {
    init(getPlatformDisplay()(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
         "the surfaceless platform");
  }
};

// The device platform (EGL_EXT_platform_device): what NVIDIA's driver offers headless, and
// Mesa too (its software device). The device chosen is kept for the report.
class EglDeviceContext final : public EglContext {
 public:
  explicit EglDeviceContext(int index) {
    const EglDevices found = enumerateEglDevices();
    if (!found.unsupported.empty()) throw GlFailure(found.unsupported);
    if (index < 0 || static_cast<size_t>(index) >= found.names.size()) {
      throw GlFailure(eglDeviceMissing(index, found.names));
    }
    const EGLDeviceEXT device = found.devices[static_cast<size_t>(index)];
    init(getPlatformDisplay()(EGL_PLATFORM_DEVICE_EXT, device, nullptr),
         "EGL device " + std::to_string(index));
    // Asked of the display, not assumed: the report names the device that really renders.
    auto attached = reinterpret_cast<PFNEGLQUERYDISPLAYATTRIBEXTPROC>(
        eglGetProcAddress("eglQueryDisplayAttribEXT"));
    EGLAttrib on = 0;
    if (attached == nullptr || !attached(display(), EGL_DEVICE_EXT, &on) ||
        reinterpret_cast<EGLDeviceEXT>(on) != device) {
      throw GlFailure("EGL: the display is not on device " + std::to_string(index));
    }
    chosen_ = {index, found.names[static_cast<size_t>(index)], found.names.size()};
    current_ = true;
  }
  ~EglDeviceContext() override {
    current_ = false;
    chosen_ = {};
  }
  static bool isCurrent() { return current_; }
  static inline EglDeviceChoice chosen_;

 private:
  static inline bool current_ = false;
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
  if (EglDeviceContext::isCurrent()) return "egl-device";
  if (eglGetCurrentContext() != EGL_NO_CONTEXT) return "egl";
#endif
#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES
  if (const OsMesaApi* api = OsMesaApi::ifLoaded(); api && api->getCurrentContext() != nullptr) {
    return "osmesa";
  }
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
  backends.push_back("egl-device");
#endif
  backends.push_back("glfw");
  return backends;
}

std::unique_ptr<HeadlessContext> createHeadlessContext(const std::string& backend,
                                                       [[maybe_unused]] int device) {
#if SHADOWS_HAVE_EGL
  if (backend == "egl-device") return std::make_unique<EglDeviceContext>(device);
  if (backend == "egl") return std::make_unique<EglSurfacelessContext>();
#endif
#if SHADOWS_HAVE_OSMESA && !SHADOWS_GLES
  if (backend == "osmesa") return std::make_unique<OsMesaContext>();
#endif
  if (backend == "glfw") return std::make_unique<HiddenWindowContext>();
  throw GlFailure("no headless backend '" + backend + "' in this build");
}

std::string checkBackend(const std::string& value) {
  const std::vector<std::string> backends = headlessBackends();
  if (std::find(backends.begin(), backends.end(), value) != backends.end()) return {};
  std::string allowed;
  for (size_t i = 0; i < backends.size(); ++i) {
    allowed += (i == 0 ? "" : i + 1 == backends.size() ? " or " : ", ") + backends[i];
  }
  return "--backend: expected " + allowed;
}

std::string eglDeviceMissing(int index, const std::vector<std::string>& names) {
  std::string list;
  for (size_t i = 0; i < names.size(); ++i) {
    list += (i == 0 ? "" : "; ") + std::to_string(i) + ": " + names[i];
  }
  return "--device " + std::to_string(index) + ": no such EGL device (" +
         (names.empty() ? std::string("there are none") : "there are " + list) + ")";
}

EglDeviceChoice currentEglDevice() {
#if SHADOWS_HAVE_EGL
  if (EglDeviceContext::isCurrent()) return EglDeviceContext::chosen_;
#endif
  return {};
}

std::string headlessProblem(const std::string& backend, int device, int& exit_code) {
  if (backend != "egl-device") return {};
#if SHADOWS_HAVE_EGL
  const EglDevices found = enumerateEglDevices();
  if (!found.unsupported.empty()) {
    exit_code = 1;
    return found.unsupported;
  }
  if (device < 0 || static_cast<size_t>(device) >= found.names.size()) {
    exit_code = 2;
    return eglDeviceMissing(device, found.names);
  }
#else
  (void)device;
  (void)exit_code;
#endif
  return {};
}

}  // namespace shadows
