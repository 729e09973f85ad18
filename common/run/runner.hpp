// The lesson base class and the runner around it: command line, window (GLFW + ImGui) or
// headless (OSMesa/EGL + ImGui into the same framebuffer), main loop, truth, report.
#pragma once

#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "core/params.hpp"
#include "core/scene.hpp"
#include "gl/gl.hpp"
#include "gl/measure.hpp"
#include "gl/program.hpp"
#include "math/shadow_math.hpp"
#include "math/texel_density.hpp"
#include "truth/truth.hpp"
#include "truth/truth_job.hpp"

namespace shadows {

class JsonWriter;

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

class Runner;

// What a lesson's render() sees: the scene, the camera, the light, the target to draw into.
struct Frame {
  Frame(Runner& runner_, Params& params_, const Scene& scene_, Measure& measure_,
        const Light& light_)
      : runner(runner_), params(params_), scene(scene_), measure(measure_), light(light_) {}
  Runner& runner;
  Params& params;
  const Scene& scene;
  Measure& measure;
  const Light& light;
  glm::mat4 view{1.0f}, projection{1.0f};
  glm::vec3 eye{0.0f};
  int width = 0, height = 0;
  GLuint target = 0;
  std::string mode;  // the view to render: "shaded", "visibility" or a lesson debug view

  // Outputs the runner uses: the light frustum the shadow term is valid in (pixels
  // outside it are not counted against the truth).
  std::optional<glm::mat4> light_view_projection;
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
};

// What Lesson::reportPixels gets: the texel pass (null without a map), row by row from the
// bottom, width x height.
struct PixelMeasures {
  int width = 0, height = 0;
  const std::vector<TexelPixel>* texels = nullptr;
};

// A part of the frame a lesson measures the error on by itself (lesson 10: the plane of
// interest, region II): its name under the report's `error`, and whether a pixel is in it, by
// the world position (xyz) and object index (w) it shows.
struct ErrorRegion {
  std::string name;
  std::function<bool(glm::vec4 position)> inside;
};

class Lesson {
 public:
  virtual ~Lesson() = default;
  virtual std::string title() const = 0;
  virtual std::string seeds() const = 0;  // which seed slides it follows, one line
  // Debug views beyond shaded and visibility (the runner adds truth and error).
  virtual std::vector<std::string> debugViews() const { return {}; }
  virtual void declare(Params& params) = 0;  // lesson parameters
  virtual void init() = 0;                   // GL resources (context is current)
  virtual void render(Frame& frame) = 0;     // draw frame.mode into frame.target
  virtual void panel(Frame&) {}              // extra ImGui lines under the sliders
  virtual void report(JsonWriter&) const {}  // extra report fields (what the lesson derived)
  // Report fields measured per pixel by the runner's texel pass.
  virtual void reportPixels(JsonWriter&, const PixelMeasures&) const {}
  // The regions whose error the runner reports as `error.<name>` (counted_pixels,
  // false_shadow_pct, false_lit_pct), this frame's: every figure derived from the truth lives
  // under `error`, which is there exactly when the truth was traced.
  virtual std::vector<ErrorRegion> errorRegions() const { return {}; }
  // Shared parameters (light.fov, light.near, ...) this lesson has no use for: the runner
  // does not offer them.
  virtual std::vector<std::string> unusedSharedParams() const { return {}; }
  // The scene presets the lesson offers, its default first.
  virtual std::vector<std::string> scenes() const { return scenePresets(); }
  // A path next to the lesson's main.cpp, or its copy in a bundle (program.hpp).
  static std::filesystem::path lessonFile(const std::string& lessonDir, const std::string& file) {
    return shadows::lessonFile(lessonDir, file);
  }
};

using LessonFactory = std::function<std::unique_ptr<Lesson>()>;
struct LessonRegistrar {
  LessonRegistrar(const std::string& name, LessonFactory factory);
};
std::unique_ptr<Lesson> makeLesson(const std::string& name);
std::vector<std::string> registeredLessons();

#define SHADOWS_LESSON(Class)                                \
  static const ::shadows::LessonRegistrar kRegistrar##Class( \
      LESSON_NAME, [] { return std::make_unique<Class>(); })

struct RunOptions {
  bool headless = false;
  bool force_window = false;
  std::string backend;  // a headless context (headlessBackends()); empty: the build's default
  int device = 0;       // --device: the EGL device of --backend egl-device
  int width = 800, height = 600;
  int frames = 5;
  bool frames_given = false;  // --frames on the command line: a window run stops after them
  bool panel = false;         // draw the ImGui panel into headless snapshots too
  bool hide_panel = false;    // a window without the panel (key H toggles it)
  int orbit = 0;              // a window turns the camera this many degrees a frame, as a drag
  bool truth = true;          // measure error against the ray-traced truth
  std::string out, report, truth_out, error_out;
  // The truth's job and its trace as bytes (truth_job.hpp), and a trace to use instead of
  // tracing (another tracer's answer to this very job, e.g. web/truth's).
  std::string truth_job, truth_result, truth_from;
  // Whether the run measures the truth: asked for, or an output that needs it.
  bool truthAsked() const {
    return truth || !truth_out.empty() || !error_out.empty() || !truth_job.empty() ||
           !truth_result.empty() || !truth_from.empty();
  }
  std::vector<std::string> sets;
  bool list_params = false, help = false;
};

