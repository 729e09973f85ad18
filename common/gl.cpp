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
  Texture t;
  GLuint id = 0;
  glGenTextures(1, &id);
  t.name_ = GlName<deleteTexture>(id);
  t.width_ = width;
  t.height_ = height;
  const GLenum internal = bits == 16   ? GL_DEPTH_COMPONENT16
                          : bits == 24 ? GL_DEPTH_COMPONENT24
                                       : GL_DEPTH_COMPONENT32F;
  const GLenum type = bits == 32 ? GL_FLOAT : GL_UNSIGNED_INT;
  glBindTexture(GL_TEXTURE_2D, id);
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
  Texture t;
  GLuint id = 0;
  glGenTextures(1, &id);
  t.name_ = GlName<deleteTexture>(id);
  t.width_ = width;
  t.height_ = height;
  glBindTexture(GL_TEXTURE_2D, id);
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

std::filesystem::path commonShaderDir() {
  return SHADOWS_COMMON_SHADER_DIR;
}

namespace {

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw GlFailure("cannot read shader " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void appendWithIncludes(const std::filesystem::path& file, ShaderSource& out, int depth) {
  if (depth > 16) throw GlFailure(file.string() + ": #include nested too deep");
  const std::string index = std::to_string(out.files.size());
  out.files.push_back(file.filename().string());
  // GLSL wants #version first, so only included files start with their own #line.
  if (depth > 0) out.text += "#line 1 " + index + "\n";
  std::istringstream lines(readFile(file));
  std::string line;
  int number = 0;
  static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\")");
  while (std::getline(lines, line)) {
    ++number;
    std::smatch m;
    if (std::regex_search(line, m, include_re)) {
      auto target = file.parent_path() / m[1].str();
      if (!std::filesystem::exists(target)) target = commonShaderDir() / m[1].str();
      if (!std::filesystem::exists(target)) {
        throw GlFailure(file.filename().string() + ":" + std::to_string(number) +
                        ": cannot find include \"" + m[1].str() + "\"");
      }
      appendWithIncludes(target, out, depth + 1);
      out.text += "#line " + std::to_string(number + 1) + " " + index + "\n";
      continue;
    }
    out.text += line + "\n";
    if (depth == 0 && line.find("#version") != std::string::npos) {
      out.text += "#line " + std::to_string(number + 1) + " " + index + "\n";
    }
  }
}

GLuint compile(GLenum stage, const std::filesystem::path& file,
               const std::vector<std::string>& defines) {
  ShaderSource src = preprocessShader(file);
  // The variant's defines go right after #version (whose #line directive follows them, so
  // error lines still name the file's own lines).
  std::string define_lines;
  for (const std::string& d : defines) define_lines += "#define " + d + "\n";
  const size_t version = src.text.find("#version");
  const size_t after = version == std::string::npos ? 0 : src.text.find('\n', version) + 1;
  src.text.insert(after, define_lines);
  const GLuint shader = glCreateShader(stage);
  const char* text = src.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw GlFailure(mapShaderLog(log, src.files));
  }
  return shader;
}

}  // namespace

ShaderSource preprocessShader(const std::filesystem::path& file) {
  ShaderSource out;
  appendWithIncludes(file, out, 0);
  return out;
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files) {
  // Mesa writes "0:12(5): error: ..."; others "ERROR: 0:12: ...".
  static const std::regex where_re(R"((\d+):(\d+)(\(\d+\))?)");
  std::string out;
  std::smatch m;
  std::string rest = log;
  while (std::regex_search(rest, m, where_re)) {
    const size_t index = std::stoul(m[1].str());
    out += m.prefix().str();
    if (index < files.size()) {
      out += files[index] + ":" + m[2].str();
    } else {
      out += m[0].str();
    }
    rest = m.suffix().str();
  }
  out += rest;
  while (!out.empty() && (out.back() == '\n' || out.back() == '\0')) out.pop_back();
  return out;
}

Program::Program(const std::filesystem::path& vertexFile, const std::filesystem::path& fragmentFile,
                 const std::vector<std::string>& defines) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertexFile, defines);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentFile, defines);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    glDeleteProgram(program);
    throw GlFailure(vertexFile.filename().string() + " + " + fragmentFile.filename().string() +
                    ": link failed: " + log);
  }
  name_ = GlName<deleteProgram>(program);
}

void Program::use() const {
  glUseProgram(name_.id());
}

const Program& ProgramVariants::get(const std::vector<std::string>& defines) {
  std::string key;
  for (const std::string& d : defines) key += d + ";";
  auto it = programs_.find(key);
  if (it == programs_.end())
    it = programs_.emplace(key, Program(vertex_, fragment_, defines)).first;
  return it->second;
}

GLint Program::location(const std::string& name) const {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(name_.id(), name.c_str());
  locations_.emplace(name, loc);
  return loc;
}

void Program::set(const std::string& name, int v) const {
  glProgramUniform1i(name_.id(), location(name), v);
}
void Program::set(const std::string& name, float v) const {
  glProgramUniform1f(name_.id(), location(name), v);
}
void Program::set(const std::string& name, const glm::vec2& v) const {
  glProgramUniform2fv(name_.id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::vec3& v) const {
  glProgramUniform3fv(name_.id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::vec4& v) const {
  glProgramUniform4fv(name_.id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(name_.id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
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
