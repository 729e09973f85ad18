// Lesson 02 end to end, headless: the slide on the scene, every view, reverse projection
// and each of its fixes, a PNG given on the command line (and a missing or broken one as
// bad input), and what a projector without a depth test gets wrong against the truth.
#include "harness.hpp"

#include "core/json.hpp"

#include <imgui.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace shadows {
namespace {

namespace fs = std::filesystem;
using testing::fractionDiffering;
using testing::startLesson;

const std::string kLesson = "02_projective_texture";
// A projector low on the floor, pointing up at the pyramid: the cone behind it (q < 0)
// reaches down onto the floor in front of the camera, where reverse projection shows.
const std::vector<std::string> kLowProjector = {"light.pos=-1.2,0.5,1.8",
                                                "light.target=1.6,1.4,-1.2", "light.fov=80"};
const std::vector<std::string> kNoFix = {"fix.q_test=false", "fix.behind=off", "falloff=0"};

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

std::string reportText(Runner& runner) {
  JsonWriter json;
  runner.writeReport(json);
  return json.str();
}

// A fresh directory under the temporary one, removed at the end of the test.
struct TempDir {
  TempDir() {
    path = fs::temp_directory_path() /
           ("shadows_lesson02_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path path;
};

// Two halves, magenta left and cyan right: easy to find in a picture.
Image twoColourSlide(int width, int height) {
  Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &image.rgba[(static_cast<size_t>(y) * width + x) * 4];
      const bool left = x < width / 2;
      p[0] = left ? 255 : 0, p[1] = left ? 0 : 255, p[2] = 255, p[3] = 255;
    }
  }
  return image;
}

TEST(Lesson02, SnapshotMatchesTheGolden) {
  // Rendered on Mesa llvmpipe and looked at; tolerance and why in tests/golden/README.md.
  const Image image = render({});
  testing::expectMatchesGolden(image, "02_projective_texture");
}

TEST(Lesson02, SnapshotShowsTheSlideOnTheScene) {
  // Guards the golden: the red arrow, the blue checker squares and the yellow frame of the
  // built-in slide all land on the scene (the inset alone is far smaller than this).
  const Image image = render({"inset=false"});
  size_t red = 0, blue = 0, yellow = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    if (r > 110 && g < 60 && b < 60) ++red;
    if (b > 110 && b > r + 50 && b > g + 20) ++blue;
    if (r > 110 && g > 80 && b < 50) ++yellow;
  }
  const size_t pixels = image.rgba.size() / 4;
  EXPECT_GT(red, pixels / 50);
  EXPECT_GT(blue, pixels / 20);
  EXPECT_GT(yellow, pixels / 200);
}

TEST(Lesson02, EveryViewRendersWithoutGlErrorsOrNonFiniteValues) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
}

// Pixels where the slide would land from behind the projector: the texcoords view paints
// them with blue = 1 (q < 0) wherever (s/q, t/q) falls inside the slide.
std::vector<bool> reverseRegion() {
  const Image coords = render(with(kLowProjector, {"view=texcoords"}));
  std::vector<bool> region(coords.rgba.size() / 4);
  for (size_t i = 0; i < region.size(); ++i) region[i] = coords.rgba[i * 4 + 2] == 255;
  return region;
}

// The fraction of `region` that view=visibility shows lit.
double litFraction(const std::vector<std::string>& sets, const std::vector<bool>& region) {
  const Image visibility = render(with(with(kLowProjector, sets), {"view=visibility"}));
  size_t inside = 0, lit = 0;
  for (size_t i = 0; i < region.size(); ++i) {
    if (!region[i]) continue;
    ++inside;
    if (visibility.rgba[i * 4] > 127) ++lit;
  }
  return inside == 0 ? 0.0 : static_cast<double>(lit) / static_cast<double>(inside);
}

