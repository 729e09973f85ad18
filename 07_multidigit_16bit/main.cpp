// Lesson 07: McCool's multi-digit shadow comparison (seed 000, "Improving Depth Map Precision"
// .. "GeForce/Quadro Precision Extension").
//
//   Map:    depth from the light, read back as 16-bit unsigned shorts and stored as two 8-bit
//           digits (common/depth_readback; GL_LUMINANCE8_ALPHA8 then, RG8 now).
//   Pass 1: clear the stencil to 0; everything dimmed.
//   Pass 2: glDepthFunc(GL_EQUAL): lit where bigDigit(map) > bigDigit(fragment), writing
//           stencil 1 where it lights.
//   Pass 3: lit where the big digits are equal and the little digit decides, rejecting
//           stencil 1: those pixels are pass 2's already.
// "Think about comparing two 2-digit numbers: 54 and 82": the second digit matters only when
// the first ones are equal. With the same 8-bit hardware, 16 bits of depth.
#include <imgui.h>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "shadow/depth_readback.hpp"

namespace shadows {

class MultiDigit16bit final : public Lesson {
 public:
  std::string title() const override { return "Multi-digit shadows: 16 bits as two 8-bit digits"; }
  std::string seeds() const override {
    return "seed 000: Improving Depth Map Precision .. GeForce/Quadro Precision Extension";
  }
  static constexpr View kBigDigit{"big_digit"};
  static constexpr View kLittleDigit{"little_digit"};
  static constexpr View kPasses{"passes"};
  std::vector<View> debugViews() const override {
    return {kBigDigit, kLittleDigit, kPasses, views::kAliasing};
  }

  void declare(Params& p) override {
    map_.declare(p, /*linearChoice=*/false);
    // The read-back and its bias in map steps are this lesson's idea: first on the panel.
    p.claim("map.");
    p.claim("bias.");
    dimmed_ = p.addBool("pass.dimmed", true, "pass 1: everything dimmed");
    big_ =
        p.addBool("pass.big", true, "pass 2: lit where the big digits decide (writes stencil 1)");
    little_ =
        p.addBool("pass.little", true, "pass 3: lit where the little digit decides (stencil != 1)");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
    inset_ = p.at("inset");
  }

  void init() override {
    map_.init();
    const auto vertex = commonShaderDir() / "readback_eye.vert";
    passes_ = ProgramVariants(vertex, lessonFile(LESSON_DIR, "multidigit.frag"));
    pass3_ = ProgramVariants(vertex, lessonFile(LESSON_DIR, "multidigit_pass3.frag"));
    digits_view_ =
        Program(commonShaderDir() / "fullscreen.vert", lessonFile(LESSON_DIR, "digits_view.frag"));
  }

  void render(Frame& f) override {
    if (map_.prepare(f)) map_.render(f);
    map_.sampledBy(f);  // the eye reads this map: the truth counts inside its frustum
    if (f.shows(kBigDigit) || f.shows(kLittleDigit)) {
      f.clearTarget(glm::vec3(0.0f));
      drawDigits(f, f.shows(kLittleDigit) ? 1 : 0, /*inset=*/false);
      return;
    }
    // Colour, depth, and the stencil to 0. Black where nothing is drawn: the visibility view (0 is
    // shadowed) and the lit passes shown alone (pass.dimmed off), whose shadows would otherwise be
    // holes of sky.
    f.clearTarget(f.shows(views::kVisibility) || !dimmed_() ? glm::vec3(0.0f) : Frame::kSky);
    drawPasses(f, f.shows(kPasses));
    // The inset: the little digit, "here is where the information is".
    if (!f.shows(views::kVisibility) && inset_() && !map_.light().off()) {
      drawDigits(f, 1, /*inset=*/true);
    }
  }

