// The window loop: GLFW, ImGui, the orbit camera, the truth when the sliders rest.
#include "run/window.hpp"

#include "gl/context.hpp"
#include "math/orbit.hpp"
#include "run/runner.hpp"

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
  const RunOptions& options = r_.options();
  int width = options.width, height = options.height;
#ifndef __EMSCRIPTEN__  // a page fits its window (page_main.cpp)
  if (!options.size_given) {
    width = 1280 - static_cast<int>(kPanelColumn), height = 720;
  }
#endif
#ifdef __EMSCRIPTEN__  // a page's canvas is the grader's picture (exercises.cpp)
  if (r_.exercises().number() > 0 && !options.size_given)
    width = kExerciseWidth, height = kExerciseHeight;
#endif
  if (!panel_hidden_) width += static_cast<int>(kPanelColumn);
  GLFWwindow* window = glfwCreateWindow(
      width, height, (r_.lessonName() + ": " + r_.lesson().title()).c_str(), nullptr, nullptr);
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
  window_ = window;
  // With an output or --frames, a windowed run renders --frames frames, writes what was asked
  // for and exits: that is how the tests check the real window path under xvfb.
  const bool scripted = options.frames_given || !options.out.empty() || !options.report.empty() ||
                        !options.truth_out.empty() || !options.error_out.empty() ||
                        !options.truth_job.empty() || !options.truth_result.empty();
  frames_left_ = scripted ? options.frames + 1 : -1;
  // A window that runs until closed bakes a light map on a thread; a scripted run waits for it.
  r_.host().setBakeInBackground(!scripted && !options.headless);
  r_.initGl();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  // Any input since the panel was last drawn asks for it anew (panelDue): these callbacks run
  // first, then ImGui's, which it chains to them.
  glfwSetWindowUserPointer(window, this);
  static constexpr auto input = [](GLFWwindow* w) {
    static_cast<RunnerWindow*>(glfwGetWindowUserPointer(w))->panel_input_ = true;
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
  r_.initImGuiGl(/*glfw=*/true);

  changed_at_ = std::chrono::steady_clock::now();
  return true;
}

void RunnerWindow::handleInput() {
  const ImGuiIO& io = ImGui::GetIO();
  const RunOptions& options = r_.options();
  Params& params = r_.params();
  // Orbit the eye around its target with the left mouse button, zoom with the wheel.
  double x = 0, y = 0;
  glfwGetCursorPos(window_, &x, &y);
  // An exercise that does not let the student move the camera does not let the mouse either.
  const Exercise* ex = r_.exercises().chosen();
  const bool camera_locked = ex != nullptr && !ex->camera_free;
  const bool down = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  Param& pos = params.at("camera.pos");
  const glm::vec3 target = params.at("camera.target").v();
  // Every move of the eye stays in front of the walls and floor it started in front of.
  const Scene& scene = r_.scene();
  const auto moveEye = [&](glm::vec3 eye) {
    params.setVec3(pos, orbit::keepInFront(eye, scene, scene.camera.position));
  };
  if (down && !io.WantCaptureMouse && !camera_locked) {
    if (dragging_) {
      moveEye(orbit::turn(pos.v(), target, static_cast<float>(x - last_x_),
                          static_cast<float>(y - last_y_)));
    }
    dragging_ = true;
  } else {
    dragging_ = false;
  }
  last_x_ = x, last_y_ = y;
  if (options.orbit > 0) {  // a scripted drag: the same turn, without a mouse
    const float drag = -glm::radians(float(options.orbit)) / orbit::kRadiansPerPixel;
    moveEye(orbit::turn(pos.v(), target, drag, 0.0f));
  }
  if (io.MouseWheel != 0.0f && !io.WantCaptureMouse && !camera_locked) {
    moveEye(target + (pos.v() - target) * std::pow(0.9f, io.MouseWheel));
  }
  // C brings the camera back to the scene's (on the key's press), where it may move.
  const bool c_down = glfwGetKey(window_, GLFW_KEY_C) == GLFW_PRESS;
  if (c_down && !c_was_down_ && !io.WantTextInput && !camera_locked) r_.resetCamera();
  c_was_down_ = c_down;
  if (glfwGetKey(window_, GLFW_KEY_F12) == GLFW_PRESS) screenshot_requested = true;
  // H hides or shows the panel (on the key's press, not while it is held).
  const bool h_down = glfwGetKey(window_, GLFW_KEY_H) == GLFW_PRESS;
  if (h_down && !h_was_down_ && !io.WantTextInput) panel_hidden_ = !panel_hidden_;
  h_was_down_ = h_down;
}

