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
#include "run/truth_measure.hpp"

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

class Runner final : public LessonHost {
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
  const Measure& baselineMeasure() const { return *baseline_.measure; }
  // The panel's frame line: the median the report gives ("measuring..." before any frame).
  std::string costSummary() const;
  // The last frame's work counters, one line: "name N, ..., name unavailable on gles30".
  std::string counterSummary() const;
  // The next window frame is saved as a screenshot (what the F12 key does).
  void requestScreenshot() { window_.screenshot_requested = true; }
  // Why the truth and error views show no picture ("" when the build has the truth).
  static std::string truthUnavailable();
  // The panel's width as a column beside the picture, in window units (a window is the frame
  // plus this wide while the panel shows).
  static constexpr float kPanelColumn = 340.0f;
  // The picture an exercise is judged on, everywhere: --grade, a window or a page with an
  // exercise chosen (fragment counts and texels per pixel depend on the picture's size).
  static constexpr int kExerciseWidth = 640, kExerciseHeight = 480;
  // Keeps one of the panel's folded sections open ("Light and camera"): a test or a
  // tutorial script aims at a widget there.
  void openPanelSection(const std::string& title) { window_.open_sections.insert(title); }
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
  bool errorMeasureRunning() const { return truth_.running(); }
  // The running measure's progress in [0, 1], or -1 when not known (natively) or none runs.
  double errorMeasureProgress() const;
  // Whether the truth and error views can show anything: the build has a tracer, and a page
  // loaded its own (truthUnavailable() says why not).
  static bool haveTruth();
  // How many truths have been installed so far (a page's tests wait on it).
  long long truthsMeasured() const { return truth_.measured(); }
  // Whether a page's workers failed to trace the current settings (the console says why).
  bool truthFailed() const { return truth_.failed(); }
  const ErrorState& lastError() const override { return truth_.error(); }
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

  // The exercise --exercise or --grade chose (null: none), and its verdict on the last truth.
  const Exercise* exercise() const { return exercise_.chosen ? &*exercise_.chosen : nullptr; }
  const Verdict& exerciseVerdict() const { return exercise_.verdict; }
  // "" or why the command line's exercise cannot run: no such exercise, or (grading) a --set
  // of a parameter it does not let a student move.
  std::string exerciseProblem() const;
  // Chooses exercise n (0: none) in a running lesson, as the panel's selector does: every
  // parameter back to its default, the exercise's own settings, the sliders it does not let a
  // student move locked. Returns "" or why not (no such exercise).
  std::string chooseExercise(int n);
  // The settings a student changed, one name=value a line (--settings reads them back): with
  // an exercise, only those it lets a student move. Returns "" or why it could not write.
  std::string saveSettings(const std::string& path) const;
  // The same as a page's query (?a=b&c=d), for a link.
  std::string settingsQuery() const;
  // The exercise's own settings, then the command line's --set list: what a run starts from
  // ("" or the first problem, exerciseProblem()'s included).
  std::string applyStartingSettings();
  // "" or one line on parameters that parse alone but not together (near >= far).
  std::string checkConsistency() const;
  // Runs the whole program (window or headless) and returns the exit code.
  int run();
  // The window loop in steps, for a browser that calls one frame at a time
  // (emscripten_set_main_loop): open (false: no window, see run()), then frames while
  // windowFrame() says true, then close, which returns the exit code.
  bool openWindow();
  bool windowFrame();
  // Resizes the window (a page's canvas, to fill the browser's window): picture and column.
  void fitWindow(int width, int height);
  int closeWindow();

  // LessonHost: what a lesson may ask (lesson/lesson.hpp says what each does).
  void setObjectModel(size_t index, const glm::mat4& model) override;
  const glm::mat4& presetModel(size_t index) const override { return preset_models_.at(index); }

