// Lesson 02: the slide projector (seed 004 "What is projective texturing?" to "Watch out
// for reverse projection!"; seed 000 "About Projective Texturing" and "Careful about Back
// Projecting Shadow Maps").
//
//   Each vertex gets (s, t, r, q) = B * P_projector * V_projector * M * p; textureProj
//   looks the slide up at (s/q, t/q). Behind the projector q < 0 and the division mirrors
//   the slide back into the scene: reverse projection, with seed 000's fixes to choose.
//
// Lesson 03 uses this very matrix with a depth map in place of the slide.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "core/image.hpp"
#include "core/json.hpp"
#include "lesson/lesson.hpp"

namespace shadows {

namespace {

// The built-in slide: a checkerboard in a yellow frame, a red arrow pointing up and a green
// square top left, so a mirrored (the square moves right) or a turned (the arrow points
// down) projection shows at once.
Image makeSlide(int n) {
  Image image{n, n, std::vector<std::uint8_t>(static_cast<size_t>(n) * n * 4)};
  for (int y = 0; y < n; ++y) {  // rows bottom-up, as GL and image.hpp keep them
    for (int x = 0; x < n; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(n);
      const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(n);
      glm::vec3 c = (static_cast<int>(u * 8) + static_cast<int>(v * 8)) % 2 == 0
                        ? glm::vec3(0.95f, 0.93f, 0.85f)
                        : glm::vec3(0.25f, 0.45f, 0.85f);
      if (std::min({u, v, 1 - u, 1 - v}) < 0.035f) c = {1.0f, 0.8f, 0.1f};
      const bool shaft = std::abs(u - 0.5f) < 0.06f && v > 0.15f && v < 0.6f;
      const bool head = v >= 0.6f && v < 0.88f && std::abs(u - 0.5f) < 0.8f * (0.88f - v);
      if (shaft || head) c = {0.9f, 0.12f, 0.1f};
      if (u > 0.1f && u < 0.3f && v > 0.7f && v < 0.9f) c = {0.1f, 0.75f, 0.2f};
      for (int k = 0; k < 3; ++k) {
        image.rgba[(static_cast<size_t>(y) * n + x) * 4 + k] =
            static_cast<std::uint8_t>(std::lround(255.0f * c[k]));
      }
      image.rgba[(static_cast<size_t>(y) * n + x) * 4 + 3] = 255;
    }
  }
  return image;
}

bool isBuiltin(const std::string& image) {
  return image == "builtin";
}

}  // namespace

class ProjectiveTexture final : public Lesson {
 public:
  std::string title() const override {
    return "Projective texturing: a slide projector with the texture matrix B P V M";
  }
  std::string seeds() const override {
    return "seed 004: projective texturing, reverse projection; seed 000: back-projection fixes";
  }
  // The slide lands where (s/q, t/q) falls; the depth r/q, and so near and far, never matter.
  std::vector<std::string> unusedSharedParams() const override {
    return {"light.near", "light.far"};
  }
  static constexpr View kTexcoords{"texcoords"};
  static constexpr View kSlide{"slide"};
  std::vector<View> debugViews() const override { return {kTexcoords, kSlide}; }

  void declare(Params& p) override {
    // Checked when set: a missing, broken or non-PNG file is bad input, named, before any frame.
    image_ = p.addString("projector.image", "builtin",
                         "builtin (a procedural slide) or the path of a PNG to project")
                 .checkedBy(checkPngParam);
    falloff_ = p.addFloat("falloff", 0, 0, 1,
                          "spotlight falloff: the slide fades over this part of the cone, 0 = off");
    q_test_ = p.addBool("fix.q_test", true, "no light where q <= 0, i.e. behind the projector");
    behind_ =
        p.addChoice("fix.behind", {"off", "skip", "clip"}, "skip",
                    "geometry behind the projector: skip whole objects, or clip at its plane");
    inset_ = p.addBool("inset", true, "show the slide in a corner");
  }

  void init() override {
    programs_ = ProgramVariants(lessonFile(LESSON_DIR, "projector.vert"),
                                lessonFile(LESSON_DIR, "projector.frag"));
  }

