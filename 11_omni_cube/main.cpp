// Lesson 11: an omni-directional light, six view frusta in a cube map (seed 000, "Not without
// its problems": "Shadows are limited to view frustums - could use six view frustums for
// omni-directional light"; seed 003: shadow volumes handle "Omnidirectional lights (unlike
// shadow maps!)").
//
//   Pass 1, six times: the casters through one 90° frustum per face (+x, -x, +y, -y, +z, -z)
//           into that face of a depth cube map. Stored as the distance to the light (a linear
//           gl_FragDepth) or as each face's own hardware depth.
//   Pass 2: from the eye. The direction from the light to the fragment picks the face and the
//           texel (samplerCubeShadow); the reference is the fragment's value in the same store.
//
// Work the scene does not need is skipped and counted: a face holding no caster, or one the
// eye's frustum never reaches, is not rendered; casters outside a face's frustum are culled;
// the cube is kept while nothing moved.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include "core/fnv.hpp"
#include "core/json.hpp"
#include "cube_math.hpp"
#include "lesson/lesson.hpp"
#include "math/texel_density.hpp"
#include "tetra_math.hpp"

namespace shadows {

namespace {
const std::vector<std::string> kStores = {"distance", "depth"};
enum class Store { Distance, Depth };
}  // namespace

class OmniCube final : public Lesson {
 public:
  std::string title() const override { return "Omni light: six frusta in a cube map"; }
  std::string seeds() const override {
    return "seed 000: Not without its problems (six view frustums for omni-directional light); "
           "seed 003: Shadow volumes, advantages (omnidirectional lights)";
  }
  static constexpr View kCubeCross{"cube_cross"};
  static constexpr View kFace{"face"};
  static constexpr View kFaceTexels{"face_texels"};
  static constexpr View kDistance{"distance"};
  static constexpr View kTexelStats{"texel_stats"};  // measureTexels' pass, never offered
  std::vector<View> debugViews() const override {
    return {kCubeCross, kFace, kFaceTexels, kDistance};
  }
  std::vector<std::string> scenes() const override {
    return {"bulb", "torus_pyramid", "dueling", "bulb_crowd", "bulb_throng"};
  }
  // An omni light points nowhere and has no frustum of its own: each face's is fixed at 90°.
  std::vector<std::string> unusedSharedParams() const override {
    return {"light.type", "light.target", "light.fov", "light.extent"};
  }

  void declare(Params& p) override {
    constexpr auto kMap = kDirtyShadowMap | kDirtyResources;
    method_ = p.addChoice("omni.method", {"cube", "paraboloid", "tetrahedron"}, "cube",
                          "cube: six 90° frusta; paraboloid: two hemispheres warped in the vertex "
                          "shader; tetrahedron: four frusta as tiles of one map; as many texels "
                          "as the cube",
                          kDirtyShadowMap | kDirtyResources);
    size_ = p.addInt("cube.size", 512, 16, 2048, "texels along each face's side", kMap).logScale();
    store_ = p.addChoice("cube.store", kStores, "distance",
                         "distance: |p - light| / far, written linear; depth: each face's own "
                         "hardware depth",
                         kDirtyShadowMap);
    bits_ = p.addChoice("cube.bits", {"16", "24", "32"}, "24", "bits of the stored depth", kMap);
    filter_ = p.addChoice("cube.filter", {"nearest", "linear"}, "nearest",
                          "linear: the hardware's 2x2 compare, blended (bilinear PCF)");
    seamless_ = p.addBool("cube.seamless", true,
                          "linear filtering reads across face edges (always, on ES and WebGL)");
    passes_ = p.addChoice("cube.passes", {"six", "layered"}, "six",
                          "six: one pass a face; layered: one pass, a geometry shader sends each "
                          "triangle to its faces (desktop GL)",
                          kDirtyShadowMap);
    skip_ = p.addBool("cube.skip", true,
                      "skip faces with no caster or out of the eye's sight, and casters outside "
                      "a face's frustum",
                      kDirtyShadowMap);
    bias_ = p.addFloat("bias.world", 0.05f, 0.0f, 0.5f,
                       "constant bias, world units along the ray (distance) or the axis (depth)");
    normal_ = p.addFloat("bias.normal", 0.25f, 0.0f, 4.0f,
                         "normal offset, in texels of the face at the fragment's distance");
    // Lesson 04's other two methods, in each face's pass.
    faces_ = p.addChoice("bias.faces", {"front", "back"}, "front",
                         "which faces of the closed casters go into the cube: back faces only is "
                         "lesson 04's default (seed 003, slide 70)",
                         kDirtyShadowMap);
    slope_ = p.addFloat("bias.slope", 0.0f, 0.0f, 8.0f,
                        "glPolygonOffset factor in each face's pass (slope-scaled; the depth "
                        "store only: a written gl_FragDepth is not offset)",
                        kDirtyShadowMap);
    // The paraboloids and the tetrahedron are 2D maps of the distance, one pass a map or tile.
    for (const char* name : {"cube.store", "cube.passes", "cube.seamless"}) {
      p.at(name).inactive = [](const Params& ps) -> std::string {
        return ps.at("omni.method").is("cube") ? ""
                                               : "a cube's only: the paraboloids and the "
                                                 "tetrahedron store the distance in 2D maps";
      };
    }
    slope_.param().inactive = [](const Params& ps) -> std::string {
      return ps.at("cube.store").is("depth") ? ""
                                             : "the distance store writes gl_FragDepth, which "
                                               "polygon offset does not move";
    };
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "light left in shadow: dimming + (1-dimming)*shade");
    {
      const Params::SharedScope shared(p);
      cache_ =
          p.addBool("shadow.cache", true,
                    "re-render the cube only when the light or a caster changed", kDirtyShadowMap);
      off_ = p.addBool("shadow.off", false,
                       "baseline: the same frame with no shadow work (no cube, no lookup)",
                       kDirtyShadowMap);
    }
  }