 private:
  // What a Frame draws with (LessonHost): the scene's meshes and the runner's inset programs.
  void drawObjects(const Frame& frame, const Program& program, Objects which,
                   const glm::mat4* cull) const override;
  void drawObject(const Program& program, size_t index) const override;
  void drawInset(const Frame& frame, const Texture& depth, float near, float far, bool perspective,
                 bool fullscreen) const override;
  void drawImageInset(const Frame& frame, const Texture& image, bool fullscreen) const override;
  void drawFullscreen(const Frame& frame, const Program& program, bool inset) const override;
  // The aliasing view's colour bar, in the panel while that view shows (panel.cpp).
  void drawTexelLegend() const;
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
  static constexpr int kNoWindow = -1;  // runWindow could not open one (window_.error: why)
  int runWindow();
  int runHeadless();

  std::string name_;
  bool input_moving_ = false;
  std::unique_ptr<Lesson> lesson_;
  RunOptions options_;
  Params params_;
  Scene scene_;
  std::vector<glm::mat4> preset_models_;
  std::unique_ptr<Measure> measure_;
  void initImGuiGl();  // the ImGui GL backend (both window and headless)
  long long compiled_at_start_ = ProgramVariants::compiledTotal();
  std::unique_ptr<Gpu> gpu_;
  // What the lesson's last frame told the runner (Frame's outputs).
  struct FrameOutputs {
    std::optional<glm::mat4> light_frustum;
    float truth_area_radius = 0.0f;
    std::optional<AirMedium> medium;
    std::optional<ShadowSampling> shadow_sampling;
  } told_;
  // The frames with shadow.off (renderBaselineFrame), timed in their own Measure.
  struct Baseline {
    std::unique_ptr<Measure> measure;
    long long frames = 0;
    bool running = false;
  } baseline_;
  // measureTexels()'s pass, for `key`. Its frame draws into its own Measure, enabled: the
  // lesson draws with the very variants a timed frame uses (05's counted kernel, not an
  // uncounted twin), and the frame's counters stay out of the report's.
  struct TexelCache {
    std::vector<TexelPixel> pixels;
    std::optional<TexelStats> stats;
    std::string key;
    std::unique_ptr<Measure> measure;
  } texels_;
  // The runner's texel pass over the frame the lesson just drew (`aliasing` view or raw).
  void drawTexels(const Frame& frame, bool heatmap);
  TruthMeasure truth_;
  int runHeadlessOrWindow();
  int runGrade();
  struct ExerciseState {
    std::optional<Exercise> chosen;
    Verdict verdict;
    long long judged_at = -1;  // truthsMeasured() when the verdict was made
  } exercise_;
  void judgeExercise();        // after a truth is installed: the verdict on it
  void lockExerciseWidgets();  // the panel's sliders the exercise does not allow, locked
  std::vector<std::string> changedSettings() const;  // saveSettings' lines
  TruthInputs gatherTruthInputs();  // render thread: what traceTruth needs of the GPU
  struct WindowState {
    bool open = false;
    std::string error;  // why none opened, as GLFW said it
    bool screenshot_requested = false;
    int screenshots_taken = 0;
    glm::vec2 mouse{-1.0f};  // setMouse: a headless test's mouse
    bool mouse_down = false;
    // The panel's column right of the picture, in framebuffer pixels (0: over the picture, or
    // hidden), and the whole framebuffer the panel is drawn into.
    int column = 0;
    glm::ivec2 framebuffer{0};
    std::set<std::string> open_sections;  // openPanelSection
    std::string saved;                    // the panel's "Save settings": where, or why not
  } window_;
  // The window's frame: the framebuffer less the panel's column where it fits one.
  int columnFor(int framebufferWidth) const;
};

// main() of every lesson binary: parse, run, exit code (0 ok, 1 runtime failure, 2 bad input).
// `lesson`: which one, in a program that has them all (empty: the only one registered).
int runLessonMain(int argc, char** argv, const std::string& lesson = {});

}  // namespace shadows
