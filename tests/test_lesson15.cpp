// Lesson 15 end to end, headless: light maps baked with the truth's tracer. The golden and
// every view; the bake close to the truth where nothing moved, and its error falling with the
// texel density and the samples a texel; a moved caster's shadow left behind (baked) and put
// back (hybrid); seams dark without dilation; the disk cache; the bake's progress and cancel;
// what each figure of the report counts.
#include "harness.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <thread>

#include "run/light_map_bake.hpp"

namespace shadows {
namespace {

using testing::reportNumber;
using testing::startLesson;

const std::string kLesson = "15_light_maps";

bool flag(Runner& runner, const std::string& key) {
  const nlohmann::ordered_json v = testing::reportValue(runner, key);
  EXPECT_TRUE(v.is_boolean()) << key << " = " << v.dump();
  return v.is_boolean() && v.get<bool>();
}

double error(const std::vector<std::string>& sets, const std::string& figure = "/error/vis_mae") {
  auto runner = startLesson(kLesson, sets);
  runner->renderFrame();
  runner->measureError();
  return reportNumber(*runner, figure);
}

TEST(Lesson15, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson15, EveryViewIsCleanAndDistinct) {
  for (const char* mode : {"baked", "hybrid"}) {
    auto runner = startLesson(kLesson, {std::string("lightmap.mode=") + mode, "move.x=-1.5"});
    testing::expectEveryViewCleanAndDistinct(*runner, mode);
  }
}

TEST(Lesson15, WhereNothingMovedTheBakeIsTheTruthsOwnAnswer) {
  // README (at 640x480; these run at 320x240): 0.0034 at the defaults (16 texels a unit, 64
  // samples), against lesson 03's hard map at 0.0061 on the same disk light's truth.
  const double baked = error({});
  EXPECT_LT(baked, 0.005);
  EXPECT_LT(baked, 0.7 * error({"lightmap.mode=map"}));
}

TEST(Lesson15, ErrorFallsWithTexelsAndSamples) {
  // README's table: 4 / 8 / 16 / 32 texels a unit 0.0224 / 0.0090 / 0.0034 / 0.0016; 1 and
  // 64 samples 0.0076 and 0.0034.
  double last = 1.0;
  for (const char* density : {"4", "8", "16", "32"}) {
    const double e = error({std::string("lightmap.texels_per_unit=") + density});
    EXPECT_LT(e, 0.7 * last) << density;
    last = e;
  }
  EXPECT_GT(error({"lightmap.samples=1"}), 1.5 * error({"lightmap.samples=64"}));
}

TEST(Lesson15, AMovedCasterLeavesItsShadowBehindAndTheHybridPutsItBack) {
  // README: the ball 1.5 to the left, vis_mae 0.033 baked, 0.0028 hybrid.
  const double still = error({});
  const double moved = error({"move.x=-1.5"});
  const double hybrid = error({"move.x=-1.5", "lightmap.mode=hybrid"});
  EXPECT_GT(moved, 5.0 * still);
  EXPECT_LT(hybrid, 1.5 * still);
  // Baking again where things stand now repairs it too, at the cost of a bake per move.
  EXPECT_LT(error({"move.x=-1.5", "lightmap.bake_at=current"}), 1.5 * still);
}

TEST(Lesson15, AMovedLightLeavesTheBakedShadowsWhereTheyWere) {
  const std::vector<std::string> moved = {"light.pos=-3.5,6,4"};
  auto with = [&](std::vector<std::string> sets, const std::string& more) {
    sets.push_back(more);
    return sets;
  };
  EXPECT_GT(error(moved), 5.0 * error(with(moved, "lightmap.bake_at=current")));
}

TEST(Lesson15, WithoutDilationTheSeamsGoDark) {
  // README (640x480): along the seams 0.0007 dilated, 0.066 not; charts ending on texel edges
  // 0.0027.
  const double dilated = error({}, "/error/seams/vis_mae");
  EXPECT_GT(error({"lightmap.dilate=false"}, "/error/seams/vis_mae"), 20.0 * dilated);
  EXPECT_GT(error({"lightmap.texel_centres=false"}, "/error/seams/vis_mae"), 3.0 * dilated);
}

TEST(Lesson15, EachSliderEndBakesCleanly) {
  // Each of the bake's two knobs at its end, with the other small (both at their ends would be
  // 1.5 G rays, a student's bake with its progress and cancel).
  testing::expectFiniteAndErrorFree(
      kLesson, {{"lightmap.texels_per_unit=128", "lightmap.samples=1"},
                {"lightmap.texels_per_unit=1", "lightmap.samples=256"},
                {"lightmap.texels_per_unit=4", "lightmap.samples=256", "lightmap.padding=8",
                 "lightmap.texel_centres=false", "lightmap.dilate=false"},
                {"lightmap.padding=0", "lightmap.light_radius=0"}});
}

TEST(Lesson15, ABakedFrameDrawsNoMapAndTheHybridsMapHoldsOneObject) {
  // The map re-rendered every frame (shadow.cache=false), so each mode shows what it draws.
  const auto work = [](const std::string& mode) {
    auto runner = startLesson(kLesson, {"lightmap.mode=" + mode, "shadow.cache=false"});
    runner->renderFrame();
    runner->renderFrame();
    const auto& passes = runner->measure().lastFrameWork();
    const auto shadow = passes.find("shadow");
    return std::pair<long long, long long>(
        runner->measure().lastFrameCounts().at("shadow_map_renders"),
        shadow == passes.end() ? -1 : shadow->second.draw_calls);
  };
  EXPECT_EQ(work("baked"), std::make_pair(0LL, -1LL));  // no map, no pass
  EXPECT_EQ(work("hybrid"), std::make_pair(1LL, 1LL));  // the ball alone
  EXPECT_EQ(work("map"), std::make_pair(1LL, 3LL));     // torus, pyramid, ball
}

TEST(Lesson15, EveryModeIsCountedInOneFrustumAndOnlyAMapsReaderHasItsTexelsPerPixel) {
  // The lesson says what its eye reads (LightView writes nothing of the frame's): every mode
  // is scored in lesson 03's light frustum, so the three count the same pixels, and the
  // runner's texels per pixel are of the map, which the baked mode does not read.
  std::map<std::string, long long> counted;
  for (const std::string mode : {"map", "baked", "hybrid"}) {
    auto runner = startLesson(kLesson, {"lightmap.mode=" + mode}, 160, 120);
    runner->renderFrame();
    counted[mode] = runner->measureError().metrics.counted_pixels;
    EXPECT_EQ(testing::report(*runner).contains("texels_per_pixel"), mode != "baked") << mode;
  }
  EXPECT_GT(counted["map"], 0);
  EXPECT_EQ(counted["baked"], counted["map"]);
  EXPECT_EQ(counted["hybrid"], counted["map"]);
}

TEST(Lesson15, TheReportCountsTexelsRaysAndBytes) {
  auto runner = startLesson(kLesson, {"lightmap.samples=10"});  // 10 rounds to 3 x 3
  runner->renderFrame();
  const double width = reportNumber(*runner, "/lightmap/width");
  const double height = reportNumber(*runner, "/lightmap/height");
  EXPECT_EQ(reportNumber(*runner, "/lightmap/texels"), width * height);
  EXPECT_EQ(reportNumber(*runner, "/lightmap/samples_per_texel"), 9);
  // Nine rays from each covered texel that faces the light: most of them (the floor's face
  // up), not the undersides.
  const double rays = reportNumber(*runner, "/lightmap/bake_rays");
  const double covered = reportNumber(*runner, "/lightmap/covered_texels");
  EXPECT_EQ(std::fmod(rays, 9.0), 0.0);
  EXPECT_LT(rays, 9 * covered);
  EXPECT_GT(rays, 0.75 * 9 * covered);
  // torus_pyramid: a floor, a torus, a sphere and the pyramid's four sides and base.
  EXPECT_EQ(reportNumber(*runner, "/lightmap/charts"), 8);
  EXPECT_GE(reportNumber(*runner, "/lightmap/bytes"), 2 * width * height);
  EXPECT_TRUE(flag(*runner, "/lightmap/baked"));
  // The floor alone is 16 x 16 units at 16 texels a unit: 257 x 257 texel centres.
  EXPECT_GE(reportNumber(*runner, "/lightmap/covered_texels"), 257 * 257);
}

// Rays a texel, by their closed form: lightmap.samples rounded to a square, as the README says
// (round(sqrt(n))^2); one to a point light (radius 0), as the truth traces it; none in map mode,
// which bakes nothing (issue 53, 13). bake_rays is that many for each texel that faces the light.
TEST(Lesson15, RaysATexelAreTheSamplesRoundedToASquare) {
  const std::vector<std::string> small = {"lightmap.texels_per_unit=2"};
  const auto report = [&](std::vector<std::string> sets) {
    sets.insert(sets.end(), small.begin(), small.end());
    auto runner = startLesson(kLesson, sets);
    runner->renderFrame();
    return std::make_pair(reportNumber(*runner, "/lightmap/samples_per_texel"),
                          reportNumber(*runner, "/lightmap/bake_rays"));
  };
  const double facing = report({"lightmap.samples=1"}).second;  // one ray a facing texel
  ASSERT_GT(facing, 0);
  for (const int n : {2, 3, 5, 6, 7, 12, 13, 20, 21, 256}) {
    const double k = std::round(std::sqrt(static_cast<double>(n)));
    const auto [per_texel, rays] = report({"lightmap.samples=" + std::to_string(n)});
    EXPECT_EQ(per_texel, k * k) << n;
    EXPECT_EQ(rays, k * k * facing) << n;
  }
  EXPECT_EQ(report({"lightmap.samples=64", "lightmap.light_radius=0"}),
            std::make_pair(1.0, facing));
  EXPECT_EQ(report({"lightmap.samples=64", "lightmap.mode=map"}), std::make_pair(0.0, 0.0));
}

// SHADOWS_CACHE for one test, put back as ctest set it however the test ends.
struct CacheDir {
  explicit CacheDir(const std::string& dir) {
    if (const char* was = std::getenv("SHADOWS_CACHE"); was != nullptr) before = was;
    setenv("SHADOWS_CACHE", dir.c_str(), 1);
  }
  ~CacheDir() {
    if (before) {
      setenv("SHADOWS_CACHE", before->c_str(), 1);
    } else {
      unsetenv("SHADOWS_CACHE");
    }
  }
  CacheDir(const CacheDir&) = delete;
  CacheDir& operator=(const CacheDir&) = delete;
  std::optional<std::string> before;
};

TEST(Lesson15, ASecondRunLoadsTheBakeFromTheDiskCache) {
  const auto dir = std::filesystem::temp_directory_path() / "shadows_lesson15_cache_test";
  std::filesystem::remove_all(dir);
  const CacheDir cache(dir.string());
  auto first = startLesson(kLesson, {"lightmap.samples=4"});
  first->renderFrame();
  EXPECT_FALSE(flag(*first, "/lightmap/from_cache"));
  EXPECT_GT(reportNumber(*first, "/lightmap/bake_seconds"), 0);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);
  auto second = startLesson(kLesson, {"lightmap.samples=4"});
  second->renderFrame();
  EXPECT_TRUE(flag(*second, "/lightmap/from_cache"));
  EXPECT_EQ(testing::pixelsDiffering(first->readImage(), second->readImage(), 0), 0u);
  // Another input is another bake.
  auto other = startLesson(kLesson, {"lightmap.samples=9"});
  other->renderFrame();
  EXPECT_FALSE(flag(*other, "/lightmap/from_cache"));
  // A damaged file is baked again, not believed.
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::filesystem::resize_file(entry.path(), 20);
  }
  auto damaged = startLesson(kLesson, {"lightmap.samples=4"});
  damaged->renderFrame();
  EXPECT_FALSE(flag(*damaged, "/lightmap/from_cache"));
  EXPECT_EQ(testing::pixelsDiffering(first->readImage(), damaged->readImage(), 0), 0u);
  // A file of the right job and size whose values no bake gives (NaN, 7): baked again too, and
  // said on one line (issue 53, 5).
  for (const float bad : {std::nanf(""), 7.0f}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      std::fstream file(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
      file.seekp(40);
      const auto size = std::filesystem::file_size(entry.path());
      for (std::uintmax_t at = 40; at < size; at += 4) {
        file.write(reinterpret_cast<const char*>(&bad), 4);
      }
    }
    ::testing::internal::CaptureStderr();
    auto forged = startLesson(kLesson, {"lightmap.samples=4"});
    forged->renderFrame();
    const std::string said = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(flag(*forged, "/lightmap/from_cache")) << bad;
    EXPECT_EQ(testing::pixelsDiffering(first->readImage(), forged->readImage(), 0), 0u) << bad;
    EXPECT_NE(said.find("the cached bake is damaged"), std::string::npos) << said;
    EXPECT_NE(said.find("not in [0, 1]"), std::string::npos) << said;
  }
  std::filesystem::remove_all(dir);
}

