// Lesson 12: cascaded shadow maps for the sun (seed 003, "Problem: Aliasing Artifacts",
// perspective aliasing; seed 002: "not allocating enough shadow map samples to regions that
// matter to the viewer").
//
//   One map over a street 200 units deep gives the metre at the eye's feet as few texels as
//   the metre at the horizon, though it covers a thousand times the pixels. Cut the eye's
//   frustum into slices along its depth and give each slice a map of its own:
//   Pass 1, once a cascade: the casters through an orthographic box around its slice, into
//           its tile of one atlas (culled per cascade).
//   Pass 2: from the eye. The fragment's view depth picks the cascade (and, in a band before
//           its far end, blends with the next), then Williams' comparison in that tile.
//   Lesson 10's focusing is the one-cascade case: one box around the whole visible slice.
//
// Shimmer, measured: the eye steps along a short path; the points of the world this frame
// shows keep their shadow in the truth (the sun and the scene stand still), so every flip of
// one between two steps is the map's doing. Snapped, sphere-bounded boxes move by whole
// texels and never change size: their texels stay put on the ground and nothing flips.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>

#include "cascade_math.hpp"
#include "core/fnv.hpp"
#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "visible_depths.hpp"

namespace shadows {

namespace {
constexpr int kMaxCascades = 4;
constexpr int kShimmerSteps = 8;  // the path: eight steps of 3 cm and 0.1°
enum class Fit { Slice, Sphere };
enum class Range { Fixed, Visible };
enum class Path { Walk, Turn, Both };
const std::array<glm::vec3, kMaxCascades> kCascadeColors = {
    glm::vec3(0.95f, 0.35f, 0.3f), glm::vec3(0.35f, 0.85f, 0.35f), glm::vec3(0.35f, 0.5f, 0.95f),
    glm::vec3(0.95f, 0.8f, 0.25f)};
}  // namespace

// One depth texture holding every cascade's tile, and what each tile was fitted for.
struct Atlas {
  Texture texture;
  std::unique_ptr<Framebuffer> framebuffer;
  std::array<cascade::Fit, kMaxCascades> fits{};
  glm::mat4 view{0.0f};  // the eye the first cascade was rendered for (0: nothing yet)
  int kept = 0;          // cascades whose boxes were fitted for an earlier eye (a bit each)
};

class Cascades final : public Lesson {
 public:
  std::string title() const override { return "Cascaded shadow maps for the sun, and shimmer"; }
  std::string seeds() const override {
    return "seed 003: Problem: Aliasing Artifacts (perspective aliasing); seed 002: allocate "
           "shadow map samples to regions that matter to the viewer";
  }
  static constexpr View kCascades{"cascades"};
  static constexpr View kMaps{"maps"};
  static constexpr View kTexelGrid{"texel_grid"};
  static constexpr View kShimmer{"shimmer"};  // readStates' per-pixel states, never offered
  std::vector<View> debugViews() const override { return {kCascades, kMaps, kTexelGrid}; }
  std::vector<std::string> scenes() const override {
    return {"street", "street_low_sun", "receding", "torus_pyramid"};
  }
  // The sun's box is the cascades' own: the shared frustum settings do nothing here.
  std::vector<std::string> unusedSharedParams() const override {
    return {"light.fov", "light.extent", "light.near", "light.far"};
  }

