#include "gl.hpp"

#include <cstdio>
#include <fstream>
#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <sstream>

#include "measure.hpp"

namespace shadows {

void deleteTexture(GLuint id) {
  glDeleteTextures(1, &id);
}
void deleteFramebuffer(GLuint id) {
  glDeleteFramebuffers(1, &id);
}
void deleteBuffer(GLuint id) {
  glDeleteBuffers(1, &id);
}
void deleteVertexArray(GLuint id) {
  glDeleteVertexArrays(1, &id);
}
void deleteProgram(GLuint id) {
  glDeleteProgram(id);
}
void deleteQuery(GLuint id) {
  glDeleteQueries(1, &id);
}
void deleteSampler(GLuint id) {
  glDeleteSamplers(1, &id);
}

Sampler Sampler::depth(bool compare, GLenum filter) {
  Sampler sampler;
  GLuint id = 0;
  glGenSamplers(1, &id);
  sampler.name_ = GlName<deleteSampler>(id);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glSamplerParameterfv(id, GL_TEXTURE_BORDER_COLOR, border);
  return sampler;
}

Texture Texture::depth(int width, int height, int bits) {
  Texture t = create(GL_TEXTURE_2D, width, height);
  const GLenum internal = bits == 16   ? GL_DEPTH_COMPONENT16
                          : bits == 24 ? GL_DEPTH_COMPONENT24
                                       : GL_DEPTH_COMPONENT32F;
  const GLenum type = bits == 32 ? GL_FLOAT : GL_UNSIGNED_INT;
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), width, height, 0, GL_DEPTH_COMPONENT,
               type, nullptr);
  // Outside the map counts as "nothing in front": depth 1 at the border.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  t.setFilter(GL_NEAREST);
  return t;
}

Texture Texture::depthStencil(int width, int height) {
  Texture t = create(GL_TEXTURE_2D, width, height);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH24_STENCIL8, width, height);
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

Texture Texture::color(int width, int height, GLenum internalFormat) {
  Texture t = create(GL_TEXTURE_2D, width, height);
  glTexStorage2D(GL_TEXTURE_2D, 1, internalFormat, width, height);
  t.setWrap(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  t.setFilter(GL_LINEAR);
  return t;
}

Texture Texture::table1D(int width, GLenum internalFormat, GLenum format, const void* pixels) {
  Texture t = create(GL_TEXTURE_1D, width, 1);
  glTexStorage1D(GL_TEXTURE_1D, 1, internalFormat, width);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 0, width, format, GL_UNSIGNED_BYTE, pixels);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  t.setFilter(GL_NEAREST);
  return t;
}

void Texture::upload(GLenum format, GLenum type, const void* pixels) const {
  glBindTexture(target_, name_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(target_, 0, 0, 0, width_, height_, format, type, pixels);
}

void Texture::setWrap(GLenum s, GLenum t) const {
  glBindTexture(target_, name_.id());
  glTexParameteri(target_, GL_TEXTURE_WRAP_S, static_cast<GLint>(s));
  glTexParameteri(target_, GL_TEXTURE_WRAP_T, static_cast<GLint>(t));
}

void Texture::setBorder(const glm::vec4& color) const {
  glBindTexture(target_, name_.id());
  glTexParameterfv(target_, GL_TEXTURE_BORDER_COLOR, &color[0]);
}

void Texture::setSwizzle(GLenum r, GLenum g, GLenum b, GLenum a) const {
  const GLint swizzle[4] = {static_cast<GLint>(r), static_cast<GLint>(g), static_cast<GLint>(b),
                            static_cast<GLint>(a)};
  glBindTexture(target_, name_.id());
  glTexParameteriv(target_, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
}

void Texture::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(target_, name_.id());
}

void Texture::setFilter(GLenum minMag) const {
  glBindTexture(target_, name_.id());
  glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minMag));
  glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(minMag));
}

Buffer::Buffer(GLenum target, GLsizeiptr bytes, const void* data, GLenum usage)
    : target_(target), bytes_(bytes) {
  GLuint id = 0;
  glGenBuffers(1, &id);
  name_ = GlName<deleteBuffer>(id);
  glBindBuffer(target, id);
  glBufferData(target, bytes, data, usage);
}

void SamplesPassedQuery::begin() {
  if (!name_) {
    GLuint id = 0;
    glGenQueries(1, &id);
    name_ = GlName<deleteQuery>(id);
  }
  glBeginQuery(GL_SAMPLES_PASSED, name_.id());
}

