// Lesson 01: Blinn's projected planar shadows (seed 001 "Planar Projected Shadows" to
// "Generalized Shadows"; seed 003 slides 14-21, "Projection Shadows" to "Projection Shadow
// Summary").
//
//   Draw the scene lit. Then draw every caster again through one 4x4 matrix that flattens
//   it onto the receiver plane along the light's rays, M = (P.L) I - L P^T, in a dark
//   colour blended over the receiver. The stencil buffer (003 slide 19) keeps each
//   receiver pixel darkened at most once, and only where the receiver is the visible
//   surface.
//
// Every fix is one --set away, and so is the artifact it removes.
#include <imgui.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "core/json.hpp"
#include "lesson/lesson.hpp"

namespace shadows {

class ProjectedPlanar final : public Lesson {
 public:
  std::string title() const override {
    return "Projected planar shadows: flatten the casters onto the plane, blend them dark";
  }
  std::string seeds() const override {
    return "seed 001: Planar Projected Shadows .. Generalized Shadows; seed 003: slides 14-21";
  }
  // A planar shadow needs only the light's position (or direction): no frustum, no map.
  std::vector<std::string> unusedSharedParams() const override {
    return {"light.fov", "light.extent", "light.near", "light.far"};
  }
  static constexpr View kOverdraw{"overdraw"};
  std::vector<View> debugViews() const override {
    // how many shadow triangles land on each pixel
    return {kOverdraw};
  }

  void declare(Params& p) override {
    tilt_ = p.addFloat("plane.tilt", 0, -40, 40, "tilt the receiver (the floor) about x, degrees");
    offset_ = p.addFloat("plane.offset", 0, -1, 1.5f, "move the receiver along its normal");
    dimming_ =
        p.addFloat("dimming", 0.4f, 0, 1, "light left under a shadow: the blend keeps this much");
    fix_receiver_ =
        p.addBool("fix.receiver", true,
                  "stencil: darken only where the receiver is seen (off: spills past its edge)");
    fix_once_ =
        p.addBool("fix.once", true,
                  "stencil: darken each pixel once (off: overlapping triangles blend twice)");
    fix_offset_ =
        p.addBool("fix.offset", true,
                  "polygon offset toward the eye (off, with fix.receiver off: z-fighting)");
    fix_clip_ =
        p.addBool("fix.clip", true,
                  "clip casters at the plane (off: parts behind the receiver cast false shadows)");
    fix_homogeneous_ =
        p.addBool("fix.homogeneous", true,
                  "leave w to the clipper (off: divide in the shader; above the light inverts)");
  }

  void init() override {
    scene_programs_ =
        ProgramVariants(lessonFile(LESSON_DIR, "scene.vert"), lessonFile(LESSON_DIR, "scene.frag"));
    shadow_program_ =
        Program(lessonFile(LESSON_DIR, "shadow.vert"), lessonFile(LESSON_DIR, "shadow.frag"));
  }

  void render(Frame& f) override {
    const int mode = f.shows(views::kVisibility) ? 1 : f.shows(kOverdraw) ? 2 : 0;
    const bool projecting = placeReceiver(f);

    // 1. The scene, lit (slide 17: "render scene, full lighting"). The receiver comes last
    //    and marks stencil = 1 where it is the visible surface (slide 19).
    {
      auto timing = f.measure.pass("scene", /*countPassed=*/true);
      f.clearTarget(mode == 0 ? Frame::kSky : glm::vec3(0.0f));
      const Program& scene = scene_programs_.get({f.viewDefines()});
      scene.set("uViewProjection", f.projection * f.view);
      f.setLightingUniforms(scene, 1.0f);
      for (size_t i = 0; i < f.scene.objects.size(); ++i) {
        if (i != receiver_) f.drawObject(scene, i);
      }
      PassState mark;
      mark.stencil_test = true;
      mark.stencil_ref = 1;
      mark.stencil_pass = fix_receiver_() ? GL_REPLACE : GL_KEEP;
      mark.apply();
      if (receiver_ < f.scene.objects.size()) f.drawObject(scene, receiver_);
    }
    if (projecting) drawShadows(f, mode);
    PassState{}.apply();
  }

