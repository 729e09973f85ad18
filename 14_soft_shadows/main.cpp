// Lesson 14: soft shadows that harden at contact, percentage-closer soft shadows (Fernando,
// "Percentage-Closer Soft Shadows", 2005) against an area light's ray-traced truth (seed 003:
// "Hard vs. soft shadows", umbra and penumbra; "fake soft shadow through filtering").
//
// A real light has a size. Where a caster touches the floor its shadow is sharp; a metre up,
// the light's disk shows around its edge and the penumbra widens with that gap. Lesson 05's
// PCF blurs every edge by one width. PCSS measures the gap per pixel:
//   1. search the map near the pixel for blockers and average their distance from the light;
//   2. from similar triangles, the penumbra is R (z_receiver - z_blocker) / z_blocker wide;
//   3. filter with lesson 05's PCF over that width.
// Modes: pcss; fixed (lesson 05's one width, the comparison); hard (one compare, lesson 04).
// The truth is the same disk light in every mode (pcss.light_radius), so each is scored by
// how far it is from the shadow that light really casts.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "math/pcf_math.hpp"
#include "pcss_math.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

namespace {
const std::vector<std::string> kSoftModes = {"hard", "fixed", "pcss"};
enum class SoftMode { Hard, Fixed, Pcss };
// Lesson 05's kernels that take a width (none and hw2x2 have none of their own).
const std::vector<std::string> kKernels = {"grid", "dithered", "poisson"};
pcf::Mode kernelMode(const std::string& name) {
  return name == "grid"       ? pcf::Mode::Grid
         : name == "dithered" ? pcf::Mode::Dithered
                              : pcf::Mode::Poisson;
}
// The counters scene.frag adds to, in its buffer's order.
}  // namespace

class SoftShadows final : public Lesson {
 public:
  std::string title() const override { return "Soft shadows: a blocker search sets the penumbra"; }
  std::string seeds() const override {
    return "seed 003: Hard vs. soft shadows, Soft shadows (umbra, penumbra); seed 001: Soft "
           "Shadows; Fernando 2005, Percentage-Closer Soft Shadows";
  }
  static constexpr View kBlockers{"blockers"};
  static constexpr View kPenumbra{"penumbra"};
  std::vector<View> debugViews() const override {
    return {kBlockers, kPenumbra, views::kLightDepth};
  }
  std::vector<std::string> scenes() const override {
    return {"contact", "overlap", "torus_pyramid", "grazing", "dueling", "cubes"};
  }

