// Drives a lesson in-process, headless, exactly as its binary would.
#pragma once

#include "core/image.hpp"
#include "core/json.hpp"
#include "run/runner.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace shadows::testing {

inline std::unique_ptr<Runner> startLesson(const std::string& lesson,
                                           const std::vector<std::string>& sets, int width = 320,
                                           int height = 240, bool panel = false,
                                           const std::string& backend = "osmesa") {
  RunOptions options;
  options.headless = true;
  options.width = width;
  options.height = height;
  options.panel = panel;
  options.backend = backend;
  auto runner = std::make_unique<Runner>(lesson, makeLesson(lesson), options);
  const std::string error = runner->applySets(sets);
  EXPECT_EQ(error, "");
  runner->initHeadless();
  return runner;
}

// Fraction of pixels whose largest channel difference exceeds `threshold` levels.
inline double fractionDiffering(const Image& a, const Image& b, int threshold) {
  if (a.width != b.width || a.height != b.height) return 1.0;
  size_t differing = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.rgba[i + c] - b.rgba[i + c]));
    if (worst > threshold) ++differing;
  }
  return static_cast<double>(differing) / static_cast<double>(a.rgba.size() / 4);
}

// Pixels whose largest channel difference exceeds `threshold` levels.
inline size_t pixelsDiffering(const Image& a, const Image& b, int threshold) {
  if (a.width != b.width || a.height != b.height) return a.rgba.size() / 4 + 1;
  return static_cast<size_t>(
      std::lround(fractionDiffering(a, b, threshold) * static_cast<double>(a.rgba.size() / 4)));
}

inline double meanAbsDifference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) sum += std::abs(a.rgba[i] - b.rgba[i]);
  return sum / static_cast<double>(a.rgba.size());
}

// How many values of two same-size buffers (visibility images, say) differ at all.
inline size_t valuesDiffering(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
  return differing;
}

// "a=1 b=2 " for failure messages.
inline std::string label(const std::vector<std::string>& sets) {
  std::string text;
  for (const auto& s : sets) text += s + " ";
  return text;
}

// Renders the lesson once with `sets` and measures it against the truth; a GL error fails.
inline ErrorMetrics measureOnce(const std::string& lesson, const std::vector<std::string>& sets,
                                int width = 320, int height = 240) {
  auto runner = startLesson(lesson, sets, width, height);
  runner->renderFrame();
  const ErrorMetrics metrics = runner->measureError().metrics;
  EXPECT_EQ(runner->glErrors(), 0) << label(sets);
  return metrics;
}

// The lesson's --report, as the binary would write it, read by a real JSON parser (a report
// that is not JSON fails the test), keys in the order written.
inline nlohmann::ordered_json report(Runner& runner) {
  JsonWriter json;
  runner.writeReport(json);
  nlohmann::ordered_json parsed = nlohmann::ordered_json::parse(json.str(), nullptr, false);
  EXPECT_FALSE(parsed.is_discarded()) << "the report is not JSON:\n" << json.str();
  return parsed;
}

// Renders the lesson once with `sets`, measures it against the truth and returns its report
// (the error in it); a GL error fails.
inline nlohmann::ordered_json measuredReport(const std::string& lesson,
                                             const std::vector<std::string>& sets, int width = 320,
                                             int height = 240) {
  auto runner = startLesson(lesson, sets, width, height);
  runner->renderFrame();
  runner->measureError();
  EXPECT_EQ(runner->glErrors(), 0) << label(sets);
  return report(*runner);
}

