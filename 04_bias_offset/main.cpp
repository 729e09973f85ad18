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

#include "app.hpp"
#include "json.hpp"
#include "shadow_map.hpp"

namespace shadows {

class BiasOffset final : public Lesson {
 public:
  std::string title() const override { return "Bias: acne against peter panning"; }
  std::string seeds() const override {
    return "seed 000: glPolygonOffset .. Selecting the Depth Map Bias; 001: Combating Shadow "
           "Acne; 002: Depth Biasing; 003: slides 57-70";
  }
  std::vector<std::string> debugViews() const override { return {"bias_margin", "light_depth"}; }

  void declare(Params& p) override {
    ShadowMap::declare(p);
    // Lesson 03's fit on by default: a light moved past the preset's far plane would leave
    // casters out of the map, a leak no bias can fix.
    p.setDefaultFloat(p.at("shadow.fit"), 1.0);
    p.addFloat("dimming", 0.4f, 0.0f, 1.0f, "light left in shadow: dimming + (1-dimming)*shade");
    p.addChoice("bias.mode",
                {"none", "constant_only", "polygon_offset", "clip_translate", "gradient",
                 "back_faces", "normal_offset"},
                "back_faces", "where the bias goes (see the lesson README)", kDirtyShadowMap);
    p.addFloat("bias.factor", 1.1f, 0.0f, 20.0f,
               "slope scale: glPolygonOffset factor, gradient scale, normal offset in texels",
               kDirtyShadowMap);
    p.addFloat("bias.units", 4.0f, 0.0f, 1e7f,
               "constant: glPolygonOffset units (depth steps); gradient: 1/1000 world units",
               kDirtyShadowMap)
        .logarithmic = true;
    p.addFloat("bias.clamp", 0.25f, 0.0f, 10.0f,
               "gradient: largest slope bias, world units along the light's axis");
  }

  void init() override {
    depth_program_ =
        Program(lessonFile(LESSON_DIR, "depth.vert"), lessonFile(LESSON_DIR, "depth.frag"));
    eye_programs_ =
        ProgramVariants(lessonFile(LESSON_DIR, "scene.vert"), lessonFile(LESSON_DIR, "scene.frag"));
    // The same depth texture read raw (no compare), border 1 like the map: "nothing in front".
    raw_sampler_ = Sampler::depth(/*compare=*/false);
  }

  void render(Frame& f) override {
    const std::string mode = f.params.at("bias.mode").choice();
    const float factor = f.params.at("bias.factor").f(), units = f.params.at("bias.units").f();
    if (map_.prepare(f)) {
      auto timing = f.measure.pass("shadow");
      map_.beginRender();
      PassState state;
      if (mode == "back_faces") {  // 003 slide 70: the far side of each caster goes in the map
        state = ShadowMap::backFacesBias(factor, units);
      } else if (mode == "constant_only" || mode == "polygon_offset" || mode == "normal_offset") {
        // Window-space offsets, applied by the rasterizer to every depth it writes (000).
        state.polygon_offset = true;
        state.offset_factor = mode == "polygon_offset" ? factor : 0.0f;
        state.offset_units = units;
      }
      state.apply();
      depth_program_.set("uClipOffset", mode == "clip_translate" ? clipOffset(f, units) : 0.0f);
      const glm::mat4 light_view_projection = map_.lightViewProjection();
      depth_program_.set("uLightViewProjection", light_view_projection);
      f.drawObjects(depth_program_, Objects::Casters, &light_view_projection);
      PassState{}.apply();
    }
    if (map_.drawDepthView(f)) return;

    auto timing = f.measure.pass("eye");
    f.clearTarget();
    map_.texture().bind(0);  // sampler2DShadow
    map_.texture().bind(1);  // raw, through raw_sampler_
    raw_sampler_.bind(1);
    const Program& e = eyeProgram(mode == "gradient"        ? 1
                                  : mode == "normal_offset" ? 2
                                                            : 0,
                                  f.mode == "visibility"    ? 1
                                  : f.mode == "bias_margin" ? 2
                                                            : 0,
                                  map_.off());
    e.set("uViewProjection", f.projection * f.view);
    e.set("uShadowMap", 0);
    e.set("uShadowDepth", 1);
    e.set("uFactor", factor);
    e.set("uUnits", units * 1e-3f);  // gradient: the light-space constant, in world units
    e.set("uClamp", f.params.at("bias.clamp").f());
    e.set("uDepthStep", depthStep(f));
    setReceiverUniforms(e, f);
    f.setLightingUniforms(e, f.params.at("dimming").f());
    f.drawObjects(e, Objects::All);
    Sampler::unbind(1);
    if (f.mode != "visibility") map_.drawInset(f);
  }