bool RunnerWindow::frame() {
  if (glfwWindowShouldClose(window_) || frames_left_ == 0) return false;
  glfwPollEvents();
  handleInput();
  const RunOptions& options = r_.options();
  ErrorMeasure& errors = r_.errors();
  int window_w = 0, h = 0;
  glfwGetFramebufferSize(window_, &window_w, &h);
  column = columnFor(window_w);
  framebuffer = {window_w, h};
  int w = window_w - column, ph = h;  // the picture, left of the panel's column
  // An exercise is judged on the grader's picture: 640x480 in the corner, where the window
  // has room for the goal above it and the verdict beside it.
  exercise_strips = r_.exercises().chosen() != nullptr && !options.size_given && column > 0 &&
                    w >= kExerciseWidth + 200 && h >= kExerciseHeight + 160;
  if (exercise_strips) w = kExerciseWidth, ph = kExerciseHeight;
  if (w > 0 && ph > 0) {
    r_.resizePicture(w, ph);
    // The truth is re-measured once the sliders rest. Its rays (a few hundred ms) are traced
    // on a worker thread while frames go on; only the read-back of what it needs (the
    // visibility, shaded and geometry passes) takes the render thread.
    errors.poll();
    const std::string key = errors.key();
    const auto now = std::chrono::steady_clock::now();
    // Input moves while the key changes (the first frame's key is no move) or a widget is
    // held; a lesson may draw a cheaper picture then (Frame::input_moving).
    if (key != last_key_) {
      if (!last_key_.empty()) moved_at_ = now;
      changed_at_ = now, last_key_ = key;
    }
    const bool resting = now - changed_at_ > std::chrono::milliseconds(300);
    r_.setInputMoving(ImGui::IsAnyItemActive() ||
                      (moved_at_ && now - *moved_at_ <= std::chrono::milliseconds(300)));
    // Not while a light map bakes (lesson 15): the picture is about to change.
    const bool baking = r_.host().bakeState().stage == BakeState::Stage::kRunning;
    if (options.truth && resting && key != errors.truth().key() && !errors.truth().running() &&
        !ImGui::IsAnyItemActive() && !baking) {
      errors.begin();
    }
    // The last frame waits for a truth being traced, and draws its panel anew, so that a
    // window's picture shows the panel's error, not "measuring..." (README panel pictures; a
    // truth not begun, as under --orbit, is not waited for).
    const bool tracing = !panel_hidden_ && errors.truth().running();
    if (frames_left_ == 1 && !tracing) panel_input_ = true;
    r_.render({0, w, ph, r_.currentView(), /*timed=*/true, !panel_hidden_});
    // After the frame, so the panel's numbers (drawn first thing in a frame) are the
    // lesson's, not the baseline's: one frame in 32 is rendered again, off-screen, with
    // shadow.off, for the panel's "shadow: N x the frame without it".
#ifndef __EMSCRIPTEN__  // a page cannot time it (costSummary)
    if (!panel_hidden_ && frame_number_++ % 32 == 0) r_.baseline().render();
#endif
    GlErrorLog::poll();
    if (screenshot_requested) {
      screenshot_requested = false;
      r_.outputs().saveScreenshot(window_w, h, /*window=*/true);  // as Runner::screenshot
    }
    if (frames_left_ > 0 && !(frames_left_ == 1 && tracing) && --frames_left_ == 0) {
      writeLastFrame(window_w, h);
    }
  }
  glfwSwapBuffers(window_);
  return true;
}

