// A program from shader files: #include, file:line errors, variants by #define.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "gl/gl.hpp"

namespace shadows {

// A vertex + fragment program read from files. `#include "x.glsl"` is resolved against the
// including file's directory, then the shared common/shaders directory. Compile errors
// name the original file and line. `defines` ("PASS 2", ...) select a variant of a shader
// written with #if blocks: each is compiled with only the code its settings need.
class Program {
 public:
  Program() = default;
  Program(const std::filesystem::path& vertexFile, const std::filesystem::path& fragmentFile,
          const std::vector<std::string>& defines = {});
  // With a geometry shader between them (Caps::geometry_shaders: desktop GL 3.2; throws
  // GlFailure where the flavour has none).
  Program(const std::filesystem::path& vertexFile, const std::filesystem::path& geometryFile,
          const std::filesystem::path& fragmentFile, const std::vector<std::string>& defines);
  void use() const;
  GLint location(const std::string& name) const;
  void set(const std::string& name, int v) const;
  void set(const std::string& name, float v) const;
  void set(const std::string& name, const glm::vec2& v) const;
  void set(const std::string& name, const glm::vec3& v) const;
  void set(const std::string& name, const glm::vec4& v) const;
  void set(const std::string& name, const glm::mat4& v) const;
  void set(const std::string& name, const std::vector<glm::vec2>& v) const;  // an array
  // Binds the uniform block `block` to the buffer binding point `binding`.
  void bindBlock(const std::string& block, GLuint binding) const;
  GLuint id() const { return name_.id(); }

 private:
  GlName<deleteProgram> name_;
  mutable std::map<std::string, GLint> locations_;
};

// One vertex + fragment pair compiled per set of defines, on first use, and kept: a lesson
// whose views and modes are #if blocks of one shader runs only the block its settings need.
class ProgramVariants {
 public:
  ProgramVariants() = default;
  ProgramVariants(std::filesystem::path vertexFile, std::filesystem::path fragmentFile)
      : vertex_(std::move(vertexFile)), fragment_(std::move(fragmentFile)) {}
  // With a geometry shader (lesson 11's layered pass), compiled on first use like the rest.
  ProgramVariants(std::filesystem::path vertexFile, std::filesystem::path geometryFile,
                  std::filesystem::path fragmentFile)
      : vertex_(std::move(vertexFile)),
        geometry_(std::move(geometryFile)),
        fragment_(std::move(fragmentFile)) {}
  // The program for these defines, each part the lines one setting contributes:
  // get({pcf_mode_.defines(), define("PCF_COUNT", counting), frame.viewDefines()}).
  const Program& get(std::initializer_list<std::vector<std::string>> parts);
  // How many variants this one compiled so far.
  size_t compiled() const { return programs_.size(); }
  // Every get() since the last call, as "scene.frag: PCF_MODE=PCF_MODE_GRID, ...": the runner
  // records which variant each pass of a frame ran (the report's shader_variants).
  static std::vector<std::string> takeUsed();
  // Programs compiled by every ProgramVariants so far (the report's shader_variants_compiled).
  static long long compiledTotal();

 private:
  std::filesystem::path vertex_, geometry_, fragment_;
  std::map<std::string, Program> programs_;  // by the defines, joined
};

// One #define line, "NAME value", for a setting that is not a parameter (a pass number).
inline std::vector<std::string> define(const std::string& name, int value) {
  return {name + " " + std::to_string(value)};
}

// A feature's #if block, compiled only where its setting does work. At the setting's neutral
// value (a blend of 0, a normal offset of 0) the code would change no pixel and still run for
// every one: feature(name, working) leaves it out there. keepNeutralCode(true), or
// SHADOWS_KEEP_NEUTRAL_CODE=1 in the environment (or =A,B: the features named), compiles the
// code in anyway, so a test can see that leaving it out changes nothing and
// scripts/neutral_code.sh can count what it saves.
std::vector<std::string> feature(const std::string& name, bool working);
void keepNeutralCode(bool keep);
// Whether the neutral code of `name` is kept (as above): for work a lesson skips in C++ rather
// than in a shader (08's slices at air.density=0), so the same switch draws it anyway.
bool neutralCodeKept(const std::string& name);

// One #define line "NAME vec2[](vec2(x, y), ...)": constants computed in C++ compiled into a
// shader (`const vec2 k[N] = NAME;`). Each float is written so that it reads back as the same
// float, so the shader computes with exactly the values the C++ (and its tests) has.
std::string defineVec2Array(const std::string& name, const std::vector<glm::vec2>& values);

// The preprocessed source and the file behind each GLSL source-string number.
struct ShaderSource {
  std::string text;
  std::vector<std::string> files;
};
ShaderSource preprocessShader(const std::filesystem::path& file);
// Rewrites "0:12(5): error" style compiler messages into "file.frag:12: error".
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files);
std::filesystem::path commonShaderDir();
// A path next to a lesson's main.cpp (LESSON_DIR, fixed at build time; never the working
// directory), or the same file in a bundle.
std::filesystem::path lessonFile(const std::string& lessonDir, const std::string& file);
// A bundle (scripts/bundle.sh) keeps the shaders in bin/../share/shadows/, beside its binaries,
// and reads them from there wherever it is copied; empty for a binary of the build tree.
std::filesystem::path bundledDataDir();
// The lines that replace a file's "#version 430 core" on this context: the same where the API
// has that version, "#version 410 core" on a 4.1 build, "#version 300 es" and precision lines
// on OpenGL ES.
std::string versionLines(const std::string& fileVersion, const Caps& caps);

}  // namespace shadows