// Parses argv. Returns "" or one line naming what is wrong (the caller exits 2).
std::string parseCommandLine(int argc, char** argv, RunOptions& options);

struct ErrorState {
  ErrorMetrics metrics;
  bool valid = false;
  std::shared_ptr<const ErrorPixels> pixels;
};

class Runner {
 public:
  Runner(const std::string& lessonName, std::unique_ptr<Lesson> lesson, RunOptions options);
  ~Runner();

  // Applies the --set list (scene first, so presets do not override the rest).
  // Returns "" or the first error.
  std::string applySets(const std::vector<std::string>& sets);
  // Headless: creates the context and GL resources. Throws GlFailure.
  void initHeadless();
  // Renders one frame into the runner's framebuffer (headless) or the window; untimed, it
  // leaves the timings and counters alone.
  void renderFrame(bool timed = true);
  // The same frame with no shadow work (shadow.off), timed on its own and off-screen, so the
  // report and the panel can say what the shadow costs over it, measured in the same run. The
  // map and every dirty bit are left as they were. Nothing for lessons without shadow.off.
  void renderBaselineFrame();
  // Median frame over median baseline frame (0 before any baseline frame).
  double shadowOverhead() const;
  const Measure& baselineMeasure() const { return *baseline_measure_; }
  // The panel's frame line: the median the report gives ("measuring..." before any frame).
  std::string costSummary() const;
  // The last frame's work counters, one line: "name N, ..., name unavailable on gles30".
  std::string counterSummary() const;
  // The next window frame is saved as a screenshot (what the F12 key does).
  void requestScreenshot() { screenshot_requested_ = true; }
  // Why the truth and error views show no picture ("" when the build has the truth).
  static std::string truthUnavailable();
  // Feeds ImGui a mouse state for the next frame (headless tests drive the panel this way).
  void setMouse(glm::vec2 position, bool leftDown);
  // Whether input is moving (the window sets it each frame; tests may too): Frame::input_moving.
  void setInputMoving(bool moving) { input_moving_ = moving; }
  // Computes visibility, truth and metrics for the current parameters.
  const ErrorState& measureError();
  // The same off the frame's critical path (the window): begin renders what the truth needs
  // (a few ms of GL) and traces it on a worker thread; poll installs the result once it is
  // there (true then). One job at a time; measureError() waits for a running one.
  void beginErrorMeasure();
  bool pollErrorMeasure();
  bool errorMeasureRunning() const { return truth_job_.valid() || page_job_ != nullptr; }
  // The running measure's progress in [0, 1], or -1 when not known (natively) or none runs.
  double errorMeasureProgress() const;
  // Whether the truth and error views can show anything: the build has a tracer, and a page
  // loaded its own (truthUnavailable() says why not).
  static bool haveTruth();
  // How many truths have been installed so far (a page's tests wait on it).
  long long truthsMeasured() const { return truths_measured_; }
  // Whether a page's workers failed to trace the current settings (the console says why).
  bool truthFailed() const { return truth_failed_; }
  // The last error measured (may be stale while sliders move): lessons name it in their panel.
  const ErrorState& lastError() const { return error_; }
  Image readImage() const;
  std::vector<float> renderVisibility();
  // Renders `mode` into the float target and returns its red channel (visibility, air).
  std::vector<float> renderRed(const std::string& mode);
  // Texels per pixel (texel_density.hpp) for the current parameters, read back from the
  // runner's texel pass over the lesson's map; null when the last frame had no map.
  // Cached until a parameter or the size changes.
  const std::vector<TexelPixel>* measureTexels();

  Params& params() { return params_; }
  Measure& measure() { return *measure_; }
  Lesson& lesson() { return *lesson_; }
  const Scene& scene() const { return scene_; }
  const std::string& lessonName() const { return name_; }
  const RunOptions& options() const { return options_; }
  int glErrors() const;
  void writeReport(JsonWriter& json);

  // "" or one line on parameters that parse alone but not together (near >= far).
  std::string checkConsistency() const;
  // Runs the whole program (window or headless) and returns the exit code.
  int run();
  // The window loop in steps, for a browser that calls one frame at a time
  // (emscripten_set_main_loop): open (false: no window, see run()), then frames while
  // windowFrame() says true, then close, which returns the exit code.
  bool openWindow();
  bool windowFrame();
  int closeWindow();

  // Moves one scene object (lesson 01 tilts its receiver plane). Everything follows it: the
  // lesson's draws, the runner's geometry pass and the ray-traced truth, which is rebuilt
  // when the matrix really changed. A scene preset change puts the preset's matrix back.
  void setObjectModel(size_t index, const glm::mat4& model);
  // The object's matrix as the scene preset placed it, before any setObjectModel.
  const glm::mat4& presetModel(size_t index) const { return preset_models_.at(index); }