  void init() override {
    depth_programs_ = ProgramVariants(lessonFile(LESSON_DIR, "cube_depth.vert"),
                                      lessonFile(LESSON_DIR, "cube_depth.frag"));
    layered_programs_ = ProgramVariants(lessonFile(LESSON_DIR, "cube_layered.vert"),
                                        lessonFile(LESSON_DIR, "cube_layered.geom"),
                                        lessonFile(LESSON_DIR, "cube_depth.frag"));
    paraboloid_programs_ = ProgramVariants(lessonFile(LESSON_DIR, "paraboloid.vert"),
                                           lessonFile(LESSON_DIR, "paraboloid.frag"));
    eye_programs_ = ProgramVariants(commonShaderDir() / "shadow_coord.vert",
                                    lessonFile(LESSON_DIR, "scene.frag"));
    cross_programs_ = ProgramVariants(commonShaderDir() / "fullscreen.vert",
                                      lessonFile(LESSON_DIR, "cross.frag"));
    compare_nearest_ = Sampler::depth(/*compare=*/true, GL_NEAREST);
    compare_linear_ = Sampler::depth(/*compare=*/true, GL_LINEAR);
    raw_ = Sampler::depth(/*compare=*/false, GL_NEAREST);
  }

  void render(Frame& f) override {
    light_ = f.light.position;
    near_ = f.light.near;
    far_ = f.light.far;
    // What the cube (or the paraboloids) can hold: pixels outside it are not counted, as beyond
    // a map's frustum in 03-08 (the lookup calls them lit, in the store's own measure of far).
    // A tetrahedron's faces clip at near along their own axes, which lie within 1/3 of the
    // distance (70.5 degrees) of a point: beyond 3 near along the cube's major axis, held.
    f.light_reach = Frame::LightReach{light_,
                                      cube()          ? near_
                                      : tetrahedron() ? 3.0f * near_
                                                      : 0.0f,
                                      far_, cube() && store_() == Store::Depth};
    if (off_()) {
      f.measure.count("shadow_map_renders", 0);
      countFaces(f, 0, 0, 0);
    } else {
      releaseOtherMethods();
      if (paraboloid()) {
        renderParaboloids(f);
      } else if (tetrahedron()) {
        renderTetrahedron(f);
      } else {
        renderCube(f);
      }
    }

    {
      auto timing = f.measure.pass("eye", /*countPassed=*/true);
      f.clearTarget(f.shows(kCubeCross) ? glm::vec3(0.08f) : Frame::kSky);
      if (f.shows(kCubeCross)) return drawCross(f);
      drawEye(f, viewDefines(f, f.shown.str()));
    }
    // Where the faces' texels land on the screen, once the eye rests (as the runner's texel
    // pass does for a 2D map): the report's texels_per_pixel.
    if (!off_() && !f.input_moving && texelKey(f) != texel_key_) {
      auto texels = f.measure.pass("texels");
      measureTexels(f);
    }
  }