// The one value named `key` anywhere in the report, or a JSON pointer ("/error/vis_mae").
// A key that is missing or found twice fails the test: the caller must say which it means.
inline nlohmann::ordered_json reportValue(Runner& runner, const std::string& key) {
  const nlohmann::ordered_json whole = report(runner);
  if (!key.empty() && key[0] == '/') {
    const nlohmann::ordered_json::json_pointer at(key);
    EXPECT_TRUE(whole.contains(at)) << key;
    return whole.contains(at) ? whole.at(at) : nlohmann::ordered_json();
  }
  std::vector<nlohmann::ordered_json> found;
  const auto search = [&](const auto& self, const nlohmann::ordered_json& node) -> void {
    if (node.is_object()) {
      for (const auto& [name, child] : node.items()) {
        if (name == key) found.push_back(child);
        self(self, child);
      }
    } else if (node.is_array()) {
      for (const auto& child : node) self(self, child);
    }
  };
  search(search, whole);
  EXPECT_EQ(found.size(), 1u) << key << " is in the report " << found.size() << " times";
  return found.empty() ? nlohmann::ordered_json() : found.front();
}

// One work counter of the last frame (-1, and a failure, when the frame did not count it).
inline long long counter(Runner& runner, const std::string& name) {
  const auto& counts = runner.measure().lastFrameCounts();
  const auto it = counts.find(name);
  EXPECT_NE(it, counts.end()) << name;
  return it == counts.end() ? -1 : it->second;
}

// A number from the lesson's --report.
inline double reportNumber(Runner& runner, const std::string& key) {
  const nlohmann::ordered_json v = reportValue(runner, key);
  EXPECT_TRUE(v.is_number()) << key << " = " << v.dump();
  return v.is_number() ? v.get<double>() : 0.0;
}

// A driver without a feature, as a laptop's may be: SHADOWS_TEST_CAPS_OFF switches it off in the
// GL context's caps for the runners started while it lives (common/gl/caps.cpp).
struct CapsOff {
  explicit CapsOff(const char* names) { setenv("SHADOWS_TEST_CAPS_OFF", names, 1); }
  ~CapsOff() { unsetenv("SHADOWS_TEST_CAPS_OFF"); }
  CapsOff(const CapsOff&) = delete;
  CapsOff& operator=(const CapsOff&) = delete;
};

// A string from the lesson's --report ("" when the key is missing).
inline std::string reportString(Runner& runner, const std::string& key) {
  const nlohmann::ordered_json v = reportValue(runner, key);
  EXPECT_TRUE(v.is_string()) << key << " = " << v.dump();
  return v.is_string() ? v.get<std::string>() : std::string();
}

// Each settings list, on a fresh lesson: no GL error, no NaN or Inf anywhere it draws.
inline void expectFiniteAndErrorFree(const std::string& lesson,
                                     const std::vector<std::vector<std::string>>& settings) {
  for (const auto& sets : settings) {
    auto runner = startLesson(lesson, sets, 160, 120);
    runner->renderFrame();
    EXPECT_EQ(runner->measureError().metrics.nonfinite_pixels, 0) << label(sets);
    EXPECT_EQ(runner->glErrors(), 0) << label(sets);
  }
}

// The ends of the shadow-map sliders every shadow-map lesson shares (ShadowMap, the light,
// the camera, dimming), as settings lists for expectFiniteAndErrorFree. Near and far are set
// with the fit off, so they reach the map.
inline std::vector<std::vector<std::string>> shadowMapSliderExtremes() {
  return {{"shadow.size=64", "shadow.height=4096", "shadow.format=16"},
          {"shadow.size=4096", "shadow.format=32f", "shadow.filter=linear"},
          {"light.near=0.001", "light.far=1000", "shadow.fit=false"},
          {"light.near=100", "light.far=0.01", "shadow.fit=false"},  // far < near: sanitized
          {"light.fov=5"},
          {"light.fov=160"},
          {"light.pos=0,0.5,0", "light.target=0,0.5,0"},   // degenerate: eye == target
          {"light.pos=0,50,0", "light.target=0,0,0"},      // looking straight down
          {"light.pos=-50,0.01,0", "light.target=0,0,0"},  // grazing
          {"light.type=directional", "light.extent=0.5"},
          {"camera.pos=0,0.6,0", "camera.target=0,0.6,0"},
          {"light.pos=3,-6,4"},                             // below the floor
          {"camera.pos=0.6,0.45,1.6", "light.pos=-3,7,2"},  // the eye inside the sphere
          {"dimming=0"},
          {"dimming=1"}};
}