  void declare(Params& p) override {
    constexpr auto kMap = kDirtyShadowMap | kDirtyResources;
    count_ = p.addInt("cascades.count", 4, 1, kMaxCascades,
                      "slices of the eye's frustum, one map each (1: lesson 10's focusing)", kMap);
    split_ = p.addChoice("cascades.split", {"uniform", "logarithmic", "practical"}, "practical",
                         "where the slices end: even, in a geometric series, or a blend of both",
                         kDirtyShadowMap);
    lambda_ = p.addFloat("cascades.lambda", 0.75f, 0.0f, 1.0f,
                         "practical split: the logarithmic one's weight (1: logarithmic)",
                         kDirtyShadowMap);
    lambda_.param().inactive = [](const Params& ps) -> std::string {
      return ps.at("cascades.split").is("practical") ? "" : "only the practical split has it";
    };
    range_ = p.addChoice("cascades.range", {"fixed", "visible"}, "fixed",
                         "fixed: slices from the near plane to cascades.far; visible: over the "
                         "depths the eye sees this frame, reduced on the GPU (SDSM)",
                         kDirtyShadowMap);
    fit_ = p.addChoice("cascades.fit", {"slice", "sphere"}, "sphere",
                       "each map's box: the slice's own extent (tight, changes size as the eye "
                       "turns) or a square around its bounding sphere (fixed size)",
                       kDirtyShadowMap);
    snap_ = p.addBool("cascades.snap", true, "move each box by whole texels only", kDirtyShadowMap);
    blend_ = p.addFloat("cascades.blend", 0.1f, 0.0f, 0.5f,
                        "the share of a slice, at its far end, blended with the next cascade");
    size_ = p.addInt("cascades.size", 1024, 64, 2048, "texels along each cascade's side", kMap)
                .logScale();
    far_ = p.addFloat("cascades.far", 120.0f, 5.0f, 400.0f,
                      "shadow distance: where the last slice ends (beyond: no shadow)",
                      kDirtyShadowMap)
               .logScale();
    filter_ = p.addChoice("cascades.filter", {"nearest", "linear"}, "linear",
                          "linear: the hardware's 2x2 compare, blended (bilinear PCF)");
    normal_ = p.addFloat("bias.normal", 1.0f, 0.0f, 4.0f,
                         "normal offset in texels of the fragment's cascade: it scales with each "
                         "cascade's texels");
    depth_bias_ = p.addFloat("bias.depth", 1.0f, 0.0f, 8.0f,
                             "constant depth bias, in texels of the fragment's cascade");
    update_ = p.addInt("cascades.update", 1, 1, 8,
                       "render the far cascades every Nth frame the eye moves (the first: every "
                       "frame); kept ones keep their boxes");
    path_ = p.addChoice("shimmer.path", {"walk", "turn", "both"}, "both",
                        "the eye's steps the shimmer is measured over: 3 cm forward and "
                        "sideways, 0.1° of turn, or both");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
    {
      const Params::SharedScope shared(p);
      cache_ = p.addBool("shadow.cache", true,
                         "re-render the maps only when the eye, the sun or a caster changed",
                         kDirtyShadowMap);
      off_ = p.addBool("shadow.off", false,
                       "baseline: the same frame with no shadow work (no maps, no lookup)",
                       kDirtyShadowMap);
    }
  }

  void init() override {
    depth_programs_ = ProgramVariants(commonShaderDir() / "light_depth.vert",
                                      commonShaderDir() / "depth_only.frag");
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    visible_.init(lessonFile(LESSON_DIR, "depth_range.frag"));
    compare_nearest_ = Sampler::depth(/*compare=*/true, GL_NEAREST);
    compare_linear_ = Sampler::depth(/*compare=*/true, GL_LINEAR);
  }

