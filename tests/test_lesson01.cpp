// Lesson 01 end to end, headless: the picture, every view, each failure mode of projected
// planar shadows one toggle away (and gone with its fix), and what the method gets wrong
// against the ray-traced truth.
#include "harness.hpp"

#include "core/json.hpp"

#include <imgui_internal.h>

#include <algorithm>

namespace shadows {
namespace {

using testing::fractionDiffering;
using testing::startLesson;

const std::string kLesson = "01_projected_planar";
// A light below the top of the torus (about 1.9) and the pyramid (1.6): long shadows to the
// horizon, and casters that reach above the light.
const std::vector<std::string> kLowLight = {"light.pos=2.5,1.1,2.5"};

std::vector<std::string> with(std::vector<std::string> sets, const std::vector<std::string>& more) {
  sets.insert(sets.end(), more.begin(), more.end());
  return sets;
}

Image render(const std::vector<std::string>& sets, int width = 320, int height = 240) {
  auto runner = startLesson(kLesson, sets, width, height);
  runner->renderFrame();
  EXPECT_EQ(runner->glErrors(), 0);
  return runner->readImage();
}

ErrorMetrics measure(const std::vector<std::string>& sets) {
  const ErrorMetrics metrics = testing::measureOnce(kLesson, sets);
  EXPECT_EQ(metrics.nonfinite_pixels, 0);
  return metrics;
}

std::string reportText(Runner& runner) {
  JsonWriter json;
  runner.writeReport(json);
  return json.str();
}

// The first `count` numbers after "key" in a report.
std::vector<double> numbersAfter(const std::string& text, const std::string& key, size_t count) {
  std::vector<double> numbers;
  size_t at = text.find("\"" + key + "\"");
  if (at == std::string::npos) return std::vector<double>(count, 0.0);
  at += key.size() + 2;
  while (numbers.size() < count) {
    at = text.find_first_of("-0123456789", at);
    if (at == std::string::npos) break;
    size_t used = 0;
    numbers.push_back(std::stod(text.substr(at), &used));
    at += used;
  }
  numbers.resize(count, 0.0);
  return numbers;
}

int sum(const Image& image, size_t pixel) {
  return image.rgba[pixel * 4] + image.rgba[pixel * 4 + 1] + image.rgba[pixel * 4 + 2];
}

// How a shadowed picture relates to the same picture without shadows (dimming = 1 blends
// nothing): the pixels it darkened, how many of them by exactly `dimming` (blended once),
// and how many clearly darker than that (blended twice or more).
struct Darkening {
  size_t darkened = 0, once = 0, more = 0;
};
Darkening compareDarkening(const Image& lit, const Image& shadowed, float dimming) {
  Darkening d;
  for (size_t i = 0; i < lit.rgba.size() / 4; ++i) {
    const int before = sum(lit, i), after = sum(shadowed, i);
    if (before - after <= 6) continue;
    ++d.darkened;
    const float expected = dimming * static_cast<float>(before);
    if (std::abs(static_cast<float>(after) - expected) <= 4.5f) ++d.once;
    if (static_cast<float>(after) < expected - 10.0f) ++d.more;
  }
  return d;
}

TEST(Lesson01, SnapshotMatchesTheGolden) {
  // The golden was rendered by this lesson on Mesa llvmpipe and looked at; the tolerance
  // (a handful of moved pixels) and why are in tests/golden/README.md.
  const Image image = render({});
  testing::expectMatchesGolden(image, "01_projected_planar");
}

TEST(Lesson01, SnapshotShowsShadowsDarkenedByExactlyTheDimming) {
  // Guards the golden: against the unshadowed picture, a real shadow (not a black frame)
  // darkens several percent of the pixels, each to dimming x its lit colour.
  const Image lit = render({"dimming=1"});
  const Image shadowed = render({});
  const Darkening d = compareDarkening(lit, shadowed, 0.4f);
  const size_t pixels = lit.rgba.size() / 4;
  EXPECT_GT(d.darkened, pixels / 30);
  EXPECT_EQ(d.once, d.darkened);
}

TEST(Lesson01, EveryViewRendersWithoutGlErrorsOrNonFiniteValues) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
}

TEST(Lesson01, StencilDarkensEachPixelOnceWithoutItOverlapsBlendTwice) {
  // Every closed caster projects twice (front and back faces land on the same pixels), so
  // without the "once" stencil nearly every shadow pixel is blended two or more times.
  const Image lit = render({"dimming=1"});
  const Darkening fixed = compareDarkening(lit, render({}), 0.4f);
  const Darkening doubled = compareDarkening(lit, render({"fix.once=false"}), 0.4f);
  EXPECT_EQ(fixed.once, fixed.darkened) << "with the stencil every darkened pixel is equal";
  EXPECT_EQ(fixed.more, 0u);
  EXPECT_GT(doubled.more, doubled.darkened / 2) << "without it, most are darker than dimming";
  // The overdraw view counts the layers: one with the stencil, more without.
  const Image one = render({"view=overdraw"});
  const Image many = render({"view=overdraw", "fix.once=false"});
  EXPECT_GT(fractionDiffering(one, many, 40), 0.03);
}

TEST(Lesson01, ReceiverStencilKeepsTheShadowOnTheFloorWithoutItItSpillsIntoTheSky) {
  // With the light low, shadows run to the horizon and past the floor's far edge.
  const Image lit = render(with(kLowLight, {"dimming=1"}));
  const Image kept = render(kLowLight);
  const Image spilled = render(with(kLowLight, {"fix.receiver=false"}));
  size_t sky = 0, kept_dark = 0, spilled_dark = 0;
  for (size_t i = 0; i < lit.rgba.size() / 4; ++i) {
    // The clear colour (0.55, 0.62, 0.72): no surface here.
    if (lit.rgba[i * 4] != 140 || lit.rgba[i * 4 + 1] != 158 || lit.rgba[i * 4 + 2] != 184) {
      continue;
    }
    ++sky;
    if (sum(lit, i) - sum(kept, i) > 6) ++kept_dark;
    if (sum(lit, i) - sum(spilled, i) > 6) ++spilled_dark;
  }
  ASSERT_GT(sky, lit.rgba.size() / 4 / 10);
  EXPECT_EQ(kept_dark, 0u);
  EXPECT_GT(spilled_dark, sky / 20) << "shadow drawn where there is no receiver";
}

TEST(Lesson01, WithoutTheStencilOnlyTheDepthOffsetStopsZFighting) {
  // The shadow lies exactly in the plane: without an offset it loses the depth test to the
  // receiver in a speckle of pixels, which the truth counts as lit where it is shadowed.
  const ErrorMetrics stencil = measure({});
  const ErrorMetrics offset = measure({"fix.receiver=false"});
  const ErrorMetrics fighting = measure({"fix.receiver=false", "fix.offset=false"});
  EXPECT_LT(offset.false_lit_pct, stencil.false_lit_pct + 0.05);
  EXPECT_GT(fighting.false_lit_pct, offset.false_lit_pct + 1.0);
  EXPECT_LT(fighting.false_shadow_pct, 0.1) << "z-fighting only loses shadow, never adds it";
}

TEST(Lesson01, ClippingAtThePlaneStopsBuriedCastersFromCasting) {
  // Raise the floor by 1: the sphere (top 0.9) is buried, the pyramid's and torus's feet too.
  // Through M, what lies behind the plane lands on it between the light and itself: a false
  // shadow on a floor the truth sees lit (seed 003 slide 21: "objects behind receiver").
  auto runner = startLesson(kLesson, {"plane.offset=1"});
  runner->renderFrame();
  const ErrorMetrics clipped = runner->measureError().metrics;
  const std::string report = reportText(*runner);
  EXPECT_NE(report.find("sphere: entirely behind the receiver: skipped"), std::string::npos)
      << report;
  EXPECT_NE(report.find("pyramid: partly behind the receiver; clipped"), std::string::npos);
  EXPECT_EQ(runner->measure().lastFrameCounts().at("skipped_casters"), 1);
  runner.reset();  // one headless context at a time
  const ErrorMetrics buried = measure({"plane.offset=1", "fix.clip=false"});
  EXPECT_LT(clipped.false_shadow_pct, 0.1);
  EXPECT_GT(buried.false_shadow_pct, 2.0);
}

TEST(Lesson01, TheClipperCutsCastersAtTheLightsHeightDividingEarlyInvertsThem) {
  // Slide 16's 4x4 matrix leaves w = P.L - P.v for the clipper, which keeps exactly the
  // part below the light. Dividing in the shader (slide 15's similar triangles) first
  // flips everything above the light to the far side of it: the anti-shadow.
  auto runner = startLesson(kLesson, kLowLight);
  runner->renderFrame();
  const ErrorMetrics homogeneous = runner->measureError().metrics;
  const std::string report = reportText(*runner);
  EXPECT_NE(report.find("torus: reaches above the light; the clipper cuts it at w = 0"),
            std::string::npos)
      << report;
  runner.reset();
  const ErrorMetrics divided = measure(with(kLowLight, {"fix.homogeneous=false"}));
  EXPECT_LT(homogeneous.false_shadow_pct, 0.3);
  EXPECT_GT(divided.false_shadow_pct, 20.0);
  EXPECT_EQ(divided.nonfinite_pixels, 0);
}

TEST(Lesson01, LightAtOrBelowTheCastersNeverGivesNaNOrInvertedShadows) {
  // From above every caster down to below the floor: the shadows stay where the truth
  // has them (no inverted or runaway shadow), and nothing turns non-finite.
  for (const char* y : {"2.5", "1.9", "1.6", "1.1", "0.9", "0.45", "0.1", "0.01", "0", "-1"}) {
    auto runner = startLesson(kLesson, {std::string("light.pos=2.5,") + y + ",2.5"});
    runner->renderFrame();
    const ErrorMetrics& e = runner->measureError().metrics;
    EXPECT_EQ(e.nonfinite_pixels, 0) << y;
    EXPECT_EQ(runner->glErrors(), 0) << y;
    EXPECT_LT(e.false_shadow_pct, 0.5) << y;
    if (std::string(y) == "0" || std::string(y) == "-1") {
      EXPECT_NE(reportText(*runner).find("level with or behind the receiver"), std::string::npos)
          << y;
      EXPECT_EQ(runner->measure().lastFrameWork().count("shadow"), 0u) << "no shadow pass";
    }
  }
  // A caster wholly above a spot light is skipped, and the report says why.
  auto runner = startLesson(
      kLesson, {"scene=cubes", "light.type=spot", "light.pos=2,0.7,2", "light.target=0,0,0"});
  runner->renderFrame();
  EXPECT_NE(reportText(*runner).find("cube_floating: entirely at or above the light"),
            std::string::npos)
      << reportText(*runner);
  EXPECT_EQ(runner->measure().lastFrameCounts().at("skipped_casters"), 1);
  EXPECT_EQ(runner->measureError().metrics.nonfinite_pixels, 0);
}

TEST(Lesson01, TheTruthSeesTheTiltedReceiver) {
  // Tilting moves the floor object itself, so the geometry pass and the ray-traced truth
  // see the plane the shadow is projected on, also when the slider moves after the truth
  // was built: the shadows keep agreeing with the truth.
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  const ErrorMetrics flat = runner->measureError().metrics;
  for (const char* tilt : {"25", "-15", "40"}) {
    ASSERT_EQ(runner->params().set("plane.tilt", tilt), "");
    ASSERT_EQ(runner->params().set("plane.offset", "0.2"), "");
    runner->renderFrame();
    const ErrorMetrics& e = runner->measureError().metrics;
    EXPECT_LT(e.false_shadow_pct, 0.3) << tilt;
    EXPECT_LT(e.false_lit_pct, 0.5) << tilt;
    EXPECT_NE(e.counted_pixels, flat.counted_pixels) << tilt << ": the floor moved";
    // The plane the lesson projected on is tilted about x: its normal leans toward z.
    const std::vector<double> plane = numbersAfter(reportText(*runner), "receiver_plane", 4);
    EXPECT_GT(std::abs(plane[2]), 0.2) << tilt;
    EXPECT_NEAR(plane[0], 0.0, 1e-6) << tilt;
  }
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson01, ADirectionalLightCastsTheShadowsTheTruthHas) {
  // L = (-direction, 0): the shadows fall away from the light. With the direction flipped
  // every shadow vanishes (the light would be "behind the plane") and the floor under each
  // caster reads false lit (about 2.4% of the counted pixels).
  for (const char* pos : {"light.pos=3,6,4", "light.pos=1,8,-3"}) {
    auto runner = startLesson(kLesson, {"light.type=directional", pos});
    runner->renderFrame();
    const ErrorMetrics& e = runner->measureError().metrics;
    EXPECT_EQ(e.truth, "directional") << pos;
    EXPECT_LT(e.false_lit_pct, 0.5) << pos;
    EXPECT_LT(e.false_shadow_pct, 0.1) << pos;
    EXPECT_GT(e.counted_pixels, 20000) << pos;
    EXPECT_EQ(runner->measure().lastFrameWork().count("shadow"), 1u) << pos << ": shadows drawn";
    EXPECT_EQ(runner->glErrors(), 0) << pos;
  }
}

TEST(Lesson01, WhatPlanarShadowsGetWrongIsTheShadowOnEverythingButThePlane) {
  // Grazing light: the torus shadows itself and the pyramid. A planar shadow falls on
  // the floor only, so those pixels are lit where the truth has shadow.
  const ErrorMetrics grazing = measure({"scene=grazing"});
  EXPECT_GT(grazing.false_lit_pct, 1.0);
  EXPECT_LT(grazing.false_shadow_pct, 0.1);
  // From the default light the same casters barely shadow each other.
  const ErrorMetrics plain = measure({});
  EXPECT_LT(plain.false_lit_pct, 0.1);
  EXPECT_LT(plain.false_shadow_pct, 0.1);
}

TEST(Lesson01, SliderExtremesStayFiniteAndErrorFree) {
  const std::vector<std::vector<std::string>> extremes = {
      {"plane.tilt=-40", "plane.offset=-1"},
      {"plane.tilt=40", "plane.offset=1.5"},
      {"dimming=0"},
      {"dimming=1"},
      {"fix.receiver=false", "fix.once=false", "fix.offset=false", "fix.clip=false",
       "fix.homogeneous=false"},
      {"fix.homogeneous=false", "light.pos=0.6,0.45,1.6"},  // the light inside the sphere
      {"light.pos=-0.9,1.07,0.2", "light.target=0,0,0"},    // inside the torus's tube
      {"light.type=directional", "light.pos=0,5,0"},
      {"light.type=directional", "light.pos=5,0.001,0"},
      {"light.pos=0,0,0", "light.target=0,0,0"},
      {"light.pos=50,50,50"},
      {"scene=cubes", "light.type=spot", "light.pos=0,-0.5,0"},
      {"camera.pos=0,0.6,0", "camera.target=0,0.6,0"},
      {"view=overdraw", "fix.once=false", "fix.receiver=false"}};
  testing::expectFiniteAndErrorFree(kLesson, extremes);
}

TEST(Lesson01, PanelDrawsTheNotesWithoutGlErrors) {
  // The notes window ("what cannot cast") in the top-right corner, tall enough for every
  // note the report lists, and really on the picture (it differs from the frame without it).
  auto runner = startLesson(kLesson, kLowLight, 800, 600, /*panel=*/true);
  runner->setMouse({-1, -1}, false);
  // The notes come from the frame before (render runs after the panel), and an auto-sized
  // window is measured on its first frame and placed on the next.
  for (int frame = 0; frame < 4; ++frame) runner->renderFrame();
  EXPECT_GT(runner->params().at("fix.receiver").widget_max.x,
            runner->params().at("fix.receiver").widget_min.x);
  const std::string report = reportText(*runner);
  const size_t notes = static_cast<size_t>(
      std::count(report.begin() + static_cast<long>(report.find("\"notes\"")), report.end(), '"') /
      2);
  ASSERT_GE(notes, 1u) << report;
  const ImGuiWindow* window = ImGui::FindWindowByName("what cannot cast");
  ASSERT_NE(window, nullptr) << "no notes window";
  EXPECT_TRUE(window->Active) << "drawn this frame";
  EXPECT_GT(window->Pos.x, 400.0f) << "right half";
  EXPECT_LT(window->Pos.y, 50.0f) << "at the top";
  EXPECT_GE(window->ContentSize.y, static_cast<float>(notes) * ImGui::GetTextLineHeight());
  const int x0 = static_cast<int>(window->Pos.x) + 4, y0 = static_cast<int>(window->Pos.y) + 4;
  const int x1 = x0 + static_cast<int>(window->Size.x) - 8;
  const int y1 = y0 + static_cast<int>(window->Size.y) - 8;
  const Image with_notes = runner->readImage();
  EXPECT_EQ(runner->glErrors(), 0);
  runner.reset();
  const Image without = render(kLowLight, 800, 600);
  size_t differing = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      // Images are bottom-up; ImGui's y runs down.
      const size_t i = (static_cast<size_t>(599 - y) * 800 + static_cast<size_t>(x)) * 4;
      if (!std::equal(&with_notes.rgba[i], &with_notes.rgba[i] + 3, &without.rgba[i])) {
        ++differing;
      }
    }
  }
  EXPECT_GT(differing, static_cast<size_t>((x1 - x0) * (y1 - y0)) / 2) << "the window is shown";
}

}  // namespace
}  // namespace shadows
