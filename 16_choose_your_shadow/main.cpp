// Lesson 16: choose your shadow. One scene, every technique the course taught, each scored
// against the same ray-traced truth: for this scene and this budget, which one?
//
// Each technique is its own lesson's code, run inside this one (common/lesson/hosted_lesson.hpp):
//   hard       lesson 04: one map, one compare, a bias
//   pcf        lesson 05: compare, then average a kernel of taps
//   filtered   lesson 13: a map that can be blurred (VSM, ESM, moments)
//   pcss       lesson 14: a blocker search sets the penumbra's width
//   cascades   lesson 12: a sun's view split by distance, one map a slice
//   cube       lesson 11: six faces (or two paraboloids, or four) around a point light
//   volumes    lesson 09: the stencil counts entries into shadow; no map at all
//   lightmap   lesson 15: baked once with the truth's rays; a caster that moves leaves it
//   warped     lesson 10: the map's matrix warped so its texels land where the eye looks
//              (focused, LiSPSM; plane-optimal where the scene has a plane of interest)
// Every technique here is scored on every pixel of the frame (a lesson counts only the pixels
// its own light covers) against one light: a point, or a disk of light.radius. What a technique
// cannot do with this light it says, and draws the frame without a shadow.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_front.hpp"
#include "core/json.hpp"
#include "front_plot.hpp"
#include "lesson/hosted_lesson.hpp"
#include "lesson/lesson.hpp"
#include "tried.hpp"

namespace shadows {

namespace {

// Each technique: its lesson, its settings here, the knobs this lesson offers of it.
std::vector<HostedLesson::Spec> techniques() {
  // Counting taps costs atomics in the eye pass (05, 14): off, so costs compare.
  return {
      {"hard", "04_bias_offset", {"inset=false"}, {"shadow.size", "bias.mode"}, {}},
      {"pcf",
       "05_pcf_dithered",
       {"inset=false", "pcf.count=false"},
       {"shadow.size", "pcf.mode", "pcf.taps", "pcf.radius"},
       {}},
      {"filtered",
       "13_filterable_maps",
       {"inset=false"},
       {"shadow.size", "filter.method", "filter.radius"},
       {}},
      {"pcss",
       "14_soft_shadows",
       {"inset=false", "pcss.count=false"},
       {"shadow.size", "pcss.search_taps", "pcf.taps"},
       {{"light.radius", "pcss.light_radius"}}},
      {"cascades", "12_cascades", {}, {"cascades.count", "cascades.size", "cascades.blend"}, {}},
      {"cube", "11_omni_cube", {}, {"omni.method", "cube.size"}, {}},
      {"lightmap",
       "15_light_maps",
       {"inset=false"},
       {"lightmap.mode", "lightmap.texels_per_unit"},
       {{"light.radius", "lightmap.light_radius"}}},
      {"volumes", "09_shadow_volumes", {}, {}, {}},  // exact: nothing to trade
      // 10's default: plane-optimal on the floor, a 1024² map (warped/shadow.size=640 and
      // warped/shadow.height=480 make it the frame's size: a texel a floor pixel).
      {"warped",
       "10_plane_optimal",
       {"inset=false"},
       {"light.projection", "plane", "lispsm.n", "shadow.size", "shadow.height"},
       {}}};
}

}  // namespace

class ChooseYourShadow final : public Lesson {
 public:
  std::string title() const override { return "Choose your shadow: one scene, every technique"; }
  std::string seeds() const override {
    return "seed 000: Common Real-time Shadow Techniques; 003: Shadow Volumes Summary, Static "
           "Shadows; the techniques of lessons 04, 05, 09, 10, 11, 12, 13, 14 and 15 on one scene";
  }
  std::vector<std::string> scenes() const override {
    return {"contact", "street", "bulb", "yard", "torus_pyramid"};
  }
  // The preset's light range for every technique: 04's and 05's maps fit theirs to the
  // casters, 11 and 12 set their own, 13 and 14 keep the preset's, as in their lessons.
  std::vector<std::string> unusedSharedParams() const override {
    return {"light.near", "light.far"};
  }

