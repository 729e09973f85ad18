// Lesson 05 end to end, headless: the hardware's 2x2 compare filter on seed 000's example,
// every mode and view, the taps each kernel takes and the ones it skips (counted, not timed),
// the area light the truth uses, and cost against error for 4 dithered taps and 64.
#include "harness.hpp"

#include "core/json.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>

namespace shadows {
namespace {

using testing::counter;
using testing::label;
using testing::reportNumber;
using testing::startLesson;

const std::string kLesson = "05_pcf_dithered";

TEST(Lesson05, SnapshotMatchesTheGolden) {
  // Defaults (4 dithered taps over +-2 texels, dimming 0.4) on a 256² map, so the penumbrae
  // and their dither pattern cover enough pixels to matter. Tolerance and why in
  // tests/golden/README.md.
  auto runner = startLesson(kLesson, {"shadow.size=256"});
  runner->renderFrame();
  const Image image = runner->readImage();
  testing::expectMatchesGolden(image, "05_pcf_dithered");
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson05, LinearCompareOfTheSeed2x2MapIsHalfLitWhereTheAveragedDepthShadows) {
  // Seed 000 on the texture unit: a 2x2 depth map (0.25 0.63 / 0.25 0.63), looked up between
  // the four texel centres with reference depth 0.57. Through a GL_LINEAR compare sampler the
  // unit compares each texel, then blends: 0.5. Through a plain GL_LINEAR sampler it blends
  // the depths, 0.44, and 0.57 > 0.44 would put the pixel wrongly in shadow.
  auto runner = startLesson(kLesson, {}, 16, 16);  // for its GL context
  const auto dir = std::filesystem::temp_directory_path() / "shadows_test_lesson05";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "probe.vert") << "#version 330 core\n"
                                       "void main() {\n"
                                       "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                                       "  gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);\n"
                                       "}\n";
  std::ofstream(dir / "probe.frag") << "#version 330 core\n"
                                       "uniform sampler2DShadow uCompared;\n"
                                       "uniform sampler2D uBlended;\n"
                                       "uniform vec3 uCoord;\n"
                                       "out vec4 outColor;\n"
                                       "void main() {\n"
                                       "  outColor = vec4(texture(uCompared, uCoord),\n"
                                       "                  texture(uBlended, uCoord.xy).r, 0, 1);\n"
                                       "}\n";
  const Program probe(dir / "probe.vert", dir / "probe.frag");
  const Texture target = Texture::color(1, 1, GL_RGBA32F);
  Framebuffer framebuffer;
  framebuffer.attachColor(target);
  framebuffer.check();
  const Texture map = Texture::depth(2, 2, 32);
  const float depths[4] = {0.25f, 0.63f, 0.25f, 0.63f};  // rows bottom-up
  map.bind(0);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  map.bind(1);
  GLuint samplers[2];
  glGenSamplers(2, samplers);
  for (GLuint s : samplers) {
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glSamplerParameteri(samplers[0], GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(samplers[0], GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(samplers[1], GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glBindSampler(0, samplers[0]);
  glBindSampler(1, samplers[1]);
  framebuffer.bind();
  glViewport(0, 0, 1, 1);
  glDisable(GL_DEPTH_TEST);
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  probe.use();
  probe.set("uCompared", 0);
  probe.set("uBlended", 1);
  probe.set("uCoord", glm::vec3(0.5f, 0.5f, 0.57f));  // between the four texel centres
  glDrawArrays(GL_TRIANGLES, 0, 3);
  float pixel[4] = {-1, -1, -1, -1};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, pixel);
  EXPECT_NEAR(pixel[0], 0.5f, 0.02f) << "percentage closer: half the texels are in front";
  EXPECT_NEAR(pixel[1], 0.44f, 0.01f) << "the blended depth";
  EXPECT_GT(0.57f, pixel[1]) << "so comparing against it says shadowed";
  // Three quarters of the way toward the 0.63 column: 75% lit.
  probe.set("uCoord", glm::vec3(0.625f, 0.5f, 0.57f));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, pixel);
  EXPECT_NEAR(pixel[0], 0.75f, 0.02f);
  glBindSampler(0, 0);
  glBindSampler(1, 0);
  glDeleteSamplers(2, samplers);
  glDeleteVertexArrays(1, &vao);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson05, Hw2x2BlendsFourComparesWhereNoneIsOnlyLitOrShadowed) {
  // One lookup each; through the GL_LINEAR compare sampler the unit blends the 2x2 block's
  // results, so hw2x2's edges take values between 0 and 1 and nearest's never do.
  auto fractional = [](const std::string& mode) {
    auto runner = startLesson(kLesson, {"pcf.mode=" + mode, "shadow.size=128"}, 320, 240);
    runner->renderFrame();
    size_t between = 0;
    for (float v : runner->renderVisibility()) {
      // (The sky keeps the clear colour, whose red is not a shadow term.)
      between += v > 0.05f && v < 0.95f && v != Frame::kSky.r ? 1 : 0;
    }
    EXPECT_EQ(runner->glErrors(), 0) << mode;
    return between;
  };
  EXPECT_EQ(fractional("none"), 0u);
  EXPECT_GT(fractional("hw2x2"), 400u) << "soft 2x2 edges along every shadow";
}

TEST(Lesson05, EveryModeAndViewRendersWithoutGlErrorsOrNonFiniteValues) {
  auto runner = startLesson(kLesson, {"pcf.taps=64"}, 160, 120);
  for (const std::string& mode : runner->params().at("pcf.mode").choices) {
    ASSERT_EQ(runner->params().set("pcf.mode", mode), "");
    testing::expectEveryViewCleanAndDistinct(*runner, mode);
  }
}

TEST(Lesson05, EachKernelTakesTheTapsItSays) {
  // Counted in the shader (llvmpipe's statistics count fragments, not lookups). Without the
  // early out every filtered fragment takes exactly the kernel's taps.
  struct Case {
    std::vector<std::string> sets;
    long long taps_per_fragment;
  };
  const Case cases[] = {{{"pcf.mode=none"}, 1},
                        {{"pcf.mode=hw2x2"}, 1},  // one lookup; the unit reads 4 texels
                        {{"pcf.mode=dithered"}, 4},
                        {{"pcf.mode=grid", "pcf.taps=64"}, 64},
                        {{"pcf.mode=grid", "pcf.taps=20"}, 16},  // the largest square: 4 x 4
                        {{"pcf.mode=poisson", "pcf.taps=10"}, 10}};
  for (const Case& c : cases) {
    std::vector<std::string> sets = c.sets;
    sets.push_back("pcf.early_out=false");
    auto runner = startLesson(kLesson, sets, 160, 120);
    runner->renderFrame();
    const long long filtered = counter(*runner, "pcf_filtered_fragments");
    EXPECT_GT(filtered, 5000) << label(sets);
    EXPECT_EQ(counter(*runner, "pcf_taps"), c.taps_per_fragment * filtered) << label(sets);
    EXPECT_EQ(counter(*runner, "pcf_stopped_early"), 0) << label(sets);
    EXPECT_NEAR(reportNumber(*runner, "taps_per_filtered_fragment"),
                static_cast<double>(c.taps_per_fragment), 1e-9)
        << label(sets);
  }
}

TEST(Lesson05, CompiledKernelsDrawTheUniformArrayKernelsPicturesByteForByte) {
  // Each kernel is compiled into its variant (grid side, tap count and unit offsets as
  // constants, the radius a uniform) so that its loops unroll (issue 20). The pictures must not
  // move: these are FNV-1a hashes of the RGBA rows (bottom-up, Image::rgba) of pictures the
  // uniform-array shader drew (main at 04dd8d6: `05_pcf_dithered --headless --size 160x120
  // --set ...`, read back from its PNGs). Another Mesa may draw other bytes: then see
  // tests/golden/README.md.
  struct Case {
    std::vector<std::string> sets;
    std::uint64_t hash;
  };
  const Case cases[] = {
      {{"pcf.mode=grid", "pcf.taps=9", "pcf.radius=1.5", "pcf.early_out=false"},
       0x97450fcc4e6383e3},
      {{"pcf.mode=grid", "pcf.taps=9", "pcf.radius=1.5"}, 0x97450fcc4e6383e3},
      {{"pcf.mode=grid", "pcf.taps=64", "pcf.radius=2.3"}, 0x1e644bb74b403868},
      {{"pcf.mode=grid", "pcf.taps=20", "pcf.radius=4", "pcf.early_out=false"}, 0x74344000b8fdeb45},
      {{"pcf.mode=grid", "pcf.taps=4", "pcf.radius=1"}, 0x29c6d24c43d238d5},
      {{"pcf.mode=dithered", "pcf.radius=2.3"}, 0xb7f29954d644f9f9},
      {{"pcf.mode=dithered", "pcf.radius=16"}, 0xf35e1fd6eb1c708c},
      {{"pcf.mode=poisson", "pcf.taps=16", "pcf.radius=1.5"}, 0xd180b94017bbdac4},
      {{"pcf.mode=poisson", "pcf.taps=9", "pcf.radius=2.3", "pcf.early_out=false"},
       0xde554aa50a943b3d},
      {{"pcf.mode=poisson", "pcf.taps=64", "pcf.radius=4"}, 0xe84e6a14bb49b160},
      {{"pcf.mode=poisson", "pcf.taps=1", "pcf.radius=1"}, 0x68338609f7a939fb},
      {{"pcf.mode=none"}, 0x6c928200f3764fa4},
      {{"pcf.mode=hw2x2"}, 0x4f3de4ad178208d3},
      {{"view=taps", "pcf.mode=poisson", "pcf.taps=12", "pcf.radius=2.3"}, 0x6b88877adf59da0c},
      {{"view=visibility", "pcf.mode=grid", "pcf.taps=16"}, 0x1330b99b3d7e7f4d},
  };
  auto runner = startLesson(kLesson, {}, 160, 120);
  for (const Case& c : cases) {
    runner->params().resetToDefaults();
    for (const std::string& set : c.sets) ASSERT_EQ(runner->params().assign(set), "") << set;
    runner->renderFrame();
    std::uint64_t hash = 0xcbf29ce484222325;  // FNV-1a
    for (const std::uint8_t byte : runner->readImage().rgba) hash = (hash ^ byte) * 0x100000001b3;
    EXPECT_EQ(hash, c.hash) << label(c.sets) << ": hash 0x" << std::hex << hash;
  }
  EXPECT_EQ(runner->glErrors(), 0);
}

// pcf.lookup (issue 40): the same kernel read three ways draws the same shadow term, byte for
// byte, and the report says which lookup ran and why another did not.
TEST(Lesson05, EveryLookupDrawsTheComparesShadowByteForByte) {
  struct Case {
    std::vector<std::string> sets;
    const char* gather_runs;  // what pcf.lookup=gather runs for this kernel
  };
  const Case cases[] = {
      {{"pcf.mode=grid", "pcf.taps=9", "pcf.radius=1.5", "pcf.early_out=false"}, "gather"},
      {{"pcf.mode=grid", "pcf.taps=9", "pcf.radius=1.5"}, "gather"},
      {{"pcf.mode=grid", "pcf.taps=25", "pcf.radius=2.5"}, "gather"},  // odd: half blocks
      {{"pcf.mode=grid", "pcf.taps=16", "pcf.radius=2", "pcf.early_out=false"}, "gather"},
      {{"pcf.mode=grid", "pcf.taps=16", "pcf.radius=2"}, "gather"},  // corners only, early out
      {{"pcf.mode=grid", "pcf.taps=4", "pcf.radius=1"}, "gather"},   // 2 x 2: one lookup
      {{"pcf.mode=grid", "pcf.taps=64", "pcf.radius=4"}, "gather"},  // the loop between corners
      {{"pcf.mode=grid", "pcf.taps=49", "pcf.radius=3.5", "pcf.early_out=false"}, "gather"},
      {{"pcf.mode=grid", "pcf.taps=16", "pcf.radius=2.3"}, "compare"},  // not adjacent texels
      {{"pcf.mode=dithered"}, "compare"},
      {{"pcf.mode=poisson", "pcf.taps=16"}, "compare"},
      {{"pcf.mode=none"}, "compare"},
  };
  for (const char* scene : {"cubes", "dueling", "torus_pyramid"}) {
    for (const Case& c : cases) {
      std::vector<std::string> sets = c.sets;
      sets.push_back(std::string("scene=") + scene);
      sets.push_back("view=visibility");
      const auto render = [&](const std::string& lookup) {
        std::vector<std::string> all = sets;
        all.push_back("pcf.lookup=" + lookup);
        auto runner = startLesson(kLesson, all);
        runner->renderFrame();
        EXPECT_EQ(runner->glErrors(), 0) << label(sets) << " " << lookup;
        struct Result {
          std::vector<std::uint8_t> rgba;
          std::string used;
          long long lookups;
        } r{runner->readImage().rgba, testing::reportString(*runner, "/pcf_lookup_used"),
            counter(*runner, "pcf_taps")};
        return r;
      };
      const auto compare = render("compare"), fetch = render("fetch"), gather = render("gather");
      EXPECT_EQ(compare.used, "compare");
      EXPECT_EQ(fetch.used, "fetch") << label(sets);
      EXPECT_EQ(gather.used, c.gather_runs) << label(sets);
      EXPECT_TRUE(fetch.rgba == compare.rgba) << label(sets) << ": fetch";
      EXPECT_TRUE(gather.rgba == compare.rgba) << label(sets) << ": gather";
      EXPECT_EQ(fetch.lookups, compare.lookups) << label(sets);  // one texel a lookup
      // Four compares a lookup: a 3 x 3 grid every tap is 4 lookups, not 9.
      if (std::string(c.gather_runs) == "gather" && c.sets[1] == "pcf.taps=9" &&
          c.sets.size() == 4) {
        EXPECT_EQ(gather.lookups * 9, compare.lookups * 4) << label(sets);
      }
    }
  }
}

TEST(Lesson05, ALookupThatCannotRunSaysWhyAndTheCompareRuns) {
  const auto run = [](const std::vector<std::string>& sets) {
    auto runner = startLesson(kLesson, sets);
    runner->renderFrame();
    EXPECT_EQ(runner->glErrors(), 0);
    return std::pair{testing::reportString(*runner, "/pcf_lookup_used"),
                     testing::reportString(*runner, "/pcf_lookup_fallback")};
  };
  EXPECT_EQ(run({"pcf.mode=grid", "pcf.taps=9", "pcf.radius=1.5", "pcf.lookup=gather"}),
            std::pair(std::string("gather"), std::string()));
  const auto hw = run({"pcf.mode=hw2x2", "pcf.lookup=fetch"});
  EXPECT_EQ(hw.first, "compare");
  EXPECT_NE(hw.second.find("GL_LINEAR"), std::string::npos) << hw.second;
  const auto apart = run({"pcf.mode=grid", "pcf.radius=3", "pcf.lookup=gather"});
  EXPECT_EQ(apart.first, "compare");
  EXPECT_NE(apart.second.find("adjacent texels"), std::string::npos) << apart.second;
  // Where the context has no textureGather (gles30, WebGL 2; here switched off).
  std::pair<std::string, std::string> none;
  {
    const testing::CapsOff off("texture_gather");
    none = run({"pcf.mode=grid", "pcf.taps=9", "pcf.radius=1.5", "pcf.lookup=gather"});
  }
  EXPECT_EQ(none.first, "compare");
  EXPECT_NE(none.second.find("GL 4.0 or ES 3.1"), std::string::npos) << none.second;
}

TEST(Lesson05, EarlyOutSkipsMostTapsAndBarelyChangesTheShadow) {
  // 64 taps: where the 4 corner probes agree (fully lit or fully shadowed), the other 60 are
  // skipped. Only something smaller than the kernel hiding between the corners could differ.
  auto run = [](bool early) {
    auto runner =
        startLesson(kLesson, {"pcf.mode=grid", "pcf.taps=64",
                              std::string("pcf.early_out=") + (early ? "true" : "false")});
    runner->renderFrame();
    struct Result {
      long long taps, filtered, stopped;
      std::vector<float> visibility;
      double vis_mae;
    } r{counter(*runner, "pcf_taps"), counter(*runner, "pcf_filtered_fragments"),
        counter(*runner, "pcf_stopped_early"), runner->renderVisibility(),
        runner->measureError().metrics.vis_mae};
    return r;
  };
  const auto full = run(false), early = run(true);
  EXPECT_EQ(early.filtered, full.filtered);
  EXPECT_GT(early.stopped, early.filtered * 8 / 10) << "most of the picture is not an edge";
  EXPECT_LT(early.taps * 4, full.taps) << "over 4x fewer taps";
  EXPECT_EQ(early.taps, 4 * early.stopped + 64 * (early.filtered - early.stopped));
  size_t changed = 0;
  for (size_t i = 0; i < full.visibility.size(); ++i) {
    if (std::abs(full.visibility[i] - early.visibility[i]) > 0.02f) ++changed;
  }
  EXPECT_LT(static_cast<double>(changed), 0.002 * static_cast<double>(full.visibility.size()));
  EXPECT_NEAR(early.vis_mae, full.vis_mae, 0.0003);
}

TEST(Lesson05, FragmentsFacingAwayFromTheLightTakeNoTaps) {
  // dueling: the eye looks at the casters' unlit sides. Those fragments are in their own
  // shadow whatever the map says; the truth does not count them either.
  auto runner = startLesson(
      kLesson, {"scene=dueling", "pcf.mode=grid", "pcf.taps=64", "pcf.early_out=false"});
  runner->renderFrame();
  const long long away = counter(*runner, "pcf_skipped_facing_away");
  const long long filtered = counter(*runner, "pcf_filtered_fragments");
  EXPECT_GT(away, 3000);
  EXPECT_EQ(counter(*runner, "pcf_taps"), 64 * filtered) << "no taps for the ones facing away";
  EXPECT_EQ(runner->measureError().metrics.nonfinite_pixels, 0);
}

TEST(Lesson05, TheTruthIsTheAreaLightTheKernelImitates) {
  auto radius = [](const std::vector<std::string>& sets) {
    auto runner = startLesson(kLesson, sets, 160, 120);
    runner->renderFrame();
    const ErrorState& e = runner->measureError();
    const double r = reportNumber(*runner, "truth_area_radius");
    if (r > 0) {
      EXPECT_EQ(e.metrics.truth.rfind("area r=", 0), 0u) << label(sets);
    } else {
      EXPECT_EQ(e.metrics.truth, "point") << label(sets);
    }
    return r;
  };
  EXPECT_EQ(radius({"pcf.mode=none"}), 0.0);  // a hard shadow: the point light's truth
  EXPECT_EQ(radius({"pcf.mode=grid", "pcf.taps=1"}), 0.0);
  const double r2 = radius({"pcf.mode=grid", "pcf.radius=2"});
  EXPECT_GT(r2, 0.01);
  EXPECT_LT(r2, 1.0);
  EXPECT_NEAR(radius({"pcf.mode=grid", "pcf.radius=4"}), 2.0 * r2, 1e-4 * r2);
  EXPECT_NEAR(radius({"pcf.mode=dithered", "pcf.radius=2"}), r2, 1e-6);
  // The same kernel in texels of a map twice as fine blurs half as far: half the light.
  EXPECT_NEAR(radius({"pcf.mode=grid", "pcf.radius=2", "shadow.size=2048"}), 0.5 * r2, 1e-3 * r2);
  // hw2x2 blends over one texel: the light of a half-texel kernel.
  EXPECT_NEAR(radius({"pcf.mode=hw2x2"}), 0.25 * r2, 1e-4 * r2);
}

TEST(Lesson05, SixtyFourTapsAreCloserToTheTruthThanFourDitheredAndCostSixteenTimesTheTaps) {
  // The comparison of seed 001's "Comparison" slides, measured: same radius, so the same
  // area-light truth; early out off so the cost is the kernel's own.
  for (const std::string& scene : scenePresets()) {
    auto run = [&](const std::vector<std::string>& mode) {
      std::vector<std::string> sets = {"scene=" + scene, "pcf.radius=3", "pcf.early_out=false"};
      sets.insert(sets.end(), mode.begin(), mode.end());
      if (scene == "cubes") sets.push_back("camera.pos=-4,5,7");
      auto runner = startLesson(kLesson, sets);
      runner->renderFrame();
      return std::make_pair(runner->measureError().metrics, counter(*runner, "pcf_taps"));
    };
    const auto [grid, grid_taps] = run({"pcf.mode=grid", "pcf.taps=64"});
    const auto [dithered, dithered_taps] = run({"pcf.mode=dithered"});
    EXPECT_EQ(grid.truth, dithered.truth) << scene;
    EXPECT_LT(grid.vis_mae, dithered.vis_mae) << scene;
    EXPECT_EQ(grid_taps, 16 * dithered_taps) << scene;
  }
}

TEST(Lesson05, LessonFourBiasKeepsAcneAwayOnEveryPreset) {
  // The bias is lesson 04's default (back faces + glPolygonOffset(1.1, 4.0)): with no filter
  // the shadow is lesson 04's, within its bounds; the kernels must not bring acne back.
  for (const std::string& scene : scenePresets()) {
    for (const std::string mode : {"none", "grid", "poisson"}) {
      std::vector<std::string> sets = {"scene=" + scene, "shadow.size=2048", "pcf.mode=" + mode,
                                       "pcf.taps=64", "pcf.radius=4"};
      if (scene == "cubes") sets.push_back("camera.pos=-4,5,7");
      auto runner = startLesson(kLesson, sets);
      runner->renderFrame();
      const ErrorMetrics& e = runner->measureError().metrics;
      EXPECT_LE(e.false_shadow_pct, 0.2) << label(sets);
      EXPECT_LE(e.false_lit_pct, 1.0) << label(sets);
    }
  }
}

TEST(Lesson05, StaticFrameRendersNoMapAndFilterChangesDoNotEither) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "shadow_map_renders"), 1);
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "shadow_map_renders"), 0);
  for (const std::string set :
       {"pcf.mode=grid", "pcf.radius=5", "pcf.taps=9", "dimming=0.1", "pcf.early_out=false"}) {
    ASSERT_EQ(runner->params().assign(set), "");
    runner->renderFrame();
    EXPECT_EQ(counter(*runner, "shadow_map_renders"), 0) << set;
  }
  ASSERT_EQ(runner->params().assign("bias.factor=2"), "");
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "shadow_map_renders"), 1);
}

