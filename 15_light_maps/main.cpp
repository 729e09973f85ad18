// Lesson 15: static shadows baked into light maps (seed 003, "Static shadows": "incorporate
// shadows into light maps. For each texel, cast ray to each light source. Bake soft shadows
// in light maps ... sample area light sources"; seed 000 lists light maps among the common
// techniques), and the hybrid engines ship: the bake for what stands still, lesson 03's map for
// what moves.
//
//   Bake, once: every surface is cut into charts along its unwrap and packed into one atlas
//   (math/light_map_atlas.hpp); each texel's surface point casts `lightmap.samples` rays to the
//   disk light, stratified as the truth's, with the truth's own tracer (LessonHost::bake).
//   Frame: one texture lookup a pixel. Nothing is drawn from the light.
//   What breaks: move the caster (move.x, move.z) or the light after the bake, and the baked
//   shadow stays where it was. Hybrid: the bake without the moving caster, times lesson 03's
//   map of that caster alone.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "core/json.hpp"
#include "lesson/lesson.hpp"
#include "math/light_map_atlas.hpp"
#include "shadow/shadow_map.hpp"

namespace shadows {

namespace {
enum class Mode { Baked, Hybrid, Map };
enum class MapHolds { Nothing, All, Moving };  // what lesson 03's map was last drawn with
const std::vector<std::string> kModes = {"baked", "hybrid", "map"};
constexpr int kUvWidth = 1024;  // the coordinate texture's rows: 1024 vertices each
}  // namespace

class LightMaps final : public Lesson {
 public:
  std::string title() const override { return "Light maps: shadows baked once, read every frame"; }
  std::string seeds() const override {
    return "seed 003: Static shadows (light maps: a ray from each texel to each light, area "
           "lights sampled); seed 000: Common Real-time Shadow Techniques (light maps)";
  }
  static constexpr View kAtlas{"atlas"};
  static constexpr View kTexelGrid{"texel_grid"};
  static constexpr View kNoise{"noise"};
  std::vector<View> debugViews() const override {
    return {kAtlas, kTexelGrid, kNoise, views::kLightDepth};
  }
  std::vector<std::string> scenes() const override {
    return {"torus_pyramid", "contact", "overlap", "grazing", "cubes"};
  }

  void declare(Params& p) override {
    map_.declare(p);  // lesson 03's map: the hybrid's moving caster, and the comparison
    mode_ = p.addChoice("lightmap.mode", kModes, "baked",
                        "baked: the light map alone; hybrid: baked static casters times lesson "
                        "03's map of the moving one; map: lesson 03's map for everything",
                        kDirtyShadowMap);
    density_ = p.addFloat("lightmap.texels_per_unit", 16.0f, 1.0f, 128.0f,
                          "light map texels per world unit along a surface")
                   .logScale();
    samples_ = p.addInt("lightmap.samples", 64, 1, 256,
                        "rays a texel to the disk light, stratified (rounded to a square)");
    filter_ = p.addChoice("lightmap.filter", {"bilinear", "nearest"}, "bilinear",
                          "the light map lookup's filter");
    padding_ = p.addInt("lightmap.padding", 2, 0, 8, "texels between charts in the atlas");
    centres_ = p.addBool("lightmap.texel_centres", true,
                         "a chart's border on its outer texels' centres (off: on their edges, "
                         "where a bilinear lookup reads half a texel of padding)");
    dilate_ = p.addBool("lightmap.dilate", true,
                        "fill the padding and uncovered texels from their chart's neighbours");
    radius_ = p.addFloat("lightmap.light_radius", 0.3f, 0.0f, 1.0f,
                         "the light's disk radius, world units (the truth's light too)");
    bake_at_ = p.addChoice("lightmap.bake_at", {"preset", "current"}, "preset",
                           "preset: baked as the scene was built, whatever moves later; "
                           "current: baked again for the light and casters as they are now");
    moving_ = p.addInt("move.object", -1, -1, 15,
                       "the object that moves: its index in the scene (-1: the last one)",
                       kDirtyShadowMap);
    move_x_ = p.addFloat("move.x", 0.0f, -4.0f, 4.0f, "move the object along x after the bake");
    move_z_ = p.addFloat("move.z", 0.0f, -4.0f, 4.0f, "move the object along z after the bake");
    dimming_ = p.addFloat("dimming", 0.4f, 0.0f, 1.0f,
                          "diffuse left in shadow: dimming + (1-dimming)*shade");
    bias_.declare(p);  // lesson 04's default for the map: back faces, plus glPolygonOffset
    // What acts only in some modes says so on the panel (greyed, with why).
    const auto baked_only = [](const Params& ps) -> std::string {
      return ps.at("lightmap.mode").is("baked") ? "the baked mode reads no shadow map" : "";
    };
    const auto map_only = [](const Params& ps) -> std::string {
      return ps.at("lightmap.mode").is("map") ? "the map mode bakes nothing" : "";
    };
    for (Param* q : {bias_.params()[0], bias_.params()[1], &p.at("shadow.size"),
                     &p.at("shadow.height"), &p.at("shadow.format"), &p.at("shadow.filter"),
                     &p.at("shadow.fit"), &p.at("shadow.cache"), &p.at("inset")}) {
      // Keep what the map's own settings say (shadow.height: only with a size of its own).
      q->inactive = [baked_only, own = q->inactive](const Params& ps) {
        const std::string why = baked_only(ps);
        return why.empty() && own ? own(ps) : why;
      };
    }
    for (Param* q : {&density_.param(), &samples_.param(), &filter_.param(), &padding_.param(),
                     &centres_.param(), &dilate_.param(), &bake_at_.param()}) {
      q->inactive = map_only;
    }
  }

