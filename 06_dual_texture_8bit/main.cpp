// Lesson 06: Heidrich's shadow mapping for hardware without depth textures (seed 000, "An
// Alternative to Dedicated Shadow Mapping Hardware" .. "Improving Depth Map Precision").
//
//   Map:    depth from the light, glPolygonOffset applied while it is built, read back with
//           glReadPixels as unsigned bytes and loaded into an 8-bit texture (common/
//           depth_readback: the other paths of 000 are one choice away).
//   Pass 1: everything dimmed (the light "disabled -or- dimmed substantially").
//   Pass 2: glDepthFunc(GL_EQUAL), everything lit; Tex0 = the map at (s/q, t/q), Tex1 = a 1D
//           ramp at the fragment's light depth, alpha = a(Tex0) + (1 - a(Tex1)) - 0.5, and the
//           alpha test (GL_GREATER, 0.5) rejects the shadowed fragments.
// Eight bits hold on a frustum confined to the casters and break when it is expanded: that
// is the point, and lesson 07 is the fix.
#include <imgui.h>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "shadow/depth_readback.hpp"

namespace shadows {

class DualTexture8bit final : public Lesson {
 public:
  std::string title() const override { return "Dual-texture shadows: an 8-bit map and a ramp"; }
  std::string seeds() const override {
    return "seed 000: An Alternative to Dedicated Shadow Mapping Hardware .. Improving Depth "
           "Map Precision";
  }
  static constexpr View kMap{"map"};
  static constexpr View kRamp{"ramp"};
  static constexpr View kDifference{"difference"};
  std::vector<View> debugViews() const override {
    return {kMap, kRamp, kDifference, views::kAliasing};
  }

  void declare(Params& p) override {
    map_.declare(p, /*linearChoice=*/true);
    // The read-back and its bias in map steps are this lesson's idea: first on the panel.
    p.claim("map.");
    p.claim("bias.");
    ramp_lookup_ = p.addBool("ramp.lookup", true,
                             "Tex1 from the 8-bit ramp texture; off: the exact fragment depth");
    dimmed_ = p.addBool("pass.dimmed", true, "pass 1: everything dimmed");
    lit_ = p.addBool("pass.lit", true, "pass 2: lit where the alpha test passes");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
  }

  void init() override {
    map_.init();
    variants_ = ProgramVariants(commonShaderDir() / "readback_eye.vert",
                                lessonFile(LESSON_DIR, "dual_texture.frag"));
  }

  void render(Frame& f) override {
    if (map_.prepare(f)) map_.render(f);
    map_.sampledBy(f);    // the eye reads this map: the truth counts inside its frustum
    if (f.shows(kMap)) {  // the 8-bit map itself, as the light sees it
      f.clearTarget(glm::vec3(0.0f));
      map_.drawInset(f, /*fullscreen=*/true);
      return;
    }
    // Black where nothing is drawn: the visibility view (0 is shadowed) and the lit passes
    // shown alone (pass.dimmed off), whose shadows would otherwise be holes of sky.
    f.clearTarget(f.shows(views::kVisibility) || !dimmed_() ? glm::vec3(0.0f) : Frame::kSky);
    if (f.shows(kRamp) || f.shows(kDifference)) {  // one value per pixel, no test
      f.drawObjects(pass(f, 0), Objects::All);
    } else {
      drawPasses(f);
    }
    if (!f.shows(views::kVisibility)) map_.drawInset(f);
  }

  void panel(Frame&) override {
    map_.precisionPanel();
    ImGui::Text("pass 2 lit %s fragments", countText(lit_fragments_).c_str());
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    const std::vector<Figure> right = {
        {"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.1},
        {"/error/false_lit_pct", "false lit %", B::AtMost, 0.1}};
    std::vector<Figure> near_plane = right;
    near_plane.push_back({"/light_near_used", "light near plane", B::AtMost, 1.5});
    return {{.title = "How near can the near plane come? (8 bits)",
             .goal = "Kilgard's expanded frustum (near 0.1, far 500) has lost every shadow: "
                     "7.3 % false lit. Bring false shadow and false lit both to 0.1 % or less "
                     "with the light's near plane at 1.5 or nearer, so that a caster 1.5 units "
                     "from the light would still be in the map.",
             .setup = {"shadow.fit=false", "light.near=0.1", "light.far=500"},
             .allowed = {"light.near", "light.far"},
             .figures = near_plane,
             .hint = "Watch the panel's step at the nearest caster: with window depth one step "
                     "is about z*z / (255 * near). Which of the two planes is in that formula?"},
            {.title = "Heidrich's linear depth: far decides",
             .goal = "A caster may come within 0.05 of the light, so the near plane stays at "
                     "0.05, and with far at 1000 window depth has nothing left: 7.3 % false "
                     "lit. Bring false shadow and false lit both to 0.1 % or less without "
                     "moving the near plane.",
             .setup = {"shadow.fit=false", "light.near=0.05", "light.far=1000"},
             .allowed = {"map.encoding", "light.far"},
             .figures = right,
             .hint = "With window depth the near plane decides, and it is fixed here. Which "
                     "encoding spreads its 255 steps evenly from near to far, and what sizes a "
                     "step then?"}};
  }

  void report(JsonWriter& json) const override { map_.report(json); }

 private:
  // dual_texture.frag compiled as PASS 1 or 2 (0: the one-value views) for this view,
  // ramp.lookup and shadow.off (pass 1 lit, no map), with this frame's uniforms set.
  const Program& pass(const Frame& f, int number, bool unshadowed = false) {
    return map_.eyePass(f,
                        variants_.get({define("PASS", number), define("SHADOW_OFF", unshadowed),
                                       ramp_lookup_.defines(), f.viewDefines()}),
                        dimming_());
  }

  void drawPasses(Frame& f) {
    // Pass 1 lays the depth pass 2 must equal (shadow.off: one lit pass, no map, no lookup).
    if (!map_.drawBasePass(f, pass(f, 1, map_.light().off()), dimmed_())) return;
    lit_fragments_ = 0;
    if (!lit_()) return;
    auto timing = f.measure.pass("pass2");
    PassState lit;
    lit.depth_func = GL_EQUAL;
    lit.depth_write = false;
    lit.apply();
    query_.begin();
    f.drawObjects(pass(f, 2), Objects::All);
    query_.end();
    lit_fragments_ = query_.result();
    f.measure.count("pass2_lit_fragments", lit_fragments_);
    PassState{}.apply();
  }

  // How far apart, along the light's axis, two depths at the far plane must be to differ in
  // 8 bits: projective depth crowds its steps near the far plane, linear spreads them evenly.
  DepthReadback map_{1};
  ProgramVariants variants_;
  SamplesPassedQuery query_;
  std::optional<long long> lit_fragments_ = 0;  // empty: this context cannot count them
  BoolParam ramp_lookup_, dimmed_, lit_;
  FloatParam dimming_;
};

SHADOWS_LESSON(DualTexture8bit);

}  // namespace shadows
