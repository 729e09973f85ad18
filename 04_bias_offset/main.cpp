// Lesson 04: how much bias, and where to put it (seed 000 "Justification for glPolygonOffset"
// .. "Selecting the Depth Map Bias"; seed 001 "Combating Shadow Acne"; seed 002 "Depth
// Biasing"; seed 003 slides 57-70).
//
// A map texel stores one depth for a patch of surface; the receiver resamples it somewhere
// else in the texel, up to half a texel times the slope away (000 "Why You Need
// glPolygonOffset's Slope"). Too little bias: the lit surface shadows itself (acne, false
// shadow). Too much: shadows detach from their casters (peter panning) or light leaks through
// thin casters (false lit). Each way of biasing is one `bias.mode`:
//   none            lesson 03: acne everywhere
//   constant_only   glPolygonOffset(0, units): a constant in window depth, no slope
//   polygon_offset  glPolygonOffset(factor, units): slope-scaled, 000's (1.1, 4.0)
//   clip_translate  000's common mistake: clip-space z translated before the divide
//   gradient        002 (Ogre): slope from the map's neighbours plus a light-space constant
//   back_faces      003 slide 70: only back faces go into the map
//   normal_offset   (beyond the seeds) look up from a point lifted along the normal
#include <imgui.h>

#include <cmath>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

// bias.mode's choices in the order of enum Bias, each with the panel's one-line hint.
enum class Bias { None, ConstantOnly, PolygonOffset, ClipTranslate, Gradient, BackFaces, Normal };
constexpr std::pair<const char*, const char*> kBiasModes[] = {
    {"none", "no bias: lesson 03"},
    {"constant_only", "glPolygonOffset(0, units): no slope"},
    {"polygon_offset", "glPolygonOffset(factor, units) while drawing the map"},
    {"clip_translate", "clip z + t before the divide: t/2w, no slope"},
    {"gradient", "map neighbours' slope x factor + units/1000 light-space"},
    {"back_faces", "back faces only, + glPolygonOffset(factor, units)"},
    {"normal_offset", "lookup lifted factor texels along the normal, + units"}};

class BiasOffset final : public Lesson {
 public:
  std::string title() const override { return "Bias: acne against peter panning"; }
  std::string seeds() const override {
    return "seed 000: glPolygonOffset .. Selecting the Depth Map Bias; 001: Combating Shadow "
           "Acne; 002: Depth Biasing; 003: slides 57-70";
  }
  static constexpr View kBiasMargin{"bias_margin"};
  std::vector<View> debugViews() const override {
    return {kBiasMargin, views::kLightDepth, views::kAliasing};
  }

  void declare(Params& p) override {
    map_.declare(p);
    // Lesson 03's fit on by default: a light moved past the preset's far plane would leave
    // casters out of the map, a leak no bias can fix.
    p.setDefaultFloat(p.at("shadow.fit"), 1.0);
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
    std::vector<std::string> modes;
    for (const auto& [name, hint] : kBiasModes) modes.push_back(name);
    mode_ = p.addChoice("bias.mode", modes, "back_faces",
                        "where the bias goes (see the lesson README)", kDirtyShadowMap);
    factor_ = p.addFloat("bias.factor", 1.1f, 0.0f, 20.0f,
                         "slope scale: glPolygonOffset factor, gradient scale, normal offset in "
                         "texels",
                         kDirtyShadowMap);
    units_ = p.addFloat("bias.units", 4.0f, 0.0f, 1e7f,
                        "constant: glPolygonOffset units (depth steps); gradient: 1/1000 world "
                        "units",
                        kDirtyShadowMap)
                 .logScale();
    clamp_ = p.addFloat("bias.clamp", 0.25f, 0.0f, 10.0f,
                        "gradient: largest slope bias, world units along the light's axis");
  }

  void init() override {
    depth_program_ =
        Program(lessonFile(LESSON_DIR, "depth.vert"), commonShaderDir() / "depth_only.frag");
    // Lesson 03's vertex shader: the light-space coordinates projected per vertex, so the
    // modes that bias the map cost no more per fragment than 03 (normal offset alone projects
    // its moved point per fragment, in scene.frag).
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    // The same depth texture read raw (no compare), border 1 like the map: "nothing in front".
    raw_sampler_ = Sampler::depth(/*compare=*/false);
  }