  // Frame::viewDefines with the texel pass's own view among them, so that every variant
  // defines VIEW_TEXEL_STATS (an undefined macro in #if is an error on ES).
  static std::vector<std::string> viewDefines(const Frame& f, const std::string& view) {
    std::vector<std::string> views = f.params.at("view").choices;
    for (const std::string& hidden : {f.shown.str(), kTexelStats.str()}) {
      if (std::find(views.begin(), views.end(), hidden) == views.end()) views.push_back(hidden);
    }
    return choiceDefines("view", views, view);
  }

  // The eye's pass with the view `viewDefines`: the map bound, every uniform set.
  void drawEye(Frame& f, const std::vector<std::string>& viewDefines) {
    bindTetrahedron();
    cube_.bind(0);
    (filter_.name() == "linear" ? compare_linear_ : compare_nearest_).bind(0);
    cube_.bind(1);
    raw_.bind(1);
    bindParaboloids();
    // Desktop GL filters each face on its own unless told; ES and WebGL always across.
    setSeamlessCubeFiltering(seamless_());
    const Program& e = eye_programs_.get({method_.defines(), store_.defines(), viewDefines,
                                          define("SHADOW_OFF", off_()),
                                          feature("NORMAL_OFFSET", normal_() > 0.0f)});
    e.set("uViewProjection", f.projection * f.view);
    e.set("uShadowMatrix", glm::mat4(1.0f));
    e.set("uCube", 0);
    e.set("uCubeRaw", 1);
    setCubeUniforms(e);
    e.set("uBiasWorld", bias_());
    e.set("uBiasNormal", normal_());
    f.setLightingUniforms(e, dimming_());
    f.drawObjects(e, Objects::All);
    setSeamlessCubeFiltering(false);  // the GL's default, for every other pass
    for (int unit = 0; unit < 8; ++unit) Sampler::unbind(unit);
  }

  // What the texels per pixel depend on: the method and its texels, the light, the eye, the
  // frame's size and where the objects are (their matrices, hashed).
  std::string texelKey(const Frame& f) const {
    Fnv hash;
    for (const SceneObject& o : f.scene.objects) hash.add(o.model);
    hash.add(f.projection * f.view);
    hash.add(glm::vec4(light_, far_));
    return method_.name() + " " + std::to_string(size_()) + " " + std::to_string(f.width) + "x" +
           std::to_string(f.height) + " " + std::to_string(hash.h);
  }

