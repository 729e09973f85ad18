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

#include "app.hpp"
#include "json.hpp"
#include "pcf_math.hpp"
#include "shadow_map.hpp"

namespace shadows {

class PcfDithered final : public Lesson {
 public:
  std::string title() const override { return "PCF: compare, then average; 4 dithered taps vs 64"; }
  std::string seeds() const override {
    return "seed 000: Hardware Shadow Map Filtering .. Advice for Shadowed Illumination Model "
           "(2); 001: Soft Shadows .. PCF with Dithering; 003: slide 71";
  }
  std::vector<std::string> debugViews() const override { return {"taps", "light_depth"}; }

  void declare(Params& p) override {
    ShadowMap::declare(p);
    p.setDefaultFloat(p.at("shadow.fit"), 1.0);  // lesson 03's fit, as in lesson 04
    p.addFloat("dimming", 0.4f, 0.0f, 1.0f, "diffuse left in shadow: dimming + (1-dimming)*shade");
    p.addChoice("pcf.mode", {"none", "hw2x2", "grid", "dithered", "poisson"}, "dithered",
                "how the shadow term is filtered");
    p.addFloat("pcf.radius", 2.0f, 0.0f, 16.0f, "kernel half-width in texels (001's swidth x 2)");
    p.addInt("pcf.taps", 16, 1, 64, "grid: up to N x N of this; poisson: this many");
    p.addBool("pcf.early_out", true, "stop after 4 probe taps that agree");
    p.addBool("pcf.count", true, "count taps per fragment (its atomics cost the eye pass ~10%)");
    // Lesson 04's default bias: back faces into the map, plus glPolygonOffset(factor, units).
    p.addFloat("bias.factor", 1.1f, 0.0f, 20.0f, "glPolygonOffset factor", kDirtyShadowMap);
    p.addFloat("bias.units", 4.0f, 0.0f, 1e7f, "glPolygonOffset units", kDirtyShadowMap)
        .logarithmic = true;
  }