  void declare(Params& p) override {
    host_ = &p;
    std::vector<std::string> keys;
    for (HostedLesson::Spec& spec : techniques()) {
      keys.push_back(spec.key);
      hosted_.push_back(std::make_unique<HostedLesson>(std::move(spec)));
    }
    // A switch dirties no map: a technique's kept map is drawn again only if something moved
    // while another drew (render() hands every technique what the host was told).
    technique_ = p.addChoice("technique", keys, "pcf", "which lesson's technique draws the shadow");
    light_radius_ = p.addFloat("light.radius", 0.0f, 0.0f, 1.0f,
                               "the light's radius: 0 a point (hard shadows), else a disk; the "
                               "truth and PCSS take it");
    p.addFloat("dimming", 0.4f, 0.0f, 1.0f, "diffuse left in shadow: dimming + (1-dimming)*shade");
    p.addBool("shadow.off", false, "no shadow at all: the frame the cost is measured against",
              kDirtyShadowMap);
    p.addBool("shadow.cache", true,
              "re-render a map only when the light or a caster changed (off: every frame, the "
              "cost of a scene where something always moves)",
              kDirtyShadowMap);
    // One caster moved after the preset placed it, for every technique: the light map baked
    // where the preset stood (lesson 15's bake_at) is the one that cannot follow it.
    moving_ = p.addInt("move.object", -1, -1, 15,
                       "the object that moves: its index in the scene (-1: the last one)",
                       kDirtyShadowMap);
    move_x_ = p.addFloat("move.x", 0.0f, -4.0f, 4.0f, "move that object along x", kDirtyShadowMap);
    move_z_ = p.addFloat("move.z", 0.0f, -4.0f, 4.0f, "move that object along z", kDirtyShadowMap);
    for (auto& h : hosted_) {
      const std::string key = h->spec().key;
      h->declare(p, [key](const Params& ps) {
        return ps.at("technique").is(key) ? std::string() : "technique=" + key + " only";
      });
    }
    bench_.emplace(p);
  }

  void init() override {
    for (auto& h : hosted_) h->init(*host_);
  }

  void render(Frame& f) override {
    moveObject(f);  // first: a caster that moves tells the host, and the host tells them all
    // What the host was told (a light moved, a map to re-create) every technique must hear,
    // the ones not drawn now when they next are.
    const std::uint32_t dirty = f.params.dirty() & (kDirtyShadowMap | kDirtyResources);
    f.params.consume(dirty);
    for (auto& h : hosted_) h->markDirty(dirty);
    HostedLesson& h = active();
    h.sync(f.params);
    cannot_ = cannot(h, f.scene, f.light.directional);
    if (!cannot_.empty()) {
      Param& off = h.params().at("shadow.off");
      if (!off.b()) {
        off.value[0] = 1.0;
        h.markDirty(off.affects);
      }
    }
    h.render(f);
    // One light for every technique, and every pixel counted: a map that covers less of the
    // scene than its light reaches is wrong there, as the truth sees it.
    f.truth_area_radius = light_radius_();
    f.light_view_projection.reset();
    f.light_reach.reset();
  }

