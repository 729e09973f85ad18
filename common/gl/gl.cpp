#include "gl/gl.hpp"

#include <cstdio>
#include <fstream>
#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <sstream>

#include "gl/measure.hpp"

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

Buffer::Buffer(GLenum target, GLsizeiptr bytes, const void* data, GLenum usage)
    : target_(target), bytes_(bytes) {
  GLuint id = 0;
  glGenBuffers(1, &id);
  name_ = GlName<deleteBuffer>(id);
  glBindBuffer(target, id);
  glBufferData(target, bytes, data, usage);
}

void Buffer::update(GLsizeiptr bytes, const void* data) const {
  glBindBuffer(target_, name_.id());
  glBufferSubData(target_, 0, bytes, data);
}

CounterBuffer::CounterBuffer([[maybe_unused]] int count) {
#if SHADOWS_GL_VERSION >= 430 && !SHADOWS_GLES
  if (!caps().storage_buffers) return;
  count_ = count;
  GLuint id = 0;
  glGenBuffers(1, &id);
  name_ = GlName<deleteBuffer>(id);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(count * sizeof(GLuint)), nullptr,
               GL_DYNAMIC_READ);
#endif
}

void CounterBuffer::zeroAndBind([[maybe_unused]] GLuint index) const {
#if SHADOWS_GL_VERSION >= 430 && !SHADOWS_GLES
  if (!name_) return;
  const std::vector<GLuint> zero(static_cast<size_t>(count_), 0u);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, name_.id());
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                  static_cast<GLsizeiptr>(zero.size() * sizeof(GLuint)), zero.data());
#endif
}

std::vector<GLuint> CounterBuffer::read() const {
  std::vector<GLuint> counts(static_cast<size_t>(count_), 0u);
#if SHADOWS_GL_VERSION >= 430 && !SHADOWS_GLES
  if (!name_) return counts;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, name_.id());
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                     static_cast<GLsizeiptr>(counts.size() * sizeof(GLuint)), counts.data());
#endif
  return counts;
}

void SamplesPassedQuery::begin() {
  if (!caps().samples_passed) return;
  if (!name_) {
    GLuint id = 0;
    glGenQueries(1, &id);
    name_ = GlName<deleteQuery>(id);
  }
  glBeginQuery(GL_SAMPLES_PASSED, name_.id());
}

void SamplesPassedQuery::end() const {
  if (caps().samples_passed) glEndQuery(GL_SAMPLES_PASSED);
}

std::optional<long long> SamplesPassedQuery::result() const {
#if !SHADOWS_GLES
  if (caps().samples_passed) {
    GLuint64 samples = 0;
    glGetQueryObjectui64v(name_.id(), GL_QUERY_RESULT, &samples);
    return static_cast<long long>(samples);
  }
#endif
  return std::nullopt;
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
#if !SHADOWS_GLES
  if (caps().clip_distance) set(GL_CLIP_DISTANCE0, clip_plane);
#endif
}

Framebuffer::Framebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  name_ = GlName<deleteFramebuffer>(id);
}

void Framebuffer::attachDepth(const Texture& depth, int cubeFace) {
  glBindFramebuffer(GL_FRAMEBUFFER, name_.id());
  const GLenum target = cubeFace >= 0
                            ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(cubeFace)
                            : GL_TEXTURE_2D;
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, target, depth.id(), 0);
  if (draw_buffers_.empty()) {
    // Depth only: no colour is written or read.
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
  }
}

void Framebuffer::attachDepthLayered([[maybe_unused]] const Texture& cube) {
#if SHADOWS_GLES
  throw GlFailure("layered framebuffers need GL 3.2 or ES 3.2");
#else
  glBindFramebuffer(GL_FRAMEBUFFER, name_.id());
  glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, cube.id(), 0);
  const GLenum none = GL_NONE;
  glDrawBuffers(1, &none);
  glReadBuffer(GL_NONE);
#endif
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
  if (!caps().debug_output) return;  // glGetError alone (poll)
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
#if SHADOWS_GLES
  glDebugMessageCallbackKHR(onDebugMessage, nullptr);
#else
  glDebugMessageCallback(onDebugMessage, nullptr);
#endif
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