  // Over its memory limit a light map is refused before anything is drawn (exit 2).
  std::string refusal(const Params&, const Scene& scene) const override {
    return lightMapRefusal(planLightMap(scene.objects, density_(), padding_(), !centres_()));
  }

  void init() override {
    eye_programs_ = ProgramVariants(lessonFile(LESSON_DIR, "lightmap.vert"),
                                    lessonFile(LESSON_DIR, "scene.frag"));
    light_map_ = unbakedMap(1, 1);  // until a bake, and in map mode: lit everywhere
  }

  void render(Frame& f) override {
    const size_t moving = f.scene.movingObject(moving_());
    // The caster moves after the bake: everything live follows it (the map, the truth). The
    // others stand where the preset put them (one that moved before move.object changed too).
    f.placeMoved(moving, glm::vec3(move_x_(), 0.0f, move_z_()));
    if (mode_() != Mode::Map) {
      requestBake(f, moving);
    } else if (!baked_for_.empty()) {  // map mode bakes nothing, and shows nothing baked
      baked_for_.clear();
      atlas_ = {};
      refused_.clear();
      light_map_ = unbakedMap(1, 1);
      uv_ = Texture();
      shown_id_ = 0;
      covered_ = 0;
      from_cache_ = false;
      bake_seconds_ = 0.0;
      bake_rays_ = 0;
    }
    findBorders(f.scene, moving);
    showBake(f.runner.bakeState());
    f.truth_area_radius = radius_();  // every mode is scored against the disk light

    // Lesson 03's pass 1, where a mode reads a map: every caster, or only the moving one (the
    // baked mode draws none, but shows lesson 03's in its light_depth view).
    const MapHolds needed = mode_() == Mode::Hybrid ? MapHolds::Moving
                            : mode_() == Mode::Map || f.shows(views::kLightDepth)
                                ? MapHolds::All
                                : MapHolds::Nothing;
    const bool stale = map_.prepare(f);
    // Every mode is counted in lesson 03's light frustum; the runner's texels per pixel (and
    // its aliasing view) are of its map, of no meaning where no pixel reads it.
    f.light_view_projection = map_.lightViewProjection();
    if (mode_() != Mode::Baked) f.shadow_sampling = map_.light().sampling();
    if (stale) map_holds_ = MapHolds::Nothing;
    if (needed != MapHolds::Nothing && needed != map_holds_) {
      const PassState bias = bias_.state();
      if (needed == MapHolds::Moving) {
        map_.renderObject(f, moving, bias);
      } else {
        map_.renderCasters(f, bias);
      }
      map_holds_ = needed;
    }
    if (map_.drawDepthView(f)) return;
    if (f.shows(kAtlas)) {  // the light map itself, every chart in its place
      f.clearTarget(glm::vec3(0.0f));
      if (light_map_.id() != 0) f.drawImageInset(light_map_, /*fullscreen=*/true);
      return;
    }

    auto timing = f.measure.pass("eye", /*countPassed=*/true);
    f.clearTarget();
    if (light_map_.id() != 0) {
      light_map_.setFilter(filter_.name() == "nearest" ? GL_NEAREST : GL_LINEAR);
      light_map_.bind(0);
    }
    uv_.bind(1);
    map_.texture().bind(2);
    const Program& e =
        eye_programs_.get({mode_.defines(), f.viewDefines(), define("SHADOW_OFF", map_.off())});
    e.set("uViewProjection", f.projection * f.view);
    e.set("uShadowMatrix", map_.textureMatrix());
    e.set("uLightMap", 0);
    e.set("uUv", 1);
    e.set("uShadowMap", 2);
    e.set("uUvRowsPerObject", uv_rows_);
    e.set("uMovingObject", static_cast<int>(moving));
    e.set("uSamples", static_cast<float>(std::max(raysPerTexel(), 1)));
    f.setLightingUniforms(e, dimming_());
    f.drawObjects(e, Objects::All);
    if (!f.shows(views::kVisibility) && mode_() != Mode::Baked) map_.drawInset(f);
  }