  void render(Frame& f) override {
    loadSlide(image_());
    // The projector is the light: its frustum takes the slide's aspect, so nothing stretches.
    const LightFrustum frustum =
        f.light.frustum(static_cast<float>(slide_.width()) / static_cast<float>(slide_.height()));
    const glm::mat4 projection = lightProjection(frustum);
    // Only its frustum is counted; near and far do not bound the slide, so the counted frustum
    // runs from the light to beyond the scene (x and y as the projection's).
    LightFrustum counted = frustum;
    counted.near = frustum.directional ? -1e4f : 1e-3f;
    counted.far = 1e4f;
    f.light_view_projection = lightProjection(counted) * f.light.view;
    axis_ = f.light.direction;
    const glm::vec4 projector_plane{axis_, -glm::dot(axis_, f.light.position)};
    texture_matrix_ = shadowTextureMatrix(projection, f.light.view);  // B P V
    projector_plane_ = projector_plane;
    half_angle_ = glm::radians(0.5f * frustum.fov);
    extent_ = frustum.extent;

    const float grey = f.shows(views::kVisibility) ? 0.0f : 0.13f;  // visibility: 0, not counted
    f.clearTarget(glm::vec3(grey, grey, grey * 1.2f));
    if (f.shows(kSlide)) {
      f.drawImageInset(slide_, /*fullscreen=*/true);
      return;
    }
    slide_.bind(0);
    {  // Pass 1: ambient light on everything (or the texcoords view).
      auto timing = f.measure.pass("ambient", /*countPassed=*/true);
      const Program& ambient = projectorProgram(f, 0);
      ambient.set("uClip", 0);
      f.drawObjects(ambient, Objects::All);
    }
    if (f.shows(kTexcoords)) return;
    projectorPass(f, projector_plane);
    if (!f.shows(views::kVisibility) && inset_()) f.drawImageInset(slide_);
  }