  void render(Frame& f) override {
    if (off_()) {
      f.measure.count("shadow_map_renders", 0);
      f.measure.count("cascade_renders", 0);
    } else {
      ensureAtlas(atlas_);
      const std::string key = shimmerKey(f);
      // Eight steps of maps and lookups: measured once the input rests, as the truth is.
      if (key != shimmer_key_ && !f.input_moving) {
        measureShimmer(f);
        shimmer_key_ = key;
      }
      // Everything when a setting or the scene changed; when only the eye moved, the first
      // cascade, and the others every cascades.update-th such frame.
      const int all = (1 << count_()) - 1;
      int mask = 0;
      if (f.params.consume(kDirtyShadowMap) || !cache_()) {
        mask = all;
        moved_frames_ = 0;
      } else if (f.view != atlas_.view || f.projection != atlas_projection_) {
        // The depths in view move with the eye, and every slice with them.
        mask = range_() == Range::Visible || ++moved_frames_ % update_() == 0 ? all : 1;
      }
      // Live, while the eye is dragged: this frame's points in the maps as they were, then as
      // they are (the shimmer of the user's own motion, not of the path).
      const bool live = f.input_moving && mask != 0 && atlas_.view != glm::mat4(0.0f);
      if (live) {
        auto timing = f.measure.pass("shimmer");
        readStates(f, atlas_, atlas_.view, live_before_);
      }
      if (mask != 0) {
        seen_.reset();
        if (range_() == Range::Visible) {
          auto timing = f.measure.pass("depth_range");
          seen_ = visible_.measure(f, f.view);
          f.measure.count("depth_range_passes", visible_.passes());
        }
        auto timing = f.measure.pass("shadow");
        renderAtlas(f, atlas_, f.view, mask, seen_);
      }
      if (live) {
        auto timing = f.measure.pass("shimmer");
        readStates(f, atlas_, f.view, live_after_);
        const auto [counted, flips] = countFlips(live_before_, live_after_);
        live_shimmer_pct_ = counted > 0 ? std::optional<double>(100.0 * static_cast<double>(flips) /
                                                                static_cast<double>(counted))
                                        : std::nullopt;
        live_frames_ += 1;
      }
      f.measure.count("shadow_map_renders", mask != 0 ? 1 : 0);
      f.measure.count("cascade_renders", std::popcount(static_cast<unsigned>(mask)));
    }

    auto timing = f.measure.pass("eye", /*countPassed=*/true);
    f.clearTarget();
    if (f.shows(kMaps) && !off_()) {
      f.drawDepthInset(atlas_.texture, 0.0f, 1.0f, /*perspective=*/false, /*fullscreen=*/true);
      return;
    }
    const Program& e = eyeProgram(f.viewDefines(), atlas_, f.view);
    setEyeUniforms(e, f, atlas_, f.view);
    e.set("uViewProjection", f.projection * f.view);
    f.drawObjects(e, Objects::All);
    Sampler::unbind(0);
  }

  // The error slice by slice (report: error.cascade_1 ...): pixels whose view depth falls in it.
  std::vector<ErrorRegion> errorRegions() const override {
    std::vector<ErrorRegion> regions;
    const glm::mat4 view = atlas_.view;
    for (int i = 0; i < kMaxCascades; ++i) {
      const float d0 = i < used_count_ ? splits_[static_cast<size_t>(i)] : 0.0f;
      const float d1 = i < used_count_ ? splits_[static_cast<size_t>(i) + 1] : 0.0f;
      regions.push_back({"cascade_" + std::to_string(i + 1), [view, d0, d1](glm::vec4 p) {
                           const float depth = -(view * glm::vec4(glm::vec3(p), 1.0f)).z;
                           return depth > d0 && depth <= d1;
                         }});
    }
    return regions;
  }