  void panel(Frame& f) override {
    Params& p = f.params;
    auto preset = [&](const char* label, const char* mode) {
      if (ImGui::Button(label)) p.setChoice(mode_.param(), mode);
    };
    preset("baked", "baked");
    ImGui::SameLine();
    preset("hybrid", "hybrid");
    ImGui::SameLine();
    preset("map (03)", "map");
    if (mode_() == Mode::Map) {
      ImGui::TextWrapped("map mode: nothing baked, lesson 03's map for every caster");
    } else if (!refused_.empty()) {
      ImGui::TextWrapped("refused: %s", refused_.c_str());
    } else {
      bakeLines(f);
    }
    const ErrorState& error = f.runner.lastError();
    if (error.valid) {
      ImGui::TextWrapped("error: vis_mae %.4f against a disk light, r = %.2f",
                         error.metrics.vis_mae, radius_());
    }
  }

  // What the panel says of the bake: the atlas, then how far it got.
  void bakeLines(Frame& f) {
    ImGui::TextWrapped("light map: %d x %d texels, %zu charts, %.1f MB", atlas_.width,
                       atlas_.height, atlas_.charts.size(), static_cast<double>(bytes()) / 1e6);
    const BakeState& bake = f.runner.bakeState();
    switch (bake.stage) {
      case BakeState::Stage::kRunning:
        ImGui::ProgressBar(static_cast<float>(bake.progress), ImVec2(-1.0f, 0.0f), "baking");
        if (ImGui::Button("cancel the bake")) f.runner.cancelBake();
        break;
      case BakeState::Stage::kDone:
        if (bake.from_cache) {
          ImGui::TextWrapped("loaded from the disk cache (%.1f M rays when it was baked)",
                             static_cast<double>(bake.rays) / 1e6);
        } else {
          ImGui::TextWrapped("baked in %.2f s: %.1f M rays", bake.seconds,
                             static_cast<double>(bake.rays) / 1e6);
        }
        break;
      case BakeState::Stage::kCancelled:
      case BakeState::Stage::kFailed:
        ImGui::TextWrapped("bake %s: %s",
                           bake.stage == BakeState::Stage::kFailed ? "failed" : "cancelled",
                           bake.message.c_str());
        if (ImGui::Button("bake again")) baked_for_.clear();
        break;
      case BakeState::Stage::kNone:
        break;
    }
  }

  // instructor/SOLUTIONS.md has the intended solutions (kept off the students' site).
  std::vector<Exercise> exercises() const override {
    using B = Figure::Bound;
    return {{.title = "A bake on a budget",
             .goal = "4 texels a unit and 256 samples a texel: 1.16 M rays, and the shadows "
                     "come out blurred and blocky (vis_mae 0.022). Spend at most 1.2 M rays and "
                     "get vis_mae to 0.0040 or less.",
             .setup = {"lightmap.texels_per_unit=4", "lightmap.samples=256"},
             .allowed = {"lightmap.texels_per_unit", "lightmap.samples"},
             .figures = {{"/error/vis_mae", "vis_mae", B::AtMost, 0.0040},
                         {"/lightmap/bake_rays", "bake rays", B::AtMost, 1200000}},
             .hint = "Which do you see in view=noise, and which in view=texel_grid? Rays are "
                     "texels times samples: put them where the error is."},
            {.title = "The ball rolled",
             .goal = "The ball rolled 1.5 to the left after the bake, and its baked shadow "
                     "stayed behind (vis_mae 0.033). Without baking where the ball now is, get "
                     "vis_mae to 0.0045 or less.",
             .setup = {"move.x=-1.5"},
             .allowed = {"lightmap.mode", "shadow.size"},
             .figures = {{"/error/vis_mae", "vis_mae", B::AtMost, 0.0045}},
             .hint = "What engines do: keep what stands still baked, and give what moves a "
                     "shadow of its own every frame."}};
  }