void RunnerWindow::writeLastFrame(int width, int height) {
  // The same outputs as a headless run: the window as shown (the picture, and the panel's
  // column beside it), and the report, truth and error pictures asked for, all or none.
  Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  if (r_.options().truthAsked()) r_.measureError();
  outputs_failed_ = !r_.outputs().writeOutputs(r_.options().out, image);
}

int RunnerWindow::columnFor(int framebufferWidth) const {
  if (panel_hidden_ || window_ == nullptr) return 0;
  int window_width = 0, unused = 0;
  glfwGetWindowSize(window_, &window_width, &unused);
  const float scale = window_width > 0
                          ? static_cast<float>(framebufferWidth) / static_cast<float>(window_width)
                          : 1.0f;
  const int wide = static_cast<int>(kPanelColumn * scale);
  // A window too narrow for a column and a picture of some use gets the panel over it.
  return framebufferWidth - wide >= static_cast<int>(200 * scale) ? wide : 0;
}

void RunnerWindow::fit(int width, int height) {
  if (window_ == nullptr || width <= 0 || height <= 0) return;
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  if (w != width || h != height) glfwSetWindowSize(window_, width, height);
}

void RunnerWindow::fitExercise() {
  fit(kExerciseWidth + (panel_hidden_ ? 0 : static_cast<int>(kPanelColumn)), kExerciseHeight);
}

int RunnerWindow::end() {
  r_.releaseGl();
  glfwDestroyWindow(window_);
  window_ = nullptr;
  return GlErrorLog::count() > 0 || outputs_failed_ ? 1 : 0;
}

void RunnerWindow::releaseGl() {
  panel_target_.reset();
  panel_color_ = Texture();
  panel_over_ = Program();
}

std::string RunnerWindow::costSummary() const {
  // The report's numbers (median of the timed frames so far), so panel and report agree.
  char line[128];
#ifdef __EMSCRIPTEN__
  // WebGL returns from glFinish before the GPU process has drawn: a page's wall times count
  // only its calls. Its frame is timed on the GPU where the browser has a timer; where not,
  // it says so once, never a time that is not the frame's.
  if (!caps().gpu_timer) {
    return "frame: this browser has no GPU timer (WebGL 2's EXT_disjoint_timer_query_webgl2): "
           "run the lesson natively for its cost";
  }
  const size_t gpu_frames = r_.measure().gpuTimedFrames();
  if (gpu_frames == 0) return "GPU frame: measuring...";
  std::snprintf(line, sizeof line, "GPU frame %.2f ms (median of %zu)",
                r_.measure().medianGpuFrameMs(), gpu_frames);
  return line;
#else
  const size_t frames = r_.measure().timedFrames();
  if (frames == 0) return "frame: measuring...";
  std::snprintf(line, sizeof line, "frame %.2f ms (median of %zu)", r_.measure().medianFrameMs(),
                frames);
  std::string summary = line;
  if (const double overhead = r_.baseline().overhead(); overhead > 0.0) {
    std::snprintf(line, sizeof line, "\nshadow: %.2fx the frame without it (%.2f ms)", overhead,
                  r_.baseline().measure().medianFrameMs());
    summary += line;
  }
  return summary;
#endif
}

std::string RunnerWindow::counterSummary() const {
  std::string counts;
  for (const auto& [name, count] : r_.measure().lastFrameCounts()) {
    counts += (counts.empty() ? "" : ", ") + name + " " + std::to_string(count);
  }
  for (const std::string& name : r_.measure().lastFrameUnavailable()) {
    counts += (counts.empty() ? "" : ", ") + name + " " + caps().unavailable();
  }
  return counts;
}

