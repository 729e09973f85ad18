// What a lesson's main.cpp sees: the Lesson it implements, the Frame it draws into, the light
// and the objects it draws, and the little it may ask of the runner (LessonHost). The runner
// itself (run/) is not included here, so a lesson cannot reach into it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "core/scene.hpp"
#include "gl/gl.hpp"
#include "gl/measure.hpp"
#include "gl/program.hpp"
#include "lesson/exercise.hpp"
#include "lesson/view.hpp"
#include "math/shadow_math.hpp"
#include "math/texel_density.hpp"
#include "truth/truth_types.hpp"

namespace shadows {

class JsonWriter;
struct Frame;

// The light as the shared parameters describe it this frame.
struct Light {
  bool directional = false;
  glm::vec3 position{0.0f}, target{0.0f}, direction{0.0f, -1.0f, 0.0f};
  float fov = 60.0f, extent = 10.0f, near = 1.0f, far = 20.0f;
  glm::mat4 view{1.0f};
  LightFrustum frustum(float aspect) const { return {directional, fov, extent, aspect, near, far}; }
};

// Which objects a draw takes: All is the eye's view; Casters what can shadow a surface, as
// the light sees it (SceneObject::castsFrom); Occluders every object, as the light sees it
// (in dusty air every surface shadows the air behind it, the floor the air beneath it).
enum class Objects { All, Casters, Receivers, Occluders };

struct ErrorState {
  ErrorMetrics metrics;
  bool valid = false;
  std::shared_ptr<const ErrorPixels> pixels;
};

// Lesson 15's bake (seed 003: "for each texel, cast ray to each light source"): the truth's
// own tracer, run over a light map's texels instead of the eye's pixels.
struct BakeRequest {
  std::vector<glm::vec3> positions;  // the casters' world triangles, as the bake sees them
  std::vector<glm::uvec3> triangles;
  float scene_radius = 0.0f;
  SurfaceBuffer texels;  // per texel its surface point and normal (position.w < 0: none)
  TruthLight light;      // an area light: radius and samples a texel
};
struct BakeState {
  enum class Stage { kNone, kRunning, kDone, kFailed, kCancelled };
  Stage stage = Stage::kNone;
  std::uint64_t id = 0;   // the request's (its inputs' hash; the disk cache's key)
  double progress = 0.0;  // [0, 1], of the rows traced
  bool from_cache = false;
  double seconds = 0.0;  // the trace's time, this run's (0 when loaded from the cache)
  long long rays = 0;    // shadow rays the trace casts (texels facing the light x samples)
  std::string message;   // kFailed: why; else where the cache file is, or why there is none
  std::shared_ptr<const std::vector<float>> visibility;  // kDone: one value per texel
};

// What a lesson may ask of the runner that runs it (Frame::runner): the last error measured,
// and one scene object's placement. Everything else of the runner is out of a lesson's reach.
class LessonHost {
 public:
  // The last error measured (may be stale while sliders move): lessons name it in their panel.
  virtual const ErrorState& lastError() const = 0;
  // Moves one scene object (lesson 01 tilts its receiver plane). Everything follows it: the
  // lesson's draws, the runner's geometry pass and the ray-traced truth, which is rebuilt
  // when the matrix really changed. A scene preset change puts the preset's matrix back.
  virtual void setObjectModel(size_t index, const glm::mat4& model) = 0;
  // The object's matrix as the scene preset placed it, before any setObjectModel.
  virtual const glm::mat4& presetModel(size_t index) const = 0;
  // Bakes a light map (lesson 15): starts the request unless it is the one already running or
  // done, and answers from the disk cache when it holds the same inputs. A window bakes on a
  // thread while frames go on (bakeState() says how far), a page in Web Workers; a headless
  // run waits for it. One bake at a time: a new request cancels the running one.
  virtual void bake(BakeRequest request) = 0;
  virtual const BakeState& bakeState() const = 0;
  virtual void cancelBake() = 0;

