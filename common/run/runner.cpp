#include "run/runner.hpp"

#include "core/json.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

namespace shadows {

// ---------------------------------------------------------------- lesson registry

namespace {
std::map<std::string, LessonFactory>& registry() {
  static std::map<std::string, LessonFactory> lessons;
  return lessons;
}
std::vector<std::string>& hosts() {
  static std::vector<std::string> names;
  return names;
}
}  // namespace

LessonRegistrar::LessonRegistrar(const std::string& name, LessonFactory factory, bool host) {
  registry()[name] = std::move(factory);
  if (host) hosts().push_back(name);
}

std::vector<std::string> registeredHosts() {
  return hosts();
}

std::unique_ptr<Lesson> makeLesson(const std::string& name) {
  auto it = registry().find(name);
  if (it == registry().end()) throw std::invalid_argument("no lesson named " + name);
  return it->second();
}

std::vector<std::string> registeredLessons() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : registry()) names.push_back(name);
  return names;
}

// ---------------------------------------------------------------- Runner

View Runner::currentView() const {
  const std::string& name = params_.at("view").choice();
  for (const View& v : views_)
    if (v.name() == name) return v;
  return views::kShaded;  // unreachable: the choices are views_' names
}

Runner::Runner(const std::string& lessonName, std::unique_ptr<Lesson> lesson, RunOptions options)
    : name_(lessonName), lesson_(std::move(lesson)), options_(std::move(options)) {
  const std::vector<std::string> scenes = lesson_->scenes();
  params_.addChoice("scene", scenes, scenes.front(),
                    "scene preset (sets light and camera defaults)", kDirtyScene | kDirtyShadowMap);
  views_ = lesson_->views();
  std::vector<std::string> names;
  for (const View& v : views_) names.push_back(v.str());
  params_.addChoice("view", names, names.front(),
                    "what to show: shaded, the shadow term alone, debug views, the ray-traced "
                    "truth, or the error against it");
  lesson_->declare(params_);
  exercise_.pick(options_.exercise);
  errors_.onMeasured([this] { judgeExercise(); });
  declareShared();
  loadScene();
}

Runner::~Runner() {
  releaseGl();
  if (window_.is_open) glfwTerminate();
}

void Runner::declareShared() {
  // Sliders a lesson has no use for are not offered at all (a slider that does nothing
  // misleads), and --set rejects them.
  Params all;
  declareSharedInto(all);
  const Params::SharedScope shared(params_);  // the light and camera: every lesson's
  const auto unused = lesson_->unusedSharedParams();
  for (const Param& p : all.all()) {
    if (std::find(unused.begin(), unused.end(), p.name) == unused.end()) params_.add(p);
  }
}

void Runner::declareSharedInto(Params& params) {
  constexpr std::uint32_t kLight = kDirtyShadowMap;
  params.addChoice("light.type", {"spot", "directional"}, "spot",
                   "spot: perspective frustum; directional: orthographic", kLight);
  params.addVec3("light.pos", {3, 6, 4}, -50, 50, "light position", kLight);
  params.addVec3("light.target", {0, 0, 0}, -50, 50, "where the light points", kLight);
  params.addFloat("light.fov", 60, 5, 160, "spot light field of view, degrees", kLight).inactive =
      [](const Params& ps) {
        return ps.at("light.type").is("directional") ? "a directional light has no angle" : "";
      };
  params.addFloat("light.extent", 10, 0.5f, 50, "directional: half width of the light box", kLight)
      .inactive = [](const Params& ps) {
    return ps.at("light.type").is("spot") ? "a spot light has no box" : "";
  };
  // Near and far are the casters' own while shadow.fit is on (lessons with a shadow map).
  const auto fitted = [](const Params& ps) -> std::string {
    const Param* fit = ps.find("shadow.fit");
    return fit != nullptr && fit->b() ? "shadow.fit is on: near and far fit the casters" : "";
  };
  params.addFloat("light.near", 1, 0.001f, 100, "light frustum near plane", kLight).logarithmic =
      true;
  params.at("light.near").inactive = fitted;
  params.addFloat("light.far", 20, 0.01f, 1000, "light frustum far plane", kLight).logarithmic =
      true;
  params.at("light.far").inactive = fitted;
  params.addVec3("camera.pos", {0, 4, 8}, -100, 100, "eye position (drag in the window)");
  params.addVec3("camera.target", {0, 0, 0}, -100, 100, "what the eye looks at");
  params.addFloat("camera.fov", 45, 10, 120, "eye vertical field of view, degrees");
}

