// Lesson 05: percentage-closer filtering, dithered (seed 000 "Hardware Shadow Map Filtering"
// .. "Advice for Shadowed Illumination Model (2)"; seed 001 "Soft Shadows" .. its dithered
// PCF shader; seed 003 slide 71).
//
// A shadow-map texel says lit or shadowed, nothing in between; its edges are blocky. Depths
// cannot be blended (0.25 and 0.63 average to 0.44, a depth where nothing is), so PCF compares
// first and averages the results: the fraction of a neighbourhood that is lit. Modes:
//   none      one tap, lesson 04's hard shadow
//   hw2x2     one tap through a GL_LINEAR compare sampler: the texture unit does 4 compares
//   grid      N x N taps over +-radius texels, up to 8 x 8 = 64 (001's "64 samples")
//   dithered  001's 4 taps whose pattern alternates with gl_FragCoord mod 2
//   poisson   taps on a Poisson disk of that radius (003)
// The shadow term goes into 000's illumination model with dimming (common/shaders/lighting.glsl).
// Work that cannot change the result is skipped and counted: fragments facing away from the
// light take no taps, and a kernel whose 4 probe taps agree stops there.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "math/pcf_math.hpp"
#include "shadow/area_match.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

class PcfDithered final : public Lesson {
 public:
  std::string title() const override { return "PCF: compare, then average; 4 dithered taps vs 64"; }
  std::string seeds() const override {
    return "seed 000: Hardware Shadow Map Filtering .. Advice for Shadowed Illumination Model "
           "(2); 001: Soft Shadows .. PCF with Dithering; 003: slide 71";
  }
  static constexpr View kTaps{"taps"};
  std::vector<View> debugViews() const override {
    return {kTaps, views::kLightDepth, views::kAliasing};
  }