  void panel(Frame& f) override {
    // What cannot cast, and why, in a corner of its own where it cannot scroll away.
    if (notes_.empty()) return;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(f.width) - 8.0f, 8.0f), ImGuiCond_Always,
                            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("what cannot cast", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 20.0f);
    for (const auto& note : notes_) ImGui::Bullet(), ImGui::TextWrapped("%s", note.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "The shadow fights the floor (slides 13 and 18)",
             .goal = "Without the stencil mark the flattened shadow is depth-tested against the "
                     "floor it lies in, and loses about half the time: 3.1 % false lit. Bring "
                     "false lit to 0.1 % or less, and false shadow to 0.15 % or less, moving "
                     "only the fixes.",
             .setup = {"fix.receiver=false", "fix.offset=false"},
             .allowed = {"fix.receiver", "fix.offset", "fix.once", "fix.clip", "dimming"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.15},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.1}},
             .hint = "The shadow and the floor have the same depth, so the depth test flips a "
                     "coin. Lift the shadow toward the eye (slide 13), or let the stencil say "
                     "where the floor is seen and skip the depth test (slide 19)."},
            {.title = "A light below the casters' tops: the anti-shadow",
             .goal = "The light is at height 1.1, under the torus's top (1.9) and the "
                     "pyramid's (1.6), and the shader divides by w itself: the parts above the "
                     "light flip through it onto the floor, 68 % false shadow. Bring false "
                     "shadow to 0.05 % or less, keeping false lit at 2.8 % or less (the 2.3 % no "
                     "planar shadow can fix), without moving the light.",
             .setup = {"light.pos=2.5,1.1,2.5", "fix.homogeneous=false"},
             .allowed = {"fix.homogeneous", "fix.clip", "fix.receiver", "fix.once", "dimming"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.05},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 2.8}},
             .hint = "w = P.L - P.v is negative above the light. Divided in the shader, those "
                     "points land on the other side of the light; what does the clipper do "
                     "with w < 0?"},
            {.title = "Casters behind the receiver (slide 21)",
             .goal = "The floor is raised to 1 and buries the sphere and the feet of the torus "
                     "and the pyramid, which still cast up through it: 4.3 % false shadow. "
                     "Bring false shadow to 0.05 % or less without moving the floor.",
             .setup = {"plane.offset=1", "fix.clip=false"},
             .allowed = {"fix.clip", "fix.receiver", "fix.once", "fix.homogeneous", "dimming"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.05}},
             .hint = "M sends a point under the plane onto the plane too. Which part of a "
                     "caster should never reach the projection?"}};
  }

  void report(JsonWriter& json) const override {
    json.beginArray("receiver_plane");
    for (int k = 0; k < 4; ++k) json.value("", plane_[k]);
    json.endArray();
    json.value("casters_drawn", casters_drawn_);
    json.beginArray("notes");
    for (const auto& note : notes_) json.value("", note);
    json.endArray();
  }

 private:
  // The receiver is the scene's floor (its receiver-only plane), tilted and moved by the
  // sliders. The runner moves the object itself, so the truth sees the same plane. Returns
  // whether anything can be projected, and says why not in notes_.
  bool placeReceiver(Frame& f) {
    notes_.clear();
    casters_drawn_ = 0;
    receiver_ = f.scene.objects.size();
    for (size_t i = 0; i < f.scene.objects.size(); ++i) {
      const SceneObject& o = f.scene.objects[i];
      if (o.receiver && !o.caster) receiver_ = i;
    }
    if (receiver_ == f.scene.objects.size()) {
      notes_.push_back("this scene has no receiver plane: nothing to project onto");
      return false;
    }
    // The preset's floor (a y-up plane), before our tilt.
    const glm::mat4& preset_model = f.runner.presetModel(receiver_);
    const glm::vec3 centre{preset_model[3]};
    const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), glm::radians(tilt_()), glm::vec3(1, 0, 0));
    const glm::vec3 normal{tilt * glm::vec4(0, 1, 0, 0)};
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), centre + offset_() * normal) * tilt *
                            glm::translate(glm::mat4(1.0f), -centre) * preset_model;
    f.runner.setObjectModel(receiver_, model);

    // P = (A, B, C, D) through the floor's centre; L homogeneous: w = 0 for a direction.
    plane_ = glm::vec4(normal, -glm::dot(normal, glm::vec3(model[3])));
    light_ = f.light.directional ? glm::vec4(-f.light.direction, 0.0f)
                                 : glm::vec4(f.light.position, 1.0f);
    if (glm::dot(plane_, light_) <= 1e-4f) {
      notes_.push_back(
          "the light is level with or behind the receiver plane: the plane is "
          "unlit and there is nothing to project");
      return false;
    }
    return true;
  }

  // Which casters can reach the plane: a point at or above the light's height (P.v >= P.L)
  // cannot, nor can one behind the receiver (P.v < 0). Skips wholly hopeless casters.
  bool canCast(const Frame& f, size_t index) {
    const SceneObject& o = f.scene.objects[index];
    float lowest = 1e30f, highest = -1e30f;
    for (const Vertex& v : o.mesh.vertices) {
      const float d = glm::dot(plane_, o.model * glm::vec4(v.position, 1.0f));
      lowest = std::min(lowest, d), highest = std::max(highest, d);
    }
    const float light_height = glm::dot(plane_, light_);  // for a point light
    const bool clip = fix_clip_();
    if (light_.w > 0.0f && lowest >= light_height) {
      notes_.push_back(o.name +
                       ": entirely at or above the light, it cannot reach the plane: "
                       "skipped");
      return false;
    }
    if (clip && highest <= 0.0f) {
      notes_.push_back(o.name + ": entirely behind the receiver: skipped");
      return false;
    }
    if (light_.w > 0.0f && highest >= light_height) {
      notes_.push_back(o.name + (fix_homogeneous_()
                                     ? ": reaches above the light; the clipper cuts it at w = 0"
                                     : ": reaches above the light; dividing by w in the shader "
                                       "flips that part into an anti-shadow"));
    }
    if (lowest < 0.0f) {
      notes_.push_back(o.name + (clip ? ": partly behind the receiver; clipped at the plane"
                                      : ": partly behind the receiver; casts a false shadow"));
    }
    return true;
  }

  // 2. Each caster again, through M, in black (slide 17: "render selected shadow caster with
  //    framebuffer blending enabled"). The fixes are GL state.
  void drawShadows(Frame& f, int mode) {
    auto timing = f.measure.pass("shadow");
    const bool receiver = fix_receiver_(), once = fix_once_();
    // Slide 19: draw only where stencil = 1 (the receiver), and zero it on the way, so every
    // receiver pixel is touched at most once. Without the receiver mark, "once" still works
    // on a stencil that starts at 0.
    PassState state;
    state.stencil_test = receiver || once;
    state.stencil_func = GL_EQUAL;
    state.stencil_ref = receiver ? 1 : 0;
    state.stencil_pass = !once ? GL_KEEP : receiver ? GL_ZERO : GL_INCR;
    // With the stencil mark the receiver is known to be the visible surface there: no depth
    // test at all (slide 19). Without it, the shadow lies exactly in the plane and needs an
    // offset toward the eye to win the depth test (slide 13: "elevate above hit polygon").
    state.depth_test = !receiver;
    state.depth_write = false;
    state.polygon_offset = fix_offset_();
    state.offset_factor = -1.0f, state.offset_units = -2.0f;
    state.clip_plane = fix_clip_();
    shadow_program_.set("uClip", fix_clip_() ? 1 : 0);
    state.blend = true;
    if (mode == 2) {
      state.blend_dst = GL_ONE;  // overdraw: each layer adds the same amount
      shadow_program_.set("uShadowColor", glm::vec4(0.3f, 0.15f, 0.0f, 1.0f));
    } else {
      // dst = dst * (1 - a): a = 1 - dimming, and the shadow term alone is 0 (visibility).
      state.blend_src = GL_SRC_ALPHA, state.blend_dst = GL_ONE_MINUS_SRC_ALPHA;
      const float a = mode == 1 ? 1.0f : 1.0f - dimming_();
      shadow_program_.set("uShadowColor", glm::vec4(0.0f, 0.0f, 0.0f, a));
    }
    state.apply();
    shadow_program_.set("uShadowMatrix", planarShadowMatrix(plane_, light_));
    shadow_program_.set("uViewProjection", f.projection * f.view);
    shadow_program_.set("uPlane", plane_);
    shadow_program_.set("uDivide", fix_homogeneous_() ? 0 : 1);
    long long skipped = 0;
    for (size_t i = 0; i < f.scene.objects.size(); ++i) {
      if (!f.scene.objects[i].caster || i == receiver_) continue;
      if (!canCast(f, i)) {
        ++skipped;
        continue;
      }
      f.drawObject(shadow_program_, i);
      ++casters_drawn_;
    }
    f.measure.count("skipped_casters", skipped);
  }

  ProgramVariants scene_programs_;
  Program shadow_program_;
  size_t receiver_ = 0;
  glm::vec4 plane_{0.0f}, light_{0.0f};
  long long casters_drawn_ = 0;
  std::vector<std::string> notes_;
  FloatParam tilt_, offset_, dimming_;
  BoolParam fix_receiver_, fix_once_, fix_offset_, fix_clip_, fix_homogeneous_;
};

SHADOWS_LESSON(ProjectedPlanar);

}  // namespace shadows