void Runner::loadScene() {
  host_.load(makeScene(params_.at("scene").choice()));
  const Scene& scene = host_.scene();
  const LightSetup& l = scene.light;
  // An omni light (11) has neither a type nor a target.
  if (Param* type = params_.find("light.type")) {
    params_.setDefaultChoice(*type, l.directional ? "directional" : "spot");
  }
  params_.setDefaultVec3(params_.at("light.pos"), l.position);
  if (Param* target = params_.find("light.target")) params_.setDefaultVec3(*target, l.target);
  const std::pair<const char*, float> frustum[] = {{"light.fov", l.fov},
                                                   {"light.extent", l.extent},
                                                   {"light.near", l.near},
                                                   {"light.far", l.far}};
  for (const auto& [name, value] : frustum) {
    if (Param* p = params_.find(name)) params_.setDefaultFloat(*p, value);
  }
  params_.setDefaultVec3(params_.at("camera.pos"), scene.camera.position);
  params_.setDefaultVec3(params_.at("camera.target"), scene.camera.target);
  params_.setDefaultFloat(params_.at("camera.fov"), scene.camera.fov);
  params_.consume(kDirtyScene);
  errors_.truth().forgetTracer();
}

void Runner::resetCamera() {
  const Scene& preset = host_.scene();
  params_.setVec3(params_.at("camera.pos"), preset.camera.position);
  params_.setVec3(params_.at("camera.target"), preset.camera.target);
  params_.setFloat(params_.at("camera.fov"), preset.camera.fov);
}

std::string Runner::applySets(const std::vector<std::string>& sets) {
  // The scene goes first: its preset sets light and camera defaults the others may override.
  for (const auto& s : sets) {
    if (s.rfind("scene=", 0) == 0) {
      if (auto e = params_.assign(s); !e.empty()) return e;
      loadScene();
    }
  }
  for (const auto& s : sets) {
    if (s.rfind("scene=", 0) == 0) continue;
    if (auto e = params_.assign(s); !e.empty()) return e;
  }
  return {};
}

std::string Runner::checkConsistency() const {
  const Param* near = params_.find("light.near");
  const Param* far = params_.find("light.far");
  if (near != nullptr && far != nullptr && near->f() >= far->f()) {
    return "light.near (" + near->text() + ") must be less than light.far (" + far->text() + ")";
  }
  return lesson_->refusal(params_, scene());
}

Light Runner::currentLight() const {
  const Params& p = params_;
  Light l;
  const Param* type = p.find("light.type");
  const Param* target = p.find("light.target");
  l.directional = type != nullptr && type->is("directional");
  l.position = p.at("light.pos").v();
  l.target = target != nullptr ? target->v() : scene().light.target;
  const glm::vec3 d = l.target - l.position;
  l.direction = glm::dot(d, d) > 1e-12f ? glm::normalize(d) : glm::vec3(0, -1, 0);
  // A lesson that does not offer a frustum slider gets the scene preset's value.
  auto value = [&](const char* name, float preset) {
    const Param* param = p.find(name);
    return param != nullptr ? param->f() : preset;
  };
  l.fov = value("light.fov", scene().light.fov);
  l.extent = value("light.extent", scene().light.extent);
  l.near = value("light.near", scene().light.near);
  l.far = value("light.far", scene().light.far);
  l.view = lookAtSafe(l.position, l.target);
  return l;
}

std::string Runner::lightOnSurface() const {
  const Light l = currentLight();
  if (l.directional) return {};
  return scene().surfaceAt(l.position, 1e-5f * std::max(scene().bounds().radius(), 1.0f));
}

