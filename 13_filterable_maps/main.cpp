// Lesson 13: filterable shadow maps, variance (VSM, Donnelly and Lauritzen 2006) and
// exponential (ESM, Annen et al. 2008) maps against lesson 05's PCF at the same filter width
// (seed 002: "Variance shadow maps proposes a two-parameter family of approximation functions";
// seed 003's further techniques).
//
// PCF filters the answers of compares, so it cannot blur the map once and reuse it: every
// pixel pays its N x N taps. A filterable map stores something whose average still means
// something, blurs it once per map (two passes of N taps), and answers with one lookup:
//   VSM  stores z and z^2; the blurred pair is a mean and a variance, and Chebyshev's
//        inequality bounds the fraction of the filter's texels at or beyond the receiver;
//   ESM  stores exp(c z); the blur averages exponentials and exp(-c t) turns that into a
//        soft compare, exp(-c (t - z)) per texel: 1 at the receiver's own depth, near 0
//        (never 0) behind a blocker far enough in front of it;
//   MSM  (moment shadow maps, Peters and Klein 2015) stores z, z^2, z^3, z^4: seed 002's
//        "other approximating functional forms". Four moments bound the lit fraction as
//        tightly as any distribution with them allows (msm_math.hpp): two blockers at two
//        depths no longer bleed.
// Seed 002's critique, measured: the two-parameter VSM is right for one blocker over one
// receiver and bleeds light where two blockers at different depths share the filter.
#include <imgui.h>

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "math/pcf_math.hpp"
#include "msm_math.hpp"
#include "shadow/area_match.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

namespace {
const std::vector<std::string> kMethods = {"pcf", "vsm", "esm", "msm"};
enum class Method { Pcf, Vsm, Esm, Msm };

}  // namespace

class FilterableMaps final : public Lesson {
 public:
  std::string title() const override {
    return "Filterable maps: blur the map once (VSM, ESM, MSM)";
  }
  std::string seeds() const override {
    return "seed 002: Variance shadow maps (two-parameter approximation, Deep Shadow Maps; "
           "other approximating functional forms: four moments); 003: further techniques; "
           "000: Percentage Closer filtering";
  }
  static constexpr View kMoments{"moments"};
  std::vector<View> debugViews() const override { return {kMoments}; }
  std::vector<std::string> scenes() const override {
    return {"stacked", "overlap", "torus_pyramid", "contact", "grazing", "dueling", "cubes"};
  }