// Without SHADOWS_CACHE, a home that is not there (or not ours to write) is never created: the
// bake is not kept, and one line says so.
TEST(Lesson15, AMissingHomeGetsNoCacheAndIsNotCreated) {
  const auto tmp = std::filesystem::temp_directory_path() / "shadows_lesson15_home_test";
  std::filesystem::remove_all(tmp);
  const auto saved = [](const char* name) -> std::optional<std::string> {
    const char* v = std::getenv(name);
    return v ? std::optional<std::string>(v) : std::nullopt;
  };
  const std::optional<std::string> cache = saved("SHADOWS_CACHE"), xdg = saved("XDG_CACHE_HOME"),
                                   home = saved("HOME");
  unsetenv("SHADOWS_CACHE");
  unsetenv("XDG_CACHE_HOME");
  setenv("HOME", (tmp / "absent" / "home").c_str(), 1);
  const LightMapBaker::CacheDirectory none = LightMapBaker::cacheDirectory();
  ::testing::internal::CaptureStderr();
  {
    auto runner = startLesson(kLesson, {"lightmap.samples=1", "lightmap.texels_per_unit=2"});
    runner->renderFrame();
    EXPECT_TRUE(flag(*runner, "/lightmap/baked"));
    EXPECT_FALSE(flag(*runner, "/lightmap/from_cache"));
  }
  const std::string said = ::testing::internal::GetCapturedStderr();
  // An XDG_CACHE_HOME that is a folder is used (its shadows/ made in it).
  std::filesystem::create_directories(tmp / "xdg");
  setenv("XDG_CACHE_HOME", (tmp / "xdg").c_str(), 1);
  const LightMapBaker::CacheDirectory xdg_dir = LightMapBaker::cacheDirectory();
  const auto put = [](const char* name, const std::optional<std::string>& v) {
    if (v) {
      setenv(name, v->c_str(), 1);
    } else {
      unsetenv(name);
    }
  };
  put("SHADOWS_CACHE", cache);
  put("XDG_CACHE_HOME", xdg);
  put("HOME", home);
  EXPECT_EQ(none.path, "");
  EXPECT_NE(none.why.find("absent/home"), std::string::npos) << none.why;
  EXPECT_FALSE(std::filesystem::exists(tmp / "absent"));
  EXPECT_NE(said.find("light map: no disk cache"), std::string::npos) << said;
  EXPECT_EQ(xdg_dir.path, (tmp / "xdg" / "shadows").string());
  std::filesystem::remove_all(tmp);
}