  void panel(Frame& f) override {
    const HostedLesson& h = active();
    ImGui::TextWrapped("%s: lesson %s, \"%s\"", h.spec().key.c_str(), h.spec().lesson.c_str(),
                       h.lesson().title().c_str());
    if (!cannot_.empty()) ImGui::TextWrapped("cannot here: %s", cannot_.c_str());
    ImGui::Text("holds: %.2f MiB of maps", static_cast<double>(h.textureBytes()) / (1 << 20));
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      ImGui::Text("error: vis_mae %.5f against a %s", error.metrics.vis_mae,
                  light_radius_() > 0.0f ? "disk light" : "point light");
    }
    drawBench(f);
    recordTried(f);
    drawTried(f);
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    // The choice and every technique's knobs, as techniques() offers them.
    std::vector<std::string> every = {"technique"};
    for (const HostedLesson::Spec& spec : techniques()) {
      for (const std::string& knob : spec.knobs) every.push_back(spec.key + "/" + knob);
    }
    return {{.title = "A bulb in a room",
             .goal = "A bare bulb lights every direction; lesson 05's map covers a cone of "
                     "them (vis_mae 0.073). Get vis_mae to 0.002 or less, holding at most 2 MiB "
                     "of maps.",
             .setup = {"scene=bulb", "technique=pcf"},
             .allowed = every,
             .figures = {{"/error/vis_mae", "vis_mae", B::AtMost, 0.002},
                         {"/technique_texture_bytes", "bytes of maps", B::AtMost, 2 << 20}},
             .hint = "Which lessons' lights reach every direction from a point?"},
            {.title = "A soft table",
             .goal = "A light 0.2 wide over the table: lesson 04's hard map, 1024 texels a "
                     "side, draws every edge sharp (vis_mae 0.0025). Get vis_mae to 0.0008 or "
                     "less, holding at most 16 MiB of maps.",
             .setup = {"scene=contact", "light.radius=0.1", "technique=hard"},
             .allowed = every,
             .figures = {{"/error/vis_mae", "vis_mae", B::AtMost, 0.0008},
                         {"/technique_texture_bytes", "bytes of maps", B::AtMost, 16 << 20}},
             .hint = "Near the floor the truth's shadow is sharp, a metre up it is soft: "
                     "which technique's blur follows the gap?"},
            {.title = "The street in 16 MiB",
             .goal = "A 4096-texel map holds the street's shadows well (vis_mae 0.00063) in "
                     "64 MiB. Keep vis_mae at 0.0009 or less in a quarter of the bytes.",
             .setup = {"scene=street", "technique=hard", "hard/shadow.size=4096"},
             .allowed = every,
             .figures = {{"/error/vis_mae", "vis_mae", B::AtMost, 0.0009},
                         {"/technique_texture_bytes", "bytes of maps", B::AtMost, 16 << 20}},
             .hint = "More than one technique gets there: try three, and read each one's "
                     "frame time beside its bytes."},
            {.title = "The ball rolled",
             .goal = "In the yard the ball rolled 1.2 after lesson 15's light map was baked, "
                     "and its baked shadow stayed behind (vis_mae 0.019). Get vis_mae to "
                     "0.001 or less, holding at most 8 MiB.",
             .setup = {"scene=yard", "move.x=1.2", "technique=lightmap"},
             .allowed = every,
             .figures = {{"/error/vis_mae", "vis_mae", B::AtMost, 0.001},
                         {"/technique_texture_bytes", "bytes of maps", B::AtMost, 8 << 20}},
             .hint = "Which techniques redraw their shadow every frame, and what does lesson "
                     "15's hybrid still take from the bake?"}};
  }

  // Under a light with a size, the error where the truth is partly lit, not at all, wholly
  // (lesson 14's regions); a point light has no penumbra to break the error down by.
  std::vector<ErrorRegion> errorRegions() const override {
    if (light_radius_() <= 0.0f) return {};
    return {ErrorRegion::penumbra(), ErrorRegion::umbra(), ErrorRegion::lit()};
  }

  std::string refusal(const Params& p, const Scene& scene) const override {
    // Asked of the technique's parameters as the next frame will set them; then what its own
    // lesson refuses (15's light map past its memory limit).
    HostedLesson& h = *hosted_.at(static_cast<size_t>(p.at("technique").i()));
    h.sync(p);
    std::string why = cannot(h, scene, p.at("light.type").is("directional"));
    if (why.empty()) why = h.lesson().refusal(h.params(), scene);
    return why.empty() ? why : "technique=" + h.spec().key + ": " + why;
  }

