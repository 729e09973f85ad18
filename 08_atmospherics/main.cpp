// Lesson 08: shadows in a dusty room (seed 000, "Combine with Projective Texturing for
// Spotlight Shadows" and "Combining Shadows with Atmospherics", Cass Everitt's demo):
//   1. construct the shadow map from the spotlight
//   2. draw the scene with it, lit by the spotlight's projected texture
//   3. modulate the projected spotlight texture with the projected shadow map
//   4. blend slices facing the eye back to front, so the air glows where the light reaches
//      it and goes dark behind the casters.
// The slices are a Riemann sum of the light scattered along each eye ray; the truth
// (common/truth/air_truth.cpp) integrates the same light with Embree shadow rays.
#include <imgui.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/json.hpp"
#include "core/spotlight.hpp"
#include "lesson/lesson.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

class Atmospherics final : public Lesson {
 public:
  std::string title() const override { return "Light shafts: shadowed spotlight in dusty air"; }
  std::string seeds() const override {
    return "seed 000: Combine with Projective Texturing for Spotlight Shadows; Combining "
           "Shadows with Atmospherics";
  }
  static constexpr View kSurfaces{"surfaces"};
  static constexpr View kSpot{"spot"};
  std::vector<View> debugViews() const override {
    return {views::kAir, kSurfaces, kSpot, views::kLightDepth, views::kAliasing};
  }
  std::vector<std::string> scenes() const override {
    std::vector<std::string> all = {"room"};
    for (const auto& s : scenePresets()) all.push_back(s);
    return all;
  }

  void declare(Params& p) override {
    map_.declare(p);
    slices_ = p.addInt("air.slices", 64, 1, 256, "slices through the lit air, back to front");
    density_ = p.addFloat("air.density", 0.15f, 0.0f, 1.0f, "dust: light scattered per world unit");
    jitter_ = p.addBool("air.jitter", true,
                        "move each pixel's sample within its slice: noise, not bands");
    bound_ = p.addBool("air.bound", true,
                       "slices only over the depth range and screen area of the cone");
    early_reject_ =
        p.addBool("air.early_reject", true,
                  "slice fragments behind surfaces fail the depth test before they are shaded");
    downsample_ = p.addInt("air.downsample", 2, 1, 4,
                           "air at 1/N of the width and height, brought back by surface depth");
    // A missing or broken file is bad input, named.
    image_ = p.addString("spot.image", "builtin",
                         "builtin (a round spot) or the path of a PNG to project")
                 .checkedBy(checkPngParam);
    falloff_ = p.addFloat("spot.falloff", 0.35f, 0.0f, 1.0f,
                          "builtin spot: the outer part of its radius over which it fades");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
  }

  void init() override {
    glGenVertexArrays(1, &empty_vao_);  // slices need no vertices: gl_VertexID, gl_InstanceID
    rects_buffer_ = Buffer(GL_UNIFORM_BUFFER, 256 * sizeof(glm::vec4), nullptr, GL_DYNAMIC_DRAW);
    // Compiled per shadow.off (the baseline: no lookup), air.early_reject, air.jitter and the
    // view, on first use.
    room_ =
        ProgramVariants(lessonFile(LESSON_DIR, "room.vert"), lessonFile(LESSON_DIR, "room.frag"));
    slice_programs_ =
        ProgramVariants(lessonFile(LESSON_DIR, "slice.vert"), lessonFile(LESSON_DIR, "slice.frag"));
    depth_program_ =
        ProgramVariants(lessonFile(LESSON_DIR, "room.vert"), commonShaderDir() / "depth_only.frag");
    air_depth_program_ = ProgramVariants(lessonFile(LESSON_DIR, "room.vert"),
                                         lessonFile(LESSON_DIR, "air_depth.frag"));
    upsample_program_ = ProgramVariants(commonShaderDir() / "fullscreen.vert",
                                        lessonFile(LESSON_DIR, "air_upsample.frag"));
  }
  ~Atmospherics() override {
    if (empty_vao_ != 0) glDeleteVertexArrays(1, &empty_vao_);
  }