TEST(Lesson02, ReverseProjectionShowsWithoutAFixAndEachFixRemovesIt) {
  const std::vector<bool> region = reverseRegion();
  const auto size = static_cast<size_t>(std::count(region.begin(), region.end(), true));
  ASSERT_GT(size, region.size() / 50) << "the cone behind the projector is in view";
  EXPECT_GT(litFraction(kNoFix, region), 0.95) << "no fix: the mirrored slide is lit";
  EXPECT_EQ(litFraction(with(kNoFix, {"fix.q_test=true"}), region), 0.0) << "q < 0 test";
  EXPECT_EQ(litFraction(with(kNoFix, {"falloff=0.2"}), region), 0.0) << "spotlight cone";
  EXPECT_LT(litFraction(with(kNoFix, {"fix.behind=clip"}), region), 0.01) << "clip plane";
  // Skipping objects wholly behind the projector cannot help a floor that straddles it.
  EXPECT_GT(litFraction(with(kNoFix, {"fix.behind=skip"}), region), 0.95) << "skip";
  // And the shaded picture shows it too: the mirrored slide brightens the floor there.
  const Image fixed = render(kLowProjector), broken = render(with(kLowProjector, kNoFix));
  EXPECT_GT(fractionDiffering(fixed, broken, 24), 0.02);
}

TEST(Lesson02, TheClipPlaneLeavesTheForwardProjectionWhole) {
  // The clip plane cuts triangles into new ones; lit with depth EQUAL they would drop out
  // as holes. In front of the projector clip must light exactly what q_test lights.
  const Image q_test = render(with(kLowProjector, {"view=visibility"}));
  const Image clip =
      render(with(kLowProjector, {"view=visibility", "fix.q_test=false", "fix.behind=clip"}));
  EXPECT_LT(fractionDiffering(q_test, clip, 127), 0.002);
}

TEST(Lesson02, ObjectsWhollyBehindTheProjectorAreNotDrawnInItsPass) {
  // A projector just in front of the sphere, pointing away from it: the sphere is skipped.
  const std::vector<std::string> sets = {"light.pos=0.6,0.6,0.9", "light.target=0,0.6,-3"};
  auto skip = startLesson(kLesson, sets);
  skip->renderFrame();
  EXPECT_EQ(skip->measure().lastFrameCounts().at("skipped_behind_projector"), 1);
  const long long skip_draws = skip->measure().lastFrameWork().at("projector").draw_calls;
  EXPECT_NE(reportText(*skip).find("\"objects_skipped_behind\": 1"), std::string::npos);
  skip.reset();  // one headless context at a time
  auto off = startLesson(kLesson, with(sets, {"fix.behind=off"}));
  off->renderFrame();
  EXPECT_EQ(off->measure().lastFrameCounts().at("skipped_behind_projector"), 0);
  EXPECT_EQ(off->measure().lastFrameWork().at("projector").draw_calls, skip_draws + 1);
}

TEST(Lesson02, APngFromTheCommandLineIsProjectedWithItsAspect) {
  TempDir dir;
  const std::string path = (dir.path / "two colours.png").string();
  ASSERT_TRUE(writePng(path, twoColourSlide(64, 32)));
  auto runner = startLesson(kLesson, {"projector.image=" + path, "inset=false"});
  runner->renderFrame();
  const Image image = runner->readImage();
  size_t magenta = 0, cyan = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    if (r > 80 && b > 80 && g < 40) ++magenta;
    if (g > 80 && b > 80 && r < 40) ++cyan;
  }
  EXPECT_GT(magenta, image.rgba.size() / 4 / 20);
  EXPECT_GT(cyan, image.rgba.size() / 4 / 20);
  const std::string report = reportText(*runner);
  EXPECT_NE(report.find("\"slide\": \"" + path + "\""), std::string::npos) << report;
  EXPECT_NE(report.find("\"projector.image\": \"" + path + "\""), std::string::npos);
  EXPECT_NE(report.find("\"slide_size\": [\n    64,\n    32"), std::string::npos) << report;
  // Back to the built-in slide at run time: the same picture as a fresh start.
  ASSERT_EQ(runner->params().set("projector.image", "builtin"), "");
  runner->renderFrame();
  const Image back = runner->readImage();
  EXPECT_EQ(runner->glErrors(), 0);
  runner.reset();  // one headless context at a time
  EXPECT_EQ(fractionDiffering(back, render({"inset=false"}), 0), 0.0);
}