void Runner::initHeadless() {
  context_ = createHeadlessContext(
      options_.backend.empty() ? headlessBackends().front() : options_.backend, options_.device);
  initGl();
  if (options_.panel) {
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    initImGuiGl();
  }
}

void Runner::initImGuiGl(bool glfw) {
  imgui_glfw_ = glfw;
  ImGui_ImplOpenGL3_Init(caps().es ? "#version 300 es" : "#version 330 core");
  // The font atlas read NEAREST: its glyphs land on whole pixels, so the panel looks the same
  // (headless panel pictures byte-identical) and costs a quarter less to draw on llvmpipe.
  ImGui_ImplOpenGL3_CreateDeviceObjects();
  glBindTexture(GL_TEXTURE_2D,
                static_cast<GLuint>(reinterpret_cast<std::intptr_t>(ImGui::GetIO().Fonts->TexID)));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  imgui_ = true;
}

void Runner::releaseGl() {
  // GL objects go while their context is still there: the lesson's, the timers', the
  // pieces', ImGui's, then the context.
  lesson_.reset();
  measure_.reset();
  baseline_.release();
  texels_.releaseGl();
  errors_.releaseGl();
  host_.releaseGl();
  headless_.target().release();
  floats_.release();
  window_.releaseGl();
  if (imgui_) {
    ImGui_ImplOpenGL3_Shutdown();
    if (imgui_glfw_) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    imgui_ = imgui_glfw_ = false;
  }
  context_.reset();
}

void Runner::initGl() {
  GlErrorLog::install();
  GlErrorLog::reset();
  measure_ = std::make_unique<Measure>();
  baseline_.init();
  errors_.initGl();
  host_.initGl();
  texels_.initGl();
  headless_.target().ensure(options_.width, options_.height);
  lesson_->init();
}

void Runner::resizePicture(int width, int height) {
  options_.width = width, options_.height = height;
  headless_.target().ensure(width, height);  // the frames without shadow draw there
}

bool Runner::panelShown() const {
  return imgui_ && (window_.is_open ? !window_.panelHidden() : options_.panel);
}

void Runner::setMouse(glm::vec2 position, bool leftDown) {
  window_.mouse = position;
  window_.mouse_down = leftDown;
}

int Runner::glErrors() const {
  return GlErrorLog::poll();
}

void Runner::renderFrame(bool timed) {
  const GLuint target = window_.is_open ? 0 : headless_.target().id();
  // In a window options_ holds the picture's size: the framebuffer less the panel's column.
  const int w = options_.width, h = options_.height;
  const bool panel = imgui_ && (window_.is_open || options_.panel);
  render({target, w, h, currentView(), timed, panel});
  GlErrorLog::poll();
}

FrameOutputs Runner::render(const FrameRequest& request) {
  const GLuint target = request.target;
  const int width = request.width, height = request.height;
  const bool withPanel = request.panel;
  Measure& measure = request.measure != nullptr ? *request.measure : *measure_;
  measure.setEnabled(request.timed);
  if (params_.consume(kDirtyScene)) loadScene();
  Light light;
  Frame frame(host_, params_, host_.scene(), measure, light);
  // The light and camera as the parameters say now; again after the panel, whose widgets
  // may move them this very frame (the lesson must draw with what its map is built for).
  const auto readParams = [&] {
    light = currentLight();
    frame.eye = params_.at("camera.pos").v();
    frame.view = cameraView();
    frame.projection = cameraProjection(width, height);
  };
  readParams();
  frame.width = width;
  frame.height = height;
  frame.target = target;
  frame.shown = request.view;
  frame.input_moving = input_moving_;

  // In a window the panel is drawn anew only when it may have changed (input, or every
  // quarter second for its numbers) and laid over the other frames from a texture: ImGui's
  // thousands of blended triangles cost a CPU rasterizer as much as some lessons' shadows.
  // A window's panel is drawn over its whole framebuffer (a column right of the picture).
  const glm::ivec2 panel_size = window_.is_open && window_.framebuffer.x > 0
                                    ? window_.framebuffer
                                    : glm::ivec2(width, height);
  const bool draw_panel =
      withPanel &&
      (!window_.is_open || (!baseline_.running() && window_.panelDue(panel_size.x, panel_size.y)));
  if (draw_panel) {
    newPanelFrame(width, height);
    drawPanel(frame);
    ImGui::Render();
    // A widget may have changed the scene, the light, the camera or the view this frame.
    if (params_.consume(kDirtyScene)) loadScene();
    readParams();
    frame.shown = currentView();
  }

  FrameOutputs told;  // none where the lesson draws nothing (the truth's views)
  measure.beginFrame();
  frame.bindTarget();
  resetGlState();  // every lesson starts from the same GL state
  if (frame.shows(views::kTruth) || frame.shows(views::kError)) {
    showTruth(frame, request.timed);
  } else {
    told = renderLesson(frame);
  }
  if (withPanel && !window_.is_open) {
    frame.bindTarget();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  } else if (withPanel) {
    if (draw_panel) window_.drawPanelTexture(panel_size.x, panel_size.y);
    window_.laySavedPanel(frame, host_);
  }
  measure.endFrame();
  measure.setEnabled(true);
  return told;
}