  void render(Frame& f) override {
    const Bias mode = mode_();
    const float factor = factor_(), units = units_();
    if (map_.prepare(f)) {
      PassState state;
      if (mode == Bias::BackFaces) {  // 003 slide 70: the far side of each caster goes in the map
        state = ShadowMap::backFacesBias(factor, units);
      } else if (mode == Bias::ConstantOnly || mode == Bias::PolygonOffset ||
                 mode == Bias::Normal) {
        // Window-space offsets, applied by the rasterizer to every depth it writes (000).
        state.polygon_offset = true;
        state.offset_factor = mode == Bias::PolygonOffset ? factor : 0.0f;
        state.offset_units = units;
      }
      if (mode != Bias::ClipTranslate) last_clip_offset_ = last_clip_near_ = last_clip_far_ = 0;
      depth_program_.set("uClipOffset", mode == Bias::ClipTranslate ? clipOffset(units) : 0.0f);
      map_.renderCasters(f, depth_program_, state);
    }
    map_.sampledBy(f);  // the eye reads this map: the truth counts inside its frustum
    if (map_.drawDepthView(f)) return;

    auto timing = f.measure.pass("eye", /*countPassed=*/true);
    f.clearTarget();
    map_.texture().bind(0);  // sampler2DShadow
    map_.texture().bind(1);  // raw, through raw_sampler_
    raw_sampler_.bind(1);
    // scene.frag compiled for this bias mode, view and shadow.off: a frame runs only its code.
    // A term whose slider is at 0 adds nothing: its code is left out (issue 56).
    const bool gradient = mode == Bias::Gradient;
    const std::vector<std::string> none;
    const Program& e = eye_programs_.get(
        {mode_.defines(), f.viewDefines(), define("SHADOW_OFF", map_.off()),
         gradient ? feature("GRADIENT_TERM", factor != 0.0f && clamp_() != 0.0f) : none,
         gradient ? feature("CONSTANT_TERM", units != 0.0f) : none,
         mode == Bias::Normal ? feature("NORMAL_OFFSET", factor != 0.0f) : none});
    e.set("uViewProjection", f.projection * f.view);
    e.set("uShadowMap", 0);
    e.set("uShadowDepth", 1);
    e.set("uFactor", factor);
    e.set("uUnits", units * 1e-3f);  // gradient: the light-space constant, in world units
    e.set("uClamp", clamp_());
    e.set("uDepthStep", depthStep());
    setReceiverUniforms(e, f);
    f.setLightingUniforms(e, dimming_());
    f.drawObjects(e, Objects::All);
    Sampler::unbind(1);
    if (!f.shows(views::kVisibility)) map_.drawInset(f);
  }

