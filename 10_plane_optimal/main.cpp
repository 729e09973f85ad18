// Lesson 10: where the map's texels land (seed 002, "Playing with Projection Matrices" and
// "Theory and Analysis"; seed 003, "Problem: Aliasing Artifacts").
//
//   The map is still Williams' two passes (lesson 03); what changes is the matrix M that takes
//   the world to the map, and with it how many texels each screen pixel gets:
//   uniform        the light's frustum, as lessons 03-08 use it;
//   focused        that frustum cropped to what the eye sees (view frustum, scene, light);
//   lispsm         Wimmer et al.'s perspective warp along the view direction, free parameter n;
//   plane_optimal  Chong and Gortler: on a plane of interest the light image IS the camera
//                  image, so with a map the size of the frame each pixel there gets one texel.
//   A configuration a projection cannot handle falls back to uniform and says why.
//   Depth replacement (TSM, cited by 002): the map stores the light's linear depth instead of
//   the warped z/w, so the warp changes sampling and nothing else.
#include <imgui.h>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "math/warped_projection.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

enum class Projection { Uniform, Focused, Lispsm, PlaneOptimal };
enum class PlaneChoice { Floor, Wall, Table };

class PlaneOptimal final : public Lesson {
 public:
  std::string title() const override {
    return "Where the texels land: uniform, focused, LiSPSM and plane-optimal projections";
  }
  std::string seeds() const override {
    return "seed 002: Playing with Projection Matrices, Theory and Analysis; seed 003: Problem: "
           "Aliasing Artifacts";
  }
  static constexpr View kLightView{"light_view"};
  static constexpr View kRegions{"regions"};
  std::vector<View> debugViews() const override { return {views::kAliasing, kLightView, kRegions}; }
  std::vector<std::string> scenes() const override {
    return {"dueling", "strategy", "receding", "torus_pyramid", "grazing", "cubes"};
  }

  void declare(Params& p) override {
    map_.declare(p);
    projection_ =
        p.addChoice("light.projection", {"uniform", "focused", "lispsm", "plane_optimal"},
                    "plane_optimal", "the matrix from the world to the map", kDirtyShadowMap);
    lispsm_n_ = p.addFloat("lispsm.n", 1.0f, 0.05f, 20.0f,
                           "LiSPSM's free parameter: the warp's near distance, times Wimmer's "
                           "n_opt (large: uniform, small: strong warp)",
                           kDirtyShadowMap)
                    .logScale();
    lispsm_n_.param().inactive = [](const Params& ps) -> std::string {
      return ps.at("light.projection").is("lispsm") ? "" : "only lispsm has it";
    };
    plane_ =
        p.addChoice("plane", {"floor", "wall", "table"}, "floor",
                    "plane_optimal's plane of interest (its region: the object)", kDirtyShadowMap);
    replace_ = p.addBool("depth.replace", true,
                         "TSM's depth replacement: store the light's linear depth, not the "
                         "warped z/w",
                         kDirtyShadowMap);
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
  }

  void init() override {
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    depth_programs_ =
        ProgramVariants(lessonFile(LESSON_DIR, "depth.vert"), lessonFile(LESSON_DIR, "depth.frag"));
  }