  void panel(Frame& f) override {
    ImGui::Text("slide: %s, %dx%d", loaded_.c_str(), slide_.width(), slide_.height());
    if (f.light.directional) {
      ImGui::TextWrapped(
          "parallel projector: q = 1 everywhere, so the q test cannot see what "
          "is behind it; falloff or fix.behind can");
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "Where a projector with no depth test is right",
             .goal = "A slide projector compares no depths: its light goes through the casters "
                     "onto what they should shadow, 7.3 % false lit from the preset's light. "
                     "Move the projector (it keeps aiming at the scene's centre) until false lit "
                     "is 0.5 % or less.",
             .setup = {"scene=torus_pyramid"},
             .allowed = {"light.pos"},
             .figures = {{"/error/false_lit_pct", "false lit %", B::AtMost, 0.5}},
             .hint = "The error is every surface the projector lights through a caster. From "
                     "which point does no surface you can see hide behind another?"},
            {.title = "Don't draw what lies behind the projector (seed 000)",
             .goal = "The projector sits low behind the sphere, pointing up; the q test hides "
                     "the mirrored copy pixel by pixel, but the projector pass still draws all 4 "
                     "objects, the sphere that lies wholly behind it too. Draw at most 3, "
                     "without darkening what it lights (false shadow 0.05 % or less).",
             .setup = {"light.pos=0.6,0.3,0.6", "light.target=0.6,2.5,-2.4", "light.fov=80",
                       "fix.behind=off"},
             .allowed = {"fix.behind", "falloff"},
             .figures = {{"/counters/projector/draw_calls", "projector draw calls", B::AtMost, 3},
                         {"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.05}},
             .hint = "The q test works per pixel, a clip plane per triangle. Kilgard: \"simply "
                     "avoid drawing geometry behind the light\"."}};
  }

  void report(JsonWriter& json) const override {
    json.value("slide", loaded_);
    json.beginArray("slide_size");
    json.value("", slide_.width());
    json.value("", slide_.height());
    json.endArray();
    json.value("objects_skipped_behind", skipped_);
  }

 private:
  // Pass 2: the projector's light, added on the same surfaces (depth EQUAL). Seed 000:
  // "simply avoid drawing geometry behind the light" (skip), or a clip plane (clip).
  void projectorPass(Frame& f, const glm::vec4& projector_plane) {
    auto timing = f.measure.pass("projector");
    const std::string& behind = behind_.name();
    PassState add;
    add.blend = true;
    add.blend_dst = GL_ONE;  // the projector's light adds to the ambient
    add.depth_func = GL_EQUAL;
    add.depth_write = false;
    // Each pixel takes the projector's light once: the first fragment to pass marks the
    // stencil, any other at that pixel (clip's LEQUAL lets a nearly coincident back face
    // through at silhouettes) is rejected.
    add.stencil_test = true;
    add.stencil_func = GL_EQUAL;
    add.stencil_ref = 0;
    add.stencil_pass = GL_INCR;
    if (behind == "clip") {
      // Clipping makes new vertices whose depths are not bit-identical to pass 1's, so the
      // cut triangles would fail an EQUAL test: compare LEQUAL, nudged toward the eye.
      add.clip_plane = true;
      add.polygon_offset = true;
      add.offset_factor = add.offset_units = -1.0f;
      add.depth_func = GL_LEQUAL;
    }
    add.apply();
    const Program& program = projectorProgram(f, 1);
    program.set("uClip", behind == "clip" ? 1 : 0);
    skipped_ = 0;
    for (size_t i = 0; i < f.scene.objects.size(); ++i) {
      if (behind == "skip" && entirelyBehind(f.scene.objects[i], projector_plane)) {
        ++skipped_;
        continue;
      }
      f.drawObject(program, i);
    }
    f.measure.count("skipped_behind_projector", skipped_);
    PassState{}.apply();
  }

  // Uploads the slide when the parameter names another one. Its border is black: outside
  // the slide the projector sends no light.
  void loadSlide(const std::string& path) {
    const std::string name = isBuiltin(path) ? "builtin" : path;
    if (name == loaded_ && slide_.id() != 0) return;
    const Image image = name == "builtin" ? makeSlide(256) : readPng(path);
    slide_ = Texture::color(image.width, image.height, GL_RGBA8);
    slide_.upload(GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    slide_.setWrap(GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
    slide_.setBorder(glm::vec4(0, 0, 0, 1));
    loaded_ = name;
  }

  static bool entirelyBehind(const SceneObject& object, const glm::vec4& plane) {
    const Bounds b = object.worldBounds();
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 c{(corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                        (corner & 4) ? b.max.z : b.min.z};
      if (glm::dot(plane, glm::vec4(c, 1.0f)) > 0.0f) return false;
    }
    return true;
  }

  // The slide itself, over the whole target or in the bottom-right corner.
  // The pass's variant (issue 56: the view, the pass and a falloff of 0 are compiled in, not
  // branched on per fragment), with the uniforms both passes share.
  const Program& projectorProgram(const Frame& f, int pass) {
    const Program& p = programs_.get(
        {f.viewDefines(), define("PASS", pass), feature("SPOT_FALLOFF", falloff_() > 0.0f)});
    p.set("uSlide", 0);
    p.set("uViewProjection", f.projection * f.view);
    p.set("uTextureMatrix", texture_matrix_);
    p.set("uProjectorPlane", projector_plane_);
    p.set("uQTest", q_test_() ? 1 : 0);
    p.set("uFalloff", falloff_());
    p.set("uHalfAngle", half_angle_);
    p.set("uExtent", extent_);
    p.set("uAxis", axis_);
    f.setLightingUniforms(p, 0.0f);
    return p;
  }

  ProgramVariants programs_;
  glm::mat4 texture_matrix_{1.0f};
  glm::vec4 projector_plane_{0.0f};
  glm::vec3 axis_{0.0f};
  float half_angle_ = 0.0f, extent_ = 0.0f;
  Texture slide_;
  std::string loaded_;
  StringParam image_;
  FloatParam falloff_;
  BoolParam q_test_, inset_;
  ChoiceParam<> behind_;
  long long skipped_ = 0;
};

SHADOWS_LESSON(ProjectiveTexture);

}  // namespace shadows