  void report(JsonWriter& json) const override {
    json.value("cascade_count", used_count_);
    json.value("cascade_split", split_.name());
    json.value("cascade_fit", fit_.name());
    json.value("cascade_snap", snap_());
    json.value("shadow_distance", far_());
    json.value("cascade_range", range_.name());
    // The depths the eye saw, which the slices then covered: none with a fixed range.
    const char* why = off_()                     ? "shadow.off: no cascade is rendered"
                      : range_() == Range::Fixed ? "cascades.range=fixed: not measured"
                                                 : "no surface in view";
    const std::optional<glm::vec2> seen = off_() ? std::nullopt : seen_;
    json.figure("visible_depth_near", seen ? std::optional<double>(seen->x) : std::nullopt, why);
    json.figure("visible_depth_far", seen ? std::optional<double>(seen->y) : std::nullopt, why);
    json.beginArray("cascade_splits");
    for (int i = 0; i <= used_count_; ++i) json.value("", splits_[static_cast<size_t>(i)]);
    json.endArray();
    // One texel's side on the ground facing the sun, cascade by cascade: what each slice gets.
    json.beginArray("cascade_texel_world");
    for (int i = 0; i < used_count_; ++i) {
      json.value("", atlas_.fits[static_cast<size_t>(i)].texel_world);
    }
    json.endArray();
    // Null where a cascade shades no sunlit pixel (or nothing is rendered), and why beside.
    json.beginArray("cascade_texels_per_pixel");
    std::string none;
    for (int i = 0; i < used_count_; ++i) {
      const std::optional<double> t = texels_per_pixel_[static_cast<size_t>(i)];
      json.value("", off_() || !t ? kNoFigure : *t);
      if (!off_() && !t) none += (none.empty() ? "" : ", ") + std::to_string(i + 1);
    }
    json.endArray();
    if (off_()) {
      json.value("cascade_texels_per_pixel_not_counted", "shadow.off: no cascade is rendered");
    } else if (!none.empty()) {
      json.value("cascade_texels_per_pixel_not_counted",
                 "cascade " + none + ": no sunlit pixel in the frame reads it");
    }
    // The same as two figures an exercise can bound: how many cascades shade a sunlit pixel,
    // and the least texels a pixel among them (none while a cascade shades nothing).
    int shading = 0;
    double least = 1e30;
    for (int i = 0; i < used_count_; ++i) {
      if (const std::optional<double> t = texels_per_pixel_[static_cast<size_t>(i)]) {
        ++shading, least = std::min(least, *t);
      }
    }
    json.value("cascades_shading", off_() ? 0 : shading);
    json.figure("cascade_texels_per_pixel_least",
                off_() || !none.empty() || shading == 0 ? std::nullopt : std::optional(least),
                off_() ? "shadow.off: no cascade is rendered"
                       : "cascade " + none + ": no sunlit pixel in the frame reads it");
    json.value("atlas_bytes",
               static_cast<long long>(atlas_.texture.width()) * atlas_.texture.height() * 4);
    json.value("shimmer_path", path_.name());
    json.value("shimmer_steps", kShimmerSteps);
    // A share of no pixel, or of no frame, is no figure: null, and why (a 0 reads "steady").
    json.figure("shimmer_pct", off_() ? std::nullopt : shimmer_pct_,
                off_() ? "shadow.off: no cascade is rendered"
                       : "no sunlit pixel inside the cascades along the path");
    json.value("shimmer_pixels", off_() ? 0LL : shimmer_counted_);
    // The same, frame to frame, while input moved the eye (a window's drag; 0 frames headless).
    json.value("shimmer_live_frames", live_frames_);
    json.figure("shimmer_live_pct", live_shimmer_pct_,
                live_frames_ > 0 ? "no sunlit pixel inside the cascades in the last moving frame"
                                 : "no frame moved the eye (a window's drag measures it)");
  }