long long SamplesPassedQuery::result() const {
  GLuint64 samples = 0;
  glGetQueryObjectui64v(name_.id(), GL_QUERY_RESULT, &samples);
  return static_cast<long long>(samples);
}

void PassState::apply() const {
  const auto set = [](GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); };
  set(GL_DEPTH_TEST, depth_test);
  glDepthFunc(depth_func);
  glDepthMask(depth_write ? GL_TRUE : GL_FALSE);
  const GLboolean color = color_write ? GL_TRUE : GL_FALSE;
  glColorMask(color, color, color, color);
  set(GL_CULL_FACE, cull);
  glCullFace(cull_face);
  set(GL_POLYGON_OFFSET_FILL, polygon_offset);
  glPolygonOffset(offset_factor, offset_units);
  set(GL_BLEND, blend);
  glBlendFunc(blend_src, blend_dst);
  set(GL_STENCIL_TEST, stencil_test);
  glStencilFunc(stencil_func, stencil_ref, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, stencil_pass);
  glStencilMask(0xFF);
}

void Texture::setCompare(bool compare) const {
  glBindTexture(GL_TEXTURE_2D, name_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE,
                  compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

Framebuffer::Framebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  name_ = GlName<deleteFramebuffer>(id);
}

void Framebuffer::attachDepth(const Texture& depth) {
  glBindFramebuffer(GL_FRAMEBUFFER, name_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0);
  if (draw_buffers_.empty()) {
    // Depth only: no colour is written or read.
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
  }
}

void Framebuffer::attachDepthStencil(const Texture& depthStencil) {
  glBindFramebuffer(GL_FRAMEBUFFER, name_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                         depthStencil.id(), 0);
}

void Framebuffer::attachColor(const Texture& color, int index) {
  glBindFramebuffer(GL_FRAMEBUFFER, name_.id());
  const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index);
  glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, color.id(), 0);
  draw_buffers_.push_back(attachment);
  glDrawBuffers(static_cast<GLsizei>(draw_buffers_.size()), draw_buffers_.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
}

void Framebuffer::check() const {
  glBindFramebuffer(GL_FRAMEBUFFER, name_.id());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char msg[64];
    std::snprintf(msg, sizeof msg, "framebuffer incomplete (0x%04x)", status);
    throw GlFailure(msg);
  }
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, name_.id());
}

Mesh::Mesh(const MeshData& data) {
  const auto& vertices = data.vertices;
  const auto& indices = data.indices;
  GLuint ids[3] = {};
  glGenVertexArrays(1, &ids[0]);
  glGenBuffers(2, &ids[1]);
  vao_ = GlName<deleteVertexArray>(ids[0]);
  vbo_ = GlName<deleteBuffer>(ids[1]);
  ebo_ = GlName<deleteBuffer>(ids[2]);
  glBindVertexArray(ids[0]);
  glBindBuffer(GL_ARRAY_BUFFER, ids[1]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ids[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glBindVertexArray(0);
  index_count_ = static_cast<GLsizei>(indices.size());
}

void Mesh::draw() const {
  countDrawCall();
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

namespace {
int g_error_count = 0;
int g_count_at_last_poll = 0;
std::string g_last_error;

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei,
                               const GLchar* message, const void*) {
  // A shader that does not compile is reported once, by Program, with file:line.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  if (type == GL_DEBUG_TYPE_ERROR) {
    ++g_error_count;
    g_last_error = message;
    std::fprintf(stderr, "GL error: %s\n", message);
  } else if (severity == GL_DEBUG_SEVERITY_HIGH) {
    std::fprintf(stderr, "GL: %s\n", message);
  }
}
}  // namespace

void GlErrorLog::install() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
}

int GlErrorLog::poll() {
  // Errors the callback already counted are also latched by glGetError; count the
  // latched ones only when the callback saw nothing since the last poll.
  int latched = 0;
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) ++latched;
  if (latched > 0 && g_error_count == g_count_at_last_poll) {
    g_error_count += latched;
    g_last_error = "glGetError reported an error the debug callback missed";
    std::fprintf(stderr, "GL error: %s\n", g_last_error.c_str());
  }
  g_count_at_last_poll = g_error_count;
  return g_error_count;
}

int GlErrorLog::count() {
  return g_error_count;
}
void GlErrorLog::reset() {
  g_error_count = 0;
  g_count_at_last_poll = 0;
}
const std::string& GlErrorLog::last() {
  return g_last_error;
}

}  // namespace shadows
