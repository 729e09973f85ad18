// Textures and samplers: depth maps (2D and cube), colour targets, 1D tables, their filtering,
// wrapping, borders, swizzles and compare mode, each where the flavour has it (gl.hpp).
#include <algorithm>

#include "gl/gl.hpp"

namespace shadows {

Sampler Sampler::depth(bool compare, GLenum filter) {
  Sampler sampler;
  GLuint id = 0;
  glGenSamplers(1, &id);
  sampler.name_ = GlName<deleteSampler>(id);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  const GLint wrap = caps().border_clamp ? GL_CLAMP_TO_BORDER : GL_CLAMP_TO_EDGE;
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, wrap);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, wrap);
#if !SHADOWS_GLES
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  if (caps().border_clamp) glSamplerParameterfv(id, GL_TEXTURE_BORDER_COLOR, border);
#endif
  return sampler;
}

namespace {
// The bytes a texture of this format holds, every level down from width x height: the
// format's own size (a 24-bit depth is stored in 4 bytes, as the GL's implementations do).
long long storageBytes(GLenum internalFormat, int width, int height, int levels = 1) {
  long long per_texel = 4;
  switch (internalFormat) {
    case GL_R8:
      per_texel = 1;
      break;
    case GL_RG8:
    case GL_DEPTH_COMPONENT16:
    case GL_R16F:
      per_texel = 2;
      break;
    case GL_RG16F:
      per_texel = 4;
      break;
    case GL_RG32F:
    case GL_RGBA16F:
      per_texel = 8;
      break;
    case GL_RGBA32F:
      per_texel = 16;
      break;
    default:  // RGBA8, R32F, depth 24 and 32F, depth 24 + stencil 8
      break;
  }
  long long bytes = 0;
  for (int level = 0; level < levels; ++level) {
    bytes += per_texel * std::max(1, width >> level) * std::max(1, height >> level);
  }
  return bytes;
}

// A depth map's storage for 16, 24 or 32 (float) bits: its internal format and the pixel type
// glTexImage2D takes with it.
struct DepthFormat {
  GLint internal;
  GLenum type;
};
DepthFormat depthFormat(int bits) {
  const GLenum internal = bits == 16   ? GL_DEPTH_COMPONENT16
                          : bits == 24 ? GL_DEPTH_COMPONENT24
                                       : GL_DEPTH_COMPONENT32F;
  return {static_cast<GLint>(internal), bits == 32 ? GLenum{GL_FLOAT} : GLenum{GL_UNSIGNED_INT}};
}
}  // namespace

Texture Texture::depth(int width, int height, int bits) {
  Texture t = create(GL_TEXTURE_2D, width, height);
  const DepthFormat format = depthFormat(bits);
  glTexImage2D(GL_TEXTURE_2D, 0, format.internal, width, height, 0, GL_DEPTH_COMPONENT, format.type,
               nullptr);
  t.bytes_ = TextureBytes::Share(storageBytes(static_cast<GLenum>(format.internal), width, height));
  // Outside the map counts as "nothing in front": depth 1 at the border.
  t.setWrap(GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
  t.setBorder(glm::vec4(1.0f));
  t.setFilter(GL_NEAREST);
  return t;
}

void setSeamlessCubeFiltering([[maybe_unused]] bool on) {
#if !SHADOWS_GLES
  if (!caps().seamless_cube_switch) return;
  on ? glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS) : glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
#endif
}

Texture Texture::depthCube(int size, int bits) {
  Texture t = create(GL_TEXTURE_CUBE_MAP, size, size);
  const DepthFormat format = depthFormat(bits);
  for (GLenum face = 0; face < 6; ++face) {
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, format.internal, size, size, 0,
                 GL_DEPTH_COMPONENT, format.type, nullptr);
  }
  t.bytes_ =
      TextureBytes::Share(6 * storageBytes(static_cast<GLenum>(format.internal), size, size));
  // Every direction lands on some face: no border, and the edge texels are the face's own.
  t.setWrap(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  t.setFilter(GL_NEAREST);
  return t;
}

namespace {
// Storage for one level of a 2D texture: immutable where the API has it (GL 4.2, ES 3.0), else
// glTexImage2D with the format and type that go with the internal format (GL 4.1).
void allocate2D(GLenum internalFormat, int width, int height, int levels = 1) {
#if SHADOWS_GL_VERSION >= 420 || SHADOWS_GLES
  glTexStorage2D(GL_TEXTURE_2D, levels, internalFormat, width, height);
#else
  GLenum format = GL_RGBA, type = GL_UNSIGNED_BYTE;
  switch (internalFormat) {
    case GL_DEPTH24_STENCIL8:
      format = GL_DEPTH_STENCIL, type = GL_UNSIGNED_INT_24_8;
      break;
    case GL_RGBA32F:
      type = GL_FLOAT;
      break;
    case GL_R8:
      format = GL_RED;
      break;
    case GL_RG8:
      format = GL_RG;
      break;
    case GL_RG32F:  // lesson 13's moments
      format = GL_RG, type = GL_FLOAT;
      break;
    case GL_RG16F:
      format = GL_RG, type = GL_HALF_FLOAT;
      break;
    default:
      break;
  }
  for (int level = 0; level < levels; ++level) {
    glTexImage2D(GL_TEXTURE_2D, level, static_cast<GLint>(internalFormat),
                 std::max(1, width >> level), std::max(1, height >> level), 0, format, type,
                 nullptr);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);  // complete with these
#endif
}
}  // namespace