  void panel(Frame&) override {
    if (shimmer_pct_) {
      ImGui::TextWrapped(
          "shimmer: %.4f %% of the sunlit pixels flip between two steps of the "
          "eye (the truth: none)",
          *shimmer_pct_);
    } else {
      ImGui::TextWrapped("shimmer: none counted (no sunlit pixel inside the cascades)");
    }
    if (live_shimmer_pct_) {
      ImGui::TextWrapped("while you drag: %.4f %% flipped in the last frame the eye moved",
                         *live_shimmer_pct_);
    }
    std::string slices;
    for (int i = 0; i < used_count_; ++i) {
      char line[128];
      const std::optional<double> t = texels_per_pixel_[static_cast<size_t>(i)];
      char texels[48] = "no pixel reads it";
      if (t) std::snprintf(texels, sizeof texels, "%.2f texels a pixel", *t);
      std::snprintf(line, sizeof line, "%s%.1f-%.1f m: %.1f cm a texel, %s", i ? "; " : "",
                    splits_[static_cast<size_t>(i)], splits_[static_cast<size_t>(i) + 1],
                    100.0f * atlas_.fits[static_cast<size_t>(i)].texel_world, texels);
      slices += line;
    }
    ImGui::TextWrapped("cascades: %s", slices.c_str());
    if (range_() == Range::Visible) {
      if (seen_) {
        ImGui::TextWrapped("surfaces in view: %.2f-%.2f m (the slices cover them)", seen_->x,
                           seen_->y);
      } else {
        ImGui::TextWrapped("surfaces in view: none (the slices cover the fixed range)");
      }
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {
        {.title = "Stop the crawl",
         .goal = "Boxes fitted to their slices and moved freely make the shadows' edges "
                 "crawl: 0.058 % of the sunlit pixels flip at each step of the eye's walk "
                 "and turn, where the truth flips none. Bring the shimmer to 0.01 % or less "
                 "with the same texels, false shadow and false lit at most 0.2 % each.",
         .setup = {"cascades.fit=slice", "cascades.snap=false"},
         .allowed = {"cascades.fit", "cascades.snap", "cascades.blend", "bias.normal",
                     "bias.depth"},
         .figures = {{"/shimmer_pct", "shimmer %", B::AtMost, 0.01},
                     {"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.2},
                     {"/error/false_lit_pct", "false lit %", B::AtMost, 0.2}},
         .hint = "What changes a box's size as the eye turns, and where can it move to?"},
        {.title = "Where the texels go",
         .goal = "Two cascades of 256 texels split evenly give the slice at the eye's feet "
                 "60 metres, 43 cm a texel: 0.39 % false shadow and 0.66 % false lit. With "
                 "the same two maps over the same 120 metres, bring each to 0.3 % or less.",
         .setup = {"cascades.count=2", "cascades.size=256", "cascades.split=uniform"},
         // Not cascades.far: shadows past the last cascade are dropped, and a far of 30
         // metres met the goal by covering less, not by placing the texels.
         .allowed = {"cascades.split", "cascades.lambda", "bias.normal", "bias.depth"},
         .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.3},
                     {"/error/false_lit_pct", "false lit %", B::AtMost, 0.3}},
         .hint = "Texels per metre should fall with distance as the eye's pixels per metre "
                 "do."},
        {.title = "Four maps, four slices in use",
         .goal = "On torus_pyramid every surface lies 5 to 16 metres from the eye, and the "
                 "slices from the near plane to 120 metres leave cascades 3 and 4 shading "
                 "nothing. Put all four to work, each at 1.2 texels a pixel or more.",
         .setup = {"scene=torus_pyramid"},
         .allowed = {"cascades.range", "cascades.far", "cascades.split", "cascades.lambda"},
         .figures = {{"/cascades_shading", "cascades shading pixels", B::AtLeast, 4},
                     {"/cascade_texels_per_pixel_least", "least texels a pixel", B::AtLeast, 1.2}},
         .hint = "Where do the slices start and end, and where are the surfaces?"}};
  }

 private:
  void ensureAtlas(Atlas& atlas) {
    const int n = count_(), size = size_();
    cols_ = n == 1 ? 1 : 2, rows_ = n <= 2 ? 1 : 2;
    Texture& t = atlas.texture;
    if (t.width() == cols_ * size && t.height() == rows_ * size) return;
    t = Texture::depth(cols_ * size, rows_ * size, 24);
    atlas.framebuffer = std::make_unique<Framebuffer>();
    atlas.framebuffer->attachDepth(t);
    atlas.framebuffer->check();
    atlas.view = glm::mat4(0.0f);  // nothing in it yet
  }

  // The slices for the eye `view` (over the depths it sees, where `seen` has them), their
  // boxes, and the casters of each into its tile.
  void renderAtlas(Frame& f, Atlas& atlas, const glm::mat4& view, int mask,
                   std::optional<glm::vec2> seen) {
    used_count_ = count_();
    float near = f.scene.camera.near;
    float far = std::max(far_(), near * 2.0f);
    // The nearest and farthest visible surfaces a hair inside the slices, never past
    // cascades.far (a 24-bit depth reads back to about 1e-4 of the distance); where every
    // surface lies beyond it, the fixed range.
    if (seen && seen->x * 0.999f < far) {
      near = std::max(seen->x * 0.999f, near);
      far = std::clamp(seen->y * 1.001f, near * 1.001f, far);
    }
    const float lambda = lambda_();
    for (int i = 0; i <= used_count_; ++i) {
      splits_[static_cast<size_t>(i)] =
          cascade::splitDistance(split_(), i, used_count_, near, far, lambda);
    }
    const glm::mat4 light = cascade::lightRotation(f.light.direction);
    const Bounds scene = f.scene.bounds();
    const float fov = glm::radians(f.params.at("camera.fov").f());
    const float aspect = static_cast<float>(f.width) / static_cast<float>(std::max(f.height, 1));
    atlas.framebuffer->bind();
    PassState{}.apply();
    glViewport(0, 0, atlas.texture.width(), atlas.texture.height());
    glClearDepthf(1.0f);
    glEnable(GL_SCISSOR_TEST);  // each tile cleared on its own: the others may be kept
    const Program& d = depth_programs_.get({});
    for (int i = 0; i < used_count_; ++i) {
      if (((mask >> i) & 1) == 0) continue;  // kept: its box and its depths as they were
      const auto k = static_cast<size_t>(i);
      const auto corners = cascade::sliceCorners(view, fov, aspect, splits_[k], splits_[k + 1]);
      cascade::Fit& fit = atlas.fits[k];
      fit = cascade::fitCascade(corners, light, size_(), fit_() == Fit::Sphere, snap_(),
                                scene.center(), scene.radius());
      glViewport((i % cols_) * size_(), (i / cols_) * size_(), size_(), size_());
      glScissor((i % cols_) * size_(), (i / cols_) * size_(), size_(), size_());
      glClear(GL_DEPTH_BUFFER_BIT);
      d.set("uLightViewProjection", fit.view_projection);
      f.drawObjects(d, Objects::Casters, &fit.view_projection);
    }
    glDisable(GL_SCISSOR_TEST);
    PassState{}.apply();
    if ((mask & 1) != 0) atlas.view = view;  // the eye the first cascade follows
    const int all = (1 << used_count_) - 1;
    atlas.kept = mask == all ? 0 : (atlas.kept | all) & ~mask;
    atlas_projection_ = f.projection;
  }

