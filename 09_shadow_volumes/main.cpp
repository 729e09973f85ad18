// Lesson 09: Crow's shadow volumes with the stencil buffer (seed 003 slides 22-50, "Shadow
// Volumes (Crow 1977)" to "Shadow Volume Issues"; seed 002 "additive light masking"; seed 000
// "Hybrid of Shadow Volumes and Shadow Mapping").
//
//   1. The scene with the light dimmed; it also fills the depth buffer (slide 34).
//   2. Clear the stencil, draw every caster's volume without colour or depth writes.
//      z-pass: front faces that pass the depth test increment, then back faces decrement.
//      z-fail (Carmack's reverse): back faces that fail increment first, then front faces
//      decrement; the volume then needs its light and dark caps (slides 39-46).
//   3. Light every pixel whose count is 0, blended additively.
//
// The volumes are extruded in the vertex shader to infinity (w = 0), so the eye's projection
// sends its far plane to infinity too (slide 45), or clamps depth (slide 50).
#include <imgui.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "core/json.hpp"
#include "gl/caps.hpp"
#include "lesson/lesson.hpp"
#include "math/shadow_math.hpp"
#include "math/shadow_volume.hpp"
#include "ray_count.hpp"

namespace shadows {

enum class Method { ZPass, ZFail, Auto };
enum class Far { Infinite, Finite, DepthClamp };
enum class Stencil { TwoPass, TwoSided };
enum class Combine { Additive, Modulative };

class ShadowVolumes final : public Lesson {
 public:
  std::string title() const override {
    return "Shadow volumes: count the volume faces in front of each pixel in the stencil";
  }
  std::string seeds() const override {
    return "seed 003: slides 22-50 (Shadow Volumes .. Shadow Volume Issues); seed 002: additive "
           "light masking";
  }
  static constexpr View kVolumes{"volumes"};
  static constexpr View kCount{"count"};
  static constexpr View kOverview{"overview"};
  std::vector<View> debugViews() const override { return {kVolumes, kCount, kOverview}; }
  // A volume reaches to infinity: no light frustum, no map.
  std::vector<std::string> unusedSharedParams() const override {
    return {"light.fov", "light.extent", "light.near", "light.far"};
  }
  std::vector<std::string> scenes() const override {
    std::vector<std::string> s = scenePresets();
    // And 11's omni bulb, as more casters crowd around it (bench: omni_volumes_vs_cube).
    s.insert(s.end(), {"eye_in_shadow", "fence", "bulb", "bulb_crowd", "bulb_throng"});
    return s;
  }

  void declare(Params& p) override {
    method_ = p.addChoice("volume.method", {"zpass", "zfail", "auto"}, "auto",
                          "zpass counts faces in front, zfail behind (Carmack's reverse); auto "
                          "takes zfail for a caster whose volume may reach the near plane");
    light_cap_ = p.addBool("volume.light_cap", true,
                           "zfail: draw the caster's triangles facing the light (the light cap)");
    dark_cap_ = p.addBool("volume.dark_cap", true,
                          "zfail: draw the triangles facing away, at infinity (the dark cap)");
    far_ = p.addChoice("volume.far", {"infinite", "finite", "depth_clamp"}, "infinite",
                       "the eye's far plane: at infinity, at volume.far_distance (clips the "
                       "volumes), or there with GL_DEPTH_CLAMP (desktop GL only)");
    far_distance_ = p.addFloat("volume.far_distance", 30.0f, 2.0f, 1000.0f,
                               "the finite far plane's distance (volume.far=finite, depth_clamp); "
                               "the scene's surfaces lie within 30")
                        .logScale();
    geometry_ = p.addChoice("volume.geometry", {"silhouette", "per_triangle"}, "silhouette",
                            "extrude only possible silhouette edges, or one volume per triangle");
    stencil_ = p.addChoice("stencil.mode", {"two_pass", "two_sided"}, "two_pass",
                           "the incrementing faces, then the decrementing ones, in two culled "
                           "passes; or one pass with glStencilOpSeparate (wrap only: with clamp "
                           "two passes)");
    wrap_ = p.addChoice("stencil.op", {"wrap", "clamp"}, "wrap",
                        "GL_INCR_WRAP/DECR_WRAP, or GL_INCR/DECR, which stop at 255 and 0");
    combine_ = p.addChoice("combine", {"additive", "modulative"}, "additive",
                           "light added where the count is 0 (seed 002), or the shadow darkened "
                           "over a lit frame (keeps a dimmed highlight in shadow)");
    // The panel greys out what the current settings do not use, and says why.
    const auto unless_zfail = [](const Params& ps) -> std::string {
      return ps.at("volume.method").is("zpass") ? "z-pass draws no caps" : "";
    };
    light_cap_.param().inactive = unless_zfail;
    dark_cap_.param().inactive = unless_zfail;
    far_distance_.param().inactive = [](const Params& ps) -> std::string {
      return ps.at("volume.far").is("infinite") ? "the far plane is at infinity" : "";
    };
    cull_ = p.addBool("volume.cull", true, "skip volumes that cannot reach the view frustum");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
    off_ = p.addBool("shadow.off", false, "no volumes at all: everything lit (the baseline)");
  }

