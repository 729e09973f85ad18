// GL helpers with a real (headless) context: shader errors name file and line, #include
// works, and the error log catches every GL error.
#include "gl/context.hpp"
#include "gl/gl.hpp"
#include "gl/program.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace shadows {
namespace {

namespace fs = std::filesystem;

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext("osmesa");
    GlErrorLog::install();
  }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("shadows_gl_" + std::to_string(getpid()));
    fs::create_directories(dir_);
    GlErrorLog::poll();
    GlErrorLog::reset();
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  static std::unique_ptr<HeadlessContext> context_;
  fs::path dir_;
};
std::unique_ptr<HeadlessContext> GlTest::context_;

const char* kVertex =
    "#version 330 core\nlayout(location = 0) in vec3 p;\nvoid main() { gl_Position = "
    "vec4(p, 1.0); }\n";

TEST_F(GlTest, IncludesAreInlinedFromTheFilesDirectoryThenCommonShaders) {
  write("local.glsl", "float localThing() { return 1.0; }\n");
  const auto frag = write("a.frag",
                          "#version 330 core\n#include \"local.glsl\"\n#include "
                          "\"lighting.glsl\"\nout vec4 c;\nvoid main() { c = "
                          "vec4(localThing()); }\n");
  const ShaderSource source = preprocessShader(frag);
  EXPECT_NE(source.text.find("localThing() { return 1.0; }"), std::string::npos);
  EXPECT_NE(source.text.find("shadeSurface"), std::string::npos) << "from common/shaders";
  ASSERT_EQ(source.files.size(), 3u);
  EXPECT_EQ(source.files[1], "local.glsl");
  EXPECT_NO_THROW(Program(write("v.vert", kVertex), frag));
}

TEST_F(GlTest, CompileErrorsNameTheFileAndLineEvenInsideAnInclude) {
  write("broken.glsl", "float ok() { return 1.0; }\nfloat bad() { return undefined_name; }\n");
  const auto frag = write("main.frag",
                          "#version 330 core\n#include \"broken.glsl\"\nout vec4 c;\n"
                          "void main() { c = vec4(bad()); }\n");
  try {
    Program program(write("v.vert", kVertex), frag);
    FAIL() << "a broken shader compiled";
  } catch (const GlFailure& e) {
    EXPECT_NE(std::string(e.what()).find("broken.glsl:2"), std::string::npos) << e.what();
  }
  const auto frag2 =
      write("second.frag", "#version 330 core\nout vec4 c;\n\nvoid main() { c = 1; }\n");
  try {
    Program program(write("v.vert", kVertex), frag2);
    FAIL() << "a broken shader compiled";
  } catch (const GlFailure& e) {
    EXPECT_NE(std::string(e.what()).find("second.frag:4"), std::string::npos) << e.what();
  }
}

