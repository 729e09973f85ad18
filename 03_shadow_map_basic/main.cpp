// Lesson 03: Williams' two-pass shadow map (seed 000 "The Shadow Mapping Concept" to
// "Shadow Map Operation"; seed 001 "Shadow Maps" to "Combating Shadow Acne").
//
//   Pass 1: render depth from the light into a depth texture on a framebuffer object.
//   Pass 2: render from the eye; each fragment's (s, t, r, q) = B * P_light * V_light * M * p
//           and textureProj(sampler2DShadow) compares B = r/q against the stored A.
//
// No bias on purpose: the acne you see is what lesson 04 fixes.
#include <imgui.h>

#include <cstdio>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

class ShadowMapBasic final : public Lesson {
 public:
  std::string title() const override { return "Shadow map: depth from the light, then compare"; }
  std::string seeds() const override {
    return "seed 000: The Shadow Mapping Concept .. Shadow Map Operation; seed 001: Shadow Maps";
  }
  static constexpr View kLightView{"light_view"};
  static constexpr View kProjectedDepth{"projected_depth"};
  static constexpr View kLightDistance{"light_distance"};
  static constexpr View kCompare{"compare"};
  std::vector<View> debugViews() const override {
    // Kilgard's visualizations (seed 000, "Visualizing the Shadow Mapping Technique").
    // aliasing: the runner's texels per pixel (texel_density.hpp)
    return {kLightView,     views::kLightDepth, kProjectedDepth,
            kLightDistance, kCompare,           views::kAliasing};
  }

  void declare(Params& p) override {
    map_.declare(p);     // shadow.size/height/format/filter/fit/cache, inset
    p.claim("shadow.");  // the map is this lesson's idea: its sliders come first on the panel
    p.claim("inset");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
  }

  void init() override {
    // Pass 1's shaders are common/shaders/light_depth.vert and depth_only.frag (position only,
    // no colour). Pass 2: common/shaders/shadow_coord.vert, then scene.frag compiled per view,
    // with the lookup or without it (shadow.off), when a setting first asks for it.
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    raw_sampler_ = Sampler::depth(/*compare=*/false);
  }

  void render(Frame& f) override {
    // Pass 1: depth from the light, only when something it depends on changed (a static
    // frame renders no map). Only casters inside the light frustum are drawn into it.
    if (map_.prepare(f)) map_.renderCasters(f);  // P_light * V_light * M * p
    map_.sampledBy(f);  // the eye reads this map: the truth counts inside its frustum
    if (map_.drawDepthView(f)) return;  // Kilgard's second view: the depth map itself

    // Pass 2 from the eye (or, for Kilgard's first view, from the light): each fragment
    // gets (s, t, r, q) = B * P_light * V_light * M * p and textureProj compares r/q.
    auto timing = f.measure.pass("eye", /*countPassed=*/true);
    f.clearTarget();
    map_.texture().bind(0);  // as sampler2DShadow
    map_.texture().bind(1);  // the same texture read raw, for the debug views
    raw_sampler_.bind(1);
    const bool from_light = f.shows(kLightView);
    const Program& e = eye_programs_.get({f.viewDefines(), define("SHADOW_OFF", map_.off())});
    e.set("uViewProjection", from_light ? map_.lightViewProjection() : f.projection * f.view);
    e.set("uShadowMatrix", biasMatrix() * map_.lightProjection() * map_.lightView());
    e.set("uShadowMap", 0);
    e.set("uShadowDepth", 1);
    e.set("uLightNear", map_.frustum().near);
    e.set("uLightFar", map_.frustum().far);
    e.set("uLightPerspective", map_.frustum().directional ? 0 : 1);
    f.setLightingUniforms(e, dimming_());
    if (from_light) e.set("uEye", f.light.position);
    f.drawObjects(e, Objects::All);
    Sampler::unbind(1);
    if (!f.shows(views::kVisibility)) map_.drawInset(f);
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "Just enough map for the dueling frusta",
             .goal = "Light and eye face each other, and a 256-wide map leaves 0.50 % false "
                     "lit along the shadows' staircase edges (nearest filtering). Find a map "
                     "size that brings false lit to 0.15 % or less without wasting texels: at "
                     "most 0.5 texels per pixel (the panel's median, least axis).",
             .setup = {"scene=dueling", "shadow.filter=nearest", "shadow.size=256"},
             .allowed = {"shadow.size"},
             .figures = {{"/error/false_lit_pct", "false lit %", B::AtMost, 0.15},
                         {"/texels_per_pixel/min_axis/median", "texels per pixel", B::AtMost, 0.5}},
             .hint = "False lit falls about as 1/size, texels per pixel grows as size: there is "
                     "a window between them. view=aliasing shows where the texels fall short."},
            {.title = "From dueling frusta to a miner's lamp",
             .goal = "Light and eye face each other: 89 % of the pixels get less than one map "
                     "texel (1024-wide map). Move the light (it keeps aiming where it aims, "
                     "same map) until at most 10 % are under-sampled, lighting at least 140000 "
                     "counted pixels.",
             .setup = {"scene=dueling"},
             .allowed = {"light.pos"},
             .figures = {{"/undersampled_pct", "under-sampled %", B::AtMost, 10},
                         {"/error/counted_pixels", "counted pixels", B::AtLeast, 140000}},
             .hint = "\"Great match if eye and light frustum's are nearly identical\" (Kilgard). "
                     "Where is the eye?"}};
  }

  void report(JsonWriter& json) const override {
    json.value("light_near_used", map_.frustum().near);
    json.value("light_far_used", map_.frustum().far);
  }

  void panel(Frame&) override {
    ImGui::Text("light near %.3f  far %.3f%s", map_.frustum().near, map_.frustum().far,
                map_.fitted() ? " (fitted to casters)" : "");
  }

 private:
  ShadowMap map_;
  FloatParam dimming_;
  ProgramVariants eye_programs_;
  Sampler raw_sampler_;
};

SHADOWS_LESSON(ShadowMapBasic);

}  // namespace shadows