  void init() override {
    scene_programs_ =
        ProgramVariants(lessonFile(LESSON_DIR, "scene.vert"), lessonFile(LESSON_DIR, "scene.frag"));
    volume_programs_ = ProgramVariants(lessonFile(LESSON_DIR, "volume.vert"),
                                       lessonFile(LESSON_DIR, "volume.frag"));
    flat_ = Program(commonShaderDir() / "fullscreen.vert", lessonFile(LESSON_DIR, "flat.frag"));
    lines_ = Program(lessonFile(LESSON_DIR, "lines.vert"), lessonFile(LESSON_DIR, "flat.frag"));
  }

  void render(Frame& f) override {
    eyeProjection(f);
    // The truth's passes render other modes with view=overview: the ray stays for the report.
    if (f.params.at("view").choice() != kOverview.name()) ray_.reset();
    if (f.shows(kOverview)) return renderOverview(f);
    const bool visibility = f.shows(views::kVisibility);
    const bool modulative = combine_() == Combine::Modulative;
    // 1. The scene, dimmed (additive) or fully lit (modulative); the depth buffer.
    {
      auto timing = f.measure.pass("eye", /*countPassed=*/true);
      f.clearTarget(visibility ? glm::vec3(0.0f) : Frame::kSky);
      drawScene(f, modulative ? "full" : "dim");
    }
    // 2. The volumes into the stencil (the counters say 0 on a frame without them).
    volumes_ = zfail_ = culled_ = triangles_ = silhouettes_ = open_edges_ = 0;
    open_names_.clear();
    if (!off_()) countVolumes(f);
    // 3. Light where the count is 0, or darken where it is not.
    {
      auto timing = f.measure.pass("light");
      PassState state;
      state.depth_write = false;
      state.stencil_test = true;
      state.blend = true;
      if (modulative) {
        state.depth_test = false;
        state.stencil_func = GL_NOTEQUAL;
        state.blend_src = GL_ZERO, state.blend_dst = GL_SRC_COLOR;  // dst * colour
        state.apply();
        const float k = visibility ? 0.0f : dimming_();
        flat_.use();
        flat_.set("uColor", glm::vec4(k, k, k, 1.0f));
        f.drawFullscreen(flat_);
      } else {
        state.depth_func = GL_EQUAL;  // the surfaces pass 1 left, nothing behind them
        state.stencil_func = GL_EQUAL;
        state.blend_dst = GL_ONE;
        state.apply();
        drawScene(f, "light");
      }
    }
    if (f.shows(kVolumes)) drawVolumesSeen(f);
    if (f.shows(kCount)) drawCounts(f);
    PassState{}.apply();
  }