 protected:
  ~LessonHost() = default;
  // What Frame's draw helpers do: the scene's meshes and the runner's inset programs.
  friend struct Frame;
  virtual void drawObjects(const Frame& frame, const Program& program, Objects which,
                           const glm::mat4* cull) const = 0;
  virtual void drawObject(const Program& program, size_t index) const = 0;
  virtual void drawInset(const Frame& frame, const Texture& depth, float near, float far,
                         bool perspective, bool fullscreen) const = 0;
  virtual void drawImageInset(const Frame& frame, const Texture& image, bool fullscreen) const = 0;
  virtual void drawFullscreen(const Frame& frame, const Program& program, bool inset) const = 0;
};

// What a lesson's render() sees: the scene, the camera, the light, the target to draw into.
struct Frame {
  Frame(LessonHost& runner_, Params& params_, const Scene& scene_, Measure& measure_,
        const Light& light_)
      : runner(runner_), params(params_), scene(scene_), measure(measure_), light(light_) {}
  LessonHost& runner;
  Params& params;
  const Scene& scene;
  Measure& measure;
  const Light& light;
  glm::mat4 view{1.0f}, projection{1.0f};
  glm::vec3 eye{0.0f};
  int width = 0, height = 0;
  GLuint target = 0;
  View shown = views::kShaded;  // the view to render: shaded, visibility or a debug view
  bool shows(View v) const { return shown == v; }

  // Outputs the runner uses: the light frustum the shadow term is valid in (pixels
  // outside it are not counted against the truth).
  std::optional<glm::mat4> light_view_projection;
  // An omni light's reach (lesson 11), as light_view_projection is a map's frustum: pixels the
  // cube cannot hold (before its near plane along a face's axis, at or beyond its far) are not
  // counted either.
  struct LightReach {
    glm::vec3 position{0.0f};
    float near = 0.0f;            // along the face's axis (max |v.x|, |v.y|, |v.z|); 0: none
    float far = 0.0f;             // along the axis, or the distance itself
    bool far_along_axis = false;  // a depth cube's faces end at far; a distance store at |v|
  };
  std::optional<LightReach> light_reach;
  // The light the truth should use: 0 = a point (hard shadows); a soft-shadow lesson sets
  // the radius of the area light its filter imitates.
  float truth_area_radius = 0.0f;
  // A lesson with a participating medium (08) describes it here: the runner then also renders
  // its view "air" (the in-scattered light alone, unscaled, in red) and measures it against
  // Truth::airLight.
  std::optional<AirMedium> medium;
  // A window while its camera or a slider moves (until input rests, as the truth waits): a
  // lesson may draw a cheaper picture and say so. Never in a headless run.
  bool input_moving = false;
  // A map lesson's map as the eye's pixels sample it (LightView::update sets it): the runner's
  // `aliasing` view and the report's texels per pixel come from it.
  std::optional<ShadowSampling> shadow_sampling;

  // The view as shader #defines: VIEW_SHADED 0, VIEW_VISIBILITY 1, ... for every view the
  // lesson has, and VIEW as the one to render (`#if VIEW == VIEW_VISIBILITY`).
  std::vector<std::string> viewDefines() const;

  void bindTarget() const;
  // Binds the target and clears colour, depth and stencil (to the sky, by default).
  void clearTarget(glm::vec3 color = kSky) const;
  static constexpr glm::vec3 kSky{0.55f, 0.62f, 0.72f};
  // What the truth and error views show in a build without the truth (the browser's).
  static constexpr glm::vec3 kNoTruthColor{0.12f, 0.12f, 0.14f};
  // Draws objects with `program`, setting uModel and uColor per object. With `cull`, objects
  // whose bounds lie outside that view-projection are skipped and counted as culled.
  void drawObjects(const Program& program, Objects which, const glm::mat4* cull = nullptr) const;
  // Draws the one scene object with this index, with the same per-object uniforms.
  void drawObject(const Program& program, size_t index) const;
  // Light position/direction, eye and dimming uniforms of common/shaders/lighting.glsl.
  void setLightingUniforms(const Program& program, float dimming) const;
  // A depth texture in a corner of the target, or over all of it (linearized for a
  // perspective light, whose raw depths crowd near 1).
  void drawDepthInset(const Texture& depth, float near, float far, bool perspective,
                      bool fullscreen = false) const;
  // A colour texture in a corner (keeping its aspect), or over the whole target.
  void drawImageInset(const Texture& image, bool fullscreen = false) const;
  // One triangle over the whole target (or, with `inset`, the corner square the depth inset
  // uses) with `program` (common/shaders/fullscreen.vert gives vUv), no depth test: for
  // debug views computed per pixel.
  void drawFullscreen(const Program& program, bool inset = false) const;
  // Every object where its scene preset put it, the one at `moving` moved by `offset` (lessons
  // 15 and 16's move.*: Scene::movingObject says which).
  void placeMoved(size_t moving, glm::vec3 offset) const;
};

// What Lesson::reportPixels gets: the texel pass (null without a map), row by row from the
// bottom, width x height.
struct PixelMeasures {
  int width = 0, height = 0;
  const std::vector<TexelPixel>* texels = nullptr;
};

// A part of the frame a lesson measures the error on by itself (lesson 10: the plane of
// interest, region II): its name under the report's `error`, and whether a pixel is in it, by
// the world position (xyz) and object index (w) it shows and, where `pixel_inside` is given,
// by the truth's visibility there and the lesson's (lesson 14: the penumbra, 0 < truth < 1;
// lesson 13: light bleeding, drawn lighter than the truth).
struct ErrorRegion {
  std::string name;
  std::function<bool(glm::vec4 position)> inside;
  std::function<bool(float truth, float rendered)> pixel_inside = {};

