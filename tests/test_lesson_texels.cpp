// Texels per pixel (common/math/texel_density.hpp) in every shadow-map lesson: a closed-form case,
// the dueling frusta's under-sampling in numbers, the `aliasing` view and the report fields.
#include "harness.hpp"

#include "core/json.hpp"

namespace shadows {
namespace {

using testing::report;
using testing::startLesson;

const std::vector<std::string> kMapLessons = {"03_shadow_map_basic", "04_bias_offset",
                                              "05_pcf_dithered",     "06_dual_texture_8bit",
                                              "07_multidigit_16bit", "08_atmospherics"};

// An orthographic light straight above the floor, the eye straight down from height H with a
// vertical field of view f: one pixel spans 2 H tan(f/2) / rows of floor, one texel
// 2 extent / N. With extent = H tan(f/2) a pixel spans exactly N / rows texels, both ways.
std::vector<std::string> straightDown(int mapSize) {
  const float height = 10.0f, fov = 45.0f;
  const float extent = height * std::tan(glm::radians(0.5f * fov));
  return {"scene=torus_pyramid",
          "light.type=directional",
          "light.pos=0,12,0",
          "light.target=0,0,0",
          "light.extent=" + std::to_string(extent),
          "light.near=1",
          "light.far=20",
          "camera.pos=0,10,0",
          "camera.target=0,0,0",
          "camera.fov=45",
          "shadow.size=" + std::to_string(mapSize),
          "inset=false"};
}

TEST(Texels, StraightDownIsMapSizeOverFrameSizeAlongBothAxes) {
  constexpr int kRows = 120;
  for (const int map : {64, 120, 240}) {
    auto runner = startLesson("03_shadow_map_basic", straightDown(map), kRows, kRows);
    runner->renderFrame();
    const std::vector<TexelPixel>* pixels = runner->texels().measure();
    ASSERT_NE(pixels, nullptr);
    const TexelStats floor = texelStats(*pixels, /*floor=*/0);
    const float expected = static_cast<float>(map) / kRows;
    EXPECT_GT(floor.pixels, kRows * kRows / 2) << map;
    for (const TexelAxisStats& axis : {floor.min_axis, floor.max_axis}) {
      EXPECT_NEAR(axis.p5, expected, 1e-3f * expected) << map;
      EXPECT_NEAR(axis.p95, expected, 1e-3f * expected) << map;
    }
    // The report says the same (the casters' tops, nearer the eye, are a minority).
    const auto json = report(*runner);
    EXPECT_NEAR(json["texels_per_pixel"]["min_axis"]["median"].get<double>(), expected,
                1e-3 * expected);
    EXPECT_NEAR(json["texels_per_pixel"]["max_axis"]["median"].get<double>(), expected,
                1e-3 * expected);
    EXPECT_EQ(floor.undersampled_pct, map < kRows ? 100.0 : 0.0) << map;
    EXPECT_EQ(runner->glErrors(), 0);
  }
}

// The view's colours say the same: red under-sampled, green one to one, blue over-sampled.
TEST(Texels, TheAliasingViewColoursTheFloorByItsTexelsPerPixel) {
  const std::vector<std::pair<int, glm::ivec3>> cases = {
      {64, {1, 0, 0}}, {120, {0, 1, 0}}, {480, {0, 0, 1}}};
  for (const auto& [map, dominant] : cases) {
    auto sets = straightDown(map);
    sets.push_back("view=aliasing");
    auto runner = startLesson("03_shadow_map_basic", sets, 120, 120);
    runner->renderFrame();
    const Image image = runner->readImage();
    // A corner of the floor, away from the casters in the middle.
    const size_t i = (static_cast<size_t>(12) * 120 + 12) * 4;
    const glm::ivec3 c(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]);
    // The dominant channel clearly above both others.
    const int top = dominant.x ? c.x : dominant.y ? c.y : c.z;
    const int other = dominant.x   ? std::max(c.y, c.z)
                      : dominant.y ? std::max(c.x, c.z)
                                   : std::max(c.x, c.y);
    EXPECT_GT(top, other + 40) << map << ": " << c.x << "," << c.y << "," << c.z;
  }
}

TEST(Texels, DuelingFrustaAreUnderSampledWhereTheDefaultViewIsNot) {
  // The same map and frame: only the light and eye differ.
  const auto measure = [](const std::string& scene) {
    auto runner = startLesson("03_shadow_map_basic", {"scene=" + scene, "shadow.size=512"});
    runner->renderFrame();
    return report(*runner);
  };
  const auto dueling = measure("dueling"), usual = measure("torus_pyramid");
  const double dueling_under = dueling["undersampled_pct"], usual_under = usual["undersampled_pct"];
  EXPECT_GT(dueling_under, 60.0);
  EXPECT_LT(usual_under, 25.0);
  EXPECT_LT(dueling["texels_per_pixel"]["min_axis"]["median"].get<double>(), 1.0);
  EXPECT_GT(usual["texels_per_pixel"]["min_axis"]["median"].get<double>(), 1.0);
  // p5 <= median <= p95, and the least axis never above the most.
  for (const auto* json : {&dueling, &usual}) {
    for (const char* axis : {"min_axis", "max_axis"}) {
      const auto& a = (*json)["texels_per_pixel"][axis];
      EXPECT_LE(a["p5"].get<double>(), a["median"].get<double>());
      EXPECT_LE(a["median"].get<double>(), a["p95"].get<double>());
    }
    EXPECT_LE((*json)["texels_per_pixel"]["min_axis"]["median"].get<double>(),
              (*json)["texels_per_pixel"]["max_axis"]["median"].get<double>());
  }
}

TEST(Texels, EveryMapLessonOffersTheViewAndTheFieldsAndNoOtherDoes) {
  for (const std::string& lesson : kMapLessons) {
    auto runner = startLesson(lesson, {"scene=dueling"}, 160, 120);
    const auto& views = runner->params().at("view").choices;
    EXPECT_NE(std::find(views.begin(), views.end(), "aliasing"), views.end()) << lesson;
    runner->renderFrame();
    const auto json = report(*runner);
    ASSERT_TRUE(json.contains("texels_per_pixel")) << lesson;
    EXPECT_GT(json["texels_per_pixel"]["pixels"].get<long long>(), 1000) << lesson;
    EXPECT_GT(json["undersampled_pct"].get<double>(), 0.0) << lesson;
    // shadow.off: no map, nothing to measure.
    ASSERT_EQ(runner->params().set("shadow.off", "true"), "");
    runner->renderFrame();
    EXPECT_FALSE(report(*runner).contains("texels_per_pixel")) << lesson;
    EXPECT_EQ(runner->glErrors(), 0) << lesson;
  }
  for (const std::string lesson :
       {"01_projected_planar", "02_projective_texture", "09_shadow_volumes"}) {
    auto runner = startLesson(lesson, {}, 96, 72);
    runner->renderFrame();
    EXPECT_FALSE(report(*runner).contains("undersampled_pct")) << lesson;
  }
}

}  // namespace
}  // namespace shadows