  void panel(Frame&) override {
    ImGui::TextWrapped(
        "volumes %lld (z-fail %lld, culled %lld), %lld triangles, %lld silhouette "
        "edges; eye far plane %s",
        volumes_, zfail_, culled_, triangles_, silhouettes_,
        far_used_ > 0.0f ? std::to_string(far_used_).c_str() : "at infinity");
    ImGui::TextWrapped("volume_open_edges %lld%s%s", open_edges_,
                       open_edges_ > 0 ? ": closed as two-sided shells: " : "",
                       open_names_.c_str());
    if (clamp_refused_) ImGui::TextWrapped("GL_DEPTH_CLAMP is not offered here: finite far");
    if (ray_) {
      ImGui::TextWrapped(
          "centre ray: the eye is in %d volume(s); before the surface it enters %d (green) and "
          "leaves %d (red): z-pass counts %d, the surface is in %d",
          ray_->at_eye, ray_->enters, ray_->leaves, ray_->zpassCount(), ray_->at_surface);
    }
    if (stencil_() == Stencil::TwoSided && !two_sided_used_) {
      ImGui::TextWrapped(
          "two-sided stencil needs stencil.op=wrap (one pass has no fixed face "
          "order): drawn in two passes");
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    const std::vector<Figure> exact = {
        {"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.05},
        {"/error/false_lit_pct", "false lit %", B::AtMost, 0.05}};
    std::vector<Figure> cheap = exact;
    cheap.push_back({"/counters/volume_triangles", "volume triangles", B::AtMost, 1000});
    return {{.title = "The eye in the shadow (slide 38)",
             .goal = "The eye sits in the torus's shadow and z-pass inverts the picture. Make "
                     "every pixel right again (false shadow and false lit both 0.05 % or "
                     "less) without moving the eye.",
             .setup = {"scene=eye_in_shadow", "volume.method=zpass"},
             .allowed = {"volume.method", "volume.light_cap", "volume.dark_cap", "volume.far",
                         "stencil.op"},
             .figures = exact,
             .hint = "z-pass counts from the eye, and the near plane cut the face the eye "
                     "entered through. Count from the other end (slide 39)."},
            {.title = "The same shadows with fewer triangles (slides 47-48)",
             .goal = "Every caster's triangles cast a volume of their own: 33 thousand volume "
                     "triangles. Get the same shadows (both errors 0.05 % or less) with at most "
                     "1000 volume triangles.",
             .setup = {"volume.geometry=per_triangle"},
             .allowed = {"volume.geometry", "volume.method", "volume.cull"},
             .figures = cheap,
             .hint = "Two neighbouring triangles that both face the light share an edge whose "
                     "two side quads cancel. Which edges remain?"}};
  }

  void report(JsonWriter& json) const override {
    json.value("volume_open_edges", open_edges_);
    json.value("volume_open_casters", open_names_);
    json.value("eye_far_used", far_used_);  // 0: at infinity
    json.value("depth_clamp", depth_clamp_ ? 1 : 0);
    json.value("stencil_passes", two_sided_used_ ? 1 : 2);
    if (ray_) {  // view=overview: the centre pixel's ray through the volumes (slides 24-26)
      json.beginObject("center_ray");
      json.value("at_eye", ray_->at_eye);
      json.value("enters", ray_->enters);
      json.value("leaves", ray_->leaves);
      json.value("zpass_count", ray_->zpassCount());
      json.value("at_surface", ray_->at_surface);
      json.endObject();
    }
  }

 private:
  // One caster's volume: its adjacency and the buffer the vertex shader extrudes.
  struct Volume {
    EdgeMesh edges;
    Buffer vbo;
    GlName<deleteVertexArray> vao;
    GLsizei cap_vertices = 0, side_vertices = 0;
  };

  // Slide 45: "send far plane to infinity in projection matrix", so the dark cap (w = 0)
  // survives clipping. Only the depth row changes: the pixels are the runner's and the truth's.
  void eyeProjection(Frame& f) {
    const float fov = glm::radians(f.params.at("camera.fov").f());
    const float aspect = static_cast<float>(f.width) / static_cast<float>(std::max(f.height, 1));
    const float near = f.scene.camera.near;
    depth_clamp_ = false;
    clamp_refused_ = false;
    if (far_() == Far::Infinite) {
      // Epsilon-tweaked: a vertex at infinity lands just inside the far plane, not on it.
      f.projection = glm::tweakedInfinitePerspective(fov, aspect, near, 1e-6f);
      far_used_ = 0.0f;
      return;
    }
    far_used_ = far_distance_();
    f.projection = glm::perspective(fov, aspect, near, far_used_);
    if (far_() == Far::DepthClamp) {
      // Slide 50, "hardware capping": desktop GL 3.2 (GLES 3.0 has no depth clamp).
      depth_clamp_ = caps().depth_clamp;
      clamp_refused_ = !depth_clamp_;
    }
  }

  void drawScene(Frame& f, const char* pass) {
    const Program& p = scene_programs_.get(
        {f.viewDefines(), choiceDefines("pass", {"dim", "light", "full"}, pass)});
    p.set("uViewProjection", f.projection * f.view);
    f.setLightingUniforms(p, dimming_());
    f.drawObjects(p, Objects::All);
  }

  // The light in an object's space: (position, 1) or (-direction, 0).
  static glm::vec4 lightIn(const Frame& f, const SceneObject& o) {
    const glm::vec4 world = f.light.directional ? glm::vec4(-f.light.direction, 0.0f)
                                                : glm::vec4(f.light.position, 1.0f);
    return glm::inverse(o.model) * world;
  }

  void buildVolumes(const Frame& f) {
    const auto geometry = static_cast<VolumeGeometry>(geometry_());
    const std::string key = f.scene.name + "/" + geometry_.name();
    if (key == built_for_ && volumes_by_object_.size() == f.scene.objects.size()) return;
    built_for_ = key;
    volumes_by_object_.clear();
    for (const SceneObject& o : f.scene.objects) {
      Volume v;
      v.edges = buildEdgeMesh(o.mesh);
      const VolumeBuffer b = buildVolumeBuffer(v.edges, geometry);
      v.cap_vertices = static_cast<GLsizei>(b.cap_vertices);
      v.side_vertices = static_cast<GLsizei>(b.vertices.size() - b.cap_vertices);
      GLuint vao = 0;
      glGenVertexArrays(1, &vao);
      v.vao = GlName<deleteVertexArray>(vao);
      glBindVertexArray(vao);
      v.vbo =
          Buffer(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(b.vertices.size() * sizeof(VolumeVertex)),
                 b.vertices.data(), GL_STATIC_DRAW);
      v.vbo.bind();
      const auto stride = static_cast<GLsizei>(sizeof(VolumeVertex));
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(offsetof(VolumeVertex, position)));
      glEnableVertexAttribArray(1);
      glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(offsetof(VolumeVertex, plane)));
      glEnableVertexAttribArray(2);
      glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(offsetof(VolumeVertex, owner)));
      glBindVertexArray(0);
      volumes_by_object_.push_back(std::move(v));
    }
  }

