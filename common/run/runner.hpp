// The runner around a lesson (lesson/lesson.hpp): command line, window (GLFW + ImGui) or
// headless (OSMesa/EGL + ImGui into the same framebuffer), main loop, truth, report.
#pragma once

#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "lesson/lesson.hpp"
#include "run/error_measure.hpp"
#include "run/exercise_run.hpp"
#include "run/headless_run.hpp"
#include "run/scene_host.hpp"
#include "run/side_passes.hpp"
#include "run/truth_measure.hpp"
#include "run/window.hpp"

namespace shadows {

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
  bool size_given = false;  // --size on the command line
  int exercise = 0;         // --exercise N or --grade N: the lesson's exercise N (1-based)
  bool grade = false;       // --grade N: headless, the verdict its exit code
};

// Parses argv. Returns "" or one line naming what is wrong (the caller exits 2).
std::string parseCommandLine(int argc, char** argv, RunOptions& options);

// What a lesson's last frame told the runner (Frame's outputs).
struct FrameOutputs {
  std::optional<glm::mat4> light_frustum;
  std::optional<Frame::LightReach> light_reach;
  float truth_area_radius = 0.0f;
  std::optional<AirMedium> medium;
  std::optional<ShadowSampling> shadow_sampling;
};

class Runner final {
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
  // The frames without shadow the cost is measured against, and the texel-density pass.
  BaselineFrames& baseline() { return baseline_; }
  TexelPass& texels() { return texels_; }
  // Feeds ImGui a mouse state for the next frame (headless tests drive the panel this way).
  void setMouse(glm::vec2 position, bool leftDown);
  // Whether input is moving (the window sets it each frame; tests may too): Frame::input_moving.
  void setInputMoving(bool moving) { input_moving_ = moving; }
  // The error against the truth for the current parameters, now or off the frame's path.
  const ErrorState& measureError() { return errors_.measure(); }
  ErrorMeasure& errors() { return errors_; }
  const ErrorMeasure& errors() const { return errors_; }
  Image readImage() const;
  // Saves the picture as a window's F12 does (out/screenshots/<lesson>_N.png, a new N each
  // time); returns the line said on stderr and under the panel's button.
  std::string screenshot();
  std::vector<float> renderVisibility();
  // Renders `view` into the float target and returns its red channel (visibility, air).
  std::vector<float> renderRed(View view);
  // The view the `view` parameter chooses, as the lesson declared it.
  View currentView() const;

  Params& params() { return params_; }
  Measure& measure() { return *measure_; }
  Lesson& lesson() { return *lesson_; }
  const Scene& scene() const { return host_.scene(); }
  // What a lesson may ask of the runner (LessonHost), and what its Frames draw through.
  SceneHost& host() { return host_; }
  const std::string& lessonName() const { return name_; }
  const RunOptions& options() const { return options_; }
  int glErrors() const;
  void writeReport(JsonWriter& json);

  // The exercise --exercise, --grade or the panel chose, its verdict, the student's settings.
  ExerciseRun& exercises() { return exercise_; }
  const ExerciseRun& exercises() const { return exercise_; }
  // The exercise's own settings, then the command line's --set list: what a run starts from
  // ("" or the first problem, the exercise's included).
  std::string applyStartingSettings();
  // "" or one line on parameters that parse alone but not together (near >= far).
  std::string checkConsistency() const;
  // Runs the whole program (window or headless) and returns the exit code.
  int run();
  // The window: its loop in steps (a page's), the panel's column, a test's panel sections.
  RunnerWindow& window() { return window_; }

 private:
  struct Gpu;
  void declareShared();
  static void declareSharedInto(Params& params);
  void initGl();     // the runner's GL resources and the lesson's, once a context is current
  void releaseGl();  // all of them, in an order that keeps the context alive to the end
  static void resetGlState();
  void loadScene();
  // The eye back where the scene's preset puts it (camera.pos, .target, .fov): the panel's
  // button and the window's C key, for an eye dragged out of sight.
  void resetCamera();
  Light currentLight() const;
  // The object a point light sits on (within 1e-5 of the scene's radius), or "": the report's
  // light_on_surface and the panel's warning.
  std::string lightOnSurface() const;
  void renderInto(GLuint target, int width, int height, View view, bool timed, bool withPanel);
  void drawPanel(Frame& frame);
  // The chosen exercise: its goal, the sliders it lets the student move, each figure now and
  // the verdict, Save settings, the hint; in the panel's column, or around the picture
  // (RunnerWindow::exercise_strips).
  void drawExercise(const Exercise& ex);
  void showImage(const Frame& frame, const Image& image);  // a CPU picture over the target
  // The eye's matrices from camera.*: one definition for the lesson and the truth's pass.
  glm::mat4 cameraView() const;
  glm::mat4 cameraProjection(int width, int height) const;

  std::string name_;
  bool input_moving_ = false;
  std::unique_ptr<Lesson> lesson_;
  std::vector<View> views_;  // the `view` parameter's choices, in its order
  RunOptions options_;
  Params params_;
  std::unique_ptr<Measure> measure_;
  void initImGuiGl();  // the ImGui GL backend (both window and headless)
  long long compiled_at_start_ = ProgramVariants::compiledTotal();
  std::unique_ptr<Gpu> gpu_;
  FrameOutputs told_;  // what the lesson's last frame told the runner
  friend class SceneHost;
  SceneHost host_{*this};
  friend class BaselineFrames;
  BaselineFrames baseline_{*this};
  friend class TexelPass;
  TexelPass texels_{*this};
  friend class ErrorMeasure;
  ErrorMeasure errors_{*this};
  friend class HeadlessRun;
  HeadlessRun headless_{*this};
  int runHeadlessOrWindow();
  friend class ExerciseRun;
  ExerciseRun exercise_{*this};
  friend class RunnerWindow;
  RunnerWindow window_{*this};
};

// main() of every lesson binary: parse, run, exit code (0 ok, 1 runtime failure, 2 bad input).
// `lesson`: which one, in a program that has them all (empty: the only one registered).
int runLessonMain(int argc, char** argv, const std::string& lesson = {});

}  // namespace shadows
