// The runner's off-screen targets, each allocated at the size first asked for and again only
// when it changes: the picture's (what a headless run draws and reads back, and the frames
// without shadow the cost is measured against) and the float one the truth and the texel
// numbers read back.
#pragma once

#include <memory>

#include "core/image.hpp"
#include "gl/gl.hpp"
#include "gl/program.hpp"

namespace shadows {

// Colour of one format with depth and stencil.
class OffscreenTarget {
 public:
  explicit OffscreenTarget(GLenum format) : format_(format) {}
  void ensure(int width, int height);
  GLuint id() const { return framebuffer_ ? framebuffer_->id() : 0; }
  void release();

 private:
  GLenum format_;
  Texture color_, depth_;
  std::unique_ptr<Framebuffer> framebuffer_;
  int width_ = 0, height_ = 0;
};

// RGBA8: the picture.
class PictureTarget : public OffscreenTarget {
 public:
  PictureTarget() : OffscreenTarget(GL_RGBA8) {}
  Image read(int width, int height) const;  // bottom-up rows, as the PNGs are written
};

// RGBA32F: allocated only where the truth or the texel numbers are measured (a --no-truth run
// without --report never clears its 20 bytes a pixel, a fifth of a short headless run on
// llvmpipe). ensure() throws GlFailure without float colour targets.
class FloatTarget : public OffscreenTarget {
 public:
  FloatTarget() : OffscreenTarget(GL_RGBA32F) {}
};

// The GL state every pass of the runner's starts from (and every lesson's frame).
void resetGlState();

}  // namespace shadows