  // What the truth shows of the atlas's seams: pixels within 1.5 texels of a chart's border.
  std::vector<ErrorRegion> errorRegions() const override {
    const float reach = 1.5f / std::max(density_(), 1e-3f);
    const auto* borders = &borders_;
    return {{"seams", [borders, reach](glm::vec4 p) {
               const int object = static_cast<int>(p.w);
               if (object < 0 || static_cast<size_t>(object) >= borders->size()) return false;
               for (const Segment& s : (*borders)[static_cast<size_t>(object)]) {
                 if (distanceToSegment(glm::vec3(p), s) <= reach) return true;
               }
               return false;
             }}};
  }

  void report(JsonWriter& json) const override {
    json.value("truth_area_radius", radius_());
    json.beginObject("lightmap");
    json.value("width", atlas_.width);
    json.value("height", atlas_.height);
    json.value("texels", atlas_.texels());
    json.value("covered_texels", covered_);
    json.value("charts", static_cast<long long>(atlas_.charts.size()));
    json.value("samples_per_texel", raysPerTexel());
    json.value("bytes", bytes());
    json.value("baked", shown_id_ != 0);
    json.value("from_cache", from_cache_);
    json.value("bake_seconds", bake_seconds_);
    json.value("bake_rays", bake_rays_);
    json.endObject();
  }

 private:
  int samplesPerTexel() const {
    const int k = TruthLight::sampleSide(samples_());
    return k * k;
  }
  // The rays the bake casts from a texel, as the truth traces them (one to a point light);
  // none in map mode.
  int raysPerTexel() const {
    return mode_() == Mode::Map
               ? 0
               : TruthLight{.radius = radius_(), .samples = samples_()}.raysPerPoint();
  }
  long long bytes() const {  // the texture (2 bytes a texel) and the coordinates (8 a vertex)
    return atlas_.texels() * 2 + static_cast<long long>(uv_.width()) * uv_.height() * 8;
  }

  // The bake's inputs: the objects where they stood (preset) or stand, the light likewise.
  void requestBake(Frame& f, size_t moving) {
    const bool current = bake_at_.name() == "current";
    const glm::vec3 light = current ? f.light.position : f.scene.light.position;
    const glm::vec3 target = current ? f.light.target : f.scene.light.target;
    // A preset's sun is a sun in its bake too (lesson 16's street), not a lamp where it stands.
    const bool directional = current ? f.light.directional : f.scene.light.directional;
    char key[512];
    std::snprintf(key, sizeof key, "%s|%g|%d%d|%d|%g|%d|%d|%zu|%g,%g,%g|%g,%g,%g|%g,%g",
                  f.scene.name.c_str(), density_(), padding_(), centres_() ? 1 : 0,
                  samplesPerTexel(), radius_(), current ? 1 : 0, mode_() == Mode::Hybrid ? 1 : 0,
                  moving, light.x, light.y, light.z, target.x, target.y, target.z,
                  current ? move_x_() : 0.0f, current ? move_z_() : 0.0f);
    const std::string inputs = key + std::string(directional ? "|dir" : "");
    if (inputs == baked_for_) return;
    baked_for_ = inputs;
    std::vector<SceneObject> objects = f.scene.objects;
    if (!current) {
      for (size_t k = 0; k < objects.size(); ++k) objects[k].model = f.runner.presetModel(k);
    }
    atlas_ = planLightMap(objects, density_(), padding_(), !centres_());
    refused_ = lightMapRefusal(atlas_);
    GLint most = 0;  // the GL's own limit, where it is below ours (2048 in ES 3.0 at least)
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &most);
    if (refused_.empty() && std::max(atlas_.width, atlas_.height) > most) {
      refused_ = "the light map would be " + std::to_string(atlas_.width) + " x " +
                 std::to_string(atlas_.height) + " texels, over this GL's largest texture (" +
                 std::to_string(most) + "): lower lightmap.texels_per_unit";
    }
    shown_id_ = 0;
    if (!refused_.empty()) {  // drawn unbaked, and no bake of an earlier setting goes on
      f.runner.cancelBake();
      light_map_ = unbakedMap(1, 1);
      covered_ = 0;
      return;
    }
    fillLightMap(objects, atlas_);
    covered_ = atlas_.coveredTexels();
    uploadCoordinates();
    light_map_ = unbakedMap(std::max(atlas_.width, 1), std::max(atlas_.height, 1));