  void panel(Frame&) override {
    map_.precisionPanel();
    ImGui::TextWrapped("lit by pass 2 %s, by pass 3 %s fragments", countText(lit_[0]).c_str(),
                       countText(lit_[1]).c_str());
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "How near can the near plane come? (16 bits)",
             .goal = "At the sliders' extremes (near 0.001, far 1000) even 16 bits come loose: "
                     "3.1 % false lit. Bring false shadow and false lit both to 0.1 % or less "
                     "with the light's near plane at 0.01 or nearer, a hundred times nearer "
                     "than lesson 06's 8 bits hold.",
             .setup = {"shadow.fit=false", "light.near=0.001", "light.far=1000"},
             .allowed = {"light.near", "light.far"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.1},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.1},
                         {"/light_near_used", "light near plane", B::AtMost, 0.01}},
             .hint = "One 16-bit step at the nearest caster is about z*z / (65535 * near): the "
                     "panel shows it. Does far appear in it?"},
            {.title = "Ties at a 257th of the step: the slope term",
             .goal = "With no bias every lit surface ties with its own texel and a tie is "
                     "shadowed: 13 % false shadow. Bring false shadow and false lit both to "
                     "0.05 % or less, moving only the bias, its constant at most 256 steps "
                     "(one step of lesson 06's 8 bits: more gives back what the second byte "
                     "bought).",
             .setup = {"bias.steps=0", "bias.factor=0"},
             .allowed = {"bias.mode", "bias.factor", "bias.steps"},
             // The constant alone meets the errors from about 400 steps: bounded, so that the
             // slope term is the answer (issue 54, 2).
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.05},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.05},
                         {"/params/bias.steps", "constant bias steps", B::AtMost, 256}},
             .hint = "Lesson 06's 3 constant steps leave 11 % here, and even 64 leave 1.3 %: "
                     "across one texel a tilted surface's depth changes by many 16-bit steps. "
                     "Which term of glPolygonOffset grows with the slope?"}};
  }

  void report(JsonWriter& json) const override { map_.report(json); }

 private:
  void drawPasses(Frame& f, bool additive) {
    // Pass 1 lays the depth passes 2 and 3 must equal (shadow.off: one lit pass, no lookup).
    if (!map_.drawBasePass(f, pass(f, 1, map_.light().off()), dimmed_())) return;
    PassState lit;
    lit.depth_func = GL_EQUAL;
    lit.depth_write = false;
    lit.stencil_test = true;
    lit.blend = additive;  // the "passes" view adds, so a pixel lit twice would show
    lit.blend_dst = GL_ONE;
    {
      // Off, pass 2 still marks its pixels, so pass 3 alone shows only its own share.
      auto timing = f.measure.pass("pass2");
      PassState big = lit;
      big.color_write = big_();
      big.stencil_func = GL_ALWAYS;
      big.stencil_ref = 1;
      big.stencil_pass = GL_REPLACE;
      big.apply();
      lit_[0] = countLit(f, pass(f, 2), 0);
    }
    lit_[1] = 0;
    if (little_()) {
      auto timing = f.measure.pass("pass3");
      PassState little = lit;
      little.stencil_func = GL_NOTEQUAL;  // passes where 1 != stencil
      little.stencil_ref = 1;
      little.apply();
      lit_[1] = countLit(f, pass(f, 3), 1);
    }
    f.measure.count("pass2_lit_fragments", lit_[0]);
    f.measure.count("pass3_lit_fragments", lit_[1]);
    PassState{}.apply();
  }

  // Pass 1, 2 (multidigit.frag) or 3 (its early-tests twin) compiled for this view and
  // shadow.off (pass 1 lit, no map), with this frame's uniforms set.
  const Program& pass(const Frame& f, int number, bool unshadowed = false) {
    ProgramVariants& variants = number == 3 ? pass3_ : passes_;
    return map_.eyePass(
        f,
        variants.get({define("PASS", number), define("SHADOW_OFF", unshadowed), f.viewDefines()}),
        dimming_());
  }

  std::optional<long long> countLit(const Frame& f, const Program& program, int index) {
    queries_[index].begin();
    f.drawObjects(program, Objects::All);
    queries_[index].end();
    return queries_[index].result();
  }

  void drawDigits(const Frame& f, int digit, bool inset) {
    map_.bindForLookup(f, digits_view_);
    digits_view_.set("uDigit", digit);
    f.drawFullscreen(digits_view_, inset);
  }

  DepthReadback map_{2};
  ProgramVariants passes_, pass3_;
  Program digits_view_;
  SamplesPassedQuery queries_[2];
  std::optional<long long> lit_[2] = {0, 0};  // empty: this context cannot count them
  BoolParam dimmed_, big_, little_, inset_;
  FloatParam dimming_;
};

SHADOWS_LESSON(MultiDigit16bit);

}  // namespace shadows
