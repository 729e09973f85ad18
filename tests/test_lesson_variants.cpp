// Compiled variants (issue 10): a frame runs only the shader code its settings ask for. The
// report names the variant each pass ran (shader_variants) and how many programs the run
// compiled (shader_variants_compiled): both are work counters, so they are asserted here.
#include "harness.hpp"
#include "lesson/sweep_spec.hpp"

namespace shadows {
namespace {

using testing::reportNumber;
using testing::startLesson;

std::vector<std::string> variantsRan(Runner& runner) {
  return runner.measure().lastFrameVariants();
}

bool ranVariantWith(Runner& runner, const std::string& text) {
  for (const std::string& v : variantsRan(runner)) {
    if (v.find(text) != std::string::npos) return true;
  }
  return false;
}

// Per lesson with variants: a choice that selects another variant, and a slider that does not.
struct VariantCase {
  std::string lesson, choice, slider;
};

void PrintTo(const VariantCase& c, std::ostream* os) {
  *os << c.lesson;
}

class Variants : public ::testing::TestWithParam<VariantCase> {};

TEST_P(Variants, CompileOnceAndOnlyWhenAChoiceChanges) {
  const VariantCase& c = GetParam();
  auto runner = startLesson(c.lesson, {}, 160, 120);
  runner->renderFrame();
  const double first = reportNumber(*runner, "shader_variants_compiled");
  EXPECT_GE(first, 1.0);
  runner->renderFrame();
  runner->renderFrame();
  EXPECT_EQ(reportNumber(*runner, "shader_variants_compiled"), first) << "same settings";
  ASSERT_EQ(runner->params().assign(c.slider), "");
  runner->renderFrame();
  EXPECT_EQ(reportNumber(*runner, "shader_variants_compiled"), first)
      << c.slider << " is a uniform, not a variant";
  const std::vector<std::string> before = variantsRan(*runner);
  ASSERT_EQ(runner->params().assign(c.choice), "");
  runner->renderFrame();
  EXPECT_EQ(reportNumber(*runner, "shader_variants_compiled"), first + 1) << c.choice;
  EXPECT_NE(variantsRan(*runner), before);
  // Back to the default: the first variant, kept, not compiled again.
  runner->params().resetToDefaults();
  ASSERT_EQ(runner->params().assign(c.slider), "");
  runner->renderFrame();
  EXPECT_EQ(reportNumber(*runner, "shader_variants_compiled"), first + 1);
  EXPECT_EQ(variantsRan(*runner), before);
  EXPECT_EQ(runner->glErrors(), 0);
}

INSTANTIATE_TEST_SUITE_P(
    Lessons, Variants,
    ::testing::Values(VariantCase{"03_shadow_map_basic", "view=visibility", "dimming=0.7"},
                      VariantCase{"04_bias_offset", "bias.mode=gradient", "bias.units=8"},
                      VariantCase{"05_pcf_dithered", "pcf.mode=grid", "pcf.radius=3"},
                      VariantCase{"08_atmospherics", "air.early_reject=false", "air.density=0.2"}),
    [](const ::testing::TestParamInfo<VariantCase>& test_case) { return test_case.param.lesson; });

// The default frame of lesson 05 runs the dithered kernel only; the counting instrumentation is
// compiled out when off (no atomics, no counts), and shadow.off compiles the lookup out.
TEST(Variants, Lesson05RunsOnlyItsOwnKernelAndNoInstrumentationWhenOff) {
  auto runner = startLesson("05_pcf_dithered", {}, 160, 120);
  runner->renderFrame();
  ASSERT_EQ(variantsRan(*runner).size(), 1u);
  EXPECT_TRUE(ranVariantWith(*runner, "PCF_MODE=PCF_MODE_DITHERED"));
  EXPECT_TRUE(ranVariantWith(*runner, "PCF_COUNT=1"));
  EXPECT_GT(runner->measure().lastFrameCounts().at("pcf_taps"), 0);

  ASSERT_EQ(runner->params().set("pcf.count", "false"), "");
  runner->renderFrame();
  EXPECT_TRUE(ranVariantWith(*runner, "PCF_COUNT=0"));
  EXPECT_EQ(runner->measure().lastFrameCounts().count("pcf_taps"), 0u) << "nothing counted";

  ASSERT_EQ(runner->params().set("pcf.mode", "none"), "");
  runner->renderFrame();
  EXPECT_TRUE(ranVariantWith(*runner, "PCF_MODE=PCF_MODE_NONE"));
  ASSERT_EQ(runner->params().set("shadow.off", "true"), "");
  runner->renderFrame();
  EXPECT_TRUE(ranVariantWith(*runner, "SHADOW_OFF=1"));
  EXPECT_EQ(runner->glErrors(), 0);
}

// The one setting that is not a choice yet compiles variants (the exemption from "a slider
// compiles none" above): pcf.taps sets the shape of lesson 05's kernel, its grid side or its
// Poisson tap count, which are compiled in with their offsets so that the loops unroll (issue
// 20). One variant per shape, at most 8 grids and 61 disks; none where the shape stays (taps
// within one grid side; dithered, none and hw2x2 ignore them). The radius stays a uniform.
TEST(Variants, Lesson05CompilesOneVariantPerKernelShapeAndNoneForItsRadius) {
  auto runner = startLesson("05_pcf_dithered", {"pcf.mode=grid", "pcf.taps=9"}, 160, 120);
  auto compiled = [&](const std::string& set) {
    EXPECT_EQ(runner->params().assign(set), "");
    runner->renderFrame();
    return reportNumber(*runner, "shader_variants_compiled");
  };
  const double first = compiled("pcf.radius=2");
  EXPECT_TRUE(ranVariantWith(*runner, "PCF_TAP_COUNT=9"));
  EXPECT_EQ(compiled("pcf.taps=15"), first) << "still 3 x 3";
  EXPECT_EQ(compiled("pcf.radius=5"), first) << "the radius is a uniform";
  EXPECT_EQ(compiled("pcf.taps=16"), first + 1) << "4 x 4";
  EXPECT_TRUE(ranVariantWith(*runner, "PCF_TAP_COUNT=16"));
  EXPECT_EQ(compiled("pcf.taps=9"), first + 1) << "3 x 3 again: kept";
  EXPECT_EQ(compiled("pcf.mode=dithered"), first + 2);
  EXPECT_EQ(compiled("pcf.taps=64"), first + 2) << "dithered takes 4 taps whatever pcf.taps";
  EXPECT_EQ(compiled("pcf.mode=poisson"), first + 3);
  EXPECT_EQ(compiled("pcf.taps=63"), first + 4) << "a disk of 63";
  EXPECT_EQ(compiled("pcf.radius=1"), first + 4);
  EXPECT_EQ(runner->glErrors(), 0);
}

// What that costs a full run of lesson 05's sweep (05_pcf_dithered/sweep.cpp through
// bench_sweep, which keeps one runner per lesson): every point of its axes, on one scene (no
// scene enters a define), compiles one variant per kernel, 7. The radius and the map size
// compile none.
TEST(Variants, Lesson05FullSweepCompilesOneVariantPerKernel) {
  const Sweep& sweep = registeredSweeps().at("05_pcf_dithered");
  auto runner = startLesson("05_pcf_dithered", {"scene=" + sweep.scenes.at(0)}, 64, 48);
  const double before = reportNumber(*runner, "shader_variants_compiled");
  std::vector<std::vector<std::string>> points = {sweep.fixed};
  for (const Axis& axis : sweep.axes) {
    std::vector<std::vector<std::string>> more;
    for (const auto& point : points) {
      for (const std::string& value : axis.values) {
        std::vector<std::string> sets = point;
        for (const std::string& set : settingsOf(axis, value).second) sets.push_back(set);
        more.push_back(sets);
      }
    }
    points = std::move(more);
  }
  ASSERT_EQ(points.size(), 7u * 3u * 2u);
  for (const auto& sets : points) {
    runner->params().resetToDefaults();
    for (const std::string& set : sets) ASSERT_EQ(runner->params().assign(set), "") << set;
    runner->renderFrame();
  }
  EXPECT_EQ(reportNumber(*runner, "shader_variants_compiled") - before, 7.0);
  EXPECT_EQ(runner->glErrors(), 0);
}

// Issue 56: a setting at its neutral value pays nothing for its code. Where a feature's value
// makes its code change no pixel (a blend of 0, a normal offset of 0), the frame runs the
// variant without it (gl/program.hpp, feature()), and that variant draws what the code compiled
// in draws, byte for byte: in every view, and on every scene in the shaded one.
struct NeutralCase {
  std::string lesson;
  std::vector<std::string> neutral;  // the settings that make the feature's code do nothing
  std::string feature;               // its define
  std::string working;               // a value where it works: the code compiled in
  std::string work_view = {};        // a view that shows the work itself (05's taps): it differs
};

void PrintTo(const NeutralCase& c, std::ostream* os) {
  *os << c.lesson << " " << c.feature;
}

class NeutralCode : public ::testing::TestWithParam<NeutralCase> {
 protected:
  void TearDown() override { keepNeutralCode(false); }
};

// The frame at the current settings, with the neutral code left out and compiled in, and
// whether it ran the feature's shader at all (a view may draw without it: 12's maps).
struct BothWays {
  std::vector<std::uint8_t> without, with;
  bool ran = false;
};

BothWays bothWays(Runner& runner, const std::string& feature) {
  BothWays both;
  keepNeutralCode(false);
  runner.renderFrame();
  both.without = runner.readImage().rgba;
  both.ran = ranVariantWith(runner, feature + "=");
  if (both.ran) {
    EXPECT_TRUE(ranVariantWith(runner, feature + "=0")) << "left out";
  }
  keepNeutralCode(true);
  runner.renderFrame();
  both.with = runner.readImage().rgba;
  if (both.ran) {
    EXPECT_FALSE(ranVariantWith(runner, feature + "=0")) << "compiled in";
  }
  keepNeutralCode(false);
  return both;
}

TEST_P(NeutralCode, LeftOutAtItsNeutralValueChangesNoPixel) {
  const NeutralCase& c = GetParam();
  auto runner = startLesson(c.lesson, c.neutral, 160, 120);
  for (const std::string& view : runner->params().at("view").choices) {
    if (view == "truth" || view == "error") continue;  // the tracer's, not the shader's
    if (view == c.work_view) continue;
    ASSERT_EQ(runner->params().set("view", view), "");
    const BothWays both = bothWays(*runner, c.feature);
    EXPECT_EQ(both.without, both.with) << view;
  }
  for (const std::string& scene : runner->params().at("scene").choices) {
    runner->params().resetToDefaults();  // the shaded view among them
    ASSERT_EQ(runner->applySets({"scene=" + scene}), "");
    ASSERT_EQ(runner->applySets(c.neutral), "");
    const BothWays both = bothWays(*runner, c.feature);
    EXPECT_TRUE(both.ran) << scene << ": the shaded view's shader has " << c.feature;
    EXPECT_EQ(both.without, both.with) << scene;
  }
  // Where the setting works, its code runs, kept or not (KEPT_CASCADES works on frames the eye
  // moved: test_lesson12.cpp).
  if (!c.working.empty()) {
    ASSERT_EQ(runner->params().assign(c.working), "");
    runner->renderFrame();
    EXPECT_TRUE(ranVariantWith(*runner, c.feature + "=1")) << c.working;
  }
  EXPECT_EQ(runner->glErrors(), 0);
}

INSTANTIATE_TEST_SUITE_P(
    Lessons, NeutralCode,
    ::testing::Values(
        NeutralCase{"04_bias_offset",
                    {"bias.mode=gradient", "bias.factor=0"},
                    "GRADIENT_TERM",
                    "bias.factor=1"},
        NeutralCase{"04_bias_offset",
                    {"bias.mode=gradient", "bias.clamp=0"},
                    "GRADIENT_TERM",
                    "bias.clamp=0.25"},
        NeutralCase{"04_bias_offset",
                    {"bias.mode=gradient", "bias.units=0"},
                    "CONSTANT_TERM",
                    "bias.units=4"},
        NeutralCase{"04_bias_offset",
                    {"bias.mode=normal_offset", "bias.factor=0"},
                    "NORMAL_OFFSET",
                    "bias.factor=1"},
        NeutralCase{"11_omni_cube", {"bias.normal=0"}, "NORMAL_OFFSET", "bias.normal=0.5"},
        NeutralCase{"02_projective_texture", {}, "SPOT_FALLOFF", "falloff=0.3"},
        NeutralCase{"12_cascades", {"cascades.blend=0"}, "CASCADE_BLEND", "cascades.blend=0.2"},
        NeutralCase{"12_cascades", {"cascades.count=1"}, "CASCADE_BLEND", "cascades.count=3"},
        NeutralCase{"12_cascades", {}, "KEPT_CASCADES", ""},
        NeutralCase{"12_cascades", {"cascades.update=2"}, "KEPT_CASCADES", ""},
        NeutralCase{"12_cascades", {"bias.normal=0"}, "NORMAL_OFFSET", "bias.normal=1"},
        NeutralCase{"13_filterable_maps", {}, "BLEEDING_REDUCTION", "vsm.bleeding=0.3"},
        // A kernel of radius 0 whose taps compare nearest: one lookup.
        NeutralCase{"05_pcf_dithered", {"pcf.radius=0"}, "PCF_KERNEL", "pcf.radius=1", "taps"},
        NeutralCase{"05_pcf_dithered",
                    {"pcf.radius=0", "pcf.mode=grid", "pcf.taps=9", "pcf.early_out=false"},
                    "PCF_KERNEL",
                    "pcf.radius=1",
                    "taps"},
        NeutralCase{"05_pcf_dithered",
                    {"pcf.radius=0", "pcf.mode=poisson", "pcf.taps=16", "pcf.lookup=fetch"},
                    "PCF_KERNEL",
                    "shadow.filter=linear",
                    "taps"},
        NeutralCase{"13_filterable_maps",
                    {"filter.method=pcf", "filter.radius=0"},
                    "PCF_KERNEL",
                    "filter.radius=2"},
        NeutralCase{
            "14_soft_shadows", {"pcss.mode=fixed", "pcf.radius=0"}, "PCF_KERNEL", "pcf.radius=3"},
        // A point light: the search's region is the pixel's own texel (the blockers view shows
        // the search, grey where it found only blockers, so it keeps it).
        NeutralCase{"14_soft_shadows",
                    {"pcss.light_radius=0"},
                    "PCSS_SEARCH",
                    "pcss.light_radius=0.3",
                    "blockers"}),
    [](const ::testing::TestParamInfo<NeutralCase>& test_case) {
      std::string name = test_case.param.lesson.substr(0, 2) + "_" + test_case.param.feature;
      for (const std::string& set : test_case.param.neutral) {
        for (char ch : set) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
      }
      return name;
    });

// Every lesson's view reaches its shader as the VIEW define the lesson's views name.
TEST(Variants, TheViewIsTheVariantTheFrameShows) {
  auto runner = startLesson("03_shadow_map_basic", {"view=compare"}, 160, 120);
  runner->renderFrame();
  EXPECT_TRUE(ranVariantWith(*runner, "VIEW=VIEW_COMPARE"));
  ASSERT_EQ(runner->params().set("view", "shaded"), "");
  runner->renderFrame();
  EXPECT_TRUE(ranVariantWith(*runner, "VIEW=VIEW_SHADED"));
}

}  // namespace
}  // namespace shadows