  // Slide 45: z-fail where the near plane may lie in this caster's volume, that is where the
  // caster meets the hull of the light and the near plane's rectangle (or, for a directional
  // light, the rectangle swept toward the light).
  static bool mayShadowNearPlane(const Frame& f, const SceneObject& o) {
    const glm::mat4 inv = glm::inverse(f.projection * f.view);
    glm::vec3 c[4];
    const glm::vec2 ndc[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; ++i) {
      const glm::vec4 p = inv * glm::vec4(ndc[i], -1.0f, 1.0f);
      c[i] = glm::vec3(p) / p.w;
    }
    const Bounds b = o.worldBounds();
    const glm::vec3 centre = b.center();
    const float r = b.radius();
    const glm::vec3 mid = 0.25f * (c[0] + c[1] + c[2] + c[3]);
    const glm::vec3 toward = f.light.directional ? -f.light.direction : f.light.position - mid;
    const glm::vec3 inside = mid + 0.5f * toward;  // a point inside the hull
    // Outside one face of the hull by more than the radius: cannot touch it.
    const auto outside = [&](glm::vec3 n, glm::vec3 on) {
      const float len = glm::length(n);
      if (len < 1e-12f) return false;
      n /= len;
      if (glm::dot(n, inside - on) < 0.0f) n = -n;
      return glm::dot(n, centre - on) < -r;
    };
    const glm::vec3 rect_normal = glm::cross(c[1] - c[0], c[3] - c[0]);
    if (std::abs(glm::dot(glm::normalize(rect_normal), glm::normalize(toward))) < 1e-4f) {
      return true;  // the light in the near plane's plane: no hull, be safe
    }
    if (outside(rect_normal, c[0])) return false;
    for (int i = 0; i < 4; ++i) {
      const glm::vec3 e = c[(i + 1) % 4] - c[i];
      const glm::vec3 side = f.light.directional ? toward : f.light.position - c[i];
      if (outside(glm::cross(e, side), c[i])) return false;
    }
    return true;
  }