// A request big enough to watch: a 600 x 600 plane of texels under a caster.
BakeRequest bigRequest() {
  BakeRequest r;
  r.positions = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
  r.triangles = {{0, 2, 1}, {0, 3, 2}};
  r.scene_radius = 4.0f;
  const int n = 600;
  r.texels = {n, n, {}, {}};
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const float fx = static_cast<float>(x) / static_cast<float>(n),
                  fy = static_cast<float>(y) / static_cast<float>(n);
      r.texels.position.emplace_back(4.0f * fx - 2.0f, 0.0f, 4.0f * fy - 2.0f, 0.0f);
      r.texels.normal.emplace_back(0.0f, 1.0f, 0.0f, 0.0f);
    }
  }
  r.light.position = {0.0f, 4.0f, 0.0f};
  r.light.direction = {0.0f, -1.0f, 0.0f};
  r.light.radius = 0.5f;
  r.light.samples = 256;
  return r;
}

TEST(Lesson15, ABakeReportsItsProgressAndStopsWhenCancelled) {
  const CacheDir cache("off");
  LightMapBaker baker;
  baker.start(bigRequest(), /*wait=*/false);
  ASSERT_EQ(baker.state().stage, BakeState::Stage::kRunning);
  // 92 M rays: far longer than the moment until some rows are done.
  double progress = 0.0;
  for (int k = 0; k < 400 && progress == 0.0; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    progress = baker.poll().progress;
  }
  EXPECT_GT(progress, 0.0);
  EXPECT_LT(progress, 1.0);
  const auto asked = std::chrono::steady_clock::now();
  baker.cancel();
  EXPECT_LT(std::chrono::steady_clock::now() - asked, std::chrono::seconds(2));
  EXPECT_EQ(baker.state().stage, BakeState::Stage::kCancelled);
  EXPECT_FALSE(baker.state().visibility);
  // The same request again starts over (what the panel's "bake again" asks), not kept as
  // cancelled.
  baker.start(bigRequest(), /*wait=*/false);
  EXPECT_EQ(baker.state().stage, BakeState::Stage::kRunning);
  baker.cancel();
  // A small one waited for is done; asked again, it is not traced again.
  BakeRequest small = bigRequest();
  small.light.samples = 1;
  baker.start(small, /*wait=*/true);
  EXPECT_EQ(baker.state().stage, BakeState::Stage::kDone);
  ASSERT_TRUE(baker.state().visibility);
  EXPECT_EQ(baker.state().visibility->size(), 600u * 600u);
  EXPECT_EQ(baker.state().progress, 1.0);
  // Rays from the texels under the light's disk that face it, one each: the 600 x 600 plane.
  EXPECT_EQ(baker.state().rays, 600 * 600);
  const auto* first = baker.state().visibility.get();
  baker.start(std::move(small), /*wait=*/true);
  EXPECT_EQ(baker.state().visibility.get(), first);
}