TEST(Lesson02, AMissingOrBrokenPngIsBadInputThatNamesTheFile) {
  TempDir dir;
  const std::string missing = (dir.path / "no such slide.png").string();
  const std::string broken = (dir.path / "broken.png").string();
  std::ofstream(broken) << "\x89PNG\r\n\x1a\n this is not the rest of a PNG";
  RunOptions options;
  options.headless = true;
  for (const std::string& path : {missing, broken}) {
    Runner runner(kLesson, makeLesson(kLesson), options);
    const std::string error = runner.applySets({"projector.image=" + path});
    EXPECT_NE(error.find("projector.image: "), std::string::npos) << error;
    EXPECT_NE(error.find(path), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
    EXPECT_EQ(runner.params().at("projector.image").s(), "builtin") << "nothing changed";
  }
  // The binary itself: exit 2, one line naming the file, nothing written. (Built next to
  // this test program; skipped when only the tests were built.)
  const fs::path binary = fs::read_symlink("/proc/self/exe").parent_path().parent_path() / kLesson;
  if (!fs::exists(binary)) GTEST_SKIP() << binary << " not built";
  const fs::path out = dir.path / "out";
  fs::create_directories(out);
  for (const std::string& path : {missing, broken}) {
    const std::string command =
        binary.string() + " --headless --size 64x48 --set 'projector.image=" + path + "' --out " +
        (out / "x.png").string() + " --report " + (out / "r.json").string() + " 2>&1";
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::array<char, 4096> buffer{};
    while (fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
    const int status = pclose(pipe);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << output;
    EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
    EXPECT_EQ(output.rfind(kLesson + ": projector.image: ", 0), 0u) << output;
    EXPECT_NE(output.find(path), std::string::npos) << output;
    EXPECT_TRUE(fs::is_empty(out)) << "nothing written";
  }
}

TEST(Lesson02, AProjectorLightsThroughCastersWhichTheTruthCountsAsFalseLit) {
  // No depth test against the projector: the slide goes through the torus onto the floor.
  // Only pixels inside the projector's frustum are counted, and there nothing is lit too
  // little, everything behind a caster too much.
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  const ErrorMetrics inside = runner->measureError().metrics;
  EXPECT_GT(inside.false_lit_pct, 3.0);
  EXPECT_LT(inside.false_shadow_pct, 0.1);
  runner.reset();
  // A narrow projector counts far fewer pixels: the counted set is its frustum.
  auto narrow = startLesson(kLesson, {"light.fov=10"});
  narrow->renderFrame();
  const ErrorMetrics few = narrow->measureError().metrics;
  EXPECT_LT(few.counted_pixels, inside.counted_pixels / 5);
  EXPECT_GT(few.counted_pixels, 0);
}

TEST(Lesson02, SliderExtremesStayFiniteAndErrorFree) {
  const std::vector<std::vector<std::string>> extremes = {
      {"light.fov=5"},
      {"light.fov=160", "falloff=1"},
      {"falloff=1", "fix.q_test=false", "fix.behind=off"},
      {"light.pos=0,0.5,0", "light.target=0,0.5,0"},  // degenerate: eye == target
      {"light.pos=0,50,0", "light.target=0,0,0"},     // straight down
      {"light.pos=-0.9,1.07,0.2"},                    // inside the torus's tube
      {"light.type=directional", "light.extent=0.5", "falloff=0.5"},
      {"light.type=directional", "fix.behind=clip", "fix.q_test=false"},
      {"fix.q_test=false", "fix.behind=off", "view=texcoords"},
      {"view=slide", "scene=cubes"},
      {"camera.pos=0,0.6,0", "camera.target=0,0.6,0"}};
  testing::expectFiniteAndErrorFree(kLesson, extremes);
}

TEST(Lesson02, PanelShowsTheImagePathFieldWhichLoadsATypedPng) {
  // The field is there to be used: click it, select all, type a PNG's path, press Enter.
  TempDir dir;
  const std::string path = (dir.path / "typed.png").string();
  ASSERT_TRUE(writePng(path, twoColourSlide(64, 32)));
  auto runner = startLesson(kLesson, {"inset=false"}, 800, 600, /*panel=*/true);
  runner->setMouse({-1, -1}, false);
  runner->renderFrame();
  runner->renderFrame();
  const Param& image = runner->params().at("projector.image");
  ASSERT_GT(image.widget_max.x, image.widget_min.x) << "an input field was drawn";
  const Image before = runner->readImage();
  ImGuiIO& io = ImGui::GetIO();
  constexpr int kKeyA = 65, kKeyEnter = 13;  // any indices: the test's own key map
  io.KeyMap[ImGuiKey_A] = kKeyA;
  io.KeyMap[ImGuiKey_Enter] = kKeyEnter;
  const glm::vec2 field = {image.widget_min.x + 20.0f,
                           0.5f * (image.widget_min.y + image.widget_max.y)};
  for (const bool down : {false, true, false}) {
    runner->setMouse(field, down);
    runner->renderFrame();
  }
  auto press = [&](int key, bool ctrl) {
    io.KeyCtrl = ctrl;
    io.KeysDown[key] = true;
    runner->renderFrame();
    io.KeysDown[key] = false;
    io.KeyCtrl = false;
    runner->renderFrame();
  };
  press(kKeyA, true);  // select "builtin"
  io.AddInputCharactersUTF8(path.c_str());
  runner->renderFrame();
  press(kKeyEnter, false);
  EXPECT_EQ(runner->params().at("projector.image").s(), path);
  runner->renderFrame();
  EXPECT_GT(fractionDiffering(before, runner->readImage(), 24), 0.02) << "the new slide shows";
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson02, EveryPixelTakesTheProjectorsLightAtMostOnce) {
  // With fix.behind=clip the projector pass compares LEQUAL with an offset toward the eye, and
  // at silhouettes a back face nearly as deep as the front one used to pass too: light added
  // twice, visibility above 1 (vis_mae 1.005 from this light). The stencil lets one through.
  for (const char* behind : {"clip", "skip", "off"}) {
    auto runner = testing::startLesson(
        "02_projective_texture", {"light.pos=0.6,0.45,1.6", std::string("fix.behind=") + behind});
    runner->renderFrame();
    const std::vector<float> visibility = runner->renderVisibility();
    const float most = *std::max_element(visibility.begin(), visibility.end());
    EXPECT_LE(most, 1.0f) << behind;
    EXPECT_LE(runner->measureError().metrics.vis_mae, 1.0) << behind;
    EXPECT_EQ(runner->glErrors(), 0);
  }
}

TEST(Lesson02, TheSlideMustBeBuiltinOrAPngAndEveryRefusalIsOneLine) {
  auto runner = testing::startLesson("02_projective_texture", {}, 64, 48);
  const std::string bmp = "/tmp/shadows_lesson02_slide.bmp";
  {
    std::FILE* f = std::fopen(bmp.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    const char header[] = "BM\x46\0\0\0\0\0\0\0\x36\0\0\0";  // a BMP, which stb would read
    std::fwrite(header, 1, sizeof header, f);
    std::fclose(f);
  }
  Params& p = runner->params();
  const std::string empty = p.set("projector.image", "");
  EXPECT_NE(empty.find("expected 'builtin' or the path of a PNG"), std::string::npos) << empty;
  const std::string not_png = p.set("projector.image", bmp);
  EXPECT_NE(not_png.find("not a PNG"), std::string::npos) << not_png;
  const std::string newline = p.set("projector.image", "/tmp/a\nb.png");
  EXPECT_NE(newline, "");
  for (const std::string& message : {empty, not_png, newline}) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_EQ(p.at("projector.image").s(), "builtin") << "refused values change nothing";
  std::remove(bmp.c_str());
}

}  // namespace
}  // namespace shadows
