// Shader programs from files: #include resolved, compile errors as file:line, variants
// selected by #defines and compiled on first use.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <sstream>
#include <utility>

#include "core/text.hpp"
#include "gl/program.hpp"

namespace shadows {

std::filesystem::path bundledDataDir() {
  // Asked once: the binary's own place, links resolved (a lesson in a bundle may be a link).
  static const std::filesystem::path dir = [] {
    std::error_code error;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return std::filesystem::path();
    auto share = exe.parent_path().parent_path() / "share" / "shadows";
    return std::filesystem::is_directory(share, error) ? share : std::filesystem::path();
  }();
  return dir;
}

std::filesystem::path commonShaderDir() {
  const auto bundled = bundledDataDir();
  return bundled.empty() ? std::filesystem::path(SHADOWS_COMMON_SHADER_DIR)
                         : bundled / "common" / "shaders";
}

std::filesystem::path lessonFile(const std::string& lessonDir, const std::string& file) {
  const auto bundled = bundledDataDir();
  const std::filesystem::path dir(lessonDir);
  return (bundled.empty() ? dir : bundled / dir.filename()) / file;
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

}  // namespace

std::string versionLines(const std::string& fileVersion, const Caps& c) {
  // A file states the desktop GLSL it was written for ("#version 430 core"); what it needs
  // beyond 4.1 it asks for under HAS_* (Caps::shaderDefines).
  if (c.es) {
    // No default precision for floats in ES fragment shaders, nor for the shadow samplers:
    // everything highp, as desktop GLSL computes it.
    return "#version 300 es\n"
           "precision highp float;\nprecision highp int;\n"
           "precision highp sampler2D;\nprecision highp sampler2DShadow;\n"
           "precision highp samplerCube;\nprecision highp samplerCubeShadow;\n";
  }
  int number = 330;
  std::sscanf(fileVersion.c_str(), " #version %d", &number);
  if (number > c.glsl_version) return "#version " + std::to_string(c.glsl_version) + " core\n";
  return fileVersion + "\n";
}

namespace {

// The floor of issue 56 (scripts/neutral_floor.sh): a variant's source as the GL gets it,
// named by its file and a hash of that text. SHADOWS_SHADER_DUMP=DIR writes each there;
// SHADOWS_SHADER_FLOOR=DIR compiles DIR's file of that name, where it has one (the variant
// with its neutral code stripped by hand), in its place, and says so on stderr. A file whose
// name no source hashes to any more is stale, and the script says so.
void floorSource(const std::filesystem::path& file, std::string& text) {
  const auto folder = [](const char* name) -> const char* {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0' ? value : nullptr;
  };
  static const char* dump = folder("SHADOWS_SHADER_DUMP");
  static const char* floor = folder("SHADOWS_SHADER_FLOOR");
  if (dump == nullptr && floor == nullptr) return;
  std::uint32_t hash = 2166136261u;  // FNV-1a
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
  char suffix[16];
  std::snprintf(suffix, sizeof suffix, "-%08x", hash);
  const std::string name = file.stem().string() + suffix + file.extension().string();
  if (dump != nullptr) {
    std::error_code ignored;  // a folder that cannot be made writes nothing
    std::filesystem::create_directories(dump, ignored);
    std::ofstream(std::filesystem::path(dump) / name, std::ios::binary) << text;
  }
  if (floor == nullptr) return;
  const std::filesystem::path stripped = std::filesystem::path(floor) / name;
  std::error_code none;
  if (!std::filesystem::is_regular_file(stripped, none)) return;
  text = readFile(stripped);
  std::fprintf(stderr, "shader floor: %s\n", name.c_str());
}

GLuint compile(GLenum stage, const std::filesystem::path& file,
               const std::vector<std::string>& defines) {
  ShaderSource src = preprocessShader(file);
  // The version line as this context takes it, then the context's HAS_* and the variant's
  // defines (the #line directive after them keeps error lines the file's own).
  std::string head;
  for (const std::string& d : caps().shaderDefines()) head += "#define " + d + "\n";
  for (const std::string& d : defines) head += "#define " + d + "\n";
  const size_t version = src.text.find("#version");
  if (version == std::string::npos) {
    head = versionLines("#version 330 core", caps()) + head;
    src.text.insert(0, head);
  } else {
    const size_t end = src.text.find('\n', version);
    head = versionLines(src.text.substr(version, end - version), caps()) + head;
    src.text.replace(version, end + 1 - version, head);
  }
  floorSource(file, src.text);
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

namespace {
// The shortest decimal that reads back as `v`, with a point or an exponent so that GLSL takes
// it as a float.
std::string glslFloat(float v) {
  std::string out = shortestDecimal(v);
  if (out.find_first_of(".en") == std::string::npos) out += ".0";
  return out;
}
}  // namespace

std::string defineVec2Array(const std::string& name, const std::vector<glm::vec2>& values) {
  std::string line = name + " vec2[](";
  for (size_t i = 0; i < values.size(); ++i) {
    line +=
        (i ? ", vec2(" : "vec2(") + glslFloat(values[i].x) + ", " + glslFloat(values[i].y) + ")";
  }
  return line + ")";
}

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
                 const std::vector<std::string>& defines)
    : Program(vertexFile, {}, fragmentFile, defines) {}

Program::Program(const std::filesystem::path& vertexFile, const std::filesystem::path& geometryFile,
                 const std::filesystem::path& fragmentFile,
                 const std::vector<std::string>& defines) {
  std::vector<GLuint> shaders;
  const auto release = [&] {
    for (const GLuint shader : shaders) glDeleteShader(shader);
  };
  try {
    shaders.push_back(compile(GL_VERTEX_SHADER, vertexFile, defines));
    if (!geometryFile.empty()) {
#if SHADOWS_GLES
      throw GlFailure(geometryFile.filename().string() + ": no geometry shaders on " +
                      caps().flavour);
#else
      if (!caps().geometry_shaders) {
        throw GlFailure(geometryFile.filename().string() + ": no geometry shaders here");
      }
      shaders.push_back(compile(GL_GEOMETRY_SHADER, geometryFile, defines));
#endif
    }
    shaders.push_back(compile(GL_FRAGMENT_SHADER, fragmentFile, defines));
  } catch (...) {
    release();
    throw;
  }
  const GLuint program = glCreateProgram();
  for (const GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  release();
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

namespace {
std::vector<std::string> g_used;
long long g_compiled = 0;

// "1": every feature kept; "A,B": those named; empty: none.
std::string& keptFeatures() {
  static std::string kept = [] {
    const char* value = std::getenv("SHADOWS_KEEP_NEUTRAL_CODE");
    return std::string(value != nullptr ? value : "");
  }();
  return kept;
}
}  // namespace

bool neutralCodeKept(const std::string& name) {
  const std::string& kept = keptFeatures();
  return kept == "1" || ("," + kept + ",").find("," + name + ",") != std::string::npos;
}

std::vector<std::string> feature(const std::string& name, bool working) {
  return define(name, working || neutralCodeKept(name) ? 1 : 0);
}

void keepNeutralCode(bool keep) {
  keptFeatures() = keep ? "1" : "";
}

const Program& ProgramVariants::get(std::initializer_list<std::vector<std::string>> parts) {
  std::vector<std::string> defines;
  std::string key, selected;
  for (const auto& part : parts) {
    for (const std::string& d : part) {
      defines.push_back(d);
      key += d + ";";
    }
    // A part's last line is what it selects ("PCF_MODE PCF_MODE_GRID"; the lines before it
    // name the choices).
    if (!part.empty()) {
      std::string line = part.back();
      std::replace(line.begin(), line.end(), ' ', '=');
      selected += (selected.empty() ? "" : ", ") + line;
    }
  }
  g_used.push_back(fragment_.filename().string() + ": " + selected);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    it = programs_.emplace(key, Program(vertex_, geometry_, fragment_, defines)).first;
    ++g_compiled;
  }
  return it->second;
}

std::vector<std::string> ProgramVariants::takeUsed() {
  return std::exchange(g_used, {});
}

long long ProgramVariants::compiledTotal() {
  return g_compiled;
}

GLint Program::location(const std::string& name) const {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(name_.id(), name.c_str());
  locations_.emplace(name, loc);
  return loc;
}

// glProgramUniform* on desktop GL (4.1 has it). OpenGL ES 3.0 sets uniforms only on the
// program in use: there it is bound for the call and the one in use put back.
#if SHADOWS_GLES
namespace {
class InUse {
 public:
  explicit InUse(GLuint program) : program_(program) {
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    previous_ = static_cast<GLuint>(current);
    if (previous_ != program_) glUseProgram(program_);
  }
  ~InUse() {
    if (previous_ != program_) glUseProgram(previous_);
  }
  InUse(const InUse&) = delete;
  InUse& operator=(const InUse&) = delete;

 private:
  GLuint program_, previous_ = 0;
};
}  // namespace
#define SHADOWS_SET(call, ...)             \
  do {                                     \
    const InUse in_use(name_.id());        \
    gl##call(location(name), __VA_ARGS__); \
  } while (false)
#else
#define SHADOWS_SET(call, ...) glProgram##call(name_.id(), location(name), __VA_ARGS__)
#endif

void Program::set(const std::string& name, int v) const {
  SHADOWS_SET(Uniform1i, v);
}
void Program::set(const std::string& name, float v) const {
  SHADOWS_SET(Uniform1f, v);
}
void Program::set(const std::string& name, const glm::vec2& v) const {
  SHADOWS_SET(Uniform2fv, 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::vec3& v) const {
  SHADOWS_SET(Uniform3fv, 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::vec4& v) const {
  SHADOWS_SET(Uniform4fv, 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::mat4& v) const {
  SHADOWS_SET(UniformMatrix4fv, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const std::string& name, const std::vector<glm::vec2>& v) const {
  if (v.empty()) return;
  SHADOWS_SET(Uniform2fv, static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}

void Program::bindBlock(const std::string& block, GLuint binding) const {
  const GLuint index = glGetUniformBlockIndex(name_.id(), block.c_str());
  if (index != GL_INVALID_INDEX) glUniformBlockBinding(name_.id(), index, binding);
}

}  // namespace shadows