TEST(Lesson15, PastTheMemoryLimitNothingIsBaked) {
  // The cubes' floor is 50 units wide: at 128 texels a unit, 6401 texels. The binary refuses it
  // (exit 2,
  // test_cli.cpp); a window's panel says why and draws the scene unbaked, the earlier bake
  // gone with its setting.
  auto runner = startLesson(kLesson, {"view=visibility"});
  runner->renderFrame();
  ASSERT_TRUE(flag(*runner, "/lightmap/baked"));
  const Image baked = runner->readImage();
  ASSERT_EQ(runner->params().set("scene", "cubes"), "");
  runner->renderFrame();
  const Image cubes = runner->readImage();  // baked at 16 texels a unit
  ASSERT_EQ(runner->params().set("lightmap.texels_per_unit", "128"), "");
  EXPECT_NE(runner->checkConsistency().find("4096 texels a side"), std::string::npos);
  runner->renderFrame();
  EXPECT_FALSE(flag(*runner, "/lightmap/baked"));
  ASSERT_EQ(runner->params().set("shadow.off", "true"), "");  // every pixel lit
  runner->renderFrame();
  const Image lit = runner->readImage();
  ASSERT_EQ(runner->params().set("shadow.off", "false"), "");
  runner->renderFrame();
  EXPECT_EQ(testing::pixelsDiffering(runner->readImage(), lit, 0), 0u) << "drawn unbaked";
  EXPECT_GT(testing::pixelsDiffering(cubes, lit, 0), 1000u);
  EXPECT_GT(testing::pixelsDiffering(baked, cubes, 0), 1000u);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson15, MapModeShowsNothingBakedAndTheFloorNeverMoves) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  ASSERT_EQ(runner->params().set("lightmap.mode", "map"), "");
  runner->renderFrame();
  EXPECT_FALSE(flag(*runner, "/lightmap/baked"));
  EXPECT_EQ(reportNumber(*runner, "/lightmap/texels"), 0);
  // Back: the bake is shown again (from the baker, not traced again).
  ASSERT_EQ(runner->params().set("lightmap.mode", "baked"), "");
  runner->renderFrame();
  EXPECT_TRUE(flag(*runner, "/lightmap/baked"));
  // move.object 0 names the floor, which casts nothing: the last caster (the ball) moves.
  auto floor = startLesson(kLesson, {"move.object=0", "move.x=-1.5"});
  floor->renderFrame();
  auto ball = startLesson(kLesson, {"move.x=-1.5"});
  ball->renderFrame();
  EXPECT_EQ(testing::pixelsDiffering(floor->readImage(), ball->readImage(), 0), 0u);
}

}  // namespace
}  // namespace shadows