  // Whether a volume (the caster's sphere swept away from the light) lies wholly outside one
  // plane of the view frustum: the sphere outside it, and the sweep going further out.
  static bool volumeOutsideView(const Frame& f, const SceneObject& o) {
    const glm::mat4 m = glm::transpose(f.projection * f.view);  // rows as columns
    const Bounds b = o.worldBounds();
    const glm::vec3 centre = b.center();
    const float r = b.radius();
    for (int i = 0; i < 5; ++i) {  // left, right, bottom, top, near: the far one may not exist
      const glm::vec4 plane = m[3] + (i % 2 == 0 ? 1.0f : -1.0f) * m[i / 2];
      const float len = glm::length(glm::vec3(plane));
      const float d = (glm::dot(glm::vec3(plane), centre) + plane.w) / len;
      if (d + r >= 0.0f) continue;
      // Along the sweep the distance changes by (d(p) - d(light)) per unit (point light), or
      // by the direction's component (directional): it must not come back in.
      const float light_side = f.light.directional
                                   ? -glm::dot(glm::vec3(plane), f.light.direction) / len
                                   : (glm::dot(glm::vec3(plane), f.light.position) + plane.w) / len;
      if (f.light.directional ? light_side >= 0.0f : light_side >= d + r) return true;
    }
    return false;
  }

  struct Ops {
    GLenum fail_front, pass_front, fail_back, pass_back;
  };
  Ops opsFor(bool zfail) const {
    const bool wrap = wrap_() == 0;
    const GLenum inc = wrap ? GL_INCR_WRAP : GL_INCR, dec = wrap ? GL_DECR_WRAP : GL_DECR;
    // z-pass: faces in front of the surface count; z-fail: faces behind it, reversed.
    return zfail ? Ops{dec, GL_KEEP, inc, GL_KEEP} : Ops{GL_KEEP, inc, GL_KEEP, dec};
  }