// The ends of the sliders lessons 06 and 07 share (common/depth_readback: map size, light
// frustum, path, bias), as settings lists for expectFiniteAndErrorFree.
inline std::vector<std::vector<std::string>> readbackMapSliderExtremes() {
  return {{"shadow.size=64", "shadow.height=4096", "map.path=copy_texture"},
          {"shadow.size=4096", "map.path=render_to_texture"},
          {"light.near=0.001", "light.far=1000", "shadow.fit=false"},
          {"light.near=100", "light.far=0.01", "shadow.fit=false"},  // far < near: sanitized
          {"bias.steps=0", "bias.factor=0"},
          {"bias.factor=20", "bias.mode=texgen"},
          {"light.fov=5"},
          {"light.fov=160"},
          {"light.pos=0,0.5,0", "light.target=0,0.5,0"},   // degenerate: eye == target
          {"light.pos=-50,0.01,0", "light.target=0,0,0"},  // grazing
          {"light.type=directional", "light.extent=0.5"},
          {"camera.pos=0,0.6,0", "camera.target=0,0.6,0"},
          {"dimming=0"},
          {"dimming=1"}};
}

// Every input the shadow map depends on, listed once for every shadow-map lesson, each as a
// change from the one before: the light (type, position, target, frustum), the map itself
// (size, height, format, the fit) and the scene. The fit goes off first so near and far
// reach the map. A lesson adds its own (its bias).
inline std::vector<std::string> shadowMapInputs() {
  return {"shadow.fit=false", "light.pos=2,7,3",   "light.target=0.5,0,-0.5", "light.fov=50",
          "light.near=1.5",   "light.far=15",      "light.type=directional",  "light.extent=6",
          "shadow.size=512",  "shadow.height=256", "shadow.format=16",        "shadow.fit=true",
          "scene=grazing"};
}

// The same for lessons 06 and 07 (common/depth_readback): no depth format, but a copy path
// and the light pass's depth bits, both of which re-create the map's storage.
inline std::vector<std::string> readbackMapInputs() {
  std::vector<std::string> inputs;
  for (const std::string& input : shadowMapInputs()) {
    if (input.rfind("shadow.format=", 0) != 0) inputs.push_back(input);
  }
  inputs.insert(inputs.end(), {"map.path=copy_texture", "map.depth_bits=16", "bias.steps=5",
                               "bias.factor=1", "bias.mode=texgen"});
  return inputs;
}

// With the cache on, each change in `inputs` renders the map again, and what the frame shows
// is what a map rendered from scratch (cache off) shows; a frame with no change renders none.
// `start`: by default the fit on, so shadowMapInputs()' first entry (fit off) is a change in
// every lesson with a ShadowMap; a lesson without one (11's cube) starts from its defaults.
inline void expectEveryMapInputRendersTheMapAgain(const std::string& lesson,
                                                  const std::vector<std::string>& inputs,
                                                  const std::vector<std::string>& start = {
                                                      "inset=false", "shadow.fit=true"}) {
  auto runner = startLesson(lesson, start, 160, 120);
  const auto renders = [&] {
    runner->renderFrame();
    return runner->measure().lastFrameCounts().at("shadow_map_renders");
  };
  EXPECT_EQ(renders(), 1);
  EXPECT_EQ(renders(), 0);
  for (const std::string& input : inputs) {
    const Param& param = runner->params().at(input.substr(0, input.find('=')));
    const std::string before = param.text();
    ASSERT_EQ(runner->params().assign(input), "") << input;
    ASSERT_NE(param.text(), before) << input << " is no change";
    EXPECT_EQ(renders(), 1) << input << " must render the map again";
    const Image cached = runner->readImage();
    ASSERT_EQ(runner->params().assign("shadow.cache=false"), "");
    EXPECT_EQ(renders(), 1);
    EXPECT_EQ(pixelsDiffering(cached, runner->readImage(), 0), 0u) << input;
    ASSERT_EQ(runner->params().assign("shadow.cache=true"), "");
    renders();
    EXPECT_EQ(renders(), 0) << input << ": a static frame keeps the map";
  }
  EXPECT_EQ(runner->glErrors(), 0);
}

