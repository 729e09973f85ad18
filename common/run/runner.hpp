// The runner around a lesson (lesson/lesson.hpp): command line, window (GLFW + ImGui) or
// headless (OSMesa/EGL + ImGui into the same framebuffer), main loop, truth, report. It owns
// the lesson, its parameters and its Measure, and the pieces (docs/ARCHITECTURE.md), each
// handed what it needs: the scene (SceneHost), the truth's error (ErrorMeasure), the texel pass
// and the frames without shadow (side_passes.hpp), the exercise (ExerciseRun). The headless
// run and the window drive it through its public interface.
#pragma once

#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "gl/context.hpp"
#include "lesson/lesson.hpp"
#include "run/error_measure.hpp"
#include "run/exercise_run.hpp"
#include "run/frame_source.hpp"
#include "run/gl_targets.hpp"
#include "run/headless_run.hpp"
#include "run/run_options.hpp"
#include "run/scene_host.hpp"
#include "run/side_passes.hpp"
#include "run/truth_measure.hpp"
#include "run/window.hpp"

namespace shadows {

class Runner final : public FrameSource {
 public:
  Runner(const std::string& lessonName, std::unique_ptr<Lesson> lesson, RunOptions options);
  ~Runner();

  // Applies a --set list (scene first, so its preset does not override the rest): "" or why not.
  std::string applySets(const std::vector<std::string>& sets);
  // Headless: creates the context and GL resources. Throws GlFailure.
  void initHeadless();
  // Once a context is current: the runner's and the lesson's GL; ImGui's (and GLFW's) backend.
  void initGl();
  void initImGuiGl(bool glfw = false);
  // All of them, in an order that keeps the context alive to the end.
  void releaseGl();
  // One frame into the picture's target (headless) or the window; untimed: nothing measured.
  void renderFrame(bool timed = true);
  // FrameSource: one frame as asked (the pieces', a window's), and what they draw with.
  FrameOutputs render(const FrameRequest& request) override;
  Measure& lessonMeasure() override { return *measure_; }
  View currentView() const override;
  Light currentLight() const override;
  glm::mat4 cameraView() const override;
  glm::mat4 cameraProjection(int width, int height) const override;
  bool panelShown() const override;
  // The picture's size: a window's, less the panel's column (options().width and height).
  void resizePicture(int width, int height);
  // The frames without shadow the cost is measured against, and the texel-density pass.
  BaselineFrames& baseline() { return baseline_; }
  TexelPass& texels() { return texels_; }
  // A mouse for the next frame's panel (a headless test's), and Frame::input_moving.
  void setMouse(glm::vec2 position, bool leftDown);
  void setInputMoving(bool moving) { input_moving_ = moving; }
  // The error against the truth for the current parameters, now or off the frame's path.
  const ErrorState& measureError() { return errors_.measure(); }
  ErrorMeasure& errors() { return errors_; }
  const ErrorMeasure& errors() const { return errors_; }
  Image readImage() const;
  // Saves the picture as F12 does (out/screenshots/<lesson>_N.png); returns the line said.
  std::string screenshot();
  // The lesson's shadow term alone (the visibility view), read back in float.
  std::vector<float> renderVisibility() { return errors_.renderRed(views::kVisibility); }
  // The eye back where the scene's preset puts it: the panel's button, the window's C key.
  void resetCamera();

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
  // Exercise n (0: none) chosen as the panel's selector does: every parameter reset, then its
  // settings, the sliders it does not allow locked, a page at the grader's size. "" or why not.
  std::string chooseExercise(int n);
  // The exercise's own settings, then --set's: what a run starts from ("" or the problem).
  std::string applyStartingSettings();
  // "" or one line on parameters that parse alone but not together (near >= far).
  std::string checkConsistency() const;
  // Runs the whole program (window or headless) and returns the exit code.
  int run();
  // The window: its loop in steps (a page's), the panel's column, a test's panel sections.
  RunnerWindow& window() { return window_; }
  // The outputs of a run (the picture, the report, the truth's pictures, screenshots).
  HeadlessRun& outputs() { return headless_; }

 private:
  void declareShared();
  static void declareSharedInto(Params& params);
  void loadScene();
  // The object a point light sits on (within 1e-5 of the scene's radius), or "".
  std::string lightOnSurface() const;
  int runHeadlessOrWindow();
  void newPanelFrame(int width, int height);  // render's parts: the panel's, the truth's, ...
  void showTruth(Frame& frame, bool timed);
  FrameOutputs renderLesson(Frame& frame);
  int grade();  // --grade N: the headless run, then the verdict line; 0: met
  // The exercise's verdict on the truth just measured, once per truth (ErrorMeasure calls it).
  void judgeExercise();

  // The panel (panel.cpp), in its sections: placed, the exercise's chooser, the warnings and
  // cost line, the sliders (and, handed what they show, the headline, cost and error).
  void drawPanel(Frame& frame);
  void beginPanel(const Frame& frame);
  void drawExerciseChooser();
  void drawPanelWarnings();
  void drawPanelSliders(Frame& frame);
  // The exercise: its goal and sliders, each figure and the verdict, Save settings, the hint;
  // in the panel's column, or around the picture (RunnerWindow::exercise_strips).
  void drawExercise(const Exercise& ex);
  // The report's first section (report.cpp; the cost, the error and the verdict are handed
  // what they report): what ran, where, at what size, with which settings.
  void reportRun(JsonWriter& json);

  std::string name_;
  bool input_moving_ = false;
  std::unique_ptr<Lesson> lesson_;
  std::vector<View> views_;  // the `view` parameter's choices, in its order
  RunOptions options_;
  Params params_;
  std::unique_ptr<HeadlessContext> context_;  // headless (a window's is GLFW's): freed last
  std::unique_ptr<Measure> measure_;
  long long compiled_at_start_ = ProgramVariants::compiledTotal();
  bool imgui_ = false, imgui_glfw_ = false;  // ImGui's context and backends are up
  // The pieces, handed what they need (of one declared later, only a reference is kept).
  FloatTarget floats_;
  HeadlessRun headless_{*this};
  ExerciseRun exercise_{lesson_->exercises(), params_, name_};
  ErrorMeasure errors_{*this, options_, params_, host_, texels_, floats_};
  SceneHost host_{params_, errors_.truth()};
  TexelPass texels_{*this, options_, params_, host_, floats_};
  BaselineFrames baseline_{*this, params_, options_, headless_.target()};
  RunnerWindow window_{*this, options_.hide_panel};
};

// main() of every lesson binary: parse, run, exit code (0 ok, 1 runtime failure, 2 bad input).
// `lesson`: which one, in a program that has them all (empty: the only one registered).
int runLessonMain(int argc, char** argv, const std::string& lesson = {});

}  // namespace shadows
