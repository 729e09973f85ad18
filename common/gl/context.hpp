// Headless GL contexts behind one small interface: OSMesa (the default on desktop GL), EGL
// surfaceless (Mesa 25.1 removed OSMesa; the only one for OpenGL ES), the EGL device platform
// (a GPU without a display: NVIDIA's driver has no surfaceless platform) and a hidden GLFW
// window (macOS, which has neither). Either way the runner draws into its own framebuffer
// object, so all give the same picture. OSMesa and EGL are optional at build time
// (SHADOWS_HAVE_OSMESA, SHADOWS_HAVE_EGL); OSMesa is loaded at run time, only when asked for.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace shadows {

class HeadlessContext {
 public:
  virtual ~HeadlessContext() = default;
  // Which API's context is current, asked of EGL, OSMesa and GLFW themselves (not the option
  // that requested one, so a silent fallback shows): "egl", "egl-device", "osmesa", "glfw" or
  // "none".
  static std::string current();
};

// The headless backends this build offers for its API, the default first.
std::vector<std::string> headlessBackends();

// "" or why `value` is not a headless backend of this build: "--backend: expected osmesa, egl,
// egl-device or glfw".
std::string checkBackend(const std::string& value);

// Creates a context of this build's API (4.5 or 4.1 core, or OpenGL ES 3.0), makes it current
// and loads GL through glad. `device` is the EGL device's index (egl-device only). Throws
// GlFailure when no context can be had.
std::unique_ptr<HeadlessContext> createHeadlessContext(const std::string& backend, int device = 0);

// Asked before anything is rendered: "" when `backend` can have `device`, else one line and
// the exit code (2: no such device, the line lists those there are; 1: this EGL cannot
// enumerate devices).
std::string headlessProblem(const std::string& backend, int device, int& exit_code);

// The EGL device of the current egl-device context (index -1 when there is none).
struct EglDeviceChoice {
  int index = -1;
  std::string name;
  size_t count = 0;  // devices there were to choose from
};
EglDeviceChoice currentEglDevice();
// "--device 3: no such EGL device (there are 0: ...; 1: ...)".
std::string eglDeviceMissing(int index, const std::vector<std::string>& names);

// The GLFW window hints for a context of this build's API (the window and the hidden-window
// backend): 4.5 core, 4.1 core forward-compatible (what macOS requires), or OpenGL ES 3.0.
void setGlfwContextHints();
// What this build asks for, for messages: "a 4.5 core context", ...
const char* contextName();

}  // namespace shadows