  void panel(Frame& f) override {
    Params& p = f.params;
    if (ImGui::Button("000: (1.1, 4.0)")) setOffset(p, 1.1f, 4.0f);
    ImGui::SameLine();
    if (ImGui::Button("001: (2.0, 4.0)")) setOffset(p, 2.0f, 4.0f);
    ImGui::SameLine();
    if (ImGui::Button("no bias")) setOffset(p, 0.0f, 0.0f);
    ImGui::TextDisabled("%s", kBiasModes[static_cast<int>(mode_())].second);
    // The two failures, named, with their numbers from the truth.
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      const double acne = error.metrics.false_shadow_pct, leak = error.metrics.false_lit_pct;
      ImGui::Text("acne (false shadow)         %7.3f%%  %s", acne,
                  acne > 0.2 ? "<- more bias" : "ok");
      ImGui::Text("peter panning (false lit)   %7.3f%%  %s", leak,
                  leak > 1.0 ? "<- less bias" : "ok");
    }
    ImGui::TextDisabled("units %.4g x depth step %.3g = %.3g", units_(), depthStep(),
                        units_() * depthStep());
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "Acne and peter panning, both, where the light grazes",
             .goal = "On the grazing preset, where the light skims the floor, bring the false "
                     "shadow (acne) and the false lit (peter panning) both to 0.07 % or less, "
                     "moving only the bias.",
             .setup = {"scene=grazing"},
             .allowed = {"bias.mode", "bias.factor", "bias.units", "bias.clamp"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.07},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.07}},
             .hint = "back_faces leaves the floor's far edge lit under the casters; which mode "
                     "scales the bias with the receiver's slope, not the caster's?"},
            {.title = "The same offset on a 16-bit map: units are steps",
             .goal = "glPolygonOffset(1.1, 4000) is clean on a 24-bit map. On a 16-bit map the "
                     "same setting detaches every shadow: 1.8 % false lit. Give the 16-bit map "
                     "the same offset in depth as 4000 units gave the 24-bit one (to within "
                     "6 %), and so both errors 0.06 % or less, moving only the units.",
             .setup = {"shadow.format=16", "bias.mode=polygon_offset", "bias.units=4000"},
             .allowed = {"bias.units"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.06},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.06},
                         {"/params/bias.units", "units", B::AtLeast, 14.7},
                         {"/params/bias.units", "units", B::AtMost, 16.6}},
             .hint = "`units` counts steps of the map's depth format (the panel's depth step). "
                     "How many 24-bit steps make one 16-bit step?"}};
  }

  void report(JsonWriter& json) const override {
    json.value("depth_step", last_step_);
    json.value("clip_translate_offset", last_clip_offset_);
    // 000's mistake: the bias clip_translate leaves in the depth buffer, in depth steps, at the
    // light's near and far planes (the same at both for an orthographic light).
    json.value("clip_translate_steps_at_near", last_clip_near_);
    json.value("clip_translate_steps_at_far", last_clip_far_);
    json.value("texel_world_at_target", last_texel_world_);
  }

 private:
  void setOffset(Params& p, float factor, float units) {
    p.setFloat(factor_.param(), factor);
    p.setFloat(units_.param(), units);
  }

  // One step of the map's depth format: what glPolygonOffset's `units` multiplies. For 32-bit
  // float it depends on the depth itself; 2^-24 is its size just below 1.
  float depthStep() {
    const int bits = map_.depthBits();
    last_step_ = bits == 16 ? 1.0f / 65535.0f : bits == 24 ? 1.0f / 16777215.0f : 0x1p-24f;
    return last_step_;
  }

  // The mistake, tuned at the near plane: there the translate is `units` depth steps, like
  // glPolygonOffset(0, units). Clip z moved by t is window depth moved by t / 2w, so at
  // distance w the map gets units * near / w steps: less and less bias away from the light,
  // and none for the slope. An orthographic light has w = 1: a constant, slope still missing.
  float clipOffset(float units) {
    const LightFrustum& fr = map_.frustum();
    const float w_near = fr.directional ? 1.0f : std::max(fr.near, 1e-3f);
    last_clip_offset_ = 2.0f * units * depthStep() * w_near;
    last_clip_near_ = units;
    last_clip_far_ = fr.directional ? units : units * w_near / std::max(fr.far, w_near);
    return last_clip_offset_;
  }

  void setReceiverUniforms(const Program& e, const Frame& f) {
    // World size of one texel at distance d from the light: a spot's grows with d.
    const glm::vec2 texel_world = map_.texelFootprint();
    last_texel_world_ = map_.texelWorldSize(glm::distance(f.light.position, f.light.target));
    e.set("uShadowMatrix", map_.textureMatrix());
    e.set("uLightView", map_.lightView());
    e.set("uTexelWorld", texel_world);
    e.set("uLightAxis", f.light.direction);
  }

  ShadowMap map_;
  Program depth_program_;
  ProgramVariants eye_programs_;  // scene.frag by variant
  Sampler raw_sampler_;
  FloatParam dimming_, factor_, units_, clamp_;
  ChoiceParam<Bias> mode_;
  float last_step_ = 0, last_clip_offset_ = 0, last_clip_near_ = 0, last_clip_far_ = 0;
  float last_texel_world_ = 0;
};

SHADOWS_LESSON(BiasOffset);

}  // namespace shadows