TEST(Lesson05, DimmingLeavesDiffuseLightInShadow) {
  // Seed 000: diffuseShade = dimming + (1 - dimming) * shade. With dimming 1 the shadow is
  // gone from the diffuse term (specular still needs light); with 0 it is black but ambient.
  auto mean = [](const std::string& dimming) {
    auto runner = startLesson(kLesson, {"dimming=" + dimming, "inset=false"});
    runner->renderFrame();
    const Image image = runner->readImage();
    double sum = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) sum += image.rgba[i] + image.rgba[i + 1];
    return sum / static_cast<double>(image.rgba.size() / 4);
  };
  const double none = mean("0"), slide = mean("0.4"), full = mean("1");
  EXPECT_LT(none, slide);
  EXPECT_LT(slide, full);
}

TEST(Lesson05, EveryInputOfTheMapRendersItAgainAndTheCachedFrameMatchesAnUncachedOne) {
  std::vector<std::string> inputs = testing::shadowMapInputs();
  inputs.insert(inputs.end(), {"bias.factor=2", "bias.units=40"});
  testing::expectEveryMapInputRendersTheMapAgain(kLesson, inputs);
}

TEST(Lesson05, MovingACasterRendersTheMapAgain) {
  testing::expectACasterMoveRendersTheMapAgain(kLesson);
}

