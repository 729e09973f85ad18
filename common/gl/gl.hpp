// Thin RAII over the GL objects the lessons use, shader programs built from files with
// #include and file:line errors, and the debug-output callback that counts GL errors.
#pragma once

#include "gl/gl_api.hpp"

#include <array>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/scene.hpp"
#include "gl/caps.hpp"

namespace shadows {

// A runtime failure: no context, a shader that does not compile (message has file:line).
struct GlFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Moves, never copies, a GL name; the deleter runs once.
template <void (*Delete)(GLuint)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint id) : id_(id) {}
  GlName(GlName&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  ~GlName() { reset(); }
  void reset() {
    if (id_ != 0) Delete(id_);
    id_ = 0;
  }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  GLuint id_ = 0;
};

void deleteTexture(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteBuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteProgram(GLuint id);
void deleteQuery(GLuint id);
void deleteSampler(GLuint id);

// Bytes of texture storage one part of the program holds (lesson 16 asks it of each technique
// it runs: "bytes of maps"). A texture created while a Scope lives is counted against its tally
// until it is destroyed; the others (the runner's targets) against none.
class TextureBytes {
 public:
  long long bytes() const { return bytes_; }
  class Scope {
   public:
    explicit Scope(TextureBytes& tally) : was_(std::exchange(current_, &tally)) {}
    // Textures that are no part of what is counted: a lesson's measuring targets.
    static Scope none() { return Scope(nullptr); }
    ~Scope() { current_ = was_; }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    explicit Scope(TextureBytes* tally) : was_(std::exchange(current_, tally)) {}
    TextureBytes* was_;
  };
  // One texture's share: on the tally from its creation to its destruction, moved with it.
  class Share {
   public:
    Share() = default;
    explicit Share(long long bytes) : tally_(current_), bytes_(bytes) {
      if (tally_ != nullptr) tally_->bytes_ += bytes_;
    }
    Share(Share&& o) noexcept : tally_(std::exchange(o.tally_, nullptr)), bytes_(o.bytes_) {}
    Share& operator=(Share&& o) noexcept {
      if (this != &o) {
        release();
        tally_ = std::exchange(o.tally_, nullptr);
        bytes_ = o.bytes_;
      }
      return *this;
    }
    ~Share() { release(); }

   private:
    void release() {
      if (tally_ != nullptr) tally_->bytes_ -= bytes_;
      tally_ = nullptr;
    }
    TextureBytes* tally_ = nullptr;
    long long bytes_ = 0;
  };

 private:
  long long bytes_ = 0;
  static inline TextureBytes* current_ = nullptr;
};

class Texture {
 public:
  // A depth texture for a shadow map: bits = 16, 24 or 32 (32 = float).
  static Texture depth(int width, int height, int bits);
  // A cube map of depth, six size x size faces (lesson 11's omni light), bits as depth(); its
  // faces are framebuffer attachments one at a time (Framebuffer::attachDepth's face).
  static Texture depthCube(int size, int bits);
  // Depth + stencil for the runner's own colour targets (GL_DEPTH24_STENCIL8).
  static Texture depthStencil(int width, int height);
  // A colour texture: GL_RGBA8, GL_RGBA32F, GL_R8, ...; `mipmapped`: with every level down to
  // 1x1, filled by generateMipmaps() (lesson 13's moments).
  static Texture color(int width, int height, GLenum internalFormat, bool mipmapped = false);
  // A 1D texture (GL_R8, GL_RG8, ...) filled from `pixels` (`format`, unsigned bytes), read
  // NEAREST and clamped to its edge texels: a lookup table such as a ramp. Where there are no
  // 1D textures (OpenGL ES) a width x 1 2D texture, the same texels (common/shaders/ramp.glsl
  // reads either).
  static Texture table1D(int width, GLenum internalFormat, GLenum format, const void* pixels);
  // Replaces every texel of a 2D texture with `pixels` (tightly packed rows).
  void upload(GLenum format, GLenum type, const void* pixels) const;
  void bind(int unit) const;
  void setFilter(GLenum minMag);
  // The levels below the first from the first (a mipmapped texture's; nothing otherwise).
  void generateMipmaps() const;
  // Anisotropic filtering up to `amount` where the context has it (Caps::max_anisotropy).
  void setAnisotropy(float amount) const;
  int levels() const { return levels_; }
  // GL_CLAMP_TO_BORDER becomes GL_CLAMP_TO_EDGE where there is no border (Caps::border_clamp):
  // the shaders then test their lookups themselves (common/shaders/border.glsl).
  void setWrap(GLenum s, GLenum t) const;
  void setBorder(const glm::vec4& color);
  // Which stored channel each of r, g, b, a reads (GL_RED, GL_GREEN, GL_ZERO, GL_ONE, ...).
  // Without Caps::texture_swizzle (WebGL 2) only kept: the image shader applies it.
  void setSwizzle(GLenum r, GLenum g, GLenum b, GLenum a);
  const std::array<GLenum, 4>& swizzle() const { return swizzle_; }
  // Makes a depth texture a sampler2DShadow (GL_COMPARE_REF_TO_TEXTURE) or a plain one.
  void setCompare(bool compare) const;
  GLuint id() const { return name_.id(); }
  GLenum target() const { return target_; }
  // The border colour setBorder gave it, and its filter: what a shader needs to emulate the
  // border where the GL has none.
  const std::optional<glm::vec4>& border() const { return border_; }
  GLenum filter() const { return filter_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  static Texture create(GLenum target, int width, int height);
  GlName<deleteTexture> name_;
  GLenum target_ = GL_TEXTURE_2D;
  GLenum filter_ = GL_NEAREST_MIPMAP_LINEAR;  // the GL's default
  std::array<GLenum, 4> swizzle_{GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
  std::optional<glm::vec4> border_;
  int width_ = 0, height_ = 0, levels_ = 1;
  TextureBytes::Share bytes_;  // its storage, on the tally of whoever created it
};

// Linear lookups in cube maps blend across face edges (GL_TEXTURE_CUBE_MAP_SEAMLESS) or not;
// where the switch is missing (Caps::seamless_cube_switch: ES 3.0, WebGL 2 always blend
// across) nothing changes.
void setSeamlessCubeFiltering(bool on);

// A buffer object (vertex data, a uniform block, a pixel-pack buffer).
class Buffer {
 public:
  Buffer() = default;
  Buffer(GLenum target, GLsizeiptr bytes, const void* data, GLenum usage);
  void bind() const { glBindBuffer(target_, name_.id()); }
  void bindBase(GLuint index) const { glBindBufferBase(target_, index, name_.id()); }
  // Replaces the first `bytes` of the buffer.
  void update(GLsizeiptr bytes, const void* data) const;
  GLuint id() const { return name_.id(); }
  GLsizeiptr bytes() const { return bytes_; }

 private:
  GlName<deleteBuffer> name_;
  GLenum target_ = GL_ARRAY_BUFFER;
  GLsizeiptr bytes_ = 0;
};

// Unsigned counters a fragment shader adds to with atomics (lesson 05's taps): a shader
// storage buffer at binding `index`. Only where Caps::storage_buffers says so (GL 4.3).
class CounterBuffer {
 public:
  CounterBuffer() = default;
  explicit CounterBuffer(int count);
  void zeroAndBind(GLuint index) const;
  std::vector<GLuint> read() const;  // after the draws that count: waits for them

 private:
  GlName<deleteBuffer> name_;
  int count_ = 0;
};

// How many samples passed every test (depth, stencil, discard) between begin() and end():
// the fragments a pass really wrote, where fragment-shader invocations also count the
// discarded ones. OpenGL ES has only boolean occlusion queries: there begin() and end() do
// nothing and result() is empty (the count is unavailable, never a wrong number).
class SamplesPassedQuery {
 public:
  void begin();  // creates the query object the first time (a context is current by then)
  void end() const;
  std::optional<long long> result() const;  // waits for the GPU

 private:
  GlName<deleteQuery> name_;
};

// The fixed-function state one pass needs, stated in full: apply() sets every field, so
// nothing a previous pass left enabled leaks into the next. The defaults are the state every
// lesson starts its frame with.
struct PassState {
  bool depth_test = true;
  GLenum depth_func = GL_LESS;
  bool depth_write = true;
  bool color_write = true;
  bool cull = false;
  GLenum cull_face = GL_BACK;
  bool polygon_offset = false;
  float offset_factor = 0.0f, offset_units = 0.0f;
  bool blend = false;
  GLenum blend_src = GL_ONE, blend_dst = GL_ZERO;
  bool stencil_test = false;
  GLenum stencil_func = GL_ALWAYS;
  GLint stencil_ref = 0;
  GLenum stencil_pass = GL_KEEP;  // what a fragment that passes depth and stencil writes
  // User clip plane 0 (gl_ClipDistance[0]; on OpenGL ES the shader discards instead,
  // common/shaders/clip_distance.glsl, and this changes nothing).
  bool clip_plane = false;
  void apply() const;
};

// How a texture unit reads, overriding the texture's own state: one depth texture can be
// read both with a compare (sampler2DShadow) and raw (sampler2D) from the same shader.
class Sampler {
 public:
  // For depth maps: compare (GL_LEQUAL, the shadow test) or raw, nearest or linear, and
  // depth 1 ("nothing in front") outside the map.
  static Sampler depth(bool compare, GLenum filter = GL_NEAREST);
  void bind(int unit) const { glBindSampler(static_cast<GLuint>(unit), name_.id()); }
  static void unbind(int unit) { glBindSampler(static_cast<GLuint>(unit), 0); }

 private:
  GlName<deleteSampler> name_;
};

class Framebuffer {
 public:
  Framebuffer();
  // `cubeFace` 0..5 (+x, -x, +y, -y, +z, -z): that face of a cube map.
  void attachDepth(const Texture& depth, int cubeFace = -1);
  // Every face of a cube map at once, for a pass that picks the face per primitive
  // (gl_Layer from a geometry shader; desktop GL 3.2).
  void attachDepthLayered(const Texture& cube);
  void attachDepthStencil(const Texture& depthStencil);
  void attachColor(const Texture& color, int index = 0);
  void check() const;  // throws GlFailure when incomplete
  void bind() const;
  GLuint id() const { return name_.id(); }

 private:
  GlName<deleteFramebuffer> name_;
  std::vector<GLenum> draw_buffers_;
};

class Mesh {
 public:
  Mesh() = default;
  explicit Mesh(const MeshData& data);
  void draw() const;
  GLsizei indexCount() const { return index_count_; }

 private:
  GlName<deleteVertexArray> vao_;
  GlName<deleteBuffer> vbo_, ebo_;
  GLsizei index_count_ = 0;
};

// Counts GL errors reported through KHR_debug (where the context has it, Caps::debug_output),
// and glGetError as a backstop.
class GlErrorLog {
 public:
  static void install();  // call once per context, after loading GL
  static int poll();      // drains glGetError into the count; returns the total so far
  static int count();
  static void reset();
  static const std::string& last();
};

}  // namespace shadows