// Moving a caster must render the map again too (SceneHost::setObjectModel).
inline void expectACasterMoveRendersTheMapAgain(const std::string& lesson,
                                                const std::vector<std::string>& start = {
                                                    "inset=false"}) {
  auto runner = startLesson(lesson, start, 160, 120);
  runner->renderFrame();
  runner->renderFrame();
  size_t caster = 0;
  while (caster < runner->scene().objects.size() && !runner->scene().objects[caster].caster) {
    ++caster;
  }
  ASSERT_LT(caster, runner->scene().objects.size());
  runner->host().setObjectModel(
      caster, glm::translate(runner->host().presetModel(caster), {0.7f, 0.3f, 0}));
  runner->renderFrame();
  EXPECT_EQ(runner->measure().lastFrameCounts().at("shadow_map_renders"), 1);
  const Image cached = runner->readImage();
  ASSERT_EQ(runner->params().assign("shadow.cache=false"), "");
  runner->renderFrame();
  EXPECT_EQ(pixelsDiffering(cached, runner->readImage(), 0), 0u) << "a stale map on screen";
}

// Renders every `view` the lesson offers: no GL error in any, no two alike (each view shows
// something of its own), and no NaN or Inf in what the lesson draws.
inline void expectEveryViewCleanAndDistinct(Runner& runner, const std::string& label = {}) {
  std::vector<std::vector<std::uint8_t>> pictures;
  const std::vector<std::string> views = runner.params().at("view").choices;
  for (const std::string& view : views) {
    ASSERT_EQ(runner.params().set("view", view), "");
    runner.renderFrame();
    EXPECT_EQ(runner.glErrors(), 0) << label << " " << view;
    pictures.push_back(runner.readImage().rgba);
  }
  for (size_t i = 0; i < pictures.size(); ++i) {
    for (size_t j = i + 1; j < pictures.size(); ++j) {
      EXPECT_NE(pictures[i], pictures[j]) << label << ": " << views[i] << " and " << views[j];
    }
  }
  ASSERT_EQ(runner.params().set("view", "shaded"), "");
  const ErrorMetrics& e = runner.measureError().metrics;
  EXPECT_EQ(e.nonfinite_pixels, 0) << label;
  // An empty surface pass would make every error metric read 0: a pass, wrongly.
  EXPECT_GT(e.counted_pixels, 1000) << label;
  EXPECT_EQ(runner.glErrors(), 0) << label;
}

// The golden tolerance (tests/golden/README.md says why): the Release build ./test.sh makes
// reproduces every golden byte for byte; a RelWithDebInfo build moves a handful of edge
// pixels. So at most kGoldenMovedPixels pixels may differ at all, however much.
inline constexpr size_t kGoldenMovedPixels = 16;

// Compares `image` with tests/golden/<name>.png; with UPDATE_GOLDEN set, writes it instead
// and skips (look at it before committing).
inline void expectMatchesGolden(const Image& image, const std::string& name) {
  const std::string path = std::string(SHADOWS_GOLDEN_DIR) + "/" + name + ".png";
  if (std::getenv("UPDATE_GOLDEN") != nullptr) {
    ASSERT_TRUE(writePng(path, image));
    GTEST_SKIP() << "golden written to " << path << ": look at it before committing";
  }
  const Image golden = readPng(path);
  EXPECT_LE(pixelsDiffering(image, golden, 0), kGoldenMovedPixels)
      << name << ": pixels off by more than 8 levels: " << pixelsDiffering(image, golden, 8)
      << ", mean difference " << meanAbsDifference(image, golden);
}

}  // namespace shadows::testing
