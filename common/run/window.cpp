// The window loop: GLFW, ImGui, the orbit camera, the truth when the sliders rest.
#include "run/runner.hpp"

#include "run/runner_gpu.hpp"

#include "core/json.hpp"
#include "gl/context.hpp"
#include "math/orbit.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <optional>

namespace shadows {

int RunnerWindow::run() {
  if (!begin()) return kNoWindow;
  while (frame()) {
  }
  return end();
}

bool RunnerWindow::begin() {
  // Until a window is open, GLFW's complaint is kept for the one line run() prints about it;
  // after that, it is printed as it comes.
  static std::string* opening_error = &error;
  opening_error = &error;
  glfwSetErrorCallback([](int, const char* description) {
    if (opening_error != nullptr) {
      *opening_error = description;
    } else {
      std::fprintf(stderr, "GLFW: %s\n", printable(description).c_str());
    }
  });
  if (!glfwInit()) {
    opening_error = nullptr;  // later errors (a headless fallback's) are printed, not kept
    return false;
  }
  is_open = true;
  setGlfwContextHints();
  // --size is the picture; the panel's column comes beside it. Without --size a window is
  // 1280x720 (a laptop's screen, less the desktop's bars), larger than a headless picture.
  int width = r_.options_.width, height = r_.options_.height;
#ifndef __EMSCRIPTEN__  // a page fits its window (page_main.cpp)
  if (!r_.options_.size_given) {
    width = 1280 - static_cast<int>(kPanelColumn), height = 720;
  }
#endif
#ifdef __EMSCRIPTEN__  // a page's canvas is the grader's picture (exercises.cpp)
  if (r_.options_.exercise > 0 && !r_.options_.size_given)
    width = kExerciseWidth, height = kExerciseHeight;
#endif
  if (!r_.options_.hide_panel) width += static_cast<int>(kPanelColumn);
  GLFWwindow* window = glfwCreateWindow(
      width, height, (r_.name_ + ": " + r_.lesson_->title()).c_str(), nullptr, nullptr);
  if (window == nullptr) {
    if (error.empty()) error = std::string("no ") + (contextName() + 2);
    glfwTerminate();
    is_open = false;
    opening_error = nullptr;
    return false;
  }
  opening_error = nullptr;
  glfwMakeContextCurrent(window);
#ifndef __EMSCRIPTEN__  // the browser paces frames itself (emscripten_set_main_loop)
  glfwSwapInterval(1);
#endif
  if (!loadGl(glfwGetProcAddress)) throw GlFailure("glad could not load GL");
  r_.gpu_ = std::make_unique<Runner::Gpu>();
  r_.gpu_->window = window;
  r_.initGl();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  // Any input since the panel was last drawn asks for it anew (panelDue): these callbacks run
  // first, then ImGui's, which it chains to them.
  glfwSetWindowUserPointer(window, r_.gpu_.get());
  static constexpr auto input = [](GLFWwindow* w) {
    static_cast<Runner::Gpu*>(glfwGetWindowUserPointer(w))->panel_input = true;
  };
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { input(w); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { input(w); });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int, int, int, int) { input(w); });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int) { input(w); });
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  // A Retina display (macOS) has two framebuffer pixels per window unit: the panel's font is
  // rasterized at that size and drawn at 1/scale, sharp there rather than doubled.
  int framebuffer_width = 0, window_width = 0, unused_height = 0;
  glfwGetFramebufferSize(window, &framebuffer_width, &unused_height);
  glfwGetWindowSize(window, &window_width, &unused_height);
  const float scale = window_width > 0
                          ? static_cast<float>(framebuffer_width) / static_cast<float>(window_width)
                          : 1.0f;
  if (scale > 1.0f) {
    ImFontConfig font;
    font.SizePixels = 13.0f * scale;
    ImGui::GetIO().Fonts->AddFontDefault(&font);
    ImGui::GetIO().FontGlobalScale = 1.0f / scale;
  }
  r_.initImGuiGl();
  r_.gpu_->imgui_glfw = true;

  // With an output or --frames, a windowed run renders --frames frames, writes what was asked
  // for and exits: that is how the tests check the real window path under xvfb.
  const bool scripted = r_.options_.frames_given || !r_.options_.out.empty() ||
                        !r_.options_.report.empty() || !r_.options_.truth_out.empty() ||
                        !r_.options_.error_out.empty() || !r_.options_.truth_job.empty() ||
                        !r_.options_.truth_result.empty();
  r_.gpu_->loop.frames_left = scripted ? r_.options_.frames + 1 : -1;
  r_.gpu_->loop.changed_at = std::chrono::steady_clock::now();
  return true;
}