  // Pass 2.
  void countVolumes(Frame& f) {
    buildVolumes(f);
    auto timing = f.measure.pass("volumes", /*countPassed=*/true);
    struct Draw {
      size_t object;
      bool zfail;
    };
    std::vector<Draw> draws;
    const auto geometry = static_cast<VolumeGeometry>(geometry_());
    const Light& l = f.light;
    for (size_t i = 0; i < f.scene.objects.size(); ++i) {
      const SceneObject& o = f.scene.objects[i];
      if (!o.castsFrom(l.position, l.directional, l.direction)) continue;
      if (cull_() && volumeOutsideView(f, o)) {
        ++culled_;
        continue;
      }
      const Method m = method_();
      const bool zfail = m == Method::ZFail || (m == Method::Auto && mayShadowNearPlane(f, o));
      draws.push_back({i, zfail});
      const Volume& v = volumes_by_object_[i];
      const VolumeWork work =
          volumeWork(v.edges, geometry, lightIn(f, o), zfail && light_cap_(), zfail && dark_cap_());
      ++volumes_, zfail_ += zfail, triangles_ += work.triangles;
      silhouettes_ += work.silhouette_edges;
      if (v.edges.open_edges > 0) {
        open_edges_ += v.edges.open_edges;
        open_names_ += (open_names_.empty() ? "" : ", ") + o.name;
      }
    }
    f.measure.count("volumes_drawn", volumes_);
    f.measure.count("volumes_zfail", zfail_);
    f.measure.count("culled_volumes", culled_);
    f.measure.count("volume_triangles", triangles_);
    f.measure.count("silhouette_edges", silhouettes_);

    PassState state;
    state.depth_write = false;
    state.color_write = false;
    state.stencil_test = true;
    state.apply();
    depthClamp(depth_clamp_);
    const Program& p = volume_programs_.get({f.viewDefines(), geometry_.defines()});
    p.use();
    p.set("uViewProjection", f.projection * f.view);
    // Increments before decrements, in each method's own order: z-pass draws the front faces
    // first (slide 34), z-fail the back faces (slide 39). With GL_INCR/GL_DECR (stencil.op=clamp)
    // a decrement that came first would stop at 0 and be lost. Two-sided stencil draws both in
    // one pass in no fixed order, which is why it came with EXT_stencil_wrap (slide 50): with
    // clamp it runs as two passes.
    two_sided_used_ = stencil_() == Stencil::TwoSided && wrap_() == 0;
    if (!two_sided_used_) glEnable(GL_CULL_FACE);
    for (int pass = 0; pass < (two_sided_used_ ? 1 : 2); ++pass) {
      for (const Draw& d : draws) {
        // Pass 0 draws the incrementing faces: z-pass's front ones (the back culled), z-fail's
        // back ones; pass 1 the decrementing ones.
        if (!two_sided_used_) glCullFace((pass == 0) != d.zfail ? GL_BACK : GL_FRONT);
        const Ops ops = opsFor(d.zfail);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, ops.fail_front, ops.pass_front);
        glStencilOpSeparate(GL_BACK, GL_KEEP, ops.fail_back, ops.pass_back);
        drawVolume(f, p, d.object, d.zfail);
      }
    }
    glDisable(GL_CULL_FACE);
    depthClamp(false);
    PassState{}.apply();
  }

  void drawVolume(const Frame& f, const Program& p, size_t object, bool caps) {
    const SceneObject& o = f.scene.objects[object];
    const Volume& v = volumes_by_object_[object];
    p.set("uModel", o.model);
    p.set("uLight", lightIn(f, o));
    glBindVertexArray(v.vao.id());
    if (caps && (light_cap_() || dark_cap_())) {
      p.set("uDropLightCap", light_cap_() ? 0 : 1);
      p.set("uDropDarkCap", dark_cap_() ? 0 : 1);
      glDrawArrays(GL_TRIANGLES, 0, v.cap_vertices);
      countDrawCall();
    }
    p.set("uDropLightCap", 0);
    p.set("uDropDarkCap", 0);
    glDrawArrays(GL_TRIANGLES, v.cap_vertices, v.side_vertices);
    countDrawCall();
    glBindVertexArray(0);
  }

  // view=overview: the eye's scene from outside (seed 003 slides 24-26 and 38): the volumes
  // closed and translucent, the eye's frustum in magenta, and its centre pixel's ray in white
  // up to the surface it sees, a green mark where it enters a volume and a red one where it
  // leaves. With the eye inside a volume (scene=eye_in_shadow) the ray starts inside: it
  // leaves more often than it enters, and z-pass, which starts counting at 0, is wrong.
  void renderOverview(Frame& f) {
    auto timing = f.measure.pass("overview");
    const glm::mat4 eye_inverse = glm::inverse(f.projection * f.view);
    const glm::vec3 eye = f.eye;
    const auto unproject = [&](glm::vec2 ndc, float z) {
      const glm::vec4 p = eye_inverse * glm::vec4(ndc, z, 1.0f);
      return glm::vec3(p) / p.w;
    };
    const glm::vec3 forward = glm::normalize(unproject({0.0f, 0.0f}, -1.0f) - eye);
    // The centre pixel's ray: the surface it sees, then the volumes along it.
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;
    f.scene.worldTriangles(positions, triangles);
    std::vector<volumes::Triangle> all;
    for (const glm::uvec3& t : triangles)
      all.push_back({positions[t.x], positions[t.y], positions[t.z]});
    const float reach = 4.0f * f.scene.bounds().radius() + glm::length(eye);
    const float surface = volumes::hit(all, eye, forward, 0.0f, reach).value_or(reach);
    std::vector<volumes::Caster> casters;
    const Light& l = f.light;
    for (const SceneObject& o : f.scene.objects) {
      if (!o.castsFrom(l.position, l.directional, l.direction)) continue;
      std::vector<volumes::Triangle> caster;
      const auto world = [&](std::uint32_t i) {
        return glm::vec3(o.model * glm::vec4(o.mesh.vertices[i].position, 1.0f));
      };
      for (size_t i = 0; i + 2 < o.mesh.indices.size(); i += 3) {
        caster.push_back(
            {world(o.mesh.indices[i]), world(o.mesh.indices[i + 1]), world(o.mesh.indices[i + 2])});
      }
      casters.emplace_back(std::move(caster));
    }
    const glm::vec4 light =
        l.directional ? glm::vec4(-l.direction, 0.0f) : glm::vec4(l.position, 1.0f);
    ray_ = volumes::countAlongRay(casters, light, eye, forward, surface);

    // The camera outside: beside and above the eye, looking at what lies between the eye and
    // the scene's centre, far enough back to hold both.
    Bounds bounds = f.scene.casterBounds(l.position, l.directional, l.direction);
    bounds.add(eye);
    const glm::vec3 centre = bounds.center();
    const float radius = std::max(bounds.radius(), 1.0f);
    const glm::vec3 up{0.0f, 1.0f, 0.0f};
    glm::vec3 side = glm::cross(forward, up);
    side = glm::length(side) < 1e-3f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::normalize(side);
    const glm::vec3 look_at = centre;
    const glm::mat4 eye_view = f.view, eye_projection = f.projection;
    f.view = lookAtSafe(
        look_at + 2.6f * radius * side + 1.8f * radius * up - 1.0f * radius * forward, look_at);
    const float aspect = static_cast<float>(f.width) / static_cast<float>(std::max(f.height, 1));
    f.projection = glm::tweakedInfinitePerspective(glm::radians(45.0f), aspect, 0.1f, 1e-6f);

    f.clearTarget();
    drawScene(f, "full");
    drawVolumesSeen(f, /*closed=*/true);

    // The lines, over everything: the frustum as far as the camera's target, the ray, marks.
    std::vector<glm::vec3> frustum, ray, enters, leaves;
    const float depth = std::max(glm::length(f.params.at("camera.target").v() - eye), 1.0f);
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    glm::vec3 near[4], far[4];
    for (int i = 0; i < 4; ++i) {
      near[i] = unproject(corners[i], -1.0f);
      far[i] = eye + glm::normalize(near[i] - eye) * depth /
                         glm::dot(glm::normalize(near[i] - eye), forward);
    }
    for (int i = 0; i < 4; ++i) {
      const int j = (i + 1) % 4;
      for (const glm::vec3 p : {near[i], near[j], far[i], far[j], eye, far[i]})
        frustum.push_back(p);
    }
    ray = {eye, eye + surface * forward};
    const float mark = 0.06f * radius;
    for (const auto& [t, by] : ray_->crossings) {
      const glm::vec3 c = eye + t * forward;
      for (const glm::vec3 axis : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
        for (const glm::vec3 p : {c - mark * axis, c + mark * axis})
          (by > 0 ? enters : leaves).push_back(p);
      }
    }
    PassState state;
    state.depth_test = false;
    state.apply();
    lines_.use();
    lines_.set("uViewProjection", f.projection * f.view);
    drawLines(frustum, {1.0f, 0.2f, 1.0f, 1.0f});
    drawLines(ray, {1.0f, 1.0f, 1.0f, 1.0f});
    drawLines(enters, {0.2f, 1.0f, 0.2f, 1.0f});
    drawLines(leaves, {1.0f, 0.15f, 0.1f, 1.0f});
    PassState{}.apply();
    f.view = eye_view, f.projection = eye_projection;
  }

  void drawLines(const std::vector<glm::vec3>& points, glm::vec4 colour) {
    if (points.empty()) return;
    lines_.set("uColor", colour);
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    const GlName<deleteVertexArray> keep(vao);
    glBindVertexArray(vao);
    const Buffer vbo(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(points.size() * sizeof(glm::vec3)),
                     points.data(), GL_STREAM_DRAW);
    vbo.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(points.size()));
    countDrawCall();
    glBindVertexArray(0);
  }

  // view=volumes (slide 29, "render shadow volume faces"), translucent over the picture: the
  // faces in front of the surfaces (what z-pass counts) strong, those behind them (what z-fail
  // counts: most back faces end under the floor) faint; front faces warm, back faces cold.
  // `closed`: with both caps, whatever the method (the overview).
  void drawVolumesSeen(Frame& f, bool closed = false) {
    buildVolumes(f);  // also with shadow.off, which counts none
    PassState state;
    state.depth_write = false;
    state.blend = true;
    state.blend_src = GL_SRC_ALPHA, state.blend_dst = GL_ONE_MINUS_SRC_ALPHA;
    depthClamp(depth_clamp_);
    const Program& p = volume_programs_.get({f.viewDefines(), geometry_.defines()});
    p.use();
    p.set("uViewProjection", f.projection * f.view);
    const Light& l = f.light;
    for (const auto& [depth_func, alpha] :
         {std::pair<GLenum, float>{GL_GREATER, 0.1f}, {GL_LESS, 0.35f}}) {
      state.depth_func = depth_func;
      // Behind means clearly behind: a side leaving a silhouette edge lies nearly in its
      // face's plane, and rounding (which differs between rasterizers) would decide.
      state.polygon_offset = depth_func == GL_GREATER;
      state.offset_factor = -2.0f, state.offset_units = -16.0f;
      state.apply();
      p.set("uAlpha", alpha);
      for (size_t i = 0; i < f.scene.objects.size(); ++i) {
        const SceneObject& o = f.scene.objects[i];
        if (o.castsFrom(l.position, l.directional, l.direction)) {
          drawVolume(f, p, i, closed || method_() == Method::ZFail);
        }
      }
    }
    depthClamp(false);
  }

  // view=count: the stencil count as a heat map, one full-screen triangle per level the
  // stencil test lets through (GLES 3.0 cannot read stencil in a shader).
  void drawCounts(Frame& f) {
    PassState state;
    state.stencil_test = true;
    state.depth_test = false;
    state.apply();
    flat_.use();
    const auto level = [&](GLenum func, GLint ref, GLuint mask, glm::vec3 colour) {
      glStencilFunc(func, ref, mask);
      flat_.set("uColor", glm::vec4(colour, 1.0f));
      f.drawFullscreen(flat_);
    };
    level(GL_LEQUAL, 8, 0x7F, {1.0f, 1.0f, 0.9f});  // 8 or more (below 128)
    const glm::vec3 ramp[7] = {{0.5f, 0.0f, 0.0f}, {0.8f, 0.1f, 0.0f}, {1.0f, 0.35f, 0.0f},
                               {1.0f, 0.6f, 0.0f}, {1.0f, 0.8f, 0.1f}, {1.0f, 0.95f, 0.3f},
                               {1.0f, 1.0f, 0.6f}};
    for (GLint k = 1; k <= 7; ++k) level(GL_EQUAL, k, 0xFF, ramp[k - 1]);
    level(GL_EQUAL, 0x80, 0x80, {0.2f, 0.4f, 1.0f});  // 128..255: negative, or clamped
  }

  // GL_DEPTH_CLAMP is desktop GL 3.2 only (not GLES 3.0): never touched without it.
  static void depthClamp(bool on) {
    if (!caps().depth_clamp) return;
    on ? glEnable(GL_DEPTH_CLAMP) : glDisable(GL_DEPTH_CLAMP);
  }

  ChoiceParam<Method> method_;
  ChoiceParam<Far> far_;
  ChoiceParam<> geometry_, wrap_;
  ChoiceParam<Stencil> stencil_;
  ChoiceParam<Combine> combine_;
  BoolParam light_cap_, dark_cap_, cull_, off_;
  FloatParam far_distance_, dimming_;
  ProgramVariants scene_programs_, volume_programs_;
  Program flat_, lines_;
  std::optional<volumes::RayCount> ray_;  // view=overview's centre ray
  std::vector<Volume> volumes_by_object_;
  std::string built_for_;
  float far_used_ = 0.0f;
  bool depth_clamp_ = false, clamp_refused_ = false, two_sided_used_ = false;
  long long volumes_ = 0, zfail_ = 0, culled_ = 0, triangles_ = 0, silhouettes_ = 0,
            open_edges_ = 0;
  std::string open_names_;
};

SHADOWS_LESSON(ShadowVolumes);

}  // namespace shadows