// A headless panel's ImGui frame takes its size and mouse from the runner (a test's); a
// window's from GLFW.
void Runner::newPanelFrame(int width, int height) {
  ImGuiIO& io = ImGui::GetIO();
  if (!window_.is_open) {
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(window_.mouse.x, window_.mouse.y);
    io.MouseDown[0] = window_.mouse_down;
  } else {
    ImGui_ImplGlfw_NewFrame();
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
}

// The runner's own views: the truth, or the error against it, as a picture over the frame.
void Runner::showTruth(Frame& frame, bool timed) {
  frame.measure.setEnabled(false);
#ifndef __EMSCRIPTEN__
  measureError();
#else
  // A page cannot wait seconds for the rays: it shows the last truth measured while its Web
  // Worker traces the current one, which the window loop starts once the sliders rest (here
  // instead when the page measures no error otherwise, ?no-truth).
  if (!options_.truth && errors_.truth().key() != errors_.key()) errors_.begin();
#endif
  frame.measure.setEnabled(timed);
  const Image& shown =
      frame.shows(views::kTruth) ? errors_.truth().truthImage() : errors_.truth().errorImage();
  if (!haveTruth() || shown.rgba.empty())
    frame.clearTarget(Frame::kNoTruthColor);  // a plain picture; the panel says why
  host_.showImage(frame, shown);
}

FrameOutputs Runner::renderLesson(Frame& frame) {
  // The texel views are the runner's, drawn over the lesson's shaded frame, whose map
  // they measure: `aliasing` (offered by map lessons) and `texels` (texels_.measure()).
  const bool texels = frame.shows(views::kAliasing) || frame.shows(views::kTexels);
  const View texel_view = frame.shown;
  if (texels) frame.shown = views::kShaded;
  ProgramVariants::takeUsed();  // only this frame's
  lesson_->render(frame);
  frame.measure.variants(ProgramVariants::takeUsed());
  if (texels) {
    frame.shown = texel_view;
    texels_.draw(frame, texel_view == views::kAliasing);
  }
  return {frame.light_view_projection, frame.light_reach, frame.truth_area_radius, frame.medium,
          frame.shadow_sampling};
}

glm::mat4 Runner::cameraView() const {
  return lookAtSafe(params_.at("camera.pos").v(), params_.at("camera.target").v());
}

glm::mat4 Runner::cameraProjection(int width, int height) const {
  const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
  return glm::perspective(glm::radians(params_.at("camera.fov").f()), aspect, scene().camera.near,
                          scene().eyeFar(params_.at("camera.pos").v()));
}

std::string Runner::screenshot() {
  headless_.saveScreenshot(options_.width, options_.height, window_.is_open);
  return headless_.screenshotSaid();
}

Image Runner::readImage() const {
  return headless_.target().read(options_.width, options_.height);
}

}  // namespace shadows
