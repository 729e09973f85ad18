// The runner's window (GLFW + ImGui): the loop in steps a browser can call one frame at a
// time, the panel's column beside the picture and its cached texture, the orbit camera, and
// the state the runner's frame and panel read (whether a window is open, the headless tests'
// mouse, the screenshot asked for). It owns the window, the loop's state between frames and
// the panel's texture; it drives the Runner through its public interface.
#pragma once

#include <chrono>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "gl/gl.hpp"
#include "gl/program.hpp"

struct GLFWwindow;

namespace shadows {

struct Frame;
class Runner;
class SceneHost;

class RunnerWindow {
 public:
  // `hidePanel`: the panel starts hidden (--hide-panel); the H key toggles it.
  RunnerWindow(Runner& runner, bool hidePanel) : r_(runner), panel_hidden_(hidePanel) {}

  // The panel's width as a column beside the picture, in window units (a window is the
  // picture plus this wide while the panel shows).
  static constexpr float kPanelColumn = 340.0f;
  static constexpr int kNoWindow = -1;  // run() could not open one (error: why)

  // The whole loop: open, frames until closed (or --frames), close; the exit code.
  int run();
  // The loop in steps, for a browser that calls one frame at a time (emscripten_set_main_loop):
  // begin (false: no window, see Runner::run()), then frames while frame() says true, then
  // end, which returns the exit code.
  bool begin();
  bool frame();
  int end();
  // Resizes the window (a page's canvas, to fill the browser's window): picture and column.
  void fit(int width, int height);
  // A page's canvas in an exercise: the grader's picture (kExerciseWidth x Height) and,
  // while the panel shows, its column (a window keeps its size: exercise_strips).
  void fitExercise();
  // The picture's part of a framebuffer this wide: all of it less the panel's column, where
  // the window is wide enough for both.
  int columnFor(int framebufferWidth) const;
  // The next frame is saved as a screenshot (what the F12 key does).
  void requestScreenshot() { screenshot_requested = true; }
  // Keeps one of the panel's folded sections open ("Light and camera"): a test or a tutorial
  // script aims at a widget there.
  void openPanelSection(const std::string& title) { open_sections.insert(title); }

  // The panel in a window is drawn anew only when it may have changed, into a texture laid
  // over the other frames (Runner::drawPanel, panel.cpp, draws what is in it).
  bool panelDue(int width, int height);
  // The panel's frame line: the median the report gives ("measuring..." before any frame).
  std::string costSummary() const;
  // The last frame's work counters, one line: "name N, ..., name unavailable on gles30".
  std::string counterSummary() const;
  void drawPanelTexture(int width, int height);
  void laySavedPanel(const Frame& frame, const SceneHost& host);
  bool panelHidden() const { return panel_hidden_; }
  void releaseGl();  // the panel's texture and program, before the context goes

  bool is_open = false;
  std::string error;  // why none opened, as GLFW said it
  bool screenshot_requested = false;
  glm::vec2 mouse{-1.0f};  // Runner::setMouse: a headless test's mouse
  bool mouse_down = false;
  // The panel's column right of the picture, in framebuffer pixels (0: over the picture, or
  // hidden), and the whole framebuffer the panel is drawn into.
  int column = 0;
  glm::ivec2 framebuffer{0};
  std::set<std::string> open_sections;  // openPanelSection
  std::set<std::string> unfold;         // sections opened once (an exercise's sliders there)
  bool was_column = false;              // the panel's layout last frame (a column or over)
  // An exercise in a window of its normal size: the grader's 640x480 picture in the bottom-left
  // corner, the goal and its sliders in the strip above it, the verdict beside it (panel.cpp,
  // drawExercise). Where the window has no room for them (or --size is given, or a page),
  // the exercise is in the panel's column.
  bool exercise_strips = false;
  std::string saved;  // the panel's "Save settings": where, or why not

 private:
  Runner& r_;
  bool panel_hidden_ = false;
  GLFWwindow* window_ = nullptr;
  // The loop's state between frames (frame()): the orbit drag, the C and H keys, when the
  // sliders last moved, the frames a scripted run has left.
  double last_x_ = 0, last_y_ = 0;
  bool h_was_down_ = false, c_was_down_ = false;
  bool dragging_ = false;
  std::chrono::steady_clock::time_point changed_at_{};
  std::optional<std::chrono::steady_clock::time_point> moved_at_;
  std::string last_key_;
  int frames_left_ = -1;
#ifndef __EMSCRIPTEN__  // a page draws no frames without shadow (costSummary)
  long long frame_number_ = 0;
#endif
  bool outputs_failed_ = false;
  // The panel: drawn into its own texture only when it may have changed, laid over every
  // frame (panelDue, drawPanelTexture, laySavedPanel).
  Texture panel_color_;
  std::unique_ptr<Framebuffer> panel_target_;
  Program panel_over_;
  glm::ivec4 panel_box_{0};  // x, y, width, height in framebuffer pixels, y up
  std::chrono::steady_clock::time_point panel_drawn_{};
  glm::dvec2 cursor_{-1.0};
  bool panel_input_ = false;  // a click, key, character or wheel turn since the last draw
  int panel_draws_ = 0;       // ImGui lays a window out over its first frames: draw those all
  bool panel_typing_ = false, buttons_down_ = false;
  // The mouse and keys of one frame: the orbit drag and wheel, C, F12 and H.
  void handleInput();
  // A scripted run's last frame: the window as shown and the outputs asked for.
  void writeLastFrame(int width, int height);
};

}  // namespace shadows
