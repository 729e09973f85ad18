// Lesson 10 end to end, headless: seed 002's guarantee in numbers (one texel per pixel on the
// plane of interest with a map the size of the frame, dueling frusta included), its edge
// error, region II, every fallback, every view.
#include "harness.hpp"

#include "core/json.hpp"

namespace shadows {
namespace {

using testing::report;
using testing::startLesson;

const std::string kLesson = "10_plane_optimal";
constexpr int kWidth = 320, kHeight = 240;

// A map the size of the frame.
std::vector<std::string> frameSized(const std::string& scene, const std::string& projection) {
  return {"scene=" + scene, "light.projection=" + projection,
          "shadow.size=" + std::to_string(kWidth), "shadow.height=" + std::to_string(kHeight),
          "inset=false"};
}

TEST(Lesson10, SnapshotMatchesTheGolden) {
  // Rendered by this lesson on Mesa llvmpipe and looked at (tests/golden/README.md).
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson10, PlaneOptimalGivesOneTexelPerPixelOnThePlaneOnEveryPreset) {
  for (const std::string scene : {"dueling", "strategy", "receding"}) {
    auto runner = startLesson(kLesson, frameSized(scene, "plane_optimal"), kWidth, kHeight);
    runner->renderFrame();
    runner->measureError();
    const auto json = report(*runner);
    EXPECT_EQ(json["projection_used"], "plane_optimal") << scene << json["fallback_reason"];
    const auto& plane = json["plane"];
    EXPECT_GT(plane["texels_per_pixel"]["pixels"].get<long long>(), 5000) << scene;
    // p5 to p95 along both axes within 1.00 +- 0.02.
    for (const char* axis : {"min_axis", "max_axis"}) {
      const auto& a = plane["texels_per_pixel"][axis];
      EXPECT_GE(a["p5"].get<double>(), 0.98) << scene << " " << axis;
      EXPECT_LE(a["p95"].get<double>(), 1.02) << scene << " " << axis;
    }
    // The edge error on the plane: false shadow + false lit (the truth's figures: under error).
    const auto& plane_error = json.at("error").at("plane");
    EXPECT_GT(plane_error["counted_pixels"].get<long long>(), 5000) << scene;
    EXPECT_LE(
        plane_error["false_shadow_pct"].get<double>() + plane_error["false_lit_pct"].get<double>(),
        0.1)
        << scene;
    EXPECT_GT(json.at("error").at("region_two").at("counted_pixels").get<long long>(), 0) << scene;
    EXPECT_EQ(json["gl_errors"], 0);
  }
}

TEST(Lesson10, UniformAtTheSameMapSizeIsWorseOnDuelingFrusta) {
  const auto measure = [](const std::string& projection) {
    auto runner = startLesson(kLesson, frameSized("dueling", projection), kWidth, kHeight);
    runner->renderFrame();
    runner->measureError();
    return report(*runner);
  };
  const auto uniform = measure("uniform"), optimal = measure("plane_optimal");
  const auto error = [](const nlohmann::ordered_json& j) {
    const auto& plane = j.at("error").at("plane");
    return plane["false_shadow_pct"].get<double>() + plane["false_lit_pct"].get<double>();
  };
  EXPECT_GT(error(uniform), 4.0 * error(optimal) + 0.2);
  EXPECT_GT(uniform["plane"]["texels_per_pixel"]["max_axis"]["p95"].get<double>(), 1.5);
  EXPECT_LT(uniform["plane"]["texels_per_pixel"]["min_axis"]["p5"].get<double>(), 0.5);
}

// Each degenerate configuration: uniform, the reason, and a sound picture (no NaN, not black).
TEST(Lesson10, EveryDegenerateConfigurationFallsBackToUniformAndSaysWhy) {
  struct Case {
    std::vector<std::string> sets;
    std::string reason;
  };
  const std::vector<Case> cases = {
      {{"scene=dueling", "plane=wall"}, "the scene has no wall"},
      {{"scene=strategy", "camera.target=0,30,-40"}, "the plane is not in view"},
      {{"scene=dueling", "light.pos=0.6,0,-7.5", "light.target=0,0,0"},
       "the light lies in the plane"},
      {{"scene=dueling", "light.pos=0.6,-3,-7.5", "light.target=0,0,0"},
       "the light is behind the plane"},
      {{"scene=dueling", "camera.pos=0,0,8"}, "the eye lies in the plane"},
      {{"scene=dueling", "camera.pos=0,-2,8"}, "the eye is behind the plane"},
      {{"scene=strategy", "light.projection=lispsm", "light.type=directional", "light.pos=0,20,0",
        "light.target=0,0,0", "camera.pos=0,15,0", "camera.target=0,0,0"},
       "the eye looks along the light: no direction to warp"},
      {{"scene=dueling", "light.projection=lispsm", "camera.pos=0.6,3.8,-9.5"},
       "the eye is behind the light: the warp would invert"},
  };
  for (const Case& c : cases) {
    auto runner = startLesson(kLesson, c.sets, 160, 120);
    runner->renderFrame();
    const auto json = report(*runner);
    EXPECT_EQ(json["projection_used"], "uniform") << c.reason;
    EXPECT_EQ(json["fallback_reason"], c.reason);
    const Image image = runner->readImage();
    double sum = 0.0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) sum += image.rgba[i] + image.rgba[i + 1];
    EXPECT_GT(sum / static_cast<double>(image.rgba.size() / 4), 40.0) << c.reason << ": black";
    EXPECT_EQ(runner->measureError().metrics.nonfinite_pixels, 0) << c.reason;
    EXPECT_EQ(runner->glErrors(), 0) << c.reason;
  }
}

TEST(Lesson10, EveryViewRendersCleanAndDistinct) {
  for (const std::string projection : {"plane_optimal", "lispsm"}) {
    auto runner = startLesson(kLesson, {"light.projection=" + projection}, 160, 120);
    testing::expectEveryViewCleanAndDistinct(*runner, projection);
  }
}

// The slider ends and every projection on every preset: finite, no GL error.
TEST(Lesson10, SliderExtremesAndEveryProjectionStayFinite) {
  std::vector<std::vector<std::string>> settings;
  for (const std::string scene : {"dueling", "receding", "cubes"}) {
    for (const std::string projection : {"uniform", "focused", "lispsm", "plane_optimal"}) {
      settings.push_back({"scene=" + scene, "light.projection=" + projection, "plane=table",
                          "depth.replace=false", "lispsm.n=0.05"});
    }
    settings.push_back({"scene=" + scene, "light.projection=lispsm", "lispsm.n=20"});
  }
  settings.push_back({"scene=strategy", "plane=table", "light.projection=plane_optimal"});
  settings.push_back({"scene=receding", "plane=wall", "light.projection=plane_optimal"});
  testing::expectFiniteAndErrorFree(kLesson, settings);
}

}  // namespace
}  // namespace shadows
