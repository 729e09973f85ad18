// Every lesson, every slider: random positions anywhere in the declared ranges (a fixed
// seed, so a failure reproduces) must render with no GL error, no NaN or Inf, no crash.
// New lessons are covered as soon as they are registered.
#include "harness.hpp"

#include <random>

namespace shadows {
namespace {

std::string randomValue(const Param& p, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto pick = [&](double lo, double hi) {
    // Logarithmic sliders are sampled in log space, so the small end gets its share.
    if (p.logarithmic && lo > 0) return lo * std::pow(hi / lo, unit(rng));
    return lo + (hi - lo) * unit(rng);
  };
  // A third of the draws sit exactly on an end of the range: the extremes matter most.
  auto value = [&]() {
    const double r = unit(rng);
    if (r < 0.17) return p.min;
    if (r < 0.33) return p.max;
    return pick(p.min, p.max);
  };
  switch (p.kind) {
    case ParamKind::Float:
      return std::to_string(value());
    case ParamKind::Int:
      return std::to_string(static_cast<long long>(std::llround(value())));
    case ParamKind::Bool:
      return unit(rng) < 0.5 ? "true" : "false";
    case ParamKind::Vec3:
      return std::to_string(value()) + "," + std::to_string(value()) + "," +
             std::to_string(value());
    case ParamKind::Choice:
      return p.choices[std::uniform_int_distribution<size_t>(0, p.choices.size() - 1)(rng)];
    case ParamKind::String:
      return p.text();  // free text (a path): keep what is in force
  }
  return {};
}

class EveryLesson : public ::testing::TestWithParam<std::string> {};

// Every boolean and every choice moved off its default, one (name, value) each; the view and
// the scene are what the tests loop over or keep.
std::vector<std::pair<std::string, std::string>> offDefaultSwitches(const Params& params) {
  std::vector<std::pair<std::string, std::string>> switches;
  for (const Param& p : params.all()) {
    if (p.name == "view" || p.name == "scene") continue;
    if (p.kind == ParamKind::Bool) switches.emplace_back(p.name, p.b() ? "false" : "true");
    if (p.kind != ParamKind::Choice) continue;
    for (const std::string& c : p.choices) {
      if (!p.is(c)) switches.emplace_back(p.name, c);
    }
  }
  return switches;
}

TEST_P(EveryLesson, RandomSliderPositionsStayFiniteAndErrorFree) {
  std::mt19937 rng(20261125);
  auto runner = testing::startLesson(GetParam(), {}, 96, 72);
  for (int round = 0; round < 24; ++round) {
    std::string settings;
    for (const Param& p : runner->params().all()) {
      // Half the parameters move each round, so combinations vary, not just values.
      if (std::uniform_int_distribution<int>(0, 1)(rng) == 0) continue;
      // Scenes and sizes of several thousand texels are slow to re-create every round.
      if (p.name == "scene" && round % 6 != 0) continue;
      std::string v = randomValue(p, rng);
      // Lesson 15 bakes a light map for each new density or sample count: at 100 texels a unit
      // and 256 samples that is over a billion rays (a student's bake, with its progress and
      // cancel). Here the two stay where a bake takes under a second; test_lesson15.cpp takes
      // each to its ends with the other small (and the refusal past the memory limit).
      // Lesson 16 offers the density as a knob (lightmap/lightmap.texels_per_unit).
      if (p.name.ends_with("lightmap.texels_per_unit"))
        v = std::to_string(std::min(std::stod(v), 12.0));
      if (p.name.ends_with("lightmap.samples")) v = std::to_string(std::min(std::stoi(v), 16));
      // A parameter with its own check (shadow.height: 0 or 64..4096) may refuse a value of
      // its range; refused, it must keep the value it had.
      const std::string before = p.text();
      const std::string refused = runner->params().set(p.name, v);
      if (!refused.empty() && p.check) {
        ASSERT_EQ(p.text(), before) << refused;
        continue;
      }
      ASSERT_EQ(refused, "") << p.name << "=" << v;
      settings += " --set " + p.name + "=" + v;
    }
    runner->renderFrame();
    const ErrorMetrics& e = runner->measureError().metrics;
    ASSERT_EQ(runner->glErrors(), 0) << "round " << round << ":" << settings;
    ASSERT_EQ(e.nonfinite_pixels, 0) << "round " << round << ":" << settings;
  }
}

TEST_P(EveryLesson, EveryViewRendersWithEverySwitchAtEachOfItsValues) {
  // A view may read what a switch leaves unbuilt (09's volumes view with shadow.off once read
  // an empty list): each boolean and choice moved off its default, one at a time, on a lesson
  // started with it (so nothing an earlier frame built hides the gap), renders every view with
  // no GL error (a crash fails the whole test program).
  std::vector<std::string> views;
  std::vector<std::pair<std::string, std::string>> switches;
  {
    auto probe = testing::startLesson(GetParam(), {}, 8, 8);
    views = probe->params().at("view").choices;
    switches = offDefaultSwitches(probe->params());
  }
  for (const auto& [name, value] : switches) {
    auto runner = testing::startLesson(GetParam(), {name + "=" + value}, 48, 36);
    for (const std::string& view : views) {
      ASSERT_EQ(runner->params().set("view", view), "");
      runner->renderFrame();
      ASSERT_EQ(runner->glErrors(), 0) << name << "=" << value << " view=" << view;
    }
  }
}

TEST_P(EveryLesson, NoSwitchOpensASkyColouredHoleOrBlacksTheFrame) {
  // The shaded frame with each boolean and choice off its default: where the default frame
  // shows a surface, the switched one must not show the sky's colour (a hole: the surface
  // not drawn), and the frame must not be black all over.
  std::vector<std::pair<std::string, std::string>> switches;
  Image reference;
  {
    auto runner = testing::startLesson(GetParam(), {}, 64, 48);
    switches = offDefaultSwitches(runner->params());
    runner->renderFrame();
    reference = runner->readImage();
  }
  const auto sky = [](const Image& image, size_t i) {
    for (int c = 0; c < 3; ++c) {
      const int level = static_cast<int>(std::lround(255.0f * Frame::kSky[c]));
      if (std::abs(image.rgba[4 * i + static_cast<size_t>(c)] - level) > 1) return false;
    }
    return true;
  };
  const size_t pixels = reference.rgba.size() / 4;
  for (const auto& [name, value] : switches) {
    auto runner = testing::startLesson(GetParam(), {name + "=" + value}, 64, 48);
    runner->renderFrame();
    const Image image = runner->readImage();
    size_t holes = 0, lit = 0;
    for (size_t i = 0; i < pixels; ++i) {
      holes += !sky(reference, i) && sky(image, i);
      lit += image.rgba[4 * i] + image.rgba[4 * i + 1] + image.rgba[4 * i + 2] > 0;
    }
    EXPECT_LE(holes, pixels / 200) << name << "=" << value << ": sky where a surface was";
    EXPECT_GT(lit, pixels / 4) << name << "=" << value << ": a black frame";
  }
}

INSTANTIATE_TEST_SUITE_P(Lessons, EveryLesson, ::testing::ValuesIn(registeredLessons()),
                         [](const ::testing::TestParamInfo<std::string>& lesson) {
                           return lesson.param;
                         });

}  // namespace
}  // namespace shadows