  void render(Frame& f) override {
    bool stale = map_.prepare(f);
    chooseProjection(f);
    stale = map_.warp(used_) || stale;
    map_.sampledBy(f);  // through the chosen matrix; the truth counts in the light's frustum
    // Pass 1: the casters' back faces (lesson 04's default), through the chosen matrix.
    const std::vector<std::string> depth_defines = define("DEPTH_REPLACE", replace_() ? 1 : 0);
    if (stale && !map_.off()) {
      const Program& d = depth_programs_.get({depth_defines});
      d.set("uDepthPlane", depth_plane_);
      map_.renderCasters(f, d, ShadowMap::backFacesBias(0.0f, 0.0f));
    }

    // Pass 2 from the eye (light_view: from the light, through the same matrix).
    auto timing = f.measure.pass("eye", /*countPassed=*/true);
    f.clearTarget();
    map_.texture().bind(0);
    const bool from_light = f.shows(kLightView);
    const Program& e =
        eye_programs_.get({f.viewDefines(), depth_defines, define("SHADOW_OFF", map_.off())});
    e.set("uViewProjection", from_light ? used_ : f.projection * f.view);
    e.set("uShadowMatrix", map_.textureMatrix());
    e.set("uShadowMap", 0);
    e.set("uDepthPlane", depth_plane_);
    e.set("uLight", light_);
    e.set("uPlane", glm::vec4(plane_space_.n, plane_space_.d));
    e.set("uHasPlane", plane_index_ >= 0 ? 1 : 0);
    e.set("uPlaneObject", plane_index_);
    e.set("uPlaneInverse", plane_inverse_);
    e.set("uPlaneHalf", plane_half_);
    e.set("uCamera", camera_);
    f.setLightingUniforms(e, dimming_());
    if (from_light) e.set("uEye", f.light.position);
    f.drawObjects(e, Objects::All);
    if (!f.shows(views::kVisibility)) map_.drawInset(f);
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {
        {.title = "One texel per pixel on the floor, light and eye face to face",
         .goal = "Through the light's own frustum the dueling frusta's floor gets 0.42 "
                 "texels per pixel along its least-sampled axis and 1.23 along its most, "
                 "and 89 % of the pixels are under-sampled. Give the floor one texel per "
                 "pixel (the medians of both axes between 0.95 and 1.05) with at most 1 % "
                 "of the pixels under-sampled, at 640x480.",
         .setup = {"light.projection=uniform"},
         .allowed = {"light.projection", "lispsm.n", "shadow.size", "shadow.height"},
         .figures = {{"/plane/texels_per_pixel/min_axis/median",
                      "floor texels per pixel, least axis", B::AtLeast, 0.95},
                     {"/plane/texels_per_pixel/max_axis/median",
                      "floor texels per pixel, most axis", B::AtMost, 1.05},
                     {"/undersampled_pct", "under-sampled %", B::AtMost, 1.0}},
         .hint = "No map size gives the light's own frustum texels the shape of the eye's "
                 "pixels. Which projection makes the map's image of the floor the camera's "
                 "picture of it, and how many texels must the map then hold?"},
        {.title = "Sampling is not depth",
         .goal = "On the receding floor the plane-optimal map, the picture's size, gives "
                 "the floor one texel per pixel, but a directional light leaves it no "
                 "depth: 5.5 % false shadow, 5.2 % false lit. Keep the floor's one texel "
                 "per pixel (least axis median 0.95 or more) and bring false shadow and "
                 "false lit both to 0.2 % or less.",
         .setup = {"scene=receding", "shadow.size=640", "shadow.height=480", "depth.replace=false"},
         .allowed = {"light.projection", "lispsm.n", "shadow.format", "depth.replace"},
         .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.2},
                     {"/error/false_lit_pct", "false lit %", B::AtMost, 0.2},
                     {"/plane/texels_per_pixel/min_axis/median",
                      "floor texels per pixel, least axis", B::AtLeast, 0.95}},
         .hint = "P L = 0: every point of a light ray lands on one texel with one z/w, "
                 "and no number of bits tells apart what is stored the same. The warp "
                 "should move texels and nothing else: what should the map store as "
                 "depth?"}};
  }

  void report(JsonWriter& json) const override {
    json.value("projection_used", used_name_);
    json.value("fallback_reason", fallback_);
    if (projection_() == Projection::Lispsm)
      json.value("lispsm_n_used", static_cast<double>(n_used_));
  }

  // Texels per pixel on the plane of interest (002's guarantee is about it alone).
  void reportPixels(JsonWriter& json, const PixelMeasures& m) const override {
    json.beginObject("plane");
    json.value("name", plane_.name());
    json.value("in_scene", plane_index_ >= 0);
    if (m.texels != nullptr && plane_index_ >= 0) {
      writeTexelsPerPixel(json, texelStats(*m.texels, plane_index_));
    }
    json.endObject();
  }

  // The error on the plane and in region II, where plane_optimal promises nothing (without a
  // plane, everything is region II).
  std::vector<ErrorRegion> errorRegions() const override {
    return {{"plane",
             [this](glm::vec4 p) {
               return plane_index_ >= 0 && static_cast<int>(p.w) == plane_index_;
             }},
            {"region_two", [this](glm::vec4 p) {
               return plane_index_ < 0 || !inRegionOne(glm::vec3(p), light_, plane_space_, camera_,
                                                       plane_inverse_, plane_half_);
             }}};
  }

  void panel(Frame&) override {
    ImGui::Text("projection used: %s", used_name_.c_str());
    if (!fallback_.empty()) ImGui::TextWrapped("fell back to uniform: %s", fallback_.c_str());
    if (projection_() == Projection::Lispsm) ImGui::Text("lispsm n = %.4g", n_used_);
  }

 private:
  // This frame's plane of interest (the named object's surface), the light as a homogeneous
  // point, the camera, and the matrix each projection gives, or uniform with the reason.
  void chooseProjection(const Frame& f) {
    const glm::mat4 uniform = map_.light().projection() * map_.light().view();
    camera_ = f.projection * f.view;
    light_ = f.light.directional ? glm::vec4(-glm::normalize(f.light.direction), 0.0f)
                                 : glm::vec4(f.light.position, 1.0f);
    // Linear depth along the light's axis, 0 at its near plane and 1 at its far plane.
    const LightFrustum& fr = map_.frustum();
    const glm::vec3 axis = glm::normalize(f.light.direction);
    depth_plane_ =
        glm::vec4(axis, -glm::dot(axis, f.light.position) - fr.near) / (fr.far - fr.near);
    findPlane(f);

    std::vector<HalfSpace> body = frustumHalfSpaces(camera_);
    const auto light_side = frustumHalfSpaces(uniform);
    body.insert(body.end(), light_side.begin(), light_side.end());
    const auto box = boxHalfSpaces(f.scene.bounds());
    body.insert(body.end(), box.begin(), box.end());
    const std::vector<glm::vec3> seen = convexVertices(body);

    Warp w{uniform, ""};
    n_used_ = 0.0f;
    switch (projection_()) {
      case Projection::Uniform:
        break;
      case Projection::Focused:
        w = focusedProjection(uniform, seen);
        break;
      case Projection::Lispsm:
        w = lispsmProjection(
            {uniform, f.eye, glm::vec3(glm::inverse(f.view)[2]) * -1.0f, seen, lispsm_n_()},
            &n_used_);
        break;
      case Projection::PlaneOptimal: {
        if (plane_index_ < 0) {
          w.fallback = "the scene has no " + plane_.name();
          break;
        }
        PlaneOptimalInput in;
        in.camera = camera_;
        in.eye = f.eye;
        in.light = light_;
        in.plane = plane_space_;
        // The plane's rectangle inside the view: its four edges, the plane itself, the frustum.
        std::vector<HalfSpace> poly = frustumHalfSpaces(camera_);
        for (const glm::vec4 edge :
             {glm::vec4(-1, 0, 0, plane_half_.x), glm::vec4(1, 0, 0, plane_half_.x),
              glm::vec4(0, 0, -1, plane_half_.y), glm::vec4(0, 0, 1, plane_half_.y)}) {
          // edge . (M^-1 p) >= 0 in the plane's own space is (M^-T edge) . p >= 0.
          const glm::vec4 world = glm::transpose(plane_inverse_) * edge;
          const float length = glm::length(glm::vec3(world));
          poly.push_back({glm::vec3(world) / length, world.w / length});
        }
        poly.push_back({plane_space_.n, plane_space_.d + 1e-4f});
        poly.push_back({-plane_space_.n, -plane_space_.d + 1e-4f});
        in.plane_in_view = convexVertices(poly);
        for (const SceneObject& o : f.scene.objects) {
          const Bounds b = o.worldBounds();
          for (int c = 0; c < 8; ++c) {
            in.depth_points.push_back(
                {c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y, c & 4 ? b.max.z : b.min.z});
          }
        }
        w = planeOptimalProjection(in);
        break;
      }
    }
    fallback_ = w.fallback;
    used_ = fallback_.empty() ? w.view_projection : uniform;
    used_name_ = fallback_.empty() ? projection_.name() : "uniform";
  }

  // The plane of interest: the object of that name, its surface y = 0 in its own space.
  void findPlane(const Frame& f) {
    plane_index_ = -1;
    const std::string name = plane_.name();
    for (size_t i = 0; i < f.scene.objects.size(); ++i) {
      const SceneObject& o = f.scene.objects[i];
      if (o.name != name) continue;
      plane_index_ = static_cast<int>(i);
      const glm::vec3 n =
          glm::normalize(glm::vec3(glm::transpose(glm::inverse(o.model)) * glm::vec4(0, 1, 0, 0)));
      const glm::vec3 origin = glm::vec3(o.model * glm::vec4(0, 0, 0, 1));
      plane_space_ = {n, -glm::dot(n, origin)};
      plane_inverse_ = glm::inverse(o.model);
      glm::vec2 half(0.0f);
      for (const Vertex& v : o.mesh.vertices) {
        half = glm::max(half, glm::abs(glm::vec2(v.position.x, v.position.z)));
      }
      plane_half_ = half;
      return;
    }
    plane_space_ = {};
    plane_inverse_ = glm::mat4(1.0f);
    plane_half_ = glm::vec2(0.0f);
  }

  ShadowMap map_;
  ChoiceParam<Projection> projection_;
  ChoiceParam<PlaneChoice> plane_;
  FloatParam lispsm_n_, dimming_;
  BoolParam replace_;
  ProgramVariants eye_programs_, depth_programs_;
  glm::mat4 used_{1.0f}, camera_{1.0f}, plane_inverse_{1.0f};
  glm::vec4 light_{0.0f}, depth_plane_{0.0f};
  HalfSpace plane_space_;
  glm::vec2 plane_half_{0.0f};
  int plane_index_ = -1;
  float n_used_ = 0.0f;
  std::string used_name_ = "uniform", fallback_;
};

SHADOWS_LESSON(PlaneOptimal);

}  // namespace shadows
