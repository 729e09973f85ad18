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

#include "app.hpp"
#include "json.hpp"

namespace shadows {

class ShadowMapBasic final : public Lesson {
 public:
  std::string title() const override { return "Shadow map: depth from the light, then compare"; }
  std::string seeds() const override {
    return "seed 000: The Shadow Mapping Concept .. Shadow Map Operation; seed 001: Shadow Maps";
  }
  std::vector<std::string> debugViews() const override {
    // Kilgard's visualizations (seed 000, "Visualizing the Shadow Mapping Technique").
    return {"light_view", "light_depth", "projected_depth", "light_distance", "compare"};
  }

  void declare(Params& p) override {
    constexpr auto kMap = kDirtyShadowMap | kDirtyResources;
    p.addInt("shadow.size", 1024, 64, 4096, "shadow map width in texels", kMap).logarithmic = true;
    p.addInt("shadow.height", 0, 0, 4096, "shadow map height (0 = square)", kMap);
    p.addChoice("shadow.format", {"16", "24", "32f"}, "24", "depth bits of the map", kMap);
    p.addChoice("shadow.filter", {"nearest", "linear"}, "nearest",
                "linear = the hardware 2x2 compare filter (shadows are not averaged depths)");
    p.addBool("shadow.fit", false, "fit the light's near/far to the casters' bounds",
              kDirtyShadowMap);
    p.addBool("shadow.cache", true, "re-render the map only when the light or a caster changed",
              kDirtyShadowMap);
    p.addFloat("dimming", 0.4f, 0.0f, 1.0f, "light left in shadow: dimming + (1-dimming)*shade");
    p.addBool("inset", true, "show the depth map in a corner");
  }

  void init() override {
    depth_program_ =
        Program(lessonFile(LESSON_DIR, "depth.vert"), lessonFile(LESSON_DIR, "depth.frag"));
    eye_program_ =
        Program(lessonFile(LESSON_DIR, "scene.vert"), lessonFile(LESSON_DIR, "scene.frag"));
    // A sampler object reads the same depth texture raw (no compare) for the debug views.
    glGenSamplers(1, &raw_sampler_);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  ~ShadowMapBasic() override {
    if (raw_sampler_ != 0) glDeleteSamplers(1, &raw_sampler_);
  }

  void render(Frame& f) override {
    Params& p = f.params;
    const int width = p.at("shadow.size").i();
    const int height = p.at("shadow.height").i() > 0 ? p.at("shadow.height").i() : width;
    if (p.consume(kDirtyResources) || !shadow_map_.id()) createShadowMap(f, width, height);

    // The light's frustum; optionally fitted to the casters so no depth range is wasted.
    LightFrustum frustum = f.light.frustum(static_cast<float>(width) / static_cast<float>(height));
    if (p.at("shadow.fit").b()) {
      fitNearFar(f.light.view, f.scene.bounds(/*castersOnly=*/true), frustum.directional,
                 frustum.near, frustum.far);
    }
    near_ = frustum.near, far_ = frustum.far;
    const glm::mat4 light_projection = lightProjection(frustum);
    const glm::mat4 light_view_projection = light_projection * f.light.view;
    f.light_view_projection = light_view_projection;

    // Pass 1, only when something it depends on changed (a static frame renders no map).
    const bool map_stale = p.consume(kDirtyShadowMap) || !p.at("shadow.cache").b();
    f.measure.count("shadow_map_renders", map_stale ? 1 : 0);
    if (map_stale) {
      auto timing = f.measure.pass("shadow");
      shadow_fbo_->bind();
      glViewport(0, 0, width, height);
      glClear(GL_DEPTH_BUFFER_BIT);
      depth_program_.set("uLightViewProjection", light_view_projection);
      // Only casters, and only those inside the light frustum, go into the map.
      f.drawObjects(depth_program_, Objects::Casters, &light_view_projection);
    }

    // Pass 2 from the eye (or, for the first of Kilgard's views, from the light).
    const std::string& mode = f.mode;
    if (mode == "light_depth") {
      f.bindTarget();
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      f.drawDepthInset(shadow_map_, near_, far_, !frustum.directional, /*fullscreen=*/true);
      return;
    }
    auto timing = f.measure.pass("eye");
    f.bindTarget();
    glClearColor(0.55f, 0.62f, 0.72f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    shadow_map_.setFilter(p.at("shadow.filter").is("linear") ? GL_LINEAR : GL_NEAREST);
    shadow_map_.bind(0);
    shadow_map_.bind(1);
    glBindSampler(1, raw_sampler_);
    const bool from_light = mode == "light_view";
    eye_program_.set("uViewProjection", from_light ? light_view_projection : f.projection * f.view);
    eye_program_.set("uShadowMatrix", shadowTextureMatrix(light_projection, f.light.view));
    eye_program_.set("uShadowMap", 0);
    eye_program_.set("uShadowDepth", 1);
    eye_program_.set("uMode", modeIndex(mode));
    eye_program_.set("uLightNear", near_);
    eye_program_.set("uLightFar", far_);
    eye_program_.set("uLightPerspective", frustum.directional ? 0 : 1);
    f.setLightingUniforms(eye_program_, p.at("dimming").f());
    if (from_light) eye_program_.set("uEye", f.light.position);
    f.drawObjects(eye_program_, Objects::All);
    glBindSampler(1, 0);
    if (p.at("inset").b() && mode != "visibility") {
      f.drawDepthInset(shadow_map_, near_, far_, !frustum.directional);
    }
  }

  void report(JsonWriter& json) const override {
    json.value("light_near_used", near_);
    json.value("light_far_used", far_);
  }

  void panel(Frame& f) override {
    ImGui::Text("light near %.3f  far %.3f%s", near_, far_,
                f.params.at("shadow.fit").b() ? " (fitted to casters)" : "");
  }

 private:
  void createShadowMap(Frame& f, int width, int height) {
    const std::string& format = f.params.at("shadow.format").choice();
    shadow_map_ = Texture::depth(width, height, format == "16" ? 16 : format == "24" ? 24 : 32);
    shadow_map_.setCompare(true);  // sampler2DShadow: the texture unit does the A/B compare
    shadow_fbo_ = std::make_unique<Framebuffer>();
    shadow_fbo_->attachDepth(shadow_map_);
    shadow_fbo_->check();
    f.params.markDirty(kDirtyShadowMap);
  }

  static int modeIndex(const std::string& mode) {
    if (mode == "visibility") return 1;
    if (mode == "projected_depth") return 2;
    if (mode == "light_distance") return 3;
    if (mode == "compare") return 4;
    return 0;  // shaded, light_view
  }

  Program depth_program_, eye_program_;
  Texture shadow_map_;
  std::unique_ptr<Framebuffer> shadow_fbo_;
  GLuint raw_sampler_ = 0;
  float near_ = 0, far_ = 0;
};

SHADOWS_LESSON(ShadowMapBasic);

}  // namespace shadows