    BakeRequest request;
    Scene casters;  // the moving caster casts into the hybrid's map, not into the bake
    for (size_t k = 0; k < objects.size(); ++k) {
      if (!(mode_() == Mode::Hybrid && k == moving)) casters.objects.push_back(objects[k]);
    }
    casters.worldTriangles(request.positions, request.triangles);
    Bounds bounds;  // the scene as baked: where the ball stands now changes no preset bake
    for (const SceneObject& o : objects) bounds.add(o.worldBounds());
    request.scene_radius = bounds.radius();
    // The points and normals go to the bake (the atlas keeps which texels they covered).
    request.texels = {atlas_.width, atlas_.height, std::move(atlas_.position),
                      std::move(atlas_.normal)};
    atlas_.position = {};
    atlas_.normal = {};
    request.light.position = light;
    request.light.directional = directional;
    const glm::vec3 axis = target - light;
    request.light.direction =
        glm::dot(axis, axis) > 0.0f ? glm::normalize(axis) : glm::vec3(0, -1, 0);
    request.light.radius = radius_();
    request.light.samples = samplesPerTexel();
    f.runner.bake(std::move(request));
  }

  static Texture unbakedMap(int width, int height) {
    Texture t = Texture::color(width, height, GL_R16F);
    t.setSwizzle(GL_RED, GL_RED, GL_RED, GL_ONE);  // grey in the atlas view
    const std::vector<float> lit(static_cast<size_t>(width) * height, 1.0f);
    t.upload(GL_RED, GL_FLOAT, lit.data());
    return t;
  }

  // The charts' borders where the objects stand now, for the seams' error.
  void findBorders(const Scene& scene, size_t moving) {
    char key[256];
    std::snprintf(key, sizeof key, "%s|%zu|%g|%g", scene.name.c_str(), moving, move_x_(),
                  move_z_());
    if (key == borders_for_) return;
    borders_for_ = key;
    borders_ = chartBorders(scene.objects);
  }

  // Per vertex its atlas coordinate, kUvWidth to a row, the same rows for every object.
  void uploadCoordinates() {
    size_t most = 1;
    for (const auto& uv : atlas_.uv) most = std::max(most, uv.size());
    uv_rows_ = static_cast<int>((most + kUvWidth - 1) / kUvWidth);
    const size_t rows = static_cast<size_t>(uv_rows_) * std::max<size_t>(atlas_.uv.size(), 1);
    std::vector<glm::vec2> texels(rows * kUvWidth, glm::vec2(-1.0f));
    for (size_t k = 0; k < atlas_.uv.size(); ++k) {
      std::copy(atlas_.uv[k].begin(), atlas_.uv[k].end(),
                texels.begin() + static_cast<std::ptrdiff_t>(k * uv_rows_ * kUvWidth));
    }
    uv_ = Texture::color(kUvWidth, static_cast<int>(rows), GL_RG32F);
    uv_.setFilter(GL_NEAREST);
    uv_.upload(GL_RG, GL_FLOAT, texels.data());
  }

  // A finished bake into the texture: facing away counts as dark, and the texels no triangle
  // covers take their neighbours' values so a bilinear lookup at a chart's edge blends in
  // nothing foreign.
  void showBake(const BakeState& bake) {
    const bool shown = bake.id == shown_id_ && dilate_() == shown_dilated_;
    if (bake.stage != BakeState::Stage::kDone || shown || !refused_.empty() || !bake.visibility ||
        bake.visibility->size() != static_cast<size_t>(atlas_.texels())) {
      return;
    }
    std::vector<float> texels = *bake.visibility;
    for (float& v : texels) v = std::max(v, 0.0f);  // kNotCounted: facing away, or no surface
    if (dilate_()) dilateLightMap(atlas_, texels, padding_() + 2);
    light_map_.upload(GL_RED, GL_FLOAT, texels.data());
    shown_id_ = bake.id;
    shown_dilated_ = dilate_();
    from_cache_ = bake.from_cache;
    bake_seconds_ = bake.from_cache ? 0.0 : bake.seconds;
    bake_rays_ = bake.rays;
  }

  ShadowMap map_;
  ProgramVariants eye_programs_;
  MapHolds map_holds_ = MapHolds::Nothing;
  Texture light_map_, uv_;
  int uv_rows_ = 1;
  LightMapAtlas atlas_;
  std::vector<std::vector<Segment>> borders_;
  long long covered_ = 0;
  std::string baked_for_, borders_for_, refused_;
  std::uint64_t shown_id_ = 0;
  bool from_cache_ = false, shown_dilated_ = false;
  double bake_seconds_ = 0.0;
  long long bake_rays_ = 0;
  ChoiceParam<Mode> mode_;
  ChoiceParam<> filter_, bake_at_;
  FloatParam density_, radius_, move_x_, move_z_, dimming_;
  BackFaceBias bias_;
  IntParam samples_, padding_, moving_;
  BoolParam centres_, dilate_;
};

SHADOWS_LESSON(LightMaps);

}  // namespace shadows