  void panel(Frame& f) override {
    Params& p = f.params;
    if (ImGui::Button("000: (1.1, 4.0)")) setOffset(p, 1.1f, 4.0f);
    ImGui::SameLine();
    if (ImGui::Button("001: (2.0, 4.0)")) setOffset(p, 2.0f, 4.0f);
    ImGui::SameLine();
    if (ImGui::Button("no bias")) setOffset(p, 0.0f, 0.0f);
    ImGui::TextDisabled("%s", modeHint(p.at("bias.mode").choice()));
    // The two failures, named, with their numbers from the truth.
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      const double acne = error.metrics.false_shadow_pct, leak = error.metrics.false_lit_pct;
      ImGui::Text("acne (false shadow)         %7.3f%%  %s", acne,
                  acne > 0.2 ? "<- more bias" : "ok");
      ImGui::Text("peter panning (false lit)   %7.3f%%  %s", leak,
                  leak > 1.0 ? "<- less bias" : "ok");
    }
    ImGui::TextDisabled("units %.4g x depth step %.3g = %.3g", p.at("bias.units").f(), depthStep(f),
                        p.at("bias.units").f() * depthStep(f));
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
  static const char* modeHint(const std::string& mode) {
    if (mode == "none") return "no bias: lesson 03";
    if (mode == "constant_only") return "glPolygonOffset(0, units): no slope";
    if (mode == "polygon_offset") return "glPolygonOffset(factor, units) while drawing the map";
    if (mode == "clip_translate") return "clip z + t before the divide: t/2w, no slope";
    if (mode == "gradient") return "map neighbours' slope x factor + units/1000 light-space";
    if (mode == "back_faces") return "back faces only, + glPolygonOffset(factor, units)";
    return "lookup lifted factor texels along the normal, + units";
  }

  // scene.frag compiled for one receiver bias and one view (and without the lookup for
  // shadow.off), once, when a setting first asks for it: a frame runs only its own code.
  const Program& eyeProgram(int receiver, int view, bool off) {
    std::vector<std::string> defines = {"RECEIVER " + std::to_string(receiver),
                                        "VIEW " + std::to_string(view)};
    if (off) defines.push_back("NO_SHADOW");
    return eye_programs_.get(defines);
  }

  static void setOffset(Params& p, float factor, float units) {
    p.setFloat(p.at("bias.factor"), factor);
    p.setFloat(p.at("bias.units"), units);
  }

  // One step of the map's depth format: what glPolygonOffset's `units` multiplies. For 32-bit
  // float it depends on the depth itself; 2^-24 is its size just below 1.
  float depthStep(const Frame& f) {
    const std::string& format = f.params.at("shadow.format").choice();
    last_step_ = format == "16" ? 1.0f / 65535.0f : format == "24" ? 1.0f / 16777215.0f : 0x1p-24f;
    return last_step_;
  }

  // The mistake, tuned at the near plane: there the translate is `units` depth steps, like
  // glPolygonOffset(0, units). Clip z moved by t is window depth moved by t / 2w, so at
  // distance w the map gets units * near / w steps: less and less bias away from the light,
  // and none for the slope. An orthographic light has w = 1: a constant, slope still missing.
  float clipOffset(const Frame& f, float units) {
    const LightFrustum& fr = map_.frustum();
    const float w_near = fr.directional ? 1.0f : std::max(fr.near, 1e-3f);
    last_clip_offset_ = 2.0f * units * depthStep(f) * w_near;
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
  ProgramVariants eye_programs_;  // scene.frag by variant (eyeProgram)
  Sampler raw_sampler_;
  float last_step_ = 0, last_clip_offset_ = 0, last_clip_near_ = 0, last_clip_far_ = 0;
  float last_texel_world_ = 0;
};

SHADOWS_LESSON(BiasOffset);

}  // namespace shadows