bool RunnerWindow::panelDue(int width, int height) {
  glm::dvec2 cursor;
  glfwGetCursorPos(window_, &cursor.x, &cursor.y);
  bool down = false;
  for (int b = GLFW_MOUSE_BUTTON_1; b <= GLFW_MOUSE_BUTTON_3; ++b) {
    down = down || glfwGetMouseButton(window_, b) == GLFW_PRESS;
  }
  const auto now = std::chrono::steady_clock::now();
  // A wheel turn waits in ImGui's io until a panel frame takes it (the orbit camera reads it
  // from there too); typing into a field wants every frame.
  const bool due =
      panel_draws_ < 3 || panel_color_.width() != width || panel_color_.height() != height ||
      cursor != cursor_ || down || down != buttons_down_ || panel_typing_ || panel_input_ ||
      ImGui::GetIO().MouseWheel != 0.0f || now - panel_drawn_ > std::chrono::milliseconds(250);
  cursor_ = cursor;
  buttons_down_ = down;
  return due;
}

void RunnerWindow::drawPanelTexture(int width, int height) {
  if (panel_color_.width() != width || panel_color_.height() != height) {
    panel_color_ = Texture::color(width, height, GL_RGBA8);
    panel_target_ = std::make_unique<Framebuffer>();
    panel_target_->attachColor(panel_color_);
    panel_target_->check();
  }
  if (panel_over_.id() == 0) {
    panel_over_ =
        Program(commonShaderDir() / "fullscreen.vert", commonShaderDir() / "panel_over.frag");
  }
  panel_target_->bind();
  glViewport(0, 0, width, height);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  const ImDrawData* data = ImGui::GetDrawData();
  ImGui_ImplOpenGL3_RenderDrawData(const_cast<ImDrawData*>(data));
  // Where it drew, in framebuffer pixels (ImGui's y points down, GL's up, and a scaled
  // display has more pixels than window units): the only pixels to lay over the frame.
  glm::vec2 lo(1e9f), hi(-1e9f);
  const glm::vec2 origin(data->DisplayPos.x, data->DisplayPos.y);
  const glm::vec2 scale(data->FramebufferScale.x, data->FramebufferScale.y);
  for (int l = 0; l < data->CmdListsCount; ++l) {
    for (const ImDrawVert& v : data->CmdLists[l]->VtxBuffer) {
      const glm::vec2 p = (glm::vec2(v.pos.x, v.pos.y) - origin) * scale;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  const glm::ivec2 a = glm::clamp(glm::ivec2(glm::floor(lo)), glm::ivec2(0), {width, height});
  const glm::ivec2 b = glm::clamp(glm::ivec2(glm::ceil(hi)), glm::ivec2(0), {width, height});
  panel_box_ =
      b.x > a.x && b.y > a.y ? glm::ivec4(a.x, height - b.y, b.x - a.x, b.y - a.y) : glm::ivec4(0);
  panel_drawn_ = std::chrono::steady_clock::now();
  panel_typing_ = ImGui::GetIO().WantTextInput;
  panel_input_ = false;
  ++panel_draws_;
}

void RunnerWindow::laySavedPanel(const Frame& frame, const SceneHost& host) {
  if (panel_box_.z == 0) return;
  // Over the whole framebuffer, the panel's column beside the picture included.
  glBindFramebuffer(GL_FRAMEBUFFER, frame.target);
  glViewport(0, 0, panel_color_.width(), panel_color_.height());
  glEnable(GL_SCISSOR_TEST);
  glScissor(panel_box_.x, panel_box_.y, panel_box_.z, panel_box_.w);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // the texture's colour carries its alpha
  panel_color_.bind(0);
  panel_over_.set("uPanel", 0);
  panel_over_.use();
  host.drawCovering();
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace shadows
