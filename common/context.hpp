// Headless GL contexts behind one small interface: OSMesa (the default) and EGL
// surfaceless (Mesa 25.1 removed OSMesa; EGL is where headless Mesa goes next). Either way
// the runner draws into its own framebuffer object, so both give the same picture.
#pragma once

#include <memory>
#include <string>

namespace shadows {

class HeadlessContext {
 public:
  virtual ~HeadlessContext() = default;
  // Which API's context is current, asked of EGL and OSMesa themselves (not the option that
  // requested one, so a silent fallback shows): "egl", "osmesa", or "none".
  static std::string current();
};

// Creates a 4.5 core context, makes it current and loads GL through glad.
// backend: "osmesa" or "egl". Throws GlFailure when no context can be had.
std::unique_ptr<HeadlessContext> createHeadlessContext(const std::string& backend);

}  // namespace shadows