Texture Texture::depthStencil(int width, int height) {
  Texture t = create(GL_TEXTURE_2D, width, height);
  allocate2D(GL_DEPTH24_STENCIL8, width, height);
  t.bytes_ = TextureBytes::Share(storageBytes(GL_DEPTH24_STENCIL8, width, height));
  return t;
}

Texture Texture::create(GLenum target, int width, int height) {
  Texture t;
  GLuint id = 0;
  glGenTextures(1, &id);
  t.name_ = GlName<deleteTexture>(id);
  t.target_ = target;
  t.width_ = width;
  t.height_ = height;
  glBindTexture(target, id);
  return t;
}

Texture Texture::color(int width, int height, GLenum internalFormat, bool mipmapped) {
  Texture t = create(GL_TEXTURE_2D, width, height);
  int levels = 1;
  while (mipmapped && std::max(width, height) >> levels > 0) ++levels;
  t.levels_ = levels;
  allocate2D(internalFormat, width, height, levels);
  t.bytes_ = TextureBytes::Share(storageBytes(internalFormat, width, height, levels));
  t.setWrap(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  t.setFilter(GL_LINEAR);
  return t;
}

Texture Texture::table1D(int width, GLenum internalFormat, GLenum format, const void* pixels) {
#if !SHADOWS_GLES
  if (caps().texture_1d) {
    Texture t = create(GL_TEXTURE_1D, width, 1);
    glTexImage1D(GL_TEXTURE_1D, 0, static_cast<GLint>(internalFormat), width, 0, format,
                 GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAX_LEVEL, 0);
    t.bytes_ = TextureBytes::Share(storageBytes(internalFormat, width, 1));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage1D(GL_TEXTURE_1D, 0, 0, width, format, GL_UNSIGNED_BYTE, pixels);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    t.setFilter(GL_NEAREST);
    return t;
  }
#endif
  // No 1D textures (OpenGL ES): one row of a 2D texture holds the same texels.
  Texture t = color(width, 1, internalFormat);
  t.upload(format, GL_UNSIGNED_BYTE, pixels);
  t.setFilter(GL_NEAREST);
  return t;
}

void Texture::upload(GLenum format, GLenum type, const void* pixels) const {
  glBindTexture(target_, name_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(target_, 0, 0, 0, width_, height_, format, type, pixels);
}

void Texture::setWrap(GLenum s, GLenum t) const {
  const auto wrap = [](GLenum mode) {
    return static_cast<GLint>(mode == GL_CLAMP_TO_BORDER && !caps().border_clamp ? GL_CLAMP_TO_EDGE
                                                                                 : mode);
  };
  glBindTexture(target_, name_.id());
  glTexParameteri(target_, GL_TEXTURE_WRAP_S, wrap(s));
  glTexParameteri(target_, GL_TEXTURE_WRAP_T, wrap(t));
}

void Texture::setBorder([[maybe_unused]] const glm::vec4& color) {
  border_ = color;
#if !SHADOWS_GLES
  if (!caps().border_clamp) return;
  glBindTexture(target_, name_.id());
  glTexParameterfv(target_, GL_TEXTURE_BORDER_COLOR, &color[0]);
#endif
}

void Texture::setSwizzle(GLenum r, GLenum g, GLenum b, GLenum a) {
  swizzle_ = {r, g, b, a};
  if (!caps().texture_swizzle) return;
  // One channel at a time: GL_TEXTURE_SWIZZLE_RGBA is desktop only.
  glBindTexture(target_, name_.id());
  glTexParameteri(target_, GL_TEXTURE_SWIZZLE_R, static_cast<GLint>(r));
  glTexParameteri(target_, GL_TEXTURE_SWIZZLE_G, static_cast<GLint>(g));
  glTexParameteri(target_, GL_TEXTURE_SWIZZLE_B, static_cast<GLint>(b));
  glTexParameteri(target_, GL_TEXTURE_SWIZZLE_A, static_cast<GLint>(a));
}

void Texture::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(target_, name_.id());
}

void Texture::setFilter(GLenum minMag) {
  filter_ = minMag;
  glBindTexture(target_, name_.id());
  // A mipmapped texture minifies between its levels (trilinear) when asked for LINEAR.
  const GLenum min = levels_ > 1 && minMag == GL_LINEAR ? GL_LINEAR_MIPMAP_LINEAR : minMag;
  glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
  glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(minMag));
}

void Texture::generateMipmaps() const {
  if (levels_ <= 1) return;
  glBindTexture(target_, name_.id());
  glGenerateMipmap(target_);
}

void Texture::setAnisotropy(float amount) const {
  if (!(caps().max_anisotropy > 1.0f)) return;
  constexpr GLenum kMaxAnisotropy = 0x84FE;  // GL 4.6 core, EXT/ARB_texture_filter_anisotropic
  glBindTexture(target_, name_.id());
  glTexParameterf(target_, kMaxAnisotropy, std::min(amount, caps().max_anisotropy));
}

void Texture::setCompare(bool compare) const {
  glBindTexture(target_, name_.id());
  glTexParameteri(target_, GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  glTexParameteri(target_, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

}  // namespace shadows
