// The runner's own GL state (targets, programs, the context, ImGui), shared by the files that
// implement Runner. Private to run/.
#pragma once

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <memory>
#include <optional>
#include <vector>

#include "gl/context.hpp"
#include "run/runner.hpp"

struct GLFWwindow;

namespace shadows {

struct Runner::Gpu {
  // First member, so it is destroyed last: every GL object below needs it to be deleted.
  std::unique_ptr<HeadlessContext> context;
  std::vector<Mesh> meshes;
  // Headless target: what the lesson draws into and the PNG is read from.
  Texture target_color, target_depth;
  std::unique_ptr<Framebuffer> target;
  // Float targets for the truth: surface (position, normal) and the lesson's visibility.
  Texture surface_position, surface_normal, surface_depth;
  std::unique_ptr<Framebuffer> surface;
  Texture float_color, float_depth;
  std::unique_ptr<Framebuffer> float_target;
  int size_w = 0, size_h = 0;
  int float_w = 0, float_h = 0;
  Program gbuffer, image, depth_inset;
  Program texel_heatmap, texel_raw;  // texel_density.frag, the aliasing view and its numbers
  Texture shown;                     // the error or truth image, uploaded for display
  // The window's panel: drawn into its own texture only when it may have changed, laid over
  // every frame (RunnerWindow::panelDue, drawPanelTexture, laySavedPanel).
  Texture panel_color;
  std::unique_ptr<Framebuffer> panel_target;
  Program panel_over;
  glm::ivec4 panel_box{0};  // x, y, width, height in framebuffer pixels, y up
  std::chrono::steady_clock::time_point panel_drawn{};
  glm::dvec2 cursor{-1.0};
  bool panel_input = false;  // a click, key, character or wheel turn since the last draw
  int panel_draws = 0;       // ImGui lays a window out over its first frames: draw those all
  bool panel_typing = false, buttons_down = false;
  GLuint empty_vao = 0;
  bool imgui = false;
  bool imgui_glfw = false;
  GLFWwindow* window = nullptr;
  // The window loop's state between frames (RunnerWindow::frame): the orbit drag, the H key,
  // when the sliders last moved, the frames a scripted run has left.
  struct WindowLoop {
    double last_x = 0, last_y = 0;
    bool h_was_down = false, c_was_down = false;
    bool dragging = false;
    std::chrono::steady_clock::time_point changed_at{};
    std::optional<std::chrono::steady_clock::time_point> moved_at;
    std::string last_key;
    int frames_left = -1;
    long long frame_number = 0;
    bool outputs_failed = false;
  } loop;

  ~Gpu() {
    if (imgui) {
      ImGui_ImplOpenGL3_Shutdown();
      if (imgui_glfw) ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
    if (empty_vao != 0) glDeleteVertexArrays(1, &empty_vao);
  }

  // The picture's target, at every size the frame is drawn at.
  void ensureTargets(int w, int h) {
    if (w == size_w && h == size_h) return;
    size_w = w, size_h = h;
    target_color = Texture::color(w, h, GL_RGBA8);
    target_depth = Texture::depthStencil(w, h);
    target = std::make_unique<Framebuffer>();
    target->attachColor(target_color);
    target->attachDepthStencil(target_depth);
    target->check();
  }
  // The float targets the truth and the texel numbers read back: only when those are measured
  // (a --no-truth run never allocates their 30 bytes a pixel, which the driver clears: a fifth
  // of a short headless run on llvmpipe).
  void ensureFloatTargets(int w, int h) {
    if (w == float_w && h == float_h) return;
    float_w = w, float_h = h;
    // The truth reads positions and normals back in float: OpenGL ES renders float colour only
    // with EXT_color_buffer_float (which WebGL 2 offers too).
    if (!caps().float_color_targets) {
      throw GlFailure("no float colour targets (EXT_color_buffer_float) for the truth's passes");
    }
    surface_position = Texture::color(w, h, GL_RGBA32F);
    surface_normal = Texture::color(w, h, GL_RGBA32F);
    surface_depth = Texture::depthStencil(w, h);
    surface = std::make_unique<Framebuffer>();
    surface->attachColor(surface_position, 0);
    surface->attachColor(surface_normal, 1);
    surface->attachDepthStencil(surface_depth);
    surface->check();
    float_color = Texture::color(w, h, GL_RGBA32F);
    float_depth = Texture::depthStencil(w, h);
    float_target = std::make_unique<Framebuffer>();
    float_target->attachColor(float_color);
    float_target->attachDepthStencil(float_depth);
    float_target->check();
  }
};

}  // namespace shadows