  void declare(Params& p) override {
    map_.declare(p);
    p.setDefaultFloat(p.at("shadow.fit"), 1.0);  // lesson 03's fit, as in lesson 04
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "diffuse left in shadow: dimming + (1-dimming)*shade");
    mode_ = p.addChoice("pcf.mode", pcf::kModeNames, "dithered", "how the shadow term is filtered");
    radius_ = p.addFloat("pcf.radius", 2.0f, 0.0f, 16.0f,
                         "kernel half-width in texels (001's swidth x 2)");
    taps_ = p.addInt("pcf.taps", 16, 1, 64, "grid: up to N x N of this; poisson: this many");
    early_out_ = p.addBool("pcf.early_out", true, "stop after 4 probe taps that agree");
    lookup_ = p.addChoice("pcf.lookup", pcf::kLookupNames, "compare",
                          "how a tap reads the map: the texture unit's compare, a fetch and a "
                          "compare in the shader (LearnOpenGL), or 4 compares a call (gather)");
    count_ = p.addBool("pcf.count", true,
                       "count taps per fragment (its atomics cost the eye pass ~10%)");
    bias_.declare(p);  // lesson 04's default: back faces into the map, plus glPolygonOffset
    linear_filter_ = p.at("shadow.filter");
  }

  void init() override {
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    // Two compare samplers for the same map: nearest (one texel per tap), linear (hw2x2).
    nearest_ = Sampler::depth(/*compare=*/true, GL_NEAREST);
    linear_ = Sampler::depth(/*compare=*/true, GL_LINEAR);
    fetch_ = Sampler::depth(/*compare=*/false, GL_NEAREST);  // pcf.lookup=fetch: depths
    counters_ = ShaderCounters(
        {"pcf_taps", "pcf_filtered_fragments", "pcf_stopped_early", "pcf_skipped_facing_away"});
  }
  void render(Frame& f) override {
    // Lesson 04's default bias: back faces into the map, plus glPolygonOffset.
    if (map_.prepare(f)) map_.renderCasters(f, bias_.state());
    map_.sampledBy(f);  // the eye reads this map: the truth counts inside its frustum
    const pcf::Mode mode = mode_();
    const float radius = radius_();
    const int grid = pcf::gridSide(taps_());
    // The area light the truth uses: the one whose penumbra this kernel's blur matches.
    kernel_texels_ = mode == pcf::Mode::None                ? 0.0f
                     : mode == pcf::Mode::Hw2x2             ? 0.5f  // a tent over 2 texels
                     : mode == pcf::Mode::Grid && grid == 1 ? 0.0f
                                                            : radius;
    match_ = matchAreaLight(f, map_, kernel_texels_);
    f.truth_area_radius = match_.radius;
    lookup_used_ = lookupUsed(mode, grid, radius);  // the report's, in every view
    if (map_.drawDepthView(f)) return;

    // Counting needs a storage buffer (GL 4.3): elsewhere the counts are unavailable.
    const bool counting = counters_.begin(f.measure, count_());
    {
      auto timing = f.measure.pass("eye", /*countPassed=*/true);
      f.clearTarget();
      map_.texture().bind(0);
      const bool linear = mode == pcf::Mode::Hw2x2 || linear_filter_.name() == "linear";
      const bool fetch = lookup_used_.lookup == pcf::Lookup::Fetch;
      (fetch ? fetch_ : linear ? linear_ : nearest_).bind(0);
      // At pcf.radius=0 every tap of a kernel reads the one texel, and where a tap answers 0 or
      // 1 (nearest, or fetch) their average is that tap's answer: one lookup is compiled.
      const bool kernel = mode == pcf::Mode::None || mode == pcf::Mode::Hw2x2 || radius > 0.0f ||
                          (linear && !fetch);
      const Program& e =
          eye_programs_.get({mode_.defines(), early_out_.defines(), kernelDefines(mode),
                             lookupDefines(grid), define("PCF_COUNT", counting), f.viewDefines(),
                             define("SHADOW_OFF", map_.off()), feature("PCF_KERNEL", kernel)});
      e.set("uViewProjection", f.projection * f.view);
      e.set("uShadowMatrix", map_.textureMatrix());  // B * P_light * V_light
      e.set("uShadowMap", 0);
      e.set("uRadius", radius);
      e.set("uTexel", glm::vec2(1.0f / static_cast<float>(map_.width()),
                                1.0f / static_cast<float>(map_.height())));
      f.setLightingUniforms(e, dimming_());
      f.drawObjects(e, Objects::All);
      Sampler::unbind(0);
    }
    counters_.end(f.measure);
    if (!f.shows(views::kVisibility)) map_.drawInset(f);
  }

  void panel(Frame& f) override {
    Params& p = f.params;
    auto preset = [&](const char* label, const char* mode, int taps) {
      if (ImGui::Button(label)) {
        p.setChoice(mode_.param(), mode);
        p.setFloat(taps_.param(), taps);
      }
    };
    preset("64 taps", "grid", 64);
    ImGui::SameLine();
    preset("4 dithered", "dithered", 16);
    ImGui::SameLine();
    preset("hw 2x2", "hw2x2", 16);
    ImGui::SameLine();
    preset("none", "none", 16);
    // Cost and error side by side, from the last measured frame (not a baseline frame's).
    const auto& counts = f.measure.lastFrameCounts();
    const auto count = [&](const char* name) {
      const auto it = counts.find(name);
      return it == counts.end() ? 0LL : it->second;
    };
    const long long filtered = count("pcf_filtered_fragments");
    const double per_fragment =
        filtered > 0 ? static_cast<double>(count("pcf_taps")) / static_cast<double>(filtered) : 0;
    const auto pass = f.measure.medianPassMs();
    const double eye_ms = pass.count("eye") ? pass.at("eye") : 0.0;
    // Where the flavour cannot count taps (no storage buffers: gl41, gles30), say so: a 0
    // would read as a kernel that takes no taps.
    if (f.measure.lastFrameUnavailable().count("pcf_taps") != 0) {
      ImGui::Text("cost:  taps %s, eye pass %.2f ms", caps().unavailable().c_str(), eye_ms);
    } else {
      if (filtered > 0) {
        ImGui::Text("cost:  %5.2f taps/fragment, eye pass %.2f ms", per_fragment, eye_ms);
      } else {  // a ratio over no fragment is none, not a kernel that takes no taps
        ImGui::Text("cost:  no fragment filtered, eye pass %.2f ms", eye_ms);
      }
      ImGui::Text("       skipped: %lld facing away, %lld after 4 probes",
                  count("pcf_skipped_facing_away"), count("pcf_stopped_early"));
    }
    ImGui::Text("lookup: %s", lookupUsedName().c_str());
    if (!lookup_used_.why.empty())
      ImGui::TextWrapped("  (not %s: %s)", lookup_.name().c_str(), lookup_used_.why.c_str());
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      ImGui::Text("error: vis_mae %.4f vs an area light r=%.3f", error.metrics.vis_mae,
                  match_.radius);
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "64 taps only where the penumbra is",
             .goal = "A 64-tap grid with every tap taken: 64 lookups for every pixel, lit, "
                     "shadowed or in between. Keep its shadow (vis_mae 0.0011 or less against "
                     "its area light, false lit 0.05 % or less) for at most 8 taps per "
                     "filtered fragment.",
             .setup = {"pcf.mode=grid", "pcf.taps=64", "pcf.early_out=false"},
             .allowed = {"pcf.early_out", "pcf.taps"},
             .figures = {{"/taps_per_filtered_fragment", "taps per fragment", B::AtMost, 8},
                         {"/error/vis_mae", "vis_mae", B::AtMost, 0.0011},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.05},
                         {"/truth_area_radius", "area light radius", B::AtLeast, 0.06}},
             .hint = "In most pixels all 64 comparisons agree. Can 4 of them, at the kernel's "
                     "corners, tell? (view=taps)"},
            {.title = "A soft edge for one lookup (seed 000, GL_LINEAR)",
             .goal = "A 256-wide map with no filter: a hard staircase, one lookup a pixel, "
                     "measured against a point light. Soften it into a penumbra the lesson "
                     "matches to an area light (radius 0.03 or more), within vis_mae 0.003 of "
                     "it, still with at most 1 tap per filtered fragment.",
             .setup = {"shadow.size=256", "pcf.mode=none"},
             .allowed = {"pcf.mode", "pcf.taps", "pcf.radius"},
             .figures = {{"/taps_per_filtered_fragment", "taps per fragment", B::AtMost, 1},
                         {"/truth_area_radius", "area light radius", B::AtLeast, 0.03},
                         {"/error/vis_mae", "vis_mae", B::AtMost, 0.003}},
             .hint = "A tap is one lookup in the shader. Can the texture unit compare more "
                     "than one texel per lookup?"}};
  }

  void report(JsonWriter& json) const override {
    json.value("kernel_half_width_texels", kernel_texels_);
    json.value("pcf_lookup_used", lookupUsedName());
    json.value("pcf_lookup_fallback", lookup_used_.why);
    json.value("truth_area_radius", match_.radius);
    json.value("match_occluder_distance", match_.occluder_distance);
    json.value("match_receiver_distance", match_.receiver_distance);
    json.value("match_texel_world", match_.texel_world);
    // Counted only with pcf.count on and storage buffers (GL 4.3); else null, never a number
    // left from another frame.
    if (caps().storage_buffers && count_()) {
      json.figure(
          "taps_per_filtered_fragment",
          counters_.last(1) > 0
              ? std::optional<double>(static_cast<double>(counters_.last(0)) / counters_.last(1))
              : std::nullopt,
          "no fragment was filtered: the map decided none");
    } else {
      json.value("taps_per_filtered_fragment", std::optional<long long>());  // uncounted
    }
  }

 private:
  // The lookup that runs (pcf.lookup where it can), and why not the one asked for ("").
  struct LookupUsed {
    pcf::Lookup lookup = pcf::Lookup::Compare;
    std::string why;
  };
  LookupUsed lookupUsed(pcf::Mode mode, int grid, float radius) const {
    const pcf::Lookup asked = lookup_();
    if (asked == pcf::Lookup::Compare) return {};
    if (mode == pcf::Mode::Hw2x2 || linear_filter_.name() == "linear") {
      return {pcf::Lookup::Compare,
              "a GL_LINEAR compare is the texture unit's own filter (hw2x2, shadow.filter=linear)"};
    }
    if (asked == pcf::Lookup::Fetch) return {pcf::Lookup::Fetch, ""};
    if (!caps().texture_gather) {
      return {pcf::Lookup::Compare,
              "textureGather with a reference needs GL 4.0 or ES 3.1: " + caps().unavailable()};
    }
    if (pcf::gatherGridSide(mode, grid, radius) == 0) {
      return {pcf::Lookup::Compare,
              "gather takes a grid of adjacent texels: pcf.mode=grid, pcf.radius = side / 2"};
    }
    return {pcf::Lookup::Gather, ""};
  }
  const std::string& lookupUsedName() const {
    return pcf::kLookupNames[static_cast<size_t>(lookup_used_.lookup)];
  }
  // pcf.lookup's #defines for the lookup that runs (PCF_LOOKUP_..., pcf.glsl), and the
  // gathered grid's side.
  std::vector<std::string> lookupDefines(int grid) const {
    std::vector<std::string> d = choiceDefines("pcf.lookup", pcf::kLookupNames, lookupUsedName());
    if (lookup_used_.lookup == pcf::Lookup::Gather) d.push_back(define("PCF_GATHER_SIDE", grid)[0]);
    return d;
  }
  // The kernel compiled into the variant: its offsets for a radius of one texel, from
  // pcf_math.hpp (what the unit tests check), as a constant array; pcf.glsl scales them by
  // the radius, the one kernel setting left a uniform. A new variant per grid side (8) or
  // Poisson tap count (61): pcf.taps is a setting of the kernel's shape, not a slider of its
  // size.
  std::vector<std::string> kernelDefines(pcf::Mode mode) const {
    if (mode == pcf::Mode::None || mode == pcf::Mode::Hw2x2) return {};
    const std::vector<glm::vec2> unit = pcf::unitTapOffsets(mode, taps_());
    // The tap count is what the report names; the grid's side is in its offsets' count.
    return {defineVec2Array("PCF_UNIT_TAPS", unit),
            define("PCF_TAP_COUNT", static_cast<int>(unit.size()))[0]};
  }

  ShadowMap map_;
  // scene.frag + pcf.glsl compiled for one filter, view, early out, counting and shadow.off,
  // when a setting first asks for it: a frame runs only its own kernel.
  ProgramVariants eye_programs_;
  Sampler nearest_, linear_, fetch_;
  ChoiceParam<pcf::Lookup> lookup_;
  LookupUsed lookup_used_;
  ShaderCounters counters_;  // taps, filtered, stopped early, facing away
  FloatParam dimming_, radius_;
  BackFaceBias bias_;
  ChoiceParam<pcf::Mode> mode_;
  ChoiceParam<> linear_filter_;
  IntParam taps_;
  BoolParam early_out_, count_;
  float kernel_texels_ = 0;
  AreaLightMatch match_;  // the truth's area light for this kernel (shadow/area_match.hpp)
};

SHADOWS_LESSON(PcfDithered);

}  // namespace shadows