  static bool anywhere(glm::vec4) { return true; }
  // Regions by the truth's visibility alone, anywhere in the frame (13 and 14): the area
  // light partly seen, not at all, wholly.
  static ErrorRegion penumbra() {
    return {"penumbra", anywhere, [](float t, float) { return t > 0.0f && t < 1.0f; }};
  }
  static ErrorRegion umbra() {
    return {"umbra", anywhere, [](float t, float) { return t == 0.0f; }};
  }
  static ErrorRegion lit() {
    return {"lit", anywhere, [](float t, float) { return t == 1.0f; }};
  }
};

class Lesson {
 public:
  virtual ~Lesson() = default;
  virtual std::string title() const = 0;
  virtual std::string seeds() const = 0;  // which seed slides it follows, one line
  // Debug views beyond shaded and visibility (the runner adds truth and error), each a constant
  // the lesson declares (view.hpp) and its render() compares frame.shows(kX) against.
  virtual std::vector<View> debugViews() const { return {}; }
  // The `view` parameter's choices, in order: shaded, visibility, the debug views, truth, error.
  std::vector<View> views() const {
    std::vector<View> all = {views::kShaded, views::kVisibility};
    for (const View& v : debugViews()) all.push_back(v);
    all.push_back(views::kTruth);
    all.push_back(views::kError);
    return all;
  }
  virtual void declare(Params& params) = 0;  // lesson parameters
  virtual void init() = 0;                   // GL resources (context is current)
  virtual void render(Frame& frame) = 0;     // draw frame.shown into frame.target
  virtual void panel(Frame&) {}              // extra ImGui lines under the sliders
  virtual void report(JsonWriter&) const {}  // extra report fields (what the lesson derived)
  // Report fields measured per pixel by the runner's texel pass.
  virtual void reportPixels(JsonWriter&, const PixelMeasures&) const {}
  // The regions whose error the runner reports as `error.<name>` (counted_pixels,
  // false_shadow_pct, false_lit_pct), this frame's: every figure derived from the truth lives
  // under `error`, which is there exactly when the truth was traced.
  virtual std::vector<ErrorRegion> errorRegions() const { return {}; }
  // "" or why these settings are refused before anything is drawn (bad input, exit 2; the
  // panel says it in a window): lesson 15's light map past its memory limit.
  virtual std::string refusal(const Params&, const Scene&) const { return {}; }
  // Shared parameters (light.fov, light.near, ...) this lesson has no use for: the runner
  // does not offer them.
  virtual std::vector<std::string> unusedSharedParams() const { return {}; }
  // Goals a student reaches with a few sliders, graded by the truth (lesson/exercise.hpp):
  // --exercise N shows the Nth in the panel, --grade N grades a run by it.
  virtual std::vector<Exercise> exercises() const { return {}; }
  // The scene presets the lesson offers, its default first.
  virtual std::vector<std::string> scenes() const { return scenePresets(); }
  // A path next to the lesson's main.cpp, or its copy in a bundle (program.hpp).
  static std::filesystem::path lessonFile(const std::string& lessonDir, const std::string& file) {
    return shadows::lessonFile(lessonDir, file);
  }
};

using LessonFactory = std::function<std::unique_ptr<Lesson>()>;
struct LessonRegistrar {
  LessonRegistrar(const std::string& name, LessonFactory factory, bool host = false);
};
std::unique_ptr<Lesson> makeLesson(const std::string& name);
std::vector<std::string> registeredLessons();
// The lessons that run others inside them (lesson/hosted_lesson.hpp): the one a binary that
// links them all with it runs.
std::vector<std::string> registeredHosts();

#define SHADOWS_LESSON(Class)                                \
  static const ::shadows::LessonRegistrar kRegistrar##Class( \
      LESSON_NAME, [] { return std::make_unique<Class>(); })
// A lesson that hosts others (lesson 16): its binary links theirs too, and runs this one.
#define SHADOWS_HOST_LESSON(Class)                           \
  static const ::shadows::LessonRegistrar kRegistrar##Class( \
      LESSON_NAME, [] { return std::make_unique<Class>(); }, /*host=*/true)

}  // namespace shadows