  void init() override {
    depth_program_ =
        Program(lessonFile(LESSON_DIR, "depth.vert"), lessonFile(LESSON_DIR, "depth.frag"));
    eye_programs_ =
        ProgramVariants(lessonFile(LESSON_DIR, "scene.vert"), lessonFile(LESSON_DIR, "scene.frag"));
    // Two compare samplers for the same map: nearest (one texel per tap), linear (hw2x2).
    nearest_ = Sampler::depth(/*compare=*/true, GL_NEAREST);
    linear_ = Sampler::depth(/*compare=*/true, GL_LINEAR);
    counters_ = Buffer(GL_SHADER_STORAGE_BUFFER, sizeof(counts_), nullptr, GL_DYNAMIC_READ);
  }
  void render(Frame& f) override {
    Params& p = f.params;
    if (map_.prepare(f)) {  // lesson 04's default bias
      auto timing = f.measure.pass("shadow");
      map_.beginRender();
      ShadowMap::backFacesBias(p.at("bias.factor").f(), p.at("bias.units").f()).apply();
      const glm::mat4 light_view_projection = map_.lightViewProjection();
      depth_program_.set("uLightViewProjection", light_view_projection);
      f.drawObjects(depth_program_, Objects::Casters, &light_view_projection);
      PassState{}.apply();
    }
    const std::string mode = p.at("pcf.mode").choice();
    const float radius = p.at("pcf.radius").f();
    const int grid = pcf::gridSide(p.at("pcf.taps").i());
    // The area light the truth uses: the one whose penumbra this kernel's blur matches.
    kernel_texels_ = mode == "none"                ? 0.0f
                     : mode == "hw2x2"             ? 0.5f  // a tent over 2 texels
                     : mode == "grid" && grid == 1 ? 0.0f
                                                   : radius;
    f.truth_area_radius = matchAreaLight(f, kernel_texels_);
    if (map_.drawDepthView(f)) return;

    const bool counting = p.at("pcf.count").b() && f.measure.enabled();
    const GLuint zero[4] = {0, 0, 0, 0};
    counters_.bindBase(0);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(zero), zero);
    {
      auto timing = f.measure.pass("eye");
      f.clearTarget();
      map_.texture().bind(0);
      const bool linear = mode == "hw2x2" || p.at("shadow.filter").is("linear");
      (linear ? linear_ : nearest_).bind(0);
      const pcf::Mode kernel = mode == "none"       ? pcf::Mode::None
                               : mode == "hw2x2"    ? pcf::Mode::Hw2x2
                               : mode == "grid"     ? pcf::Mode::Grid
                               : mode == "dithered" ? pcf::Mode::Dithered
                                                    : pcf::Mode::Poisson;
      const Program& e = eye_programs_.get(
          {"PCF_MODE " + std::to_string(static_cast<int>(kernel)),
           std::string("VIEW ") + (f.mode == "visibility" ? "1"
                                   : f.mode == "taps"     ? "2"
                                                          : "0"),
           std::string("EARLY_OUT ") + (p.at("pcf.early_out").b() ? "1" : "0"),
           std::string("COUNT ") + (counting ? "1" : "0"), map_.off() ? "NO_SHADOW" : "SHADOW"});
      e.set("uViewProjection", f.projection * f.view);
      e.set("uShadowMatrix", map_.textureMatrix());  // B * P_light * V_light
      e.set("uShadowMap", 0);
      e.set("uGridSide", grid);
      // The offsets the unit tests check are the ones the shader takes (pcf_math.hpp).
      const std::vector<glm::vec2> taps = pcf::tapOffsets(kernel, p.at("pcf.taps").i(), radius);
      glProgramUniform2fv(e.id(), e.location("uTaps"), static_cast<GLsizei>(taps.size()),
                          glm::value_ptr(taps[0]));
      e.set("uPoissonTaps", static_cast<int>(taps.size()));
      e.set("uTexel", glm::vec2(1.0f / static_cast<float>(map_.width()),
                                1.0f / static_cast<float>(map_.height())));
      f.setLightingUniforms(e, p.at("dimming").f());
      f.drawObjects(e, Objects::All);
      Sampler::unbind(0);
    }
    if (counting) {  // not during the runner's own truth renders
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(counts_), counts_);
      f.measure.count("pcf_taps", counts_[0]);
      f.measure.count("pcf_filtered_fragments", counts_[1]);
      f.measure.count("pcf_stopped_early", counts_[2]);
      f.measure.count("pcf_skipped_facing_away", counts_[3]);
    }
    if (f.mode != "visibility") map_.drawInset(f);
  }

  void panel(Frame& f) override {
    Params& p = f.params;
    auto preset = [&](const char* label, const char* mode, int taps) {
      if (ImGui::Button(label)) {
        p.setChoice(p.at("pcf.mode"), mode);
        p.setFloat(p.at("pcf.taps"), taps);
      }
    };
    preset("64 taps", "grid", 64);
    ImGui::SameLine();
    preset("4 dithered", "dithered", 16);
    ImGui::SameLine();
    preset("hw 2x2", "hw2x2", 16);
    ImGui::SameLine();
    preset("none", "none", 16);
    // Cost and error side by side.
    const double per_fragment =
        counts_[1] > 0 ? static_cast<double>(counts_[0]) / static_cast<double>(counts_[1]) : 0.0;
    const auto pass = f.measure.medianPassMs();
    const double eye_ms = pass.count("eye") ? pass.at("eye") : 0.0;
    ImGui::Text("cost:  %5.2f taps/fragment, eye pass %.2f ms", per_fragment, eye_ms);
    ImGui::Text("       skipped: %u facing away, %u after 4 probes", counts_[3], counts_[2]);
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      ImGui::Text("error: vis_mae %.4f vs an area light r=%.3f", error.metrics.vis_mae,
                  area_radius_);
    }
  }

  void report(JsonWriter& json) const override {
    json.value("kernel_half_width_texels", kernel_texels_);
    json.value("truth_area_radius", area_radius_);
    json.value("match_occluder_distance", d_occluder_);
    json.value("match_receiver_distance", d_receiver_);
    json.value("match_texel_world", texel_world_);
    json.value("taps_per_filtered_fragment",
               counts_[1] > 0 ? static_cast<double>(counts_[0]) / counts_[1] : 0.0);
  }

 private:
  // The kernel's penumbra matched where it matters most (pcf::areaLightRadius): the ray from
  // the light through the casters' centre, and the receiver the casters rest on (their
  // lowest point) further along it. The texel size is taken at that receiver.
  float matchAreaLight(const Frame& f, float kernelTexels) {
    const Bounds casters = f.scene.bounds(/*castersOnly=*/true);
    const LightFrustum& fr = map_.frustum();
    const glm::vec3 light = f.light.position, centre = casters.center();
    const glm::vec3 ray = f.light.directional || glm::distance(centre, light) < 1e-4f
                              ? f.light.direction
                              : glm::normalize(centre - light);
    d_occluder_ = glm::dot(centre - light, ray);
    const float down = -ray.y;  // how fast the ray descends toward the floor
    const float gap = down > 0.05f ? (centre.y - casters.min.y) / down : casters.radius();
    d_receiver_ = d_occluder_ + gap;
    // Depth along the light's axis (a receiver behind a spot light gets no shadow anyway).
    const float axial = std::max(glm::dot(ray * d_receiver_, f.light.direction), fr.near);
    texel_world_ = map_.texelWorldSize(axial);
    area_radius_ =
        pcf::areaLightRadius(kernelTexels, texel_world_, d_occluder_, d_receiver_, fr.directional);
    return area_radius_;
  }

  ShadowMap map_;
  Program depth_program_;
  // scene.frag + pcf.glsl compiled for one filter, view, early out, counting and shadow.off,
  // when a setting first asks for it: a frame runs only its own kernel.
  ProgramVariants eye_programs_;
  Sampler nearest_, linear_;
  Buffer counters_;
  GLuint counts_[4] = {0, 0, 0, 0};  // taps, filtered, stopped early, facing away
  float kernel_texels_ = 0, area_radius_ = 0, d_occluder_ = 0, d_receiver_ = 0, texel_world_ = 0;
};

SHADOWS_LESSON(PcfDithered);

}  // namespace shadows
