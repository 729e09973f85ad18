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

// Colour RGBA8 with depth and stencil.
class PictureTarget {
 public:
  void ensure(int width, int height);
  GLuint id() const { return framebuffer_ ? framebuffer_->id() : 0; }
  Image read(int width, int height) const;  // bottom-up rows, as the PNGs are written
  void release() { *this = PictureTarget(); }

 private:
  Texture color_, depth_;
  std::unique_ptr<Framebuffer> framebuffer_;
  int width_ = 0, height_ = 0;
};

// Colour RGBA32F with depth and stencil: allocated only where the truth or the texel numbers
// are measured (a --no-truth run without --report never clears its 20 bytes a pixel, a fifth
// of a short headless run on llvmpipe). Throws GlFailure without float colour targets.
class FloatTarget {
 public:
  void ensure(int width, int height);
  GLuint id() const { return framebuffer_ ? framebuffer_->id() : 0; }
  void release() { *this = FloatTarget(); }

 private:
  Texture color_, depth_;
  std::unique_ptr<Framebuffer> framebuffer_;
  int width_ = 0, height_ = 0;
};

// The GL state every pass of the runner's starts from (and every lesson's frame).
void resetGlState();

}  // namespace shadows