  void report(JsonWriter& json) const override {
    const HostedLesson& h = active();
    json.value("technique", h.spec().key);
    json.value("technique_lesson", h.spec().lesson);
    json.value("technique_cannot", cannot_);
    json.value("truth_area_radius", light_radius_());
    // What the technique keeps on the GPU for its shadow: maps, their copies and blurs.
    json.value("technique_texture_bytes", h.textureBytes());
    json.beginObject("technique_report");
    h.lesson().report(json);
    json.endObject();
  }

  void reportPixels(JsonWriter& json, const PixelMeasures& pixels) const override {
    active().lesson().reportPixels(json, pixels);
  }

 private:
  // "" or why a technique cannot draw this light's shadow in this scene.
  static std::string cannot(const HostedLesson& h, const Scene& scene, bool directional) {
    const std::string& key = h.spec().key;
    if (key == "cascades" && !directional) {
      return "cascades split a sun's view by distance (lesson 12); this light is a lamp";
    }
    if (key == "cube" && directional) {
      return "a cube map surrounds a light at a point (lesson 11); the sun is at infinity";
    }
    if (key == "warped" && h.params().at("light.projection").is("plane_optimal")) {
      // Lesson 10 would fall back to its light's own frustum: that is hard's map, not this.
      const std::string plane = h.params().at("plane").choice();
      const bool has = std::any_of(scene.objects.begin(), scene.objects.end(),
                                   [&](const SceneObject& o) { return o.name == plane; });
      if (!has) {
        return "plane-optimal makes the map the eye's picture of one plane (lesson 10); this "
               "scene has no " +
               plane;
      }
    }
    return {};
  }
  // The moved object where the preset put it plus the move (lesson 15's rule: Scene::
  // movingObject), every other object where the preset put it.
  void moveObject(const Frame& f) const {
    f.placeMoved(f.scene.movingObject(moving_()), glm::vec3(move_x_(), 0.0f, move_z_()));
  }