TEST_F(GlTest, MissingFilesAndIncludesAreClearErrors) {
  EXPECT_THROW(Program(dir_ / "nope.vert", dir_ / "nope.frag"), GlFailure);
  const auto frag = write("m.frag", "#version 330 core\n#include \"absent.glsl\"\n");
  try {
    preprocessShader(frag);
    FAIL();
  } catch (const GlFailure& e) {
    EXPECT_NE(std::string(e.what()).find("m.frag:2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("absent.glsl"), std::string::npos) << e.what();
  }
}

TEST_F(GlTest, EveryGlErrorIsCounted) {
  EXPECT_EQ(GlErrorLog::poll(), 0);
  glEnable(0xFFFF);  // GL_INVALID_ENUM
  EXPECT_EQ(GlErrorLog::poll(), 1);
  glBindTexture(GL_TEXTURE_2D, 987654);  // not a texture name: GL_INVALID_OPERATION
  EXPECT_EQ(GlErrorLog::poll(), 2);
  EXPECT_FALSE(GlErrorLog::last().empty());
}

TEST_F(GlTest, IncompleteFramebufferIsReported) {
  Framebuffer empty;
  EXPECT_THROW(empty.check(), GlFailure);
}

// One program per set of defines, compiled when first asked for and then reused.
TEST_F(GlTest, VariantsCompileOncePerSetOfDefinesAndSayWhichRan) {
  const auto frag = write("v.frag",
                          "#version 330 core\nout vec4 c;\nvoid main() {\n#if MODE == MODE_B\n"
                          "  c = vec4(1.0);\n#else\n  c = vec4(0.0);\n#endif\n}\n");
  ProgramVariants variants(write("v.vert", kVertex), frag);
  const long long before = ProgramVariants::compiledTotal();
  ProgramVariants::takeUsed();
  const std::vector<std::string> a = {"MODE_A 0", "MODE_B 1", "MODE MODE_A"};
  const std::vector<std::string> b = {"MODE_A 0", "MODE_B 1", "MODE MODE_B"};
  const GLuint first = variants.get({a, define("EXTRA", 1)}).id();
  EXPECT_EQ(variants.get({a, define("EXTRA", 1)}).id(), first) << "cached, not recompiled";
  const GLuint other = variants.get({b, define("EXTRA", 1)}).id();
  EXPECT_NE(other, first);
  EXPECT_EQ(variants.get({a, define("EXTRA", 1)}).id(), first);
  EXPECT_EQ(variants.compiled(), 2u);
  EXPECT_EQ(ProgramVariants::compiledTotal() - before, 2);
  EXPECT_EQ(
      ProgramVariants::takeUsed(),
      (std::vector<std::string>{"v.frag: MODE=MODE_A, EXTRA=1", "v.frag: MODE=MODE_A, EXTRA=1",
                                "v.frag: MODE=MODE_B, EXTRA=1", "v.frag: MODE=MODE_A, EXTRA=1"}));
  EXPECT_TRUE(ProgramVariants::takeUsed().empty());
  EXPECT_EQ(GlErrorLog::poll(), 0);
}

}  // namespace
}  // namespace shadows

namespace shadows {
namespace {

// What lesson 16 reports of a technique (TextureBytes, gl/gl.hpp): a texture's storage is on
// the tally that was current when it was created, every level and face of it, moved with the
// texture and off the tally when it goes; one created under no tally counts nowhere.
TEST_F(GlTest, TexturesTallyTheirStorageWhileTheyLive) {
  TextureBytes tally;
  {
    const TextureBytes::Scope counted(tally);
    Texture depth16 = Texture::depth(64, 32, 16);  // 2 bytes a texel
    EXPECT_EQ(tally.bytes(), 64 * 32 * 2);
    Texture cube = Texture::depthCube(16, 24);  // 6 faces of 4 bytes a texel
    EXPECT_EQ(tally.bytes(), 64 * 32 * 2 + 6 * 16 * 16 * 4);
    cube = Texture();
    EXPECT_EQ(tally.bytes(), 64 * 32 * 2);
    // Every level: 8x8, 4x4, 2x2, 1x1 of RG32F (8 bytes).
    Texture mipmapped = Texture::color(8, 8, GL_RG32F, /*mipmapped=*/true);
    EXPECT_EQ(tally.bytes(), 64 * 32 * 2 + 8 * (64 + 16 + 4 + 1));
    {
      const auto uncounted = TextureBytes::Scope::none();
      const Texture measuring = Texture::color(32, 32, GL_RGBA32F);
      EXPECT_EQ(tally.bytes(), 64 * 32 * 2 + 8 * 85) << "a measurement's target";
    }
    Texture moved = std::move(depth16);
    EXPECT_EQ(tally.bytes(), 64 * 32 * 2 + 8 * 85) << "counted once, moved or not";
  }
  EXPECT_EQ(tally.bytes(), 0) << "every texture gone, every byte off the tally";
  const Texture outside = Texture::color(4, 4, GL_RGBA8);  // no Scope: the runner's own
  EXPECT_EQ(tally.bytes(), 0);
  EXPECT_EQ(GlErrorLog::poll(), 0);
}

}  // namespace
}  // namespace shadows
