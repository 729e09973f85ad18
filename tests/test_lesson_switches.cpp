// Every switch whose effect is a picture, checked against what its lesson's README says it does
// (issue 41 item 4), not only "something changed": measured against the ray-traced truth.
//  - A switch that only saves work (a cache, a counter, a culling, another path to the same
//    texels) leaves the picture byte for byte and the error exactly as they were.
//  - A fix turned off, from the lesson's settings where the README shows its failure, brings
//    that failure back: the named error rises from near zero past a bound the README's
//    picture implies; a fix turned on takes it away again.
//  - Double blending (01's fix.once off) darkens where two shadows overlap and nowhere else: no
//    pixel gets lighter, and the shadow term (the error) does not change.
// At 320x240 (04 on grazing at 640x480); bounds are the measured figures with a margin.
#include <gtest/gtest.h>

#include <cctype>
#include <ostream>
#include <string>
#include <vector>

#include "harness.hpp"

#include <glm/glm.hpp>

namespace shadows {
namespace {

using testing::label;
using testing::pixelsDiffering;
using testing::startLesson;

struct Render {
  Image image;
  ErrorMetrics error;
};

Render renderWith(const std::string& lesson, const std::vector<std::string>& sets, int width = 320,
                  int height = 240) {
  auto runner = startLesson(lesson, sets, width, height);
  runner->renderFrame();
  Render r{runner->readImage(), runner->measureError().metrics};
  EXPECT_EQ(runner->glErrors(), 0) << lesson << " " << label(sets);
  return r;
}

// A case's name as GoogleTest takes it: letters, digits and underscores.
std::string testName(std::string name) {
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

std::vector<std::string> with(std::vector<std::string> base, const std::string& set) {
  base.push_back(set);
  return base;
}

// ---------------------------------------------------------------- work saved, picture kept

struct SameCase {
  std::string lesson;
  std::vector<std::string> base;
  std::string set;
  const char* why;  // what the README says the switch does
};

// The map inset shows what each path hands the lookup, which may differ in how it is drawn
// (a depth texture against the read-back bytes): the cases with an inset turn it off.
void PrintTo(const SameCase& c, std::ostream* os) {
  *os << c.lesson << " " << c.set;
}

class SwitchThatSavesWork : public ::testing::TestWithParam<SameCase> {};

TEST_P(SwitchThatSavesWork, LeavesThePictureAndTheErrorExactlyAsTheyWere) {
  const SameCase& c = GetParam();
  const Render base = renderWith(c.lesson, c.base);
  const Render off = renderWith(c.lesson, with(c.base, c.set));
  if (c.set == "shadow.cache=false") {
    // A cache is only a cache from the second frame: a frame, a light moved, another frame,
    // cached or rendered anew, must be the same.
    const auto moved = [&](const std::string& cache) {
      auto runner = startLesson(c.lesson, {cache}, 320, 240);
      runner->renderFrame();
      Param& pos = runner->params().at("light.pos");
      runner->params().setVec3(pos, pos.v() + glm::vec3(0.3f, 0.0f, -0.2f));
      runner->renderFrame();
      runner->renderFrame();
      return runner->readImage();
    };
    EXPECT_EQ(pixelsDiffering(moved("shadow.cache=true"), moved("shadow.cache=false"), 0), 0u);
  }
  EXPECT_EQ(pixelsDiffering(base.image, off.image, 0), 0u) << c.set << ": " << c.why;
  EXPECT_EQ(base.error.false_shadow_pct, off.error.false_shadow_pct) << c.set;
  EXPECT_EQ(base.error.false_lit_pct, off.error.false_lit_pct) << c.set;
  EXPECT_EQ(base.error.vis_mae, off.error.vis_mae) << c.set;
}

INSTANTIATE_TEST_SUITE_P(
    EveryLesson, SwitchThatSavesWork,
    ::testing::Values(
        SameCase{"03_shadow_map_basic", {}, "shadow.cache=false", "the map rendered every frame"},
        SameCase{"04_bias_offset", {}, "shadow.cache=false", "the map rendered every frame"},
        SameCase{"05_pcf_dithered", {}, "pcf.count=false", "the taps not counted"},
        SameCase{"06_dual_texture_8bit",
                 {},
                 "ramp.lookup=false",
                 "the exact depth for the ramp: from two steps of bias on, the fragment side's 8 "
                 "bits cost "
                 "nothing"},
        SameCase{"06_dual_texture_8bit",
                 {"inset=false"},
                 "map.path=copy_texture",
                 "glCopyTexSubImage2D: the same bytes as glReadPixels"},
        SameCase{"06_dual_texture_8bit",
                 {"inset=false"},
                 "map.path=render_to_texture",
                 "the light pass's own texture, quantized as a read-back would be"},
        SameCase{"07_multidigit_16bit",
                 {"inset=false"},
                 "map.path=copy_texture",
                 "glCopyTexSubImage2D: the same shorts as glReadPixels"},
        SameCase{"08_atmospherics",
                 {},
                 "air.early_reject=false",
                 "slice fragments behind surfaces shaded, then hidden anyway"},
        SameCase{"09_shadow_volumes",
                 {"camera.pos=5,3,6", "camera.target=6,0,8"},
                 "volume.cull=false",
                 "volumes out of the eye's view drawn, counting nothing"},
        SameCase{"09_shadow_volumes",
                 {},
                 "stencil.mode=two_sided",
                 "one pass with glStencilOpSeparate: the same count"},
        SameCase{"09_shadow_volumes",
                 {},
                 "volume.geometry=per_triangle",
                 "a volume per triangle: the same count, 50 times the triangles"},
        SameCase{"14_soft_shadows", {}, "pcss.count=false", "the taps not counted"}),
    [](const ::testing::TestParamInfo<SameCase>& test) {
      return testName(test.param.lesson.substr(0, 2) + "_" + test.param.set);
    });

// ---------------------------------------------------------------- a fix and its failure

struct FixCase {
  std::string lesson;
  std::vector<std::string> base;  // the README's settings, the fix on
  std::string set;                // the fix off (or the failure's setting)
  bool false_shadow;              // which error the failure shows: false shadow or false lit
  double at_most_with_fix;        // the error with the fix, %
  double at_least_without;        // the error without it, %
  const char* why;
  int width = 320, height = 240;  // a failure of a few pixels is measured on more of them
};

void PrintTo(const FixCase& c, std::ostream* os) {
  *os << c.lesson << " " << c.set;
}

class FixTurnedOff : public ::testing::TestWithParam<FixCase> {};

TEST_P(FixTurnedOff, BringsBackTheFailureItsReadmeShows) {
  const FixCase& c = GetParam();
  const Render fixed = renderWith(c.lesson, c.base, c.width, c.height);
  const Render broken = renderWith(c.lesson, with(c.base, c.set), c.width, c.height);
  const auto pct = [&](const Render& r) {
    return c.false_shadow ? r.error.false_shadow_pct : r.error.false_lit_pct;
  };
  const char* which = c.false_shadow ? "false shadow" : "false lit";
  EXPECT_LE(pct(fixed), c.at_most_with_fix) << which << " with the fix, " << label(c.base);
  EXPECT_GE(pct(broken), c.at_least_without) << which << " with " << c.set << ": " << c.why;
}

INSTANTIATE_TEST_SUITE_P(
    EveryLesson, FixTurnedOff,
    ::testing::Values(
        // 01 (TU Wien slides 18-21): the shadow in the floor's depth, the anti-shadow, the
        // buried casters.
        FixCase{"01_projected_planar",
                {"fix.receiver=false"},
                "fix.offset=false",
                false,
                0.05,
                1.0,
                "z-fighting: the shadow loses the depth test to the floor it lies in"},
        FixCase{"01_projected_planar",
                {"light.pos=2.5,1.1,2.5"},
                "fix.homogeneous=false",
                true,
                0.05,
                30.0,
                "divided in the shader, points above the light flip onto the floor"},
        FixCase{"01_projected_planar",
                {"plane.offset=1"},
                "fix.clip=false",
                true,
                0.05,
                2.0,
                "what lies under the floor is projected onto it too"},
        // 04: no bias at all is acne everywhere a surface faces the light.
        FixCase{"04_bias_offset", {}, "bias.mode=none", true, 0.05, 5.0, "shadow acne"},
        // 04 on grazing: back faces leave the far edge lit; the gradient does not.
        FixCase{"04_bias_offset",
                {"scene=grazing", "bias.mode=gradient"},
                "bias.mode=back_faces",
                false,
                0.1,
                0.12,
                "back faces peter-pan where the light grazes"},
        // 06: with one step of bias, the ramp's 256 texels against the map's 255 steps.
        FixCase{"06_dual_texture_8bit",
                {"bias.steps=1", "ramp.lookup=false"},
                "ramp.lookup=true",
                true,
                0.1,
                3.0,
                "the two 8-bit grids disagree by up to a step: acne"},
        // 07: each digit's pass carries its share of the compare.
        FixCase{"07_multidigit_16bit",
                {},
                "pass.little=false",
                true,
                0.05,
                5.0,
                "the big digit alone: ties across 256 little steps shadow"},
        FixCase{"07_multidigit_16bit",
                {},
                "pass.big=false",
                true,
                0.05,
                50.0,
                "the little digit alone compares nothing that matters"},
        // 09 (slides 38-41): z-pass with the eye in a volume, z-fail without its caps.
        FixCase{"09_shadow_volumes",
                {"scene=eye_in_shadow"},
                "volume.method=zpass",
                true,
                0.05,
                50.0,
                "the count starts inside the torus's volume: the picture inverts"},
        FixCase{"09_shadow_volumes",
                {"volume.method=zfail"},
                "volume.light_cap=false",
                true,
                0.05,
                5.0,
                "z-fail counts the caps: an open volume miscounts behind the caster"},
        FixCase{"09_shadow_volumes",
                {"volume.method=zfail"},
                "volume.dark_cap=false",
                true,
                0.05,
                0.12,
                "the far end open: what lies beyond the volume's reach miscounts"},
        // 10: plane-optimal's depth for the floor is gone without depth replacement.
        FixCase{"10_plane_optimal",
                {"scene=receding", "shadow.size=640", "shadow.height=480"},
                "depth.replace=false",
                true,
                0.3,
                2.0,
                "P L = 0: every light ray, one z/w"},
        FixCase{"10_plane_optimal",
                {"scene=receding", "shadow.size=640", "shadow.height=480"},
                "depth.replace=false",
                false,
                0.3,
                2.0,
                "P L = 0: every light ray, one z/w"}),
    [](const ::testing::TestParamInfo<FixCase>& test) {
      return testName(test.param.lesson.substr(0, 2) + "_" + test.param.set +
                      (test.param.false_shadow ? "_false_shadow" : "_false_lit"));
    });

// ---------------------------------------------------------------- double blending

TEST(Lesson01, DoubleBlendingDarkensWhereShadowsOverlapAndNowhereElse) {
  // fix.once=false: where two casters' flattened shadows overlap, the floor is dimmed twice
  // (TU Wien slide 18). The shadow term is the same (the visibility view draws it opaque), so
  // the error is too; the picture only darkens.
  const Render once = renderWith("01_projected_planar", {});
  const Render twice = renderWith("01_projected_planar", {"fix.once=false"});
  size_t darker = 0, lighter = 0;
  for (size_t i = 0; i < once.image.rgba.size(); i += 4) {
    for (size_t k = 0; k < 3; ++k) {
      const int a = once.image.rgba[i + k], b = twice.image.rgba[i + k];
      if (b < a) ++darker;
      if (b > a) ++lighter;
    }
  }
  EXPECT_GT(darker, 100u) << "the overlap is dimmed twice";
  EXPECT_EQ(lighter, 0u) << "double blending only darkens";
  EXPECT_EQ(once.error.false_shadow_pct, twice.error.false_shadow_pct);
  EXPECT_EQ(once.error.false_lit_pct, twice.error.false_lit_pct);
}

}  // namespace
}  // namespace shadows