  // Where the current settings' points go: the preset and the light.
  std::string where(const Frame& f) const {
    char radius[32];
    std::snprintf(radius, sizeof radius, "%g", static_cast<double>(light_radius_()));
    return f.params.at("scene").choice() + ", light.radius=" + radius;
  }
  // The current settings, as the student would --set them: the technique and its knobs.
  std::string label(const Frame& f) const {
    const HostedLesson& h = active();
    std::string text = "technique=" + h.spec().key;
    for (const std::string& name : h.spec().knobs) {
      text += " " + name + "=" + f.params.at(h.knob(name)).text();
    }
    return text;
  }
  // A new measurement of the truth (its pixels are new) is the current settings' point.
  // The frame times of the current settings, taken as the window's cost line takes them: the
  // wall time natively, the GPU's on a page (WebGL's glFinish returns before the GPU draws),
  // none on a page without a GPU timer. A new label starts them again.
  void sampleFrameTime(const Frame& f) {
    const std::string now = label(f) + " " + where(f);
    if (now != sampled_label_) sampled_label_ = now, frame_samples_.clear(), seen_frames_ = 0;
#ifdef __EMSCRIPTEN__
    const size_t frames = caps().gpu_timer ? f.measure.gpuTimedFrames() : 0;
    const double ms = f.measure.lastGpuFrameMs();
#else
    const size_t frames = f.measure.timedFrames();
    const double ms = f.measure.lastFrameMs();
#endif
    if (frames != seen_frames_ && seen_frames_ != 0) frame_samples_.push_back(ms);
    seen_frames_ = frames;
  }
  // A new measurement of the truth (its pixels are new) with the current settings' median
  // frame time is their point.
  void recordTried(const Frame& f) {
    sampleFrameTime(f);
    const ErrorState& error = f.runner.lastError();
    if (!error.valid || error.pixels == last_pixels_ || !cannot_.empty()) return;
    if (frame_samples_.empty()) return;  // not timed yet: the next frame's panel records it
    last_pixels_ = error.pixels;
    std::vector<double> ms = frame_samples_;
    std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2), ms.end());
    tried_.record({where(f), label(f), static_cast<size_t>(technique_.param().i()),
                   ms[ms.size() / 2], error.metrics.vis_mae});
  }
  // The bench's front for this preset and light (bench_sweep's, on its machine), the current
  // settings ringed where the bench measured them, their error now a line where it did not.
  void drawBench(const Frame& f) {
    const BenchFront::Here here = bench_->at(f.params);
    if (here.points.empty()) {
      ImGui::TextWrapped(
          "The bench measured each preset from its own camera and light, with light.radius 0, "
          "0.1, and 0.1 with the last caster moved 1.2 along x: its front is drawn under "
          "those (the camera back: C).");
      return;
    }
    ImGui::TextWrapped("The bench's front here (its light=%s): its %s across, vis_mae up, both log",
                       here.light.c_str(), kBenchTime);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "bench_sweep's points (docs/bench_16_choose_your_shadow.csv), timed on %s; "
          "your own machine's times are on the next plot",
          kBenchMachine);
    }
    std::vector<const Tried::Point*> points;
    for (const Tried::Point& p : here.points) points.push_back(&p);
    // A frame drawn without a shadow (refused, or shadow.off) is no point of any front.
    const bool shadowed = cannot_.empty() && !f.params.at("shadow.off").b();
    const ErrorState& error = f.runner.lastError();
    const Tried::Point* ring =
        here.current >= 0 && shadowed ? &here.points[static_cast<size_t>(here.current)] : nullptr;
    const bool line = ring == nullptr && shadowed && error.valid;
    drawFront(points, ring, line ? error.metrics.vis_mae : 0.0);
    if (ring != nullptr) {
      ImGui::TextWrapped("ringed: these settings, the bench's %s (vis_mae %.3g at %s)",
                         ring->label.c_str(), ring->error, kBenchSize);
    } else if (!shadowed) {
      ImGui::TextWrapped("this frame has no shadow: no point of a front");
    } else {
      ImGui::TextWrapped("these settings are not among the bench's%s",
                         line ? ": the red line is their error now, at this frame's size" : "");
    }
  }

  void drawTried(const Frame& f) {
    const std::vector<const Tried::Point*> here = tried_.at(where(f));
    if (here.empty()) {
      ImGui::TextWrapped("Your front: each setting you let rest is measured and drawn here.");
      return;
    }
    ImGui::TextWrapped(
        "Your front here (%zu setting%s measured): frame ms across, vis_mae "
        "up, both log",
        here.size(), here.size() == 1 ? "" : "s");
    const std::string now = label(f);
    const Tried::Point* ring = nullptr;
    for (const Tried::Point* p : here) {
      if (p->label == now) ring = p;
    }
    drawFront(here, ring, 0.0);
    if (ImGui::Button("Forget these points")) tried_.clear();
  }

  void drawFront(const std::vector<const Tried::Point*>& here, const Tried::Point* ring,
                 double error_now) const {
    std::vector<std::string> keys;
    for (const auto& h : hosted_) keys.push_back(h->spec().key);
    drawFrontPlot(here, ring, error_now, keys);
  }

  HostedLesson& active() {
    return *hosted_.at(static_cast<size_t>(technique_.param().i()));
  }
  const HostedLesson& active() const {
    return *hosted_.at(static_cast<size_t>(technique_.param().i()));
  }

  Params* host_ = nullptr;
  std::vector<std::unique_ptr<HostedLesson>> hosted_;
  ChoiceParam<> technique_;
  FloatParam light_radius_, move_x_, move_z_;
  IntParam moving_;
  std::string cannot_;
  std::optional<BenchFront> bench_;  // bench_sweep's points, for the panel's bench front
  Tried tried_;                      // what the student measured, for the panel's front
  std::shared_ptr<const ErrorPixels> last_pixels_;
  std::string sampled_label_;  // the settings frame_samples_ are of
  std::vector<double> frame_samples_;
  size_t seen_frames_ = 0;
};

SHADOWS_HOST_LESSON(ChooseYourShadow);

}  // namespace shadows