  void declare(Params& p) override {
    map_.declare(p);
    method_ = p.addChoice("filter.method", kMethods, "vsm",
                          "pcf: compare, then average (05); vsm: two moments and Chebyshev; esm: "
                          "exp(c z); msm: four moments",
                          kDirtyShadowMap);
    radius_ = p.addFloat("filter.radius", 4.0f, 0.0f, 16.0f,
                         "the filter's half-width in texels, PCF's kernel and the blur alike");
    taps_ = p.addInt("filter.taps", 5, 1, 8, "taps per axis: PCF N x N, the blur 2 passes of N");
    bits_ = p.addChoice("moments.bits", {"32", "16"}, "32", "float bits of the stored moments",
                        kDirtyShadowMap);
    mipmaps_ = p.addBool("moments.mipmaps", false,
                         "mipmaps of the blurred moments: trilinear lookups, anisotropic where "
                         "the GL has it");
    min_variance_ = p.addFloat("vsm.min_variance", 1e-5f, 0.0f, 1e-2f,
                               "the least variance Chebyshev's bound assumes (against acne)")
                        .logScale();
    bleeding_ = p.addFloat("vsm.bleeding", 0.0f, 0.0f, 0.95f,
                           "light-bleeding reduction: bounds under this count as shadow");
    exponent_ = p.addFloat("esm.c", 40.0f, 1.0f, 80.0f, "ESM's exponent c", kDirtyShadowMap);
    moment_bias_ = p.addFloat("msm.bias", 3e-5f, 0.0f, 1e-2f,
                              "MSM: the moments pulled this far toward a safe distribution "
                              "(against rounding)")
                       .logScale();
    linear_filter_ = p.at("shadow.filter");
    inset_ = p.at("inset");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "diffuse left in shadow: dimming + (1-dimming)*shade");
    bias_.declare(p, "PCF: ");  // PCF's map is lesson 04's: back faces, plus glPolygonOffset
  }

  void init() override {
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    moment_programs_ = ProgramVariants(lessonFile(LESSON_DIR, "moments.vert"),
                                       lessonFile(LESSON_DIR, "moments.frag"));
    blur_programs_ =
        ProgramVariants(commonShaderDir() / "fullscreen.vert", lessonFile(LESSON_DIR, "blur.frag"));
    compare_ = Sampler::depth(/*compare=*/true, GL_NEAREST);
    linear_ = Sampler::depth(/*compare=*/true, GL_LINEAR);  // PCF with shadow.filter=linear
  }

  void render(Frame& f) override {
    // Float colour targets (the moments') are there wherever the runner runs: its truth needs
    // them too (EXT_color_buffer_float on ES; the runner stops without).
    const Method method = method_();
    const std::vector<std::string> method_defines =
        choiceDefines("filter.method", kMethods, kMethods[static_cast<size_t>(method)]);
    const bool pcf = method == Method::Pcf;
    // 32-bit floats where they filter; else 16 bits, and the report says so.
    bits_used_ = bits_.name() == "16" || !caps().float_linear ? 16 : 32;
    const bool rendered = map_.prepare(f, kDirtyNothing);
    map_.sampledBy(f);  // the eye reads this map: the truth counts inside its frustum
    kernel_texels_ = taps_() > 1 ? radius_() : 0.0f;  // a 1-tap grid has no width (05)
    match_ = matchAreaLight(f, map_, kernel_texels_);
    f.truth_area_radius = match_.radius;
    if (pcf) {
      if (rendered) map_.renderCasters(f, bias_.state());
    } else {
      const bool storage = ensureMoments(map_.width(), map_.height());
      if (rendered || storage) renderMoments(f, method_defines);
      // The blur is per map, not per frame: again only when the map or the blur changed.
      const std::pair<float, int> blur{radius_(), taps_()};
      if (rendered || storage || blur != blurred_with_) {
        blurMoments(f);
        blurred_with_ = blur;
      }
    }
    f.measure.count("blur_passes", pcf ? 0 : blur_passes_);
    blur_passes_ = 0;
    if (f.shows(kMoments)) {
      f.clearTarget();
      if (!pcf) {
        f.drawImageInset(moments_[kBlurred], /*fullscreen=*/true);
      } else {
        map_.drawInset(f, /*fullscreen=*/true);  // PCF has no moments: its depth map
      }
      return;
    }
    auto timing = f.measure.pass("eye", /*countPassed=*/true);
    f.clearTarget();
    map_.texture().bind(0);
    (linear_filter_.name() == "linear" ? linear_ : compare_).bind(0);
    if (!pcf) moments_[kBlurred].bind(1);
    const std::vector<glm::vec2> unit = pcf::unitTapOffsets(pcf::Mode::Grid, taps_() * taps_());
    const Program& e = eye_programs_.get(
        {method_defines,
         choiceDefines("pcf.mode", pcf::kModeNames, "grid"),
         {defineVec2Array("PCF_UNIT_TAPS", unit), "PCF_TAP_COUNT " + std::to_string(unit.size()),
          "PCF_EARLY_OUT 0"},
         f.viewDefines(),
         define("SHADOW_OFF", map_.off()),
         feature("BLEEDING_REDUCTION", bleeding_() > 0.0f),
         // filter.radius=0 with nearest compares: every tap the same 0 or 1
         feature("PCF_KERNEL", !pcf || radius_() > 0.0f || linear_filter_.name() == "linear")});
    e.set("uViewProjection", f.projection * f.view);
    e.set("uShadowMatrix", map_.textureMatrix());
    e.set("uShadowMap", 0);
    e.set("uMoments", 1);
    e.set("uTexel", glm::vec2(1.0f / static_cast<float>(map_.width()),
                              1.0f / static_cast<float>(map_.height())));
    e.set("uRadius", radius_());
    e.set("uExponent", exponent_());
    e.set("uMinVariance", min_variance_());
    e.set("uBleeding", bleeding_());
    e.set("uMomentDecode", decode_);
    e.set("uEncodeOffset", msm::kEncodeOffset);
    e.set("uMomentBias", moment_bias_());
    setDepthUniforms(f, e);
    f.setLightingUniforms(e, dimming_());
    f.drawObjects(e, Objects::All);
    Sampler::unbind(0);
    // The map in a corner: PCF's depths, or the blurred moments a filterable map looks up.
    if (!f.shows(views::kVisibility)) {
      if (pcf) {
        map_.drawInset(f);
      } else if (inset_()) {
        f.drawImageInset(moments_[kBlurred]);
      }
    }
  }

  void panel(Frame& f) override {
    Params& p = f.params;
    auto preset = [&](const char* label, const char* method) {
      if (ImGui::Button(label)) p.setChoice(method_.param(), method);
    };
    preset("PCF (05)", "pcf");
    ImGui::SameLine();
    preset("VSM", "vsm");
    ImGui::SameLine();
    preset("ESM", "esm");
    ImGui::SameLine();
    preset("MSM", "msm");
    const int n = taps_();
    if (method_() == Method::Pcf) {
      ImGui::TextWrapped("cost: %d taps a pixel, every frame", n * n);
    } else {
      ImGui::TextWrapped(
          "cost: 1 lookup a pixel; the blur 2 x %d taps a texel, once per map "
          "(%s of %d bits: %d bytes a texel)",
          n, stored(), bits_used_, bytesPerTexel());
    }
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      ImGui::TextWrapped("error: vis_mae %.4f against a disk light, r = %.3f",
                         error.metrics.vis_mae, match_.radius);
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "One lookup for twenty-five taps",
             .goal = "Lesson 05's PCF, 5 x 5 taps a pixel every frame: vis_mae 0.0124, false lit "
                     "0.04 %. Keep vis_mae at 0.0130 or less and false lit at 0.1 % or less with "
                     "one lookup a pixel.",
             .setup = {"filter.method=pcf"},
             .allowed = {"filter.method", "moments.bits", "esm.c", "vsm.min_variance"},
             .figures = {{"/taps_per_pixel", "lookups a pixel", B::AtMost, 1},
                         {"/error/vis_mae", "vis_mae", B::AtMost, 0.013},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.1}},
             .hint = "Which map can be blurred once and then read once? Two store moments; "
                     "which one keeps the false lit down?"},
            {.title = "Stop the bleeding, keep the penumbra (seed 002's halo)",
             .goal = "A 512 map blurred over 8 texels: around the brick, light bleeds into the "
                     "board's umbra (1.0 % of the pixels drawn 0.25 lighter than the truth). "
                     "Bring that under 0.5 % and keep the penumbra's vis_mae at 0.175 or less, "
                     "with one lookup a pixel.",
             .setup = {"shadow.size=512", "filter.radius=8"},
             .allowed = {"vsm.bleeding", "vsm.min_variance", "esm.c", "filter.method"},
             .figures = {{"/error/bleeding/share_pct", "bleeding %", B::AtMost, 0.5},
                         {"/error/penumbra/vis_mae", "penumbra vis_mae", B::AtMost, 0.175},
                         {"/taps_per_pixel", "lookups a pixel", B::AtMost, 1}},
             .hint = "Chebyshev's bound is too light where two blockers share the filter. Cut "
                     "its lowest values off, and watch what that does to the penumbra."},
            {.title = "Less halo in the same bytes (seed 002's other functional forms)",
             .goal = "The same halo: VSM keeps 8 bytes a texel and bleeds on 0.98 % of the "
                     "pixels. Bring the bleeding under 0.7 % with the penumbra's vis_mae at "
                     "0.135 or less, one lookup a pixel and at most 8 bytes a texel.",
             .setup = {"shadow.size=512", "filter.radius=8"},
             .allowed = {"filter.method", "moments.bits", "msm.bias", "vsm.bleeding",
                         "vsm.min_variance", "esm.c"},
             .figures = {{"/error/bleeding/share_pct", "bleeding %", B::AtMost, 0.7},
                         {"/error/penumbra/vis_mae", "penumbra vis_mae", B::AtMost, 0.135},
                         {"/taps_per_pixel", "lookups a pixel", B::AtMost, 1},
                         {"/moments_bytes_per_texel", "bytes a texel", B::AtMost, 8}},
             .hint = "Two moments cannot tell two blockers at two depths apart; how many can? "
                     "And how many bits does each of them need?"}};
  }

  // The truth's penumbra, umbra and lit area, as lesson 14 has them, and the light that bleeds:
  // pixels drawn lighter than the truth by more than 0.25.
  std::vector<ErrorRegion> errorRegions() const override {
    // Light bleeding: drawn lighter than the truth by more than a quarter.
    return {ErrorRegion::penumbra(),
            ErrorRegion::umbra(),
            {"bleeding", ErrorRegion::anywhere, [](float t, float r) { return r > t + 0.25f; }}};
  }

  void report(JsonWriter& json) const override {
    json.value("truth_area_radius", match_.radius);
    json.value("kernel_half_width_texels", kernel_texels_);
    json.value("moments_bits_used", method_() == Method::Pcf ? 0 : bits_used_);
    json.figure("moments_bytes_per_texel",
                method_() == Method::Pcf ? std::nullopt : std::optional<double>(bytesPerTexel()),
                "filter.method=pcf: no moments (a depth map, compared)");
    // What the lookup filters with: the levels (1: bilinear; more: trilinear) and anisotropy.
    json.value("moments_levels", method_() == Method::Pcf ? 0 : moments_[kBlurred].levels());
    json.value("anisotropy_used", method_() != Method::Pcf && mipmaps_()
                                      ? std::min(kAnisotropy, caps().max_anisotropy)
                                      : 1.0f);
    json.value("taps_per_pixel", method_() == Method::Pcf ? taps_() * taps_() : 1);
  }

 private:
  // The moments' textures and their framebuffers: kRaw as rendered (the blur's source, kept so
  // that a new blur starts from it), kAcross blurred along x, kBlurred along y too (looked up).
  static constexpr int kBlurred = 0, kAcross = 1, kRaw = 2;
  // The channels a method's moments take (ESM fills one of two), and their bytes a texel.
  int channels() const { return method_() == Method::Msm ? 4 : 2; }
  int bytesPerTexel() const { return channels() * bits_used_ / 8; }
  const char* stored() const {
    return method_() == Method::Msm   ? "4 moments"
           : method_() == Method::Vsm ? "2 moments"
                                      : "exp(c z) in 2 channels";
  }
  static constexpr float kAnisotropy = 16.0f;
  bool ensureMoments(int width, int height) {
    const bool four = method_() == Method::Msm;
    const GLenum format =
        bits_used_ == 16 ? (four ? GL_RGBA16F : GL_RG16F) : (four ? GL_RGBA32F : GL_RG32F);
    const bool mipmapped = mipmaps_();
    if (moments_[kBlurred].width() == width && moments_[kBlurred].height() == height &&
        format_ == format && (moments_[kBlurred].levels() > 1) == mipmapped) {
      return false;
    }
    format_ = format;
    for (int k = 0; k < 3; ++k) {
      // The looked-up texture with its mipmaps when asked: trilinear where the map is
      // minified (far from the eye), plus anisotropy along grazing views.
      const bool levels = mipmapped && k == kBlurred;
      moments_[k] = Texture::color(width, height, format, levels);
      moments_[k].setFilter(GL_LINEAR);
      if (levels) moments_[k].setAnisotropy(kAnisotropy);
      // Outside the map, nothing in front: z = 1, as a depth map's border (ES: the shader).
      moments_[k].setWrap(GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
      moments_[k].setBorder(nothing());
      framebuffers_[k] = std::make_unique<Framebuffer>();
      framebuffers_[k]->attachColor(moments_[k]);
      if (k == kRaw) {
        depth_ = Texture::depth(width, height, 24);
        framebuffers_[k]->attachDepth(depth_);
      }
      framebuffers_[k]->check();
    }
    return true;
  }

  // What a texel with nothing in front stores (z = 1): the clear, the border, the blur's edge.
  // VSM z = 1 and z^2 = 1; ESM exp(c (1 - 1)) = 1; MSM the encoded powers of 1.
  glm::vec4 nothing() const {
    return method_() == Method::Msm ? msm::encode(1.0f) : glm::vec4(1.0f, 1.0f, 0.0f, 1.0f);
  }

  void setDepthUniforms(const Frame& f, const Program& program) const {
    program.set("uMapLightPos", f.light.position);
    program.set("uMapLightDir", f.light.direction);
    program.set("uNear", map_.frustum().near);
    program.set("uFar", map_.frustum().far);
  }

  // Pass 1: the moments from the light, the runner's usual faces, no polygon offset (a
  // filtered map needs no bias: the variance and the exponent soften the compare).
  void renderMoments(Frame& f, const std::vector<std::string>& methodDefines) {
    auto timing = f.measure.pass("shadow");
    f.measure.count("shadow_map_renders");
    Frame pass = f;
    pass.target = framebuffers_[kRaw]->id();
    pass.width = map_.width();
    pass.height = map_.height();
    pass.bindTarget();
    const glm::vec4 clear = nothing();
    glClearColor(clear.r, clear.g, clear.b, clear.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const Program& m = moment_programs_.get({methodDefines});
    const glm::mat4 light = map_.lightViewProjection();
    m.set("uLightViewProjection", light);
    m.set("uExponent", exponent_());
    m.set("uMomentEncode", msm::encodeMatrix());
    m.set("uEncodeOffset", msm::kEncodeOffset);
    setDepthUniforms(f, m);
    // Every object, the floor too: a moment is an average over the filter's texels, and a
    // texel the floor fills but the map leaves at the far plane would average in a depth
    // behind every receiver, lighting the penumbra's outer half (PCF's compare does not care).
    pass.drawObjects(m, Objects::Occluders, &light);
  }

  // The separable blur, x then y (raw -> across -> blurred): lesson 05's grid for 2N taps a
  // texel.
  void blurMoments(Frame& f) {
    auto timing = f.measure.pass("blur");
    const int n = taps_();
    std::vector<glm::vec2> row;
    for (int i = 0; i < n; ++i) row.push_back(pcf::gridOffsets(n, 1.0f)[static_cast<size_t>(i)]);
    const Program& b = blur_programs_.get(
        {{defineVec2Array("BLUR_UNIT_TAPS", row), "BLUR_TAPS " + std::to_string(n)}});
    b.set("uRadius", radius_());
    b.set("uSource", 0);
    b.set("uNothing", nothing());
    const glm::vec2 texel(1.0f / static_cast<float>(map_.width()),
                          1.0f / static_cast<float>(map_.height()));
    for (int axis = 0; axis < 2; ++axis) {
      Frame pass = f;
      pass.target = framebuffers_[axis == 0 ? kAcross : kBlurred]->id();
      pass.width = map_.width();
      pass.height = map_.height();
      moments_[axis == 0 ? kRaw : kAcross].bind(0);
      b.set("uAxis", axis == 0 ? glm::vec2(texel.x, 0.0f) : glm::vec2(0.0f, texel.y));
      pass.drawFullscreen(b);
      ++blur_passes_;
    }
    moments_[kBlurred].generateMipmaps();  // nothing without moments.mipmaps
  }

  ShadowMap map_;
  ProgramVariants eye_programs_, moment_programs_, blur_programs_;
  Sampler compare_, linear_;
  Texture moments_[3], depth_;
  std::unique_ptr<Framebuffer> framebuffers_[3];
  GLenum format_ = 0;
  int bits_used_ = 32, blur_passes_ = 0;
  std::pair<float, int> blurred_with_{-1.0f, 0};
  float kernel_texels_ = 0;
  AreaLightMatch match_;
  ChoiceParam<Method> method_;
  ChoiceParam<> bits_, linear_filter_;
  BoolParam inset_, mipmaps_;
  FloatParam radius_, min_variance_, bleeding_, exponent_, moment_bias_, dimming_;
  glm::mat4 decode_ = msm::decodeMatrix();
  BackFaceBias bias_;
  IntParam taps_;
};

SHADOWS_LESSON(FilterableMaps);

}  // namespace shadows