bool RunnerWindow::frame() {
  GLFWwindow* window = r_.gpu_->window;
  Runner::Gpu::WindowLoop& loop = r_.gpu_->loop;
  if (glfwWindowShouldClose(window) || loop.frames_left == 0) return false;
  {
    auto& [last_x, last_y, h_was_down, c_was_down, dragging, changed_at, moved_at, last_key,
           frames_left, frame_number, outputs_failed] = loop;
    glfwPollEvents();
    const ImGuiIO& io = ImGui::GetIO();
    // Orbit the eye around its target with the left mouse button, zoom with the wheel.
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    // An exercise that does not let the student move the camera does not let the mouse either.
    const Exercise* ex = r_.exercise_.chosen();
    const bool camera_locked = ex != nullptr && !ex->camera_free;
    const bool down = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    Param& pos = r_.params_.at("camera.pos");
    const glm::vec3 target = r_.params_.at("camera.target").v();
    // Every move of the eye stays in front of the walls and floor it started in front of.
    const auto moveEye = [&](glm::vec3 eye) {
      r_.params_.setVec3(pos, orbit::keepInFront(eye, r_.scene(), r_.scene().camera.position));
    };
    if (down && !io.WantCaptureMouse && !camera_locked) {
      if (dragging) {
        moveEye(orbit::turn(pos.v(), target, static_cast<float>(x - last_x),
                            static_cast<float>(y - last_y)));
      }
      dragging = true;
    } else {
      dragging = false;
    }
    last_x = x, last_y = y;
    if (r_.options_.orbit > 0) {  // a scripted drag: the same turn, without a mouse
      const float drag = -glm::radians(float(r_.options_.orbit)) / orbit::kRadiansPerPixel;
      moveEye(orbit::turn(pos.v(), target, drag, 0.0f));
    }
    if (io.MouseWheel != 0.0f && !io.WantCaptureMouse && !camera_locked) {
      moveEye(target + (pos.v() - target) * std::pow(0.9f, io.MouseWheel));
    }
    // C brings the camera back to the scene's (on the key's press), where it may move.
    const bool c_down = glfwGetKey(window, GLFW_KEY_C) == GLFW_PRESS;
    if (c_down && !c_was_down && !io.WantTextInput && !camera_locked) r_.resetCamera();
    c_was_down = c_down;
    if (glfwGetKey(window, GLFW_KEY_F12) == GLFW_PRESS) screenshot_requested = true;
    // H hides or shows the panel (on the key's press, not while it is held).
    const bool h_down = glfwGetKey(window, GLFW_KEY_H) == GLFW_PRESS;
    if (h_down && !h_was_down && !io.WantTextInput)
      r_.options_.hide_panel = !r_.options_.hide_panel;
    h_was_down = h_down;

    int window_w = 0, h = 0;
    glfwGetFramebufferSize(window, &window_w, &h);
    column = columnFor(window_w);
    framebuffer = {window_w, h};
    int w = window_w - column, ph = h;  // the picture, left of the panel's column
    // An exercise is judged on the grader's picture: 640x480 in the corner, where the window
    // has room for the goal above it and the verdict beside it.
    exercise_strips = r_.exercise_.chosen() != nullptr && !r_.options_.size_given && column > 0 &&
                      w >= kExerciseWidth + 200 && h >= kExerciseHeight + 160;
    if (exercise_strips) w = kExerciseWidth, ph = kExerciseHeight;
    if (w > 0 && ph > 0) {
      r_.options_.width = w, r_.options_.height = ph;
      r_.gpu_->ensureTargets(w, ph);
      // The truth is re-measured once the sliders rest. Its rays (a few hundred ms) are traced
      // on a worker thread while frames go on; only the read-back of what it needs (the
      // visibility, shaded and geometry passes) takes the render thread.
      r_.errors_.poll();
      const std::string key = r_.errors_.key();
      const auto now = std::chrono::steady_clock::now();
      // Input moves while the key changes (the first frame's key is no move) or a widget is
      // held; a lesson may draw a cheaper picture then (Frame::input_moving).
      if (key != last_key) {
        if (!last_key.empty()) moved_at = now;
        changed_at = now, last_key = key;
      }
      const bool resting = now - changed_at > std::chrono::milliseconds(300);
      r_.setInputMoving(ImGui::IsAnyItemActive() ||
                        (moved_at && now - *moved_at <= std::chrono::milliseconds(300)));
      // Not while a light map bakes (lesson 15): the picture is about to change.
      const bool baking = r_.host_.bakeState().stage == BakeState::Stage::kRunning;
      if (r_.options_.truth && resting && key != r_.errors_.truth().key() &&
          !r_.errors_.truth().running() && !ImGui::IsAnyItemActive() && !baking) {
        r_.errors_.begin();
      }
      // The last frame waits for a truth being traced, and draws its panel anew, so that a
      // window's picture shows the panel's error, not "measuring..." (README panel pictures; a
      // truth not begun, as under --orbit, is not waited for).
      const bool tracing = !r_.options_.hide_panel && r_.errors_.truth().running();
      if (frames_left == 1 && !tracing) r_.gpu_->panel_input = true;
      // The panel's "shadow: N x the frame without it": one frame in 32 is rendered again,
      // off-screen, with shadow.off.
      r_.renderInto(0, w, ph, r_.currentView(), true, !r_.options_.hide_panel);
      // After the frame, so the panel's numbers (drawn first thing in a frame) are the
      // lesson's, not the baseline's.
#ifndef __EMSCRIPTEN__  // a page cannot time it (costSummary)
      if (!r_.options_.hide_panel && frame_number++ % 32 == 0) r_.baseline_.render();
#endif
      GlErrorLog::poll();
      if (screenshot_requested) {
        screenshot_requested = false;
        r_.headless_.saveScreenshot(window_w, h);  // as Runner::screenshot
      }
      if (frames_left > 0 && !(frames_left == 1 && tracing) && --frames_left == 0) {
        // The same outputs as a headless run: the window as shown (the picture, and the
        // panel's column beside it), and the report, truth and error pictures asked for, all
        // or none.
        Image image{window_w, h, std::vector<std::uint8_t>(static_cast<size_t>(window_w) * h * 4)};
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, window_w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        if (r_.options_.truthAsked()) r_.measureError();
        outputs_failed = !r_.headless_.writeOutputs(r_.options_.out, image);
      }
    }
    glfwSwapBuffers(window);
  }
  return true;
}