  void render(Frame& f) override {
    loadSpot(image_(), falloff_());
    // Without dust (air.density=0) the air scatters no light: the slices, the low-res depth and
    // the upsample would each add exactly 0 to every pixel, so none is drawn.
    air_skipped_ = !(f.shows(views::kShaded) || f.shows(views::kAir)) ? "this view shows no air"
                   : density_() > 0.0f || neutralCodeKept("AIR_SLICES")
                       ? ""
                       : "air.density=0: no dust scatters light, no slice is drawn";
    if (!air_skipped_.empty()) f.measure.count("air_slices", 0);
    // 1. The shadow map, lesson 04's default bias (back faces + glPolygonOffset(1.1, 4)). Every
    // object goes in, the floor and walls too: they cast nothing on a surface, but they shadow
    // the air behind them (the dust beneath the floor, seen from below it).
    if (map_.prepare(f)) {
      map_.renderCasters(f, ShadowMap::backFacesBias(1.1f, 4.0f), Objects::Occluders);
    }
    map_.sampledBy(f);  // the eye reads this map: the truth counts inside its frustum
    if (map_.drawDepthView(f)) return;

    const glm::mat4 cone = coneOfLight(f);
    f.medium = AirMedium{density_(), f.light.position, cone, &spot_, 64};
    f.medium->directional = f.light.directional;  // its shadow rays run parallel
    f.medium->light_direction = f.light.direction;

    // 2 and 3. The surfaces, lit through the spot texture and the shadow map.
    {
      auto timing = f.measure.pass("surfaces", /*countPassed=*/true);
      f.clearTarget(f.shows(views::kAir) || f.shows(views::kVisibility)
                        ? glm::vec3(0.0f)
                        : glm::vec3(0.02f, 0.02f, 0.03f));
      bindLightTextures();
      const Program& room = room_.get({define("SHADOW_OFF", map_.off()), f.viewDefines()});
      room.set("uViewProjection", f.projection * f.view);
      room.set("uShadowMatrix", map_.textureMatrix());
      room.set("uSpotMatrix", biasMatrix() * cone);
      room.set("uLightPos", f.light.position);
      room.set("uEye", f.eye);
      room.set("uDimming", dimming_());
      room.set("uSpot", 0);
      room.set("uShadowMap", 1);
      f.drawObjects(room, Objects::All);
    }
    // 4. The air.
    if (air_skipped_.empty()) drawSlices(f, cone);
    if (f.shows(views::kShaded) || f.shows(kSurfaces)) map_.drawInset(f);
  }