  // The blend only where it mixes anything; the next cascade's lookup, where a point can be
  // outside its own cascade's box, only while a cascade is kept or the slices are another
  // eye's (the live shimmer's frame before).
  const Program& eyeProgram(const std::vector<std::string>& view, const Atlas& atlas,
                            const glm::mat4& cascadeView) {
    const bool kept = update_() > 1 && (atlas.kept != 0 || cascadeView != atlas.view);
    return eye_programs_.get({view, define("SHADOW_OFF", off_()), feature("KEPT_CASCADES", kept),
                              feature("CASCADE_BLEND", used_count_ > 1 && blend_() > 0.0f),
                              feature("NORMAL_OFFSET", normal_() > 0.0f)});
  }

  // What the lookup needs: each cascade's matrix into its tile, the slices, the biases.
  void setEyeUniforms(const Program& e, Frame& f, const Atlas& atlas,
                      const glm::mat4& cascadeView) const {
    atlas.texture.bind(0);
    (filter_.name() == "linear" ? compare_linear_ : compare_nearest_).bind(0);
    e.set("uAtlas", 0);
    e.set("uShadowMatrix", glm::mat4(1.0f));
    e.set("uCount", off_() ? 0 : used_count_);
    e.set("uCascadeView", cascadeView);
    const glm::vec2 tile(1.0f / static_cast<float>(cols_), 1.0f / static_cast<float>(rows_));
    const glm::vec2 half_texel(0.5f / static_cast<float>(std::max(atlas.texture.width(), 1)),
                               0.5f / static_cast<float>(std::max(atlas.texture.height(), 1)));
    for (int i = 0; i < kMaxCascades; ++i) {
      const auto k = static_cast<size_t>(i);
      char index[8];
      std::snprintf(index, sizeof index, "[%d]", i);
      const std::string at = index;
      const glm::vec2 offset(static_cast<float>(i % cols_) * tile.x,
                             static_cast<float>(i / cols_) * tile.y);
      e.set("uCascade" + at, atlas.fits[k].view_projection);
      e.set("uTileOffset" + at, offset);
      e.set("uTile" + at, glm::vec4(offset + half_texel, offset + tile - half_texel));
      e.set("uTexelWorld" + at, atlas.fits[k].texel_world);
      e.set("uDepthRange" + at, atlas.fits[k].depth_range);
      e.set("uSplitFar" + at, splits_[k + 1]);
      e.set("uSplitNear" + at, splits_[k]);
      e.set("uCascadeColor" + at, kCascadeColors[k]);
    }
    e.set("uTileScale", tile);
    e.set("uSize", static_cast<float>(size_()));
    e.set("uBiasNormal", normal_());
    e.set("uBiasDepth", depth_bias_());
    e.set("uBlend", used_count_ > 1 ? blend_() : 0.0f);
    f.setLightingUniforms(e, dimming_());
  }