int RunnerWindow::columnFor(int framebufferWidth) const {
  if (r_.options_.hide_panel || r_.gpu_ == nullptr || r_.gpu_->window == nullptr) return 0;
  int window_width = 0, unused = 0;
  glfwGetWindowSize(r_.gpu_->window, &window_width, &unused);
  const float scale = window_width > 0
                          ? static_cast<float>(framebufferWidth) / static_cast<float>(window_width)
                          : 1.0f;
  const int wide = static_cast<int>(kPanelColumn * scale);
  // A window too narrow for a column and a picture of some use gets the panel over it.
  return framebufferWidth - wide >= static_cast<int>(200 * scale) ? wide : 0;
}

void RunnerWindow::fit(int width, int height) {
  if (r_.gpu_ == nullptr || r_.gpu_->window == nullptr || width <= 0 || height <= 0) return;
  int w = 0, h = 0;
  glfwGetWindowSize(r_.gpu_->window, &w, &h);
  if (w != width || h != height) glfwSetWindowSize(r_.gpu_->window, width, height);
}

void RunnerWindow::fitExercise() {
  fit(kExerciseWidth + (r_.options_.hide_panel ? 0 : static_cast<int>(kPanelColumn)),
      kExerciseHeight);
}

int RunnerWindow::end() {
  GLFWwindow* window = r_.gpu_->window;
  const bool outputs_failed = r_.gpu_->loop.outputs_failed;
  r_.releaseGl();
  glfwDestroyWindow(window);
  return GlErrorLog::count() > 0 || outputs_failed ? 1 : 0;
}

}  // namespace shadows