 private:
  // What a Frame draws with: the scene's meshes and the runner's inset programs.
  friend struct Frame;
  void drawObjects(const Frame& frame, const Program& program, Objects which,
                   const glm::mat4* cull) const;
  void drawObject(const Program& program, size_t index) const;
  void drawInset(const Frame& frame, const Texture& depth, float near, float far, bool perspective,
                 bool fullscreen) const;
  void drawImageInset(const Frame& frame, const Texture& image, bool fullscreen) const;
  void drawFullscreen(const Frame& frame, const Program& program, bool inset) const;
  // The window's panel cache (panel.cpp).
  bool panelDue(int width, int height);
  void drawPanelTexture(int width, int height);
  void laySavedPanel(const Frame& frame);

  struct Gpu;
  void declareShared();
  static void declareSharedInto(Params& params);
  void initGl();     // the runner's GL resources and the lesson's, once a context is current
  void releaseGl();  // all of them, in an order that keeps the context alive to the end
  static void resetGlState();
  void loadScene();
  Light currentLight() const;
  // The object a point light sits on (within 1e-5 of the scene's radius), or "": the report's
  // light_on_surface and the panel's warning.
  std::string lightOnSurface() const;
  std::string errorKey() const;
  void saveScreenshot(int width, int height, const std::string& file);
  // The picture (to `out`) and the --report, --truth-out, --error-out asked for, all or none;
  // false (and one line on stderr) when any cannot be written.
  bool writeOutputs(const std::string& out, const Image& image);
  void renderInto(GLuint target, int width, int height, const std::string& mode, bool timed,
                  bool withPanel);
  void drawPanel(Frame& frame);
  void showImage(const Frame& frame, const Image& image);  // a CPU picture over the target
  // The eye's matrices from camera.*: one definition for the lesson and the truth's pass.
  glm::mat4 cameraView() const;
  glm::mat4 cameraProjection(int width, int height) const;
  static constexpr int kNoWindow = -1;  // runWindow could not open one
  std::string window_error_;            // and why, as GLFW said it
  int runWindow();
  int runHeadless();

  std::string name_;
  bool input_moving_ = false;
  std::unique_ptr<Lesson> lesson_;
  RunOptions options_;
  Params params_;
  Scene scene_;
  std::vector<glm::mat4> preset_models_;
  std::unique_ptr<Measure> measure_, baseline_measure_;
  // The texel measure's frame draws into this one, enabled: the lesson draws with the very
  // variants a timed frame uses (05's counted kernel, not an uncounted twin), and the frame's
  // counters stay out of the report's.
  std::unique_ptr<Measure> texel_measure_;
  long long baseline_frames_ = 0;
  bool in_baseline_ = false;
  void initImGuiGl();  // the ImGui GL backend (both window and headless)
  long long compiled_at_start_ = ProgramVariants::compiledTotal();
  std::unique_ptr<Gpu> gpu_;
  // Embree (or a page's JavaScript) for the current scene, shared with a trace running on
  // another thread.
  std::shared_ptr<const TruthTracer> truth_;
  std::optional<TruthTrace> given_trace_;              // --truth-from
  std::vector<std::uint8_t> job_bytes_, trace_bytes_;  // --truth-job, --truth-result
  ErrorState error_;
  std::string error_key_;
  Image error_image_, truth_image_;
  std::optional<glm::mat4> light_frustum_;
  float truth_area_radius_ = 0.0f;
  std::optional<AirMedium> medium_;
  std::optional<ShadowSampling> shadow_sampling_;
  std::vector<TexelPixel> texel_pixels_;  // measureTexels(), for texel_key_
  std::optional<TexelStats> texel_stats_;
  std::string texel_key_;
  // The runner's texel pass over the frame the lesson just drew (`aliasing` view or raw).
  void drawTexels(const Frame& frame, bool heatmap);
  Truth::AirResult air_truth_;
  struct TruthInputs;
  struct TruthResult {  // what a traced truth installs
    std::string key;
    ErrorMetrics metrics;
    Image error_image, truth_image;
    Truth::AirResult air;
    std::shared_ptr<const TruthTracer> truth;
    std::vector<std::uint8_t> job_bytes, trace_bytes;  // when the outputs ask for them
    std::shared_ptr<const ErrorPixels> pixels;
  };
  int runHeadlessOrWindow();
  TruthInputs gatherTruthInputs();                    // render thread
  static TruthResult traceTruth(TruthInputs inputs);  // any thread: no GL, no runner state
  void installTruth(TruthResult result);
  std::future<TruthResult> truth_job_;
  // A page's measure: what its Web Worker's trace will be compared with (no threads there).
  std::shared_ptr<TruthInputs> page_job_;
  long long truths_measured_ = 0;
  bool truth_failed_ = false;
  glm::vec2 mouse_{-1.0f};
  bool mouse_down_ = false;
  double last_time_ = 0.0;
  bool window_ = false;
  bool screenshot_requested_ = false;
  int screenshots_taken_ = 0;
};

// main() of every lesson binary: parse, run, exit code (0 ok, 1 runtime failure, 2 bad input).
// `lesson`: which one, in a program that has them all (empty: the only one registered).
int runLessonMain(int argc, char** argv, const std::string& lesson = {});

}  // namespace shadows