TEST(Lesson05, SliderExtremesStayFiniteAndErrorFree) {
  std::vector<std::vector<std::string>> extremes = testing::shadowMapSliderExtremes();
  extremes.push_back({"bias.factor=0", "bias.units=0"});
  extremes.push_back({"bias.factor=20", "bias.units=10000000"});
  extremes.push_back({"pcf.count=false"});
  for (const std::string mode : {"none", "hw2x2", "grid", "dithered", "poisson"}) {
    extremes.push_back({"pcf.mode=" + mode, "pcf.radius=0", "pcf.taps=1"});
    extremes.push_back({"pcf.mode=" + mode, "pcf.radius=16", "pcf.taps=64", "shadow.size=64"});
    extremes.push_back({"pcf.mode=" + mode, "pcf.radius=16", "pcf.taps=64", "light.fov=160",
                        "light.type=directional", "light.extent=50"});
  }
  testing::expectFiniteAndErrorFree(kLesson, extremes);
}

}  // namespace
}  // namespace shadows

namespace shadows {
namespace {

TEST(Lesson05, ThePanelShowsTheLessonsOwnSlidersFirstAndFoldsTheSharedOnes) {
  // The lesson's idea (pcf.*) first and open; the shadow map's settings, the light and the
  // camera, which every lesson shares, folded below it (a student once had to scroll past
  // nine of them to find pcf.mode).
  auto runner = startLesson(kLesson, {}, 800, 600, /*panel=*/true);
  runner->setMouse({-1, -1}, false);
  runner->renderFrame();
  runner->renderFrame();
  const auto drawn = [&](const std::string& name) {
    const Param& p = runner->params().at(name);
    return p.widget_max.y > p.widget_min.y;
  };
  for (const char* own : {"pcf.mode", "pcf.radius", "pcf.taps"}) {
    EXPECT_TRUE(drawn(own)) << own << " is the lesson's own: open on the panel";
    EXPECT_LT(runner->params().at(own).widget_max.y, 600.0f) << own << ": seen without scrolling";
  }
  for (const char* shared : {"shadow.size", "shadow.filter", "light.fov", "camera.fov"}) {
    EXPECT_TRUE(runner->params().at(shared).shared) << shared;
    EXPECT_FALSE(drawn(shared)) << shared << " is shared: folded";
  }
  EXPECT_FALSE(runner->params().at("pcf.mode").shared);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson05, AMapLessonClaimsTheMapsSettingsAsItsOwn) {
  // 03's idea is the map itself: its settings are its own sliders there, shared here.
  auto three = startLesson("03_shadow_map_basic", {}, 320, 240);
  EXPECT_FALSE(three->params().at("shadow.size").shared);
  EXPECT_TRUE(three->params().at("light.fov").shared);
}

}  // namespace
}  // namespace shadows