  // The eye's k-th step along the path: forward and sideways by 3 cm a step, turned by 0.1°.
  glm::mat4 stepView(const glm::mat4& view, int k) const {
    const float s = static_cast<float>(k);
    const bool walk = path_() != Path::Turn, turn = path_() != Path::Walk;
    glm::mat4 v = view;
    if (walk) v = v * glm::translate(glm::mat4(1.0f), -s * glm::vec3(0.013f, 0.0f, -0.027f));
    if (turn) v = glm::rotate(glm::mat4(1.0f), glm::radians(0.1f * s), glm::vec3(0, 1, 0)) * v;
    return v;
  }

  // Everything the shimmer depends on, as text: when it changes, the path is measured again.
  std::string shimmerKey(const Frame& f) const {
    // Every setting but the view shown (the eye and the sun are settings too), so a setting
    // added later cannot be forgotten here; and the frame's size.
    std::ostringstream key;
    key << f.width << 'x' << f.height;
    for (const Param& p : f.params.all()) {
      if (p.name != "view") key << ' ' << p.text();
    }
    // Where the objects are (a lesson may move one): their matrices' bytes, hashed (FNV-1a).
    Fnv hash;
    for (const SceneObject& o : f.scene.objects) hash.add(o.model);
    key << ' ' << hash.h;
    return key.str();
  }

  // The shimmer target: the frame's size, RGBA8, read back as bytes.
  void ensureStateTarget(const Frame& f) {
    if (shimmer_target_w_ == f.width && shimmer_target_h_ == f.height) return;
    const auto uncounted = TextureBytes::Scope::none();  // a measurement's, not the sun's
    shimmer_color_ = Texture::color(f.width, f.height, GL_RGBA8);
    shimmer_depth_ = Texture::depthStencil(f.width, f.height);
    shimmer_target_ = std::make_unique<Framebuffer>();
    shimmer_target_->attachColor(shimmer_color_);
    shimmer_target_->attachDepthStencil(shimmer_depth_);
    shimmer_target_->check();
    shimmer_target_w_ = f.width, shimmer_target_h_ = f.height;
  }

