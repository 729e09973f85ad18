#include "run/gl_targets.hpp"

namespace shadows {

void OffscreenTarget::ensure(int width, int height) {
  if (width == width_ && height == height_) return;
  // OpenGL ES renders float colour only with EXT_color_buffer_float (which WebGL 2 offers too).
  if (format_ == GL_RGBA32F && !caps().float_color_targets) {
    throw GlFailure("no float colour targets (EXT_color_buffer_float) for the truth's passes");
  }
  width_ = width, height_ = height;
  color_ = Texture::color(width, height, format_);
  depth_ = Texture::depthStencil(width, height);
  framebuffer_ = std::make_unique<Framebuffer>();
  framebuffer_->attachColor(color_);
  framebuffer_->attachDepthStencil(depth_);
  framebuffer_->check();
}

void OffscreenTarget::release() {
  framebuffer_.reset();
  color_ = Texture();
  depth_ = Texture();
  width_ = height_ = 0;
}

Image PictureTarget::read(int width, int height) const {
  Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  glBindFramebuffer(GL_FRAMEBUFFER, id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  return image;
}

void resetGlState() {
  PassState{}.apply();
#if !SHADOWS_GLES
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
#endif
}

}  // namespace shadows