  void declare(Params& p) override {
    map_.declare(p);
    // The preset's frustum (shadow.fit off), not lesson 03's fit to the casters: an area light's
    // penumbra reaches past the point light's fitted cone, and the error counts only inside it.
    mode_ = p.addChoice("pcss.mode", kSoftModes, "pcss",
                        "pcss: search, then filter by the gap; fixed: lesson 05's one width; "
                        "hard: one compare");
    light_radius_ = p.addFloat("pcss.light_radius", 0.3f, 0.0f, 1.0f,
                               "the light's disk radius, world units (the truth's light too)");
    search_taps_ = p.addInt("pcss.search_taps", 16, 1, 64, "Poisson points of the blocker search");
    skip_umbra_ =
        p.addBool("pcss.skip_umbra", true, "every search tap a blocker: umbra, no filter");
    search_cut_ = p.addChoice("pcss.search_cut", {"nearest_caster", "near_plane"}, "nearest_caster",
                              "where the search cone is cut: at the nearest caster, or at the "
                              "light's near plane (Fernando's sketch)");
    kernel_ = p.addChoice("pcf.kernel", kKernels, "poisson", "lesson 05's filter kernel");
    taps_ = p.addInt("pcf.taps", 16, 1, 64,
                     "grid: up to N x N of this; poisson: this many (4 at least)");
    fixed_radius_ =
        p.addFloat("pcf.radius", 6.0f, 0.0f, 32.0f, "fixed: the kernel's one half-width in texels");
    filter_ = p.at("shadow.filter");  // the filter's compares: 2x2 bilinear each with linear
    count_ = p.addBool("pcss.count", true, "count taps per fragment (atomics cost)");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "diffuse left in shadow: dimming + (1-dimming)*shade");
    bias_.declare(p);  // lesson 04's default: back faces into the map, plus glPolygonOffset
  }

  void init() override {
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    compare_ = Sampler::depth(/*compare=*/true, GL_NEAREST);  // the filter's compares
    linear_ = Sampler::depth(/*compare=*/true, GL_LINEAR);    // ... with shadow.filter=linear
    depths_ = Sampler::depth(/*compare=*/false, GL_NEAREST);  // the search's depths
    counters_ =
        ShaderCounters({"pcss_search_taps", "pcf_taps", "pcf_filtered_fragments", "pcss_no_blocker",
                        "pcss_all_blockers", "pcss_skipped_facing_away"});
  }

  void render(Frame& f) override {
    if (map_.prepare(f)) map_.renderCasters(f, bias_.state());
    map_.sampledBy(f);  // the eye reads this map: the truth counts inside its frustum
    // One light for every mode: a technique is scored against the shadow it imitates.
    f.truth_area_radius = light_radius_();
    if (map_.drawDepthView(f)) return;
    search_from_ = searchFrom(f);

    const bool counting = counters_.begin(f.measure, count_());
    {
      auto timing = f.measure.pass("eye", /*countPassed=*/true);
      f.clearTarget();
      map_.texture().bind(0);
      (filter_.name() == "linear" ? linear_ : compare_).bind(0);
      map_.texture().bind(1);
      depths_.bind(1);
      const pcf::Mode kernel = kernelMode(kernel_.name());
      const std::vector<glm::vec2> unit = pcf::unitTapOffsets(kernel, taps_());
      const std::vector<glm::vec2> search = searchOffsets();
      const Program& e = eye_programs_.get(
          {mode_.defines(),
           choiceDefines("pcf.mode", pcf::kModeNames, kernel_.name()),
           {defineVec2Array("PCF_UNIT_TAPS", unit), "PCF_TAP_COUNT " + std::to_string(unit.size()),
            "PCF_EARLY_OUT 0", defineVec2Array("SEARCH_UNIT_TAPS", search),
            "SEARCH_TAP_COUNT " + std::to_string(search.size())},
           skip_umbra_.defines(),
           define("PCSS_COUNT", counting),
           f.viewDefines(),
           define("SHADOW_OFF", map_.off()),
           // The fixed kernel at pcf.radius=0 with nearest compares: every tap the same 0 or 1.
           feature("PCF_KERNEL", mode_() != SoftMode::Fixed || fixed_radius_() > 0.0f ||
                                     filter_.name() == "linear"),
           // A point light (radius 0): the search finds all or none, the one compare's answer;
           // the blockers view shows the search itself.
           feature("PCSS_SEARCH", light_radius_() > 0.0f || !skip_umbra_() ||
                                      filter_.name() == "linear" || f.shows(kBlockers))});
      e.set("uViewProjection", f.projection * f.view);
      e.set("uShadowMatrix", map_.textureMatrix());  // B * P_light * V_light
      e.set("uShadowMap", 0);
      e.set("uDepthMap", 1);
      e.set("uTexel", glm::vec2(1.0f / static_cast<float>(map_.width()),
                                1.0f / static_cast<float>(map_.height())));
      e.set("uLightProjection", map_.lightProjection());
      e.set("uLightRadius", light_radius_());
      e.set("uSearchFrom", search_from_);
      e.set("uFixedRadius", fixed_radius_());
      f.setLightingUniforms(e, dimming_());
      f.drawObjects(e, Objects::All);
      Sampler::unbind(0);
      Sampler::unbind(1);
    }
    counters_.end(f.measure);
    if (!f.shows(views::kVisibility)) map_.drawInset(f);
  }

  void panel(Frame& f) override {
    Params& p = f.params;
    auto preset = [&](const char* label, const char* mode) {
      if (ImGui::Button(label)) p.setChoice(mode_.param(), mode);
    };
    preset("PCSS", "pcss");
    ImGui::SameLine();
    preset("one width (05)", "fixed");
    ImGui::SameLine();
    preset("hard (04)", "hard");
    const auto& counts = f.measure.lastFrameCounts();
    const auto count = [&](const char* name) {
      const auto it = counts.find(name);
      return it == counts.end() ? 0LL : it->second;
    };
    if (f.measure.lastFrameUnavailable().count("pcf_taps") != 0) {
      ImGui::Text("cost:  taps %s", caps().unavailable().c_str());
    } else if (!count_()) {
      ImGui::TextWrapped("cost: not counted (pcss.count is off)");
    } else {
      const long long filtered = count("pcf_filtered_fragments");
      const long long searched = filtered + count("pcss_no_blocker") + count("pcss_all_blockers");
      // A ratio over no fragment is none, never a 0 that reads as a free filter.
      const auto per = [](long long a, long long b) {
        if (b <= 0) return std::string("none");
        char text[32];
        std::snprintf(text, sizeof text, "%.1f", static_cast<double>(a) / static_cast<double>(b));
        return std::string(text);
      };
      ImGui::TextWrapped("cost: %s search + %s filter taps a fragment",
                         per(count("pcss_search_taps"), searched).c_str(),
                         per(count("pcf_taps"), filtered).c_str());
      ImGui::TextWrapped("filtered %lld; no filter: %lld lit, %lld umbra", filtered,
                         count("pcss_no_blocker"), count("pcss_all_blockers"));
    }
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      ImGui::TextWrapped("error: vis_mae %.4f against a disk light, r = %.2f",
                         error.metrics.vis_mae, light_radius_());
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "A penumbra that follows the gap",
             .goal = "Lesson 05's one width blurs the post's shadow as much at its foot as at its "
                     "tip, and no width gets the penumbra's vis_mae under 0.08. Get it to 0.05 "
                     "or less, with at most 16 filter taps per filtered fragment and at most 8 "
                     "search taps per fragment.",
             .setup = {"pcss.mode=fixed"},
             .allowed = {"pcss.mode", "pcf.radius", "pcss.search_taps"},
             .figures = {{"/error/penumbra/vis_mae", "penumbra vis_mae", B::AtMost, 0.05},
                         {"/taps_per_filtered_fragment", "filter taps", B::AtMost, 16},
                         {"/search_taps_per_fragment", "search taps", B::AtMost, 8}},
             .hint = "How wide should the blur be where the post touches the floor? Something "
                     "has to measure the gap first (view=blockers)."},
            {.title = "Half the lookups, no worse",
             .goal = "32 search taps and a 32-tap filter: the penumbra's vis_mae is 0.030. Keep "
                     "it at 0.037 or less with at most 8 search taps and 16 filter taps.",
             .setup = {"pcss.search_taps=32", "pcf.taps=32"},
             .allowed = {"pcss.search_taps", "pcf.taps", "pcf.kernel"},
             .figures = {{"/error/penumbra/vis_mae", "penumbra vis_mae", B::AtMost, 0.037},
                         {"/taps_per_filtered_fragment", "filter taps", B::AtMost, 16},
                         {"/search_taps_per_fragment", "search taps", B::AtMost, 8}},
             .hint = "The search only needs a rough average; the filter draws the edge. Lesson "
                     "05's 16-tap kernels are not equal at an edge: try each."}};
  }

  // The penumbra, the umbra and the lit area as the truth draws them: a soft shadow is right
  // or wrong mostly in the first.
  std::vector<ErrorRegion> errorRegions() const override {
    return {ErrorRegion::penumbra(), ErrorRegion::umbra(), ErrorRegion::lit()};
  }

  void report(JsonWriter& json) const override {
    json.value("truth_area_radius", light_radius_());
    json.value("search_from_distance", search_from_);
    // Counted only with pcss.count on and storage buffers (GL 4.3); else null. Over no
    // fragment, null with the reason (a 0 would read as a filter that takes no taps).
    if (!caps().storage_buffers || !count_()) {
      json.value("taps_per_filtered_fragment", std::optional<long long>());
      json.value("search_taps_per_fragment", std::optional<long long>());
      return;
    }
    const auto ratio = [](GLuint a, GLuint b) {
      return b > 0 ? std::optional<double>(static_cast<double>(a) / b) : std::nullopt;
    };
    json.figure("taps_per_filtered_fragment", ratio(counters_.last(1), counters_.last(2)),
                "no fragment was filtered: every one was lit or in umbra by its search");
    const GLuint shaded =
        counters_.last(2) + counters_.last(3) + counters_.last(4);  // fragments the map decided
    json.figure("search_taps_per_fragment", ratio(counters_.last(0), shaded),
                "no fragment read the map");
  }

 private:
  // Where the search cone is cut (pcss_math.hpp searchRadiusWorld): no blocker is nearer the
  // light than the nearest caster, so the cone stops there, not at the near plane (Fernando's
  // choice, as wide as the light is far from the near plane: a needlessly wide search, whose
  // sparse taps miss thin blockers and never find a whole umbra).
  float searchFrom(const Frame& f) const {
    const float near_plane = pcss::lightDistance(map_.lightProjection(), 0.0f);
    const Bounds casters = f.scene.bounds(/*castersOnly=*/true);
    if (casters.empty() || search_cut_.name() == "near_plane") return near_plane;
    float nearest = 1e30f;
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner((k & 1) ? casters.max.x : casters.min.x,
                             (k & 2) ? casters.max.y : casters.min.y,
                             (k & 4) ? casters.max.z : casters.min.z);
      nearest = std::min(nearest, glm::dot(corner - f.light.position, f.light.direction));
    }
    return std::max(near_plane, nearest);
  }

  // The search's Poisson points in the unit circle: lesson 05's disk, its first N. The disk
  // starts on its rim, so 2 or 3 of its points would never look at the pixel's own texel and
  // call a blocked pixel lit: under 4, the centre and then the rim.
  std::vector<glm::vec2> searchOffsets() const {
    const auto n = static_cast<std::ptrdiff_t>(search_taps_());
    if (n >= 4) return {pcf::poissonDisk().begin(), pcf::poissonDisk().begin() + n};
    std::vector<glm::vec2> taps = {glm::vec2(0.0f)};
    taps.insert(taps.end(), pcf::poissonDisk().begin(), pcf::poissonDisk().begin() + (n - 1));
    return taps;
  }

  ShadowMap map_;
  ProgramVariants eye_programs_;
  Sampler compare_, linear_, depths_;
  ShaderCounters counters_;
  ChoiceParam<SoftMode> mode_;
  ChoiceParam<> kernel_, filter_, search_cut_;
  FloatParam light_radius_, fixed_radius_, dimming_;
  BackFaceBias bias_;
  IntParam search_taps_, taps_;
  BoolParam skip_umbra_, count_;
  float search_from_ = 0.0f;  // the distance from the light where the search cone is cut
};

SHADOWS_LESSON(SoftShadows);

}  // namespace shadows
