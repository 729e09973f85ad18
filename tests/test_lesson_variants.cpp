// Compiled variants (issue 10): a frame runs only the shader code its settings ask for. The
// report names the variant each pass ran (shader_variants) and how many programs the run
// compiled (shader_variants_compiled): both are work counters, so they are asserted here.
#include "harness.hpp"

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