  // The frame's pixels (the same points of the world) looked up in `atlas`, whose slices are
  // the eye `cascadeView`'s: per pixel the state, the cascade, its texels per pixel and
  // whether it faces the sun (scene.frag, VIEW_SHIMMER).
  void readStates(Frame& f, const Atlas& atlas, const glm::mat4& cascadeView,
                  std::vector<unsigned char>& rgba) {
    ensureStateTarget(f);
    shimmer_target_->bind();
    glViewport(0, 0, f.width, f.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    std::vector<std::string> views = f.params.at("view").choices;
    views.push_back(kShimmer.str());  // a view of its own, never offered
    const Program& e = eyeProgram(choiceDefines("view", views, kShimmer.str()), atlas, cascadeView);
    setEyeUniforms(e, f, atlas, cascadeView);
    e.set("uViewProjection", f.projection * f.view);
    f.drawObjects(e, Objects::All);
    Sampler::unbind(0);
    rgba.resize(static_cast<size_t>(f.width) * static_cast<size_t>(f.height) * 4);
    glReadPixels(0, 0, f.width, f.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    f.bindTarget();
  }

  // Between two readStates: the sunlit points inside the cascades both times, and how many of
  // them flipped.
  static std::pair<long long, long long> countFlips(const std::vector<unsigned char>& a,
                                                    const std::vector<unsigned char>& b) {
    long long counted = 0, flips = 0;
    for (size_t p = 0; p + 3 < a.size() && p + 3 < b.size(); p += 4) {
      if (a[p + 3] < 128 || a[p + 1] == 0 || b[p + 1] == 0) continue;
      ++counted;
      if ((a[p] < 128) != (b[p] < 128)) ++flips;
    }
    return {counted, flips};
  }

  // The points this frame shows, shadowed or not by the maps of each step of the path: the
  // share of sunlit points whose state flips between two steps, over all steps.
  void measureShimmer(Frame& f) {
    auto timing = f.measure.pass("shimmer");
    {
      const auto uncounted = TextureBytes::Scope::none();  // a measurement's, not the sun's
      ensureAtlas(path_atlas_);  // its own: the frame's atlas and what it keeps stay as they are
    }
    // The path's slices are its own too: the frame's atlas keeps the slices it was fitted for.
    const auto splits = splits_;
    const int count = used_count_;
    std::vector<unsigned char> last, now;
    long long flips = 0, counted = 0;
    for (int k = 0; k <= kShimmerSteps; ++k) {
      const glm::mat4 view = stepView(f.view, k);
      // The far cascades follow the eye every cascades.update-th step, as they would frames.
      const int mask = k % update_() == 0 || range_() == Range::Visible ? (1 << count_()) - 1 : 1;
      const std::optional<glm::vec2> seen =
          range_() == Range::Visible ? visible_.measure(f, view) : std::nullopt;
      renderAtlas(f, path_atlas_, view, mask, seen);
      readStates(f, path_atlas_, view, now);
      if (k > 0) {
        const auto [c, n] = countFlips(last, now);
        counted += c, flips += n;
      }
      if (k == 0) texelsPerPixel(now);
      std::swap(last, now);
    }
    shimmer_counted_ = counted / kShimmerSteps;
    shimmer_pct_ = counted > 0 ? std::optional<double>(100.0 * static_cast<double>(flips) /
                                                       static_cast<double>(counted))
                               : std::nullopt;
    splits_ = splits;
    used_count_ = count;
  }

  // The median texels per pixel of each cascade over the sunlit pixels it shades (the eye's
  // own step of the path): what its slice of the frame gets; none where it shades none.
  void texelsPerPixel(const std::vector<unsigned char>& rgba) {
    std::array<std::vector<int>, kMaxCascades> levels;
    for (size_t p = 0; p + 3 < rgba.size(); p += 4) {
      if (rgba[p + 3] < 128 || rgba[p + 1] == 0 || rgba[p + 1] > kMaxCascades) continue;
      levels[static_cast<size_t>(rgba[p + 1] - 1)].push_back(
          cascade::texelLevel(rgba[p + 2], rgba[p + 3]));
    }
    for (size_t i = 0; i < levels.size(); ++i) {
      std::vector<int>& l = levels[i];
      texels_per_pixel_[i].reset();
      if (l.empty()) continue;
      std::nth_element(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(l.size() / 2), l.end());
      texels_per_pixel_[i] = cascade::texelsFromLevel(l[l.size() / 2]);
    }
  }

  IntParam count_, size_, update_;
  ChoiceParam<cascade::Split> split_;
  ChoiceParam<> filter_;
  ChoiceParam<Fit> fit_;
  ChoiceParam<Range> range_;
  ChoiceParam<Path> path_;
  FloatParam lambda_, blend_, far_, normal_, depth_bias_, dimming_;
  BoolParam snap_, cache_, off_;
  ProgramVariants depth_programs_, eye_programs_;
  Sampler compare_nearest_, compare_linear_;
  Atlas atlas_;       // the frame's
  Atlas path_atlas_;  // the shimmer path's steps
  VisibleDepths visible_;
  std::optional<glm::vec2> seen_;  // the last depths measured in view (cascades.range=visible)
  int cols_ = 1, rows_ = 1, used_count_ = 0;
  long long moved_frames_ = 0;  // frames the eye alone moved since all cascades were rendered
  std::array<float, kMaxCascades + 1> splits_{};
  glm::mat4 atlas_projection_{0.0f};
  std::string shimmer_key_;
  std::optional<double> shimmer_pct_;
  long long shimmer_counted_ = 0;
  std::array<std::optional<double>, kMaxCascades> texels_per_pixel_{};
  // While the eye is dragged: the share of sunlit points the last moving frame flipped.
  std::vector<unsigned char> live_before_, live_after_;
  std::optional<double> live_shimmer_pct_;
  long long live_frames_ = 0;
  Texture shimmer_color_, shimmer_depth_;
  std::unique_ptr<Framebuffer> shimmer_target_;
  int shimmer_target_w_ = 0, shimmer_target_h_ = 0;
};

SHADOWS_LESSON(Cascades);

}  // namespace shadows