  void panel(Frame&) override {
    if (!air_skipped_.empty()) {
      ImGui::TextWrapped("air: none (%s)", air_skipped_.c_str());
      return;
    }
    // Which air is on screen: the preview while input moves, the full air once it rests.
    const std::string resolution =
        downsample_drawn_ == 1 ? "full" : "1/" + std::to_string(downsample_drawn_);
    ImGui::Text("air: %s, %d slices at %s resolution",
                preview_ ? "PREVIEW while moving" : "full quality", slices_drawn_,
                resolution.c_str());
    ImGui::Text("slices over view depth %.2f .. %.2f (%s)", near_, far_,
                bound_() ? "the cone's" : "the whole view");
    ImGui::Text("slice fragments passed %s", countText(passed_).c_str());
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "The fewest slices",
             .goal = "8 slices leave the air 37 % off the truth (relative RMSE). Bring the air's "
                     "relative RMSE to 7.5 % or less with at most 48 slices: each slice costs "
                     "its share of the frame.",
             .setup = {"air.slices=8"},
             .allowed = {"air.slices"},
             .figures = {{"/error/air_rel_rmse", "air rel. RMSE", B::AtMost, 0.075},
                         {"/counters/air_slices", "slices", B::AtMost, 48}},
             .hint = "Each slice is one term of a Riemann sum along the eye ray: the error "
                     "halves with each doubling of the slices. 8 give 37 %; how many give "
                     "7.5 %?"}};
  }

  void report(JsonWriter& json) const override {
    // No slices drawn, none placed: where they would have gone is no figure of this frame.
    if (!air_skipped_.empty()) {
      for (const char* key : {"air_depth_near", "air_depth_far", "air_step", "air_downsample"}) {
        json.notCounted(key, air_skipped_);
      }
      json.value("air_quality", "none");
      return;
    }
    json.value("air_depth_near", near_);
    json.value("air_depth_far", far_);
    json.value("air_step", step_);
    json.value("air_downsample", downsample_drawn_);
    json.value("air_quality", std::string(preview_ ? "preview" : "full"));
  }

 private:
  // The lit air: the spot's frustum from the light to the farthest point of the scene, so it
  // is the same whatever the map's near and far (light.near/far, shadow.fit) are set to. A
  // directional light's box starts at the light too: what lies behind it gets no light.
  glm::mat4 coneOfLight(const Frame& f) const {
    // The map's aspect, so the map covers the whole lit cone (a non-square map widens it).
    LightFrustum frustum = f.light.frustum(static_cast<float>(map_.width()) /
                                           static_cast<float>(std::max(map_.height(), 1)));
    float near = frustum.near, far = frustum.far;
    if (fitNearFar(f.light.view, f.scene.bounds(), frustum.directional, near, far)) {
      frustum.far = far;
      frustum.near = frustum.directional ? 0.0f : far * 1e-3f;
    }
    return lightProjection(frustum) * f.light.view;
  }

  void loadSpot(const std::string& path, float falloff) {
    const std::string key =
        SpotTexture::isBuiltin(path) ? "builtin " + std::to_string(falloff) : path;
    if (key == spot_key_) return;
    spot_ =
        SpotTexture::isBuiltin(path) ? SpotTexture::builtin(falloff) : SpotTexture::fromPng(path);
    const Image& image = spot_.image();
    spot_texture_ = Texture::color(image.width, image.height, GL_RGBA8);
    spot_texture_.upload(GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    spot_texture_.setFilter(GL_NEAREST);  // the truth reads the same texels
    spot_texture_.setWrap(GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
    spot_texture_.setBorder(glm::vec4(0.0f));  // no light outside the frustum
    spot_key_ = key;
  }

  void bindLightTextures() const {
    spot_texture_.bind(0);
    map_.texture().bind(1);
  }

  // Where the slices go: over the view-depth range of the cone (the light's frustum, where
  // the air is) either way, so air.bound changes the cost and never the picture; bounded, each
  // slice covers only the screen rectangle around the part of the frustum its jittered samples
  // can reach, unbounded the whole screen.
  void sliceBounds(const Frame& f, const glm::mat4& cone, int count) {
    // The frustum's corners in view space: near plane 0-3, far plane 4-7 (a spot's near
    // corners lie a hair from its apex).
    std::vector<glm::vec3> points;
    const glm::mat4 inverse = glm::inverse(cone);
    for (float z : {-1.0f, 1.0f}) {
      for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        const glm::vec4 corner = inverse * glm::vec4(c, z, 1.0f);
        points.push_back(f.view * glm::vec4(glm::vec3(corner) / corner.w, 1.0f));
      }
    }
    near_ = 1e30f, far_ = 0.0f;
    for (const glm::vec3& p : points) near_ = std::min(near_, -p.z), far_ = std::max(far_, -p.z);
    near_ = std::max(near_, f.scene.camera.near);  // what the eye pass can show
    far_ = std::min(far_, f.scene.eyeFar(f.eye));
    step_ = far_ > near_ ? (far_ - near_) / static_cast<float>(count) : 0.0f;
    rects_.assign(static_cast<size_t>(count), glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
    if (!bound_()) return;
    // The frustum's 12 edges: around the near plane, around the far plane, and between them.
    const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                              {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (int i = 0; i < count; ++i) {
      // The slab [back, front] the slice's jittered samples span: the frustum's part in it is
      // the hull of its edges' crossings with both planes and its corners in between.
      const float back = far_ - static_cast<float>(i) * step_, front = back - step_;
      glm::vec2 lo(1e30f), hi(-1e30f);
      auto add = [&](const glm::vec3& p) {
        const glm::vec4 clip = f.projection * glm::vec4(p, 1.0f);
        lo = glm::min(lo, glm::vec2(clip) / clip.w);
        hi = glm::max(hi, glm::vec2(clip) / clip.w);
      };
      for (const glm::vec3& p : points) {
        if (-p.z >= front && -p.z <= back) add(p);
      }
      for (const auto& e : edges) {
        const glm::vec3 a = points[static_cast<size_t>(e[0])],
                        b = points[static_cast<size_t>(e[1])];
        for (const float depth : {front, back}) {
          const float da = -a.z - depth, db = -b.z - depth;
          if (da * db > 0.0f || da == db) continue;  // the edge does not cross this plane
          add(a + (b - a) * (da / (da - db)));
        }
      }
      // Nothing of the frustum in the slab: an empty rectangle draws nothing.
      rects_[static_cast<size_t>(i)] =
          lo.x > hi.x ? glm::vec4(0.0f)
                      : glm::vec4(glm::max(lo, glm::vec2(-1.0f)), glm::min(hi, glm::vec2(1.0f)));
    }
  }

  // The air at 1/k of the picture's width and height (k = air.downsample): the slices shade k²
  // times fewer fragments; at k = 1 they blend straight into the picture.
  void drawSlices(Frame& f, const glm::mat4& cone) {
    // While the camera or a slider moves in a window, a cheaper preview (kPreviewDownsample):
    // the same slices, so dragging air.slices still shows what it does.
    preview_ = f.input_moving && downsample_() < kPreviewDownsample;
    const int k = preview_ ? kPreviewDownsample : downsample_();
    downsample_drawn_ = k;
    slices_drawn_ = slices_();
    sliceBounds(f, cone, slices_drawn_);
    if (k > 1) airDepth(f, k, !preview_);
    drawSlicesTimed(f, cone, k);
    // Fragments the slices rasterized (llvmpipe counts them before any test), and of those
    // the ones shaded: only those that passed the depth test when it runs first.
    if (const PassWork* work = f.measure.frameWork("air")) {
      const std::optional<long long> rasterized = work->fragment_invocations;
      const std::optional<long long> shaded = early_reject_() ? passed_ : rasterized;
      f.measure.count("air_fragments_shaded", shaded);
      f.measure.count("air_fragments_skipped",
                      rasterized && shaded ? std::optional(*rasterized - *shaded) : std::nullopt);
    }
    if (k > 1) upsampleAir(f, k, !preview_);
  }

  // The low-res air's targets: the air (rgb) with the view depth its rays end at (alpha) and
  // their depth buffer, at 1/k; and, for the depth-aware upsample, the picture's own depth
  // drawn again (the picture may be the window's, whose depth no shader can read).
  void ensureLowRes(const Frame& f, int k) {
    const int w = (f.width + k - 1) / k, h = (f.height + k - 1) / k;
    if (low_ && low_->width == w && low_->height == h && low_->full_width == f.width &&
        low_->full_height == f.height) {
      return;
    }
    low_ = std::make_unique<LowRes>();
    low_->width = w, low_->height = h, low_->full_width = f.width, low_->full_height = f.height;
    low_->depth = Texture::depth(f.width, f.height, 24);
    low_->depth_target.attachDepth(low_->depth);
    low_->depth_target.check();
    low_->air = Texture::color(w, h, GL_RGBA32F);  // the sum of many small terms, unrounded
    low_->air.setFilter(GL_NEAREST);
    low_->air_depth = Texture::depth(w, h, 24);
    low_->air_target.attachColor(low_->air);
    low_->air_target.attachDepth(low_->air_depth);
    low_->air_target.check();
  }

  // From the picture's clip space to the low-res target's, where pixel (x, y) is centred on the
  // ray of the picture's pixel (k x, k y): x' = s x + o w (the slices do the same in NDC).
  glm::mat4 lowResClip(const Frame& f, int k, glm::vec2& scale, glm::vec2& offset) const {
    const glm::vec2 full(f.width, f.height), low(low_->width, low_->height);
    scale = full / (static_cast<float>(k) * low);
    offset = (full - 1.0f + static_cast<float>(k)) / (static_cast<float>(k) * low) - 1.0f;
    glm::mat4 m(1.0f);
    m[0][0] = scale.x, m[1][1] = scale.y, m[3][0] = offset.x, m[3][1] = offset.y;
    return m;
  }

  // The scene's depth where the low-res slices are tested against it, and at full resolution
  // when the upsample weighs neighbours by it.
  void airDepth(Frame& f, int k, bool depthAware) {
    auto timing = f.measure.pass("air_depth");
    ensureLowRes(f, k);
    const glm::mat4 view_projection = f.projection * f.view;
    const glm::vec2 near_far(f.scene.camera.near, f.scene.eyeFar(f.eye));
    PassState{}.apply();
    if (depthAware) {
      low_->depth_target.bind();
      glViewport(0, 0, f.width, f.height);
      glClear(GL_DEPTH_BUFFER_BIT);
      const Program& depth = depth_program_.get({});
      depth.set("uViewProjection", view_projection);
      if (scissorToSlices(f)) f.drawObjects(depth, Objects::All);
      glDisable(GL_SCISSOR_TEST);
    }
    low_->air_target.bind();
    glViewport(0, 0, low_->width, low_->height);
    const float sky[4] = {0.0f, 0.0f, 0.0f, near_far.y};  // no air yet; rays end at the far plane
    glClearBufferfv(GL_COLOR, 0, sky);
    glClear(GL_DEPTH_BUFFER_BIT);
    glm::vec2 scale, offset;
    const Program& low = air_depth_program_.get({});
    low.set("uViewProjection", lowResClip(f, k, scale, offset) * view_projection);
    low.set("uNearFar", near_far);
    f.drawObjects(low, Objects::All);
  }

  // The low-res air added to the picture (air_upsample.frag).
  void upsampleAir(Frame& f, int k, bool depthAware) {
    auto timing = f.measure.pass("air_upsample");
    f.bindTarget();
    PassState add;
    add.depth_test = false;
    add.depth_write = false;
    add.blend = true;
    add.blend_dst = GL_ONE;
    add.apply();
    const Program& program = upsample_program_.get({define("AIR_DEPTH_AWARE", depthAware)});
    low_->air.bind(2);
    low_->depth.bind(3);
    program.set("uAir", 2);
    program.set("uDepth", 3);
    program.set("uFactor", k);
    program.set("uNearFar", glm::vec2(f.scene.camera.near, f.scene.eyeFar(f.eye)));
    if (scissorToSlices(f)) drawTriangle(program);
    glDisable(GL_SCISSOR_TEST);
    PassState{}.apply();
  }

  // Scissors the picture to the slices' rectangles: no slice reaches a pixel outside them, so
  // no air does, and neither the upsample nor its depth is needed there. False: none is left.
  bool scissorToSlices(const Frame& f) const {
    glm::vec2 lo(1.0f), hi(-1.0f);
    for (const glm::vec4& r : rects_) {
      if (r.x < r.z) lo = glm::min(lo, glm::vec2(r)), hi = glm::max(hi, glm::vec2(r.z, r.w));
    }
    const glm::vec2 size(f.width, f.height);
    const glm::ivec2 from(glm::floor((lo + 1.0f) * 0.5f * size)),
        to(glm::ceil((hi + 1.0f) * 0.5f * size));
    glEnable(GL_SCISSOR_TEST);
    glScissor(from.x, from.y, std::max(to.x - from.x, 0), std::max(to.y - from.y, 0));
    return from.x < to.x && from.y < to.y;
  }

  void drawTriangle(const Program& program) const {
    program.use();
    glBindVertexArray(empty_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    countDrawCall();
  }

  void drawSlicesTimed(Frame& f, const glm::mat4& cone, int k) {
    auto timing = f.measure.pass("air");
    passed_ = 0;
    if (!(step_ > 0.0f)) return;  // the cone lies behind the eye
    const Program& slices =
        slice_programs_.get({define("SHADOW_OFF", map_.off()), early_reject_.defines(),
                             jitter_.defines(), f.viewDefines()});
    rects_buffer_.update(static_cast<GLsizeiptr>(rects_.size() * sizeof(glm::vec4)), rects_.data());
    rects_buffer_.bindBase(0);
    slices.bindBlock("Rects", 0);
    slices.set("uFar", far_);
    slices.set("uStep", step_);
    slices.set("uProjection", f.projection);
    // Low-res pixel x (centre x + 1/2) is the ray of pixel k x (centre k x + 1/2): from the
    // picture's normalized device x to the low-res target's.
    glm::vec2 scale(1.0f), offset(0.0f);
    if (k > 1) {
      lowResClip(f, k, scale, offset);
      low_->air_target.bind();
      glViewport(0, 0, low_->width, low_->height);
    }
    slices.set("uNdcScale", scale);
    slices.set("uNdcOffset", offset);
    slices.set("uPixelScale", k);
    slices.set("uInverseView", glm::inverse(f.view));
    // tan(fov/2) across and up: what the perspective matrix divides by.
    slices.set("uTanHalfFov", 1.0f / glm::vec2(f.projection[0][0], f.projection[1][1]));
    slices.set("uShadowMatrix", map_.textureMatrix());
    slices.set("uSpotMatrix", biasMatrix() * cone);
    slices.set("uDensity", density_());
    slices.set("uAirColor", glm::vec3(1.0f, 0.93f, 0.78f));
    slices.set("uSpot", 0);
    slices.set("uShadowMap", 1);
    bindLightTextures();
    PassState air;
    air.depth_write = false;  // tested against the surfaces, never hiding them
    air.blend = true;
    air.blend_dst = GL_ONE;  // additive: the air adds light
    air.apply();
    slices.use();
    glBindVertexArray(empty_vao_);
    query_.begin();
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, slices_drawn_);
    query_.end();
    countDrawCall();
    passed_ = query_.result();
    f.measure.count("air_slices", slices_drawn_);
    f.measure.count("air_fragments_passed", passed_);
    PassState{}.apply();
    f.bindTarget();
  }

  ShadowMap map_;
  ProgramVariants room_, slice_programs_, depth_program_, air_depth_program_, upsample_program_;
  struct LowRes {
    int width = 0, height = 0, full_width = 0, full_height = 0;
    Texture depth;  // the picture's depth, full resolution
    Framebuffer depth_target;
    Texture air, air_depth;  // the air and the depth it is tested against, at 1/k
    Framebuffer air_target;
  };
  std::unique_ptr<LowRes> low_;
  IntParam slices_, downsample_;
  FloatParam density_, falloff_, dimming_;
  BoolParam jitter_, bound_, early_reject_;
  StringParam image_;
  SpotTexture spot_;
  Texture spot_texture_;
  std::string spot_key_;
  GLuint empty_vao_ = 0;
  SamplesPassedQuery query_;
  std::vector<glm::vec4> rects_;  // per slice, back to front
  Buffer rects_buffer_;           // their uniform block (slice.vert)
  static constexpr int kPreviewDownsample = 8;
  bool preview_ = false;
  int slices_drawn_ = 0, downsample_drawn_ = 1;
  std::string air_skipped_;  // why this frame drew no air ("" when it did)
  float near_ = 0.0f, far_ = 0.0f, step_ = 0.0f;
  std::optional<long long> passed_ = 0;  // empty: this context cannot count them
};

SHADOWS_LESSON(Atmospherics);

}  // namespace shadows
