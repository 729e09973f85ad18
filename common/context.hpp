// Headless GL contexts behind one small interface: OSMesa (the default on desktop GL), EGL
// surfaceless (Mesa 25.1 removed OSMesa; the only one for OpenGL ES) and a hidden GLFW window
// (macOS, which has neither). Either way the runner draws into its own framebuffer object, so
// all give the same picture. OSMesa and EGL are optional at build time (SHADOWS_HAVE_OSMESA,
// SHADOWS_HAVE_EGL).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace shadows {

class HeadlessContext {
 public:
  virtual ~HeadlessContext() = default;
  // Which API's context is current, asked of EGL, OSMesa and GLFW themselves (not the option
  // that requested one, so a silent fallback shows): "egl", "osmesa", "glfw" or "none".
  static std::string current();
};

// The headless backends this build offers for its API, the default first.
std::vector<std::string> headlessBackends();

// Creates a context of this build's API (4.5 or 4.1 core, or OpenGL ES 3.0), makes it current
// and loads GL through glad. Throws GlFailure when no context can be had.
std::unique_ptr<HeadlessContext> createHeadlessContext(const std::string& backend);

// The GLFW window hints for a context of this build's API (the window and the hidden-window
// backend): 4.5 core, 4.1 core forward-compatible (what macOS requires), or OpenGL ES 3.0.
void setGlfwContextHints();
// What this build asks for, for messages: "a 4.5 core context", ...
const char* contextName();

}  // namespace shadows