  // The eye's pixels drawn with the hidden texel_stats view into a float target and read back:
  // the least and most texels a pixel spans on the face it reads (scene.frag).
  void measureTexels(Frame& f) {
    if (texel_target_w_ != f.width || texel_target_h_ != f.height) {
      const auto uncounted = TextureBytes::Scope::none();  // a measurement's, not the light's
      texel_color_ = Texture::color(f.width, f.height, GL_RGBA32F);
      texel_depth_ = Texture::depth(f.width, f.height, 24);
      texel_target_ = std::make_unique<Framebuffer>();
      texel_target_->attachColor(texel_color_);
      texel_target_->attachDepth(texel_depth_);
      texel_target_->check();
      texel_target_w_ = f.width, texel_target_h_ = f.height;
    }
    texel_target_->bind();
    glViewport(0, 0, f.width, f.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawEye(f, viewDefines(f, kTexelStats.str()));
    std::vector<TexelPixel> pixels(static_cast<size_t>(f.width) * static_cast<size_t>(f.height));
    glReadPixels(0, 0, f.width, f.height, GL_RGBA, GL_FLOAT, pixels.data());
    f.bindTarget();
    texel_stats_ = texelStats(pixels);
    texel_key_ = texelKey(f);
  }

  // Within two texels of a face's edge, from the light: where filtering reads across a seam.
  std::vector<ErrorRegion> errorRegions() const override {
    const glm::vec3 light = light_;
    const int size = size_(), tile = tetra::tileSizeFor(size_());
    if (tetrahedron()) {
      return {{"seams", [light, tile](glm::vec4 p) {
                 return tetra::seamDistanceTexels(glm::vec3(p) - light, tile) < 2.0f;
               }}};
    }
    return {{"seams", [light, size](glm::vec4 p) {
               return cube::seamDistanceTexels(glm::vec3(p) - light, size) < 2.0f;
             }}};
  }

  void report(JsonWriter& json) const override {
    json.value("omni_method", method_.name());
    // The faces' texels on the screen (as the runner gives a 2D map's): none with shadow.off.
    if (!off_() && !texel_key_.empty()) {
      writeTexelsPerPixel(json, texel_stats_);
      json.value("undersampled_pct",
                 texel_stats_.pixels > 0 ? texel_stats_.undersampled_pct : kNoFigure);
    }
    json.value("paraboloid_size", paraboloid() ? paraboloid_size_ : 0);
    json.value("tetrahedron_size", tetrahedron() ? tetra_size_ : 0);
    // One pass a face, or one layered pass, and why not the layered one where it was asked for.
    json.value("cube_passes", layered_used_ ? "layered" : "six");
    json.value("cube_passes_fallback", passesFallback());
    json.value("cube_store", store_.name());
    json.value("cube_seamless_used",
               filter_.name() == "linear" && (seamless_() || !caps().seamless_cube_switch));
    // What the cube holds, whichever frame rendered it: a cached frame renders no face.
    json.value("cube_faces_in_use",
               static_cast<long long>(std::count(drawn_.begin(), drawn_.end(), true)));
    json.value("cube_bytes",
               paraboloid()
                   ? 2LL * paraboloid_size_ * paraboloid_size_ * bytesPerTexel(paraboloid_bits_)
               : tetrahedron() ? 4LL * tetra_size_ * tetra_size_ * bytesPerTexel(tetra_bits_)
                               : 6LL * cube_size_ * cube_size_ * bytesPerTexel(cube_bits_));
    json.beginObject("cube_faces");
    for (int i = 0; i < 6; ++i) json.value(cube::kFaceNames[static_cast<size_t>(i)], faceState(i));
    json.endObject();
    json.beginObject("tetrahedron_faces");
    for (int i = 0; i < tetra::kFaces; ++i) {
      json.value(tetra::kFaceNames[static_cast<size_t>(i)], tetraState(i));
    }
    json.endObject();
  }

  void panel(Frame& f) override {
    const auto& counts = f.measure.lastFrameCounts();
    const auto count = [&](const char* name) {
      const auto it = counts.find(name);
      return it == counts.end() ? 0LL : it->second;
    };
    std::string faces;
    if (tetrahedron()) {
      for (int i = 0; i < tetra::kFaces; ++i) {
        faces += std::string(i ? ", " : "") + tetra::kFaceNames[static_cast<size_t>(i)] + " " +
                 tetraState(i);
      }
      ImGui::TextWrapped("tetrahedron faces: %s", faces.c_str());
    } else if (cube()) {
      for (int i = 0; i < 6; ++i) {
        faces += std::string(i ? ", " : "") + cube::kFaceNames[static_cast<size_t>(i)] + " " +
                 faceState(i);
      }
      ImGui::TextWrapped("cube faces: %s", faces.c_str());
    }
    ImGui::TextWrapped("this frame rendered %lld face(s); the map is kept while nothing moves",
                       count("cube_faces_rendered"));
    if (const std::string why = passesFallback(); !why.empty()) {
      ImGui::TextWrapped("cube.passes: six, %s", why.c_str());
    }
    if (filter_.name() == "linear" && !caps().seamless_cube_switch) {
      ImGui::TextWrapped("cube.seamless: always on with %s", caps().flavour.c_str());
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "A small cube that is still right",
             .goal = "With 64-texel faces the bulb's shadows are blocky: 0.29 % false shadow and "
                     "0.43 % false lit. Bring each to 0.2 % or less with a cube of at most "
                     "300000 bytes: six faces of size x size texels, 2 bytes a texel at 16 bits, "
                     "4 at 24 (padded) and 32.",
             .setup = {"cube.size=64"},
             .allowed = {"cube.size", "cube.bits", "cube.filter", "bias.world", "bias.normal"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.2},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.2},
                         {"/cube_bytes", "cube bytes", B::AtMost, 300000}},
             .hint = "Is the error in the texels' size or in their depth's bits? Spend the bytes "
                     "where the error is."},
            {.title = "Dueling frusta around a bulb",
             .goal = "Light and eye face each other: every face the eye looks into is magnified. "
                     "At 512 texels a face the preset has 0.33 % false shadow and 0.48 % false "
                     "lit. Bring each to 0.25 % or less without a bigger cube.",
             .setup = {"scene=dueling"},
             .allowed = {"cube.filter", "bias.world", "bias.normal"},
             .figures = {{"/error/false_shadow_pct", "false shadow %", B::AtMost, 0.25},
                         {"/error/false_lit_pct", "false lit %", B::AtMost, 0.25}},
             .hint = "A normal offset in texels grows with the texels; where texels are huge "
                     "near the eye, a bias in world units may be the better measure."}};
  }

 private:
  // A method's maps are held while it is used: the others' are let go (a method chosen again
  // starts as it would in a fresh run), so what the light holds is its method's alone.
  void releaseOtherMethods() {
    if (!cube() && cube_size_ != 0) {
      for (auto& fb : framebuffers_) fb.reset();
      layered_framebuffer_.reset();
      cube_ = Texture();
      cube_size_ = 0, cube_bits_ = 0;
    }
    if (!paraboloid() && paraboloid_size_ != 0) {
      for (auto& fb : paraboloid_framebuffers_) fb.reset();
      paraboloids_ = {};
      paraboloid_size_ = 0, paraboloid_bits_ = 0;
    }
    if (!tetrahedron() && tetra_size_ != 0) {
      tetra_framebuffer_.reset();
      tetra_map_ = Texture();
      tetra_size_ = 0, tetra_bits_ = 0;
    }
  }

  // The cube's storage, and which faces hold their casters for the current light.
  void renderCube(Frame& f) {
    const int bits = std::stoi(bits_.name());
    const bool recreated = size_() != cube_size_ || bits != cube_bits_;
    if (recreated) {
      cube_ = Texture::depthCube(size_(), bits);
      cube_size_ = size_(), cube_bits_ = bits;
      for (int i = 0; i < 6; ++i) {
        framebuffers_[static_cast<size_t>(i)] = std::make_unique<Framebuffer>();
        framebuffers_[static_cast<size_t>(i)]->attachDepth(cube_, i);
        framebuffers_[static_cast<size_t>(i)]->check();
      }
      layered_framebuffer_.reset();
      if (caps().geometry_shaders) {
        layered_framebuffer_ = std::make_unique<Framebuffer>();
        layered_framebuffer_->attachDepthLayered(cube_);
        layered_framebuffer_->check();
      }
    }
    const bool stale = f.params.consume(kDirtyShadowMap) || !cache_() || recreated;
    if (stale) {
      // Every face starts empty (far: lit); a face is drawn once something needs it.
      PassState{}.apply();  // depth writes on, whatever the last pass left
      for (auto& fb : framebuffers_) {
        fb->bind();
        glViewport(0, 0, cube_size_, cube_size_);
        glClearDepthf(1.0f);
        glClear(GL_DEPTH_BUFFER_BIT);
      }
      drawn_.fill(false);
    }
    const glm::mat4 projection = cube::faceProjection(near_, far_);
    const glm::mat4 eye = f.projection * f.view;
    int rendered = 0, empty = 0, unseen = 0, mask = 0;
    std::array<glm::mat4, 6> faces;
    for (int i = 0; i < 6; ++i) {
      const auto k = static_cast<size_t>(i);
      faces[k] = projection * cube::faceView(light_, i);
      has_casters_[k] = !skip_() || anyCasterIn(f, faces[k]);
      seen_[k] = !skip_() || !cube::frustaDisjoint(faces[k], eye);
      if (!has_casters_[k]) {
        ++empty;
      } else if (!seen_[k]) {
        ++unseen;
      } else if (!drawn_[k]) {  // needed, and not in the cube since it last changed
        mask |= 1 << i;
        drawn_[k] = true;
        ++rendered;
      }
    }
    layered_used_ = passes_.name() == "layered" && layered_framebuffer_ != nullptr;
    if (layered_used_ && mask != 0) {
      renderLayered(f, mask, faces);
    } else {
      for (int i = 0; i < 6; ++i) {
        if ((mask >> i) & 1) renderFace(f, i, faces[static_cast<size_t>(i)]);
      }
    }
    f.measure.count("shadow_map_renders", rendered > 0 ? 1 : 0);
    countFaces(f, rendered, empty, unseen);
  }

  // The faces' counters, every frame (0 where no cube was made): the report keeps one set.
  static void countFaces(Frame& f, int rendered, int empty, int unseen) {
    f.measure.count("cube_faces_rendered", rendered);
    f.measure.count("cube_faces_empty", empty);
    f.measure.count("cube_faces_unseen", unseen);
  }

  // Lesson 04's bias in a face's pass: which faces go in, and the slope-scaled offset.
  PassState passBias() const {
    PassState state;
    state.cull = faces_.name() == "back";
    state.cull_face = GL_FRONT;
    state.polygon_offset = slope_() > 0.0f;
    state.offset_factor = slope_();
    return state;
  }

  void renderFace(Frame& f, int i, const glm::mat4& face) {
    auto timing = f.measure.pass("shadow");
    framebuffers_[static_cast<size_t>(i)]->bind();
    glViewport(0, 0, cube_size_, cube_size_);
    passBias().apply();
    const Program& d = depth_programs_.get({store_.defines()});
    d.set("uLightViewProjection", face);
    d.set("uLightPos", light_);
    d.set("uCubeFar", far_);
    f.drawObjects(d, Objects::Casters, skip_() ? &face : nullptr);
    PassState{}.apply();
  }

  // Every face the frame needs in one pass: the geometry shader copies each triangle into the
  // faces of `mask` whose frustum it reaches (gl_Layer), so each caster is drawn once.
  void renderLayered(Frame& f, int mask, const std::array<glm::mat4, 6>& faces) {
    auto timing = f.measure.pass("shadow");
    layered_framebuffer_->bind();
    glViewport(0, 0, cube_size_, cube_size_);
    const Program& d = layered_programs_.get({store_.defines()});
    for (int i = 0; i < 6; ++i) {
      d.set("uFaceViewProjection[" + std::to_string(i) + "]", faces[static_cast<size_t>(i)]);
    }
    d.set("uFaceMask", mask);
    d.set("uLightPos", light_);
    d.set("uCubeFar", far_);
    passBias().apply();
    f.drawObjects(d, Objects::Casters);
    PassState{}.apply();
  }

  bool anyCasterIn(const Frame& f, const glm::mat4& face) const {
    const Light& l = f.light;
    for (const SceneObject& o : f.scene.objects) {
      if (!o.castsFrom(l.position, false, l.direction)) continue;
      const Bounds b = o.worldBounds();
      if (!sphereOutsideFrustum(face, b.center(), b.radius())) return true;
    }
    return false;
  }

  void drawCross(Frame& f) {
    if (off_()) return;
    if (tetrahedron()) {  // the map itself: its four tiles, distance over far
      if (tetra_size_ > 0) f.drawDepthInset(tetra_map_, 0.0f, 1.0f, false, /*fullscreen=*/true);
      return;
    }
    cube_.bind(1);
    raw_.bind(1);
    bindParaboloids();
    const Program& c = cross_programs_.get({method_.defines(), store_.defines()});
    c.set("uCubeRaw", 1);
    setCubeUniforms(c);
    c.set("uAspect", static_cast<float>(f.width) / static_cast<float>(std::max(f.height, 1)));
    int drawn = 0;
    for (int i = 0; i < 6; ++i) drawn |= drawn_[static_cast<size_t>(i)] ? 1 << i : 0;
    c.set("uFacesRendered", drawn);
    f.drawFullscreen(c);
    for (int unit = 1; unit < 6; ++unit) Sampler::unbind(unit);
  }

  void setCubeUniforms(const Program& p) const {
    p.set("uLightPos", light_);
    p.set("uCubeNear", near_);
    p.set("uCubeFar", far_);
    p.set("uCubeSize", static_cast<float>(paraboloid()    ? paraboloid_size_
                                          : tetrahedron() ? tetra_size_
                                                          : cube_size_));
    p.set("uTetra", 6);
    p.set("uTetraRaw", 7);
    if (tetrahedron()) {  // the faces' matrices only where they are read
      p.set("uTetraTexel", tetra::texelAtUnitDistance(std::max(tetra_size_, 1)));
      for (int i = 0; i < tetra::kFaces; ++i) {
        char at[8];
        std::snprintf(at, sizeof at, "[%d]", i);
        p.set(std::string("uTetraFace") + at, tetraFace(i));
        p.set(std::string("uTetraDir") + at, tetra::faceDirection(i));
      }
    }
    for (const auto& [name, unit] : {std::pair{"uParaboloidUp", 2},
                                     {"uParaboloidDown", 3},
                                     {"uParaboloidUpRaw", 4},
                                     {"uParaboloidDownRaw", 5}}) {
      p.set(name, unit);
    }
  }

  bool paraboloid() const { return method_.name() == "paraboloid"; }
  bool tetrahedron() const { return method_.name() == "tetrahedron"; }
  bool cube() const { return !paraboloid() && !tetrahedron(); }

  glm::mat4 tetraFace(int i) const {
    return tetra::faceProjection(i, near_, far_) * tetra::faceView(light_, i);
  }

  void bindTetrahedron() const {
    if (!tetrahedron() || tetra_size_ == 0) return;
    tetra_map_.bind(6);
    (filter_.name() == "linear" ? compare_linear_ : compare_nearest_).bind(6);
    tetra_map_.bind(7);
    raw_.bind(7);
  }

  // Pass 1 as four faces of a tetrahedron, each its tile of one 2D map (the distance store),
  // skipped and counted as the cube's faces are: no caster in it, or out of the eye's sight.
  void renderTetrahedron(Frame& f) {
    const int bits = std::stoi(bits_.name());
    const int tile = tetra::tileSizeFor(size_());
    const bool recreated = tile != tetra_size_ || bits != tetra_bits_;
    if (recreated) {
      tetra_map_ = Texture::depth(2 * tile, 2 * tile, bits);
      tetra_framebuffer_ = std::make_unique<Framebuffer>();
      tetra_framebuffer_->attachDepth(tetra_map_);
      tetra_framebuffer_->check();
      tetra_size_ = tile, tetra_bits_ = bits;
    }
    drawn_.fill(false);  // the cube holds nothing current while the tetrahedron is used
    tetra_framebuffer_->bind();
    PassState{}.apply();
    if (f.params.consume(kDirtyShadowMap) || !cache_() || recreated) {
      glViewport(0, 0, 2 * tile, 2 * tile);
      glClearDepthf(1.0f);
      glClear(GL_DEPTH_BUFFER_BIT);
      tetra_drawn_.fill(false);
    }
    const glm::mat4 eye = f.projection * f.view;
    int rendered = 0, empty = 0, unseen = 0;
    for (int i = 0; i < tetra::kFaces; ++i) {
      const auto k = static_cast<size_t>(i);
      const glm::mat4 face = tetraFace(i);
      tetra_casters_[k] = !skip_() || anyCasterIn(f, face);
      tetra_seen_[k] = !skip_() || !cube::frustaDisjoint(face, eye);
      if (!tetra_casters_[k]) {
        ++empty;
      } else if (!tetra_seen_[k]) {
        ++unseen;
      } else if (!tetra_drawn_[k]) {
        renderTetraFace(f, i, face);
        tetra_drawn_[k] = true;
        ++rendered;
      }
    }
    f.measure.count("shadow_map_renders", rendered > 0 ? 1 : 0);
    countFaces(f, rendered, empty, unseen);
  }

  void renderTetraFace(Frame& f, int i, const glm::mat4& face) {
    auto timing = f.measure.pass("shadow");
    tetra_framebuffer_->bind();
    const glm::ivec2 at = glm::ivec2(tetra::tileOffset(i) * 2.0f) * tetra_size_;
    glViewport(at.x, at.y, tetra_size_, tetra_size_);
    passBias().apply();
    const Program& d = depth_programs_.get({choiceDefines("cube.store", kStores, "distance")});
    d.set("uLightViewProjection", face);
    d.set("uLightPos", light_);
    d.set("uCubeFar", far_);
    f.drawObjects(d, Objects::Casters, skip_() ? &face : nullptr);
    PassState{}.apply();
  }

  std::string tetraState(int i) const {
    const auto k = static_cast<size_t>(i);
    if (!tetrahedron()) return "off";
    return tetra_drawn_[k]      ? "rendered"
           : !tetra_casters_[k] ? "empty"
           : !tetra_seen_[k]    ? "unseen"
                                : "off";
  }

  // Dual paraboloids at the cube's texel count: two p x p maps for six s x s faces, p = s √3.
  int paraboloidSize() const {
    return static_cast<int>(std::lround(static_cast<double>(size_()) * std::sqrt(3.0)));
  }

  void bindParaboloids() const {
    if (!paraboloid() || paraboloid_size_ == 0) return;
    for (int h = 0; h < 2; ++h) {
      const Texture& map = paraboloids_[static_cast<size_t>(h)];
      map.bind(2 + h);
      (filter_.name() == "linear" ? compare_linear_ : compare_nearest_).bind(2 + h);
      map.bind(4 + h);
      raw_.bind(4 + h);
    }
  }

  // Pass 1 as two hemispheres, +y then -y, each its half of space warped onto a disk.
  void renderParaboloids(Frame& f) {
    const int bits = std::stoi(bits_.name());
    const int size = paraboloidSize();
    const bool recreated = size != paraboloid_size_ || bits != paraboloid_bits_;
    if (recreated) {
      for (int h = 0; h < 2; ++h) {
        const auto k = static_cast<size_t>(h);
        paraboloids_[k] = Texture::depth(size, size, bits);
        // Outside the disk nothing is stored: lit.
        paraboloid_framebuffers_[k] = std::make_unique<Framebuffer>();
        paraboloid_framebuffers_[k]->attachDepth(paraboloids_[k]);
        paraboloid_framebuffers_[k]->check();
      }
      paraboloid_size_ = size, paraboloid_bits_ = bits;
    }
    const bool stale = f.params.consume(kDirtyShadowMap) || !cache_() || recreated;
    drawn_.fill(false);  // the cube holds nothing current while the paraboloids are used
    if (stale) {
      const Program& d = paraboloid_programs_.get({});
      PassState state = passBias();
      state.clip_plane = true;  // the other hemisphere
      for (int h = 0; h < 2; ++h) {
        auto timing = f.measure.pass("shadow");
        paraboloid_framebuffers_[static_cast<size_t>(h)]->bind();
        glViewport(0, 0, size, size);
        PassState{}.apply();
        glClear(GL_DEPTH_BUFFER_BIT);
        state.apply();
        d.set("uLightPos", light_);
        d.set("uHemisphere", h == 0 ? 1.0f : -1.0f);
        d.set("uCubeFar", far_);
        f.drawObjects(d, Objects::Casters);
        PassState{}.apply();
      }
    }
    f.measure.count("shadow_map_renders", stale ? 1 : 0);
    countFaces(f, 0, 0, 0);
  }

  // As the GL stores it: 24-bit depth is padded to 32 bits a texel.
  static int bytesPerTexel(int bits) { return bits == 16 ? 2 : 4; }

  std::string passesFallback() const {
    return passes_.name() == "layered" && !caps().geometry_shaders
               ? "no geometry shaders on " + caps().flavour
               : "";
  }

  std::string faceState(int i) const {
    const auto k = static_cast<size_t>(i);
    if (!cube()) return "off";  // another method's map is in use
    return drawn_[k] ? "rendered" : !has_casters_[k] ? "empty" : !seen_[k] ? "unseen" : "off";
  }

  ChoiceParam<Store> store_;
  ChoiceParam<> bits_, filter_, passes_, method_;
  IntParam size_;
  BoolParam seamless_, skip_, cache_, off_;
  FloatParam bias_, normal_, slope_, dimming_;
  ChoiceParam<> faces_;
  ProgramVariants depth_programs_, layered_programs_, paraboloid_programs_, eye_programs_,
      cross_programs_;
  Sampler compare_nearest_, compare_linear_, raw_;
  Texture cube_;
  std::array<std::unique_ptr<Framebuffer>, 6> framebuffers_;
  std::unique_ptr<Framebuffer> layered_framebuffer_;  // the whole cube (GL 3.2)
  bool layered_used_ = false;
  std::array<Texture, 2> paraboloids_;  // omni.method=paraboloid: +y, -y
  std::array<std::unique_ptr<Framebuffer>, 2> paraboloid_framebuffers_;
  int paraboloid_size_ = 0, paraboloid_bits_ = 0;
  Texture tetra_map_;  // omni.method=tetrahedron: four tiles, 2 x 2
  std::unique_ptr<Framebuffer> tetra_framebuffer_;
  int tetra_size_ = 0, tetra_bits_ = 0;
  std::array<bool, tetra::kFaces> tetra_drawn_{}, tetra_casters_{}, tetra_seen_{};
  // The texels per pixel (measureTexels), and what they were measured for.
  Texture texel_color_, texel_depth_;
  std::unique_ptr<Framebuffer> texel_target_;
  int texel_target_w_ = 0, texel_target_h_ = 0;
  TexelStats texel_stats_;
  std::string texel_key_;
  int cube_size_ = 0, cube_bits_ = 0;
  std::array<bool, 6> drawn_{}, has_casters_{}, seen_{};
  glm::vec3 light_{0.0f};
  float near_ = 0.1f, far_ = 20.0f;
};

SHADOWS_LESSON(OmniCube);

}  // namespace shadows
