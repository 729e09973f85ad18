// Lesson 08: shadows in a dusty room (seed 000, "Combine with Projective Texturing for
// Spotlight Shadows" and "Combining Shadows with Atmospherics", Cass Everitt's demo):
//   1. construct the shadow map from the spotlight
//   2. draw the scene with it, lit by the spotlight's projected texture
//   3. modulate the projected spotlight texture with the projected shadow map
//   4. blend slices facing the eye back to front, so the air glows where the light reaches
//      it and goes dark behind the casters.
// The slices are a Riemann sum of the light scattered along each eye ray; the truth
// (common/air_truth.cpp) integrates the same light with Embree shadow rays.
#include <imgui.h>

#include <glm/gtc/matrix_transform.hpp>

#include "app.hpp"
#include "json.hpp"
#include "shadow_map.hpp"
#include "spotlight.hpp"

namespace shadows {

class Atmospherics final : public Lesson {
 public:
  std::string title() const override { return "Light shafts: shadowed spotlight in dusty air"; }
  std::string seeds() const override {
    return "seed 000: Combine with Projective Texturing for Spotlight Shadows; Combining "
           "Shadows with Atmospherics";
  }
  std::vector<std::string> debugViews() const override {
    return {"air", "surfaces", "spot", "light_depth"};
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
  }
  ~Atmospherics() override {
    if (empty_vao_ != 0) glDeleteVertexArrays(1, &empty_vao_);
  }

  void render(Frame& f) override {
    loadSpot(image_(), falloff_());
    // 1. The shadow map, lesson 04's default bias (back faces + glPolygonOffset(1.1, 4)). Every
    // object goes in, the floor and walls too: they cast nothing on a surface, but they shadow
    // the air behind them (the dust beneath the floor, seen from below it).
    if (map_.prepare(f)) {
      map_.renderCasters(f, ShadowMap::backFacesBias(1.1f, 4.0f), Objects::Occluders);
    }
    if (map_.drawDepthView(f)) return;

    const glm::mat4 cone = coneOfLight(f);
    f.medium = AirMedium{density_(), f.light.position, cone, &spot_, 64};
    f.medium->directional = f.light.directional;  // its shadow rays run parallel
    f.medium->light_direction = f.light.direction;

    // 2 and 3. The surfaces, lit through the spot texture and the shadow map.
    {
      auto timing = f.measure.pass("surfaces", /*countPassed=*/true);
      f.clearTarget(f.mode == "air" || f.mode == "visibility" ? glm::vec3(0.0f)
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
    if (f.mode == "shaded" || f.mode == "air") drawSlices(f, cone);
    if (f.mode == "shaded" || f.mode == "surfaces") map_.drawInset(f);
  }

  void panel(Frame&) override {
    ImGui::Text("slices %d over view depth %.2f .. %.2f (%s)", slices_drawn_, near_, far_,
                bound_() ? "the cone's" : "the whole view");
    ImGui::Text("slice fragments passed %s", countText(passed_).c_str());
  }

  void report(JsonWriter& json) const override {
    json.value("air_depth_near", near_);
    json.value("air_depth_far", far_);
    json.value("air_step", step_);
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
    far_ = std::min(far_, f.scene.camera.far);
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

  void drawSlices(Frame& f, const glm::mat4& cone) {
    drawSlicesTimed(f, cone);
    // Fragments the slices rasterized (llvmpipe counts them before any test), and of those
    // the ones shaded: only those that passed the depth test when it runs first.
    if (const PassWork* work = f.measure.frameWork("air")) {
      const std::optional<long long> rasterized = work->fragment_invocations;
      const std::optional<long long> shaded = early_reject_() ? passed_ : rasterized;
      f.measure.count("air_fragments_shaded", shaded);
      f.measure.count("air_fragments_skipped",
                      rasterized && shaded ? std::optional(*rasterized - *shaded) : std::nullopt);
    }
  }

  void drawSlicesTimed(Frame& f, const glm::mat4& cone) {
    auto timing = f.measure.pass("air");
    slices_drawn_ = slices_();
    sliceBounds(f, cone, slices_drawn_);
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
  }

  ShadowMap map_;
  ProgramVariants room_, slice_programs_;
  IntParam slices_;
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
  int slices_drawn_ = 0;
  float near_ = 0.0f, far_ = 0.0f, step_ = 0.0f;
  std::optional<long long> passed_ = 0;  // empty: this context cannot count them
};

SHADOWS_LESSON(Atmospherics);

}  // namespace shadows
