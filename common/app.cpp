#include "app.hpp"

#include "context.hpp"
#include "json.hpp"

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

namespace shadows {

// ---------------------------------------------------------------- lesson registry

namespace {
std::map<std::string, LessonFactory>& registry() {
  static std::map<std::string, LessonFactory> lessons;
  return lessons;
}
}  // namespace

LessonRegistrar::LessonRegistrar(const std::string& name, LessonFactory factory) {
  registry()[name] = std::move(factory);
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

// ---------------------------------------------------------------- command line

namespace {

const char* kUsage =
    "usage: %s [options]\n"
    "  (no option)          a window with the ImGui panel if a display exists, else headless\n"
    "  --headless           render without a display (OSMesa) and write --out\n"
    "  --window             a window even when DISPLAY is unset (fails without a display)\n"
    "  --backend NAME       headless context: osmesa (default) or egl (surfaceless)\n"
    "  --size WxH           image size (default 800x600)\n"
    "  --frames N           timed frames after one warm-up frame (default 5)\n"
    "  --out FILE.png       write the final frame (default out/LESSON.png; in a window:\n"
    "                       --frames frames, then exit)\n"
    "  --panel              draw the ImGui panel into the headless picture too\n"
    "  --set name=value     set a parameter (repeatable); see --list-params\n"
    "  --list-params        list every parameter: name, type, default, range, help\n"
    "  --report FILE.json   parameters, timings, work counters, error against the truth\n"
    "  --truth-out FILE.png the ray-traced truth (white lit, black shadowed)\n"
    "  --error-out FILE.png the mistakes: magenta false shadow, cyan false lit\n"
    "  --no-truth           skip the ray-traced truth (faster)\n"
    "  --help               this text\n"
    "exit codes: 0 ok, 1 runtime failure (no context, shader error, GL error), 2 bad input\n";

bool isDevice(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  return std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
}

// "" or why `path` cannot be the output `flag` names (exit 2 before anything is rendered).
std::string outputProblem(const std::string& flag, const std::string& path) {
  const std::string shown = "'" + printable(path) + "'";
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return flag + ": cannot write " + shown + " (it is a directory)";
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.size() > 255 || path.size() > 4095) {
    return flag + ": cannot write " + shown.substr(0, 60) + "... (file name too long)";
  }
  if (!canWrite(path)) {
    return flag + ": cannot write " + shown + " (no such directory, or read-only)";
  }
  if (flag != "--report" && !isDevice(path)) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png") return flag + ": expected a .png file name, got " + shown;
  }
  return {};
}

bool parsePositive(const std::string& text, int& out, int max) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  if (text.size() > 6) return false;
  out = std::stoi(text);
  return out >= 1 && out <= max;
}

}  // namespace

std::string parseCommandLine(int argc, char** argv, RunOptions& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto next = [&](std::string& out) -> bool {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    std::string value;
    if (arg == "--headless") {
      o.headless = true;
    } else if (arg == "--window") {
      o.force_window = true;
    } else if (arg == "--panel") {
      o.panel = true;
    } else if (arg == "--no-truth") {
      o.truth = false;
    } else if (arg == "--list-params") {
      o.list_params = true;
    } else if (arg == "--help" || arg == "-h") {
      o.help = true;
    } else if (arg == "--backend") {
      if (!next(value) || (value != "osmesa" && value != "egl")) {
        return "--backend: expected osmesa or egl";
      }
      o.backend = value;
    } else if (arg == "--size") {
      const auto x = next(value) ? value.find('x') : std::string::npos;
      if (x == std::string::npos || !parsePositive(value.substr(0, x), o.width, 8192) ||
          !parsePositive(value.substr(x + 1), o.height, 8192)) {
        return "--size: expected WxH with W and H in 1..8192, got '" + value + "'";
      }
    } else if (arg == "--frames") {
      if (!next(value) || !parsePositive(value, o.frames, 100000)) {
        return "--frames: expected a whole number in 1..100000, got '" + value + "'";
      }
    } else if (arg == "--set") {
      if (!next(value)) return "--set: expected name=value";
      o.sets.push_back(value);
    } else if (arg == "--out" || arg == "--report" || arg == "--truth-out" ||
               arg == "--error-out") {
      if (!next(value)) return arg + ": expected a file name";
      if (std::string why = outputProblem(arg, value); !why.empty()) return why;
      (arg == "--out"         ? o.out
       : arg == "--report"    ? o.report
       : arg == "--truth-out" ? o.truth_out
                              : o.error_out) = value;
    } else {
      return "unknown option '" + printable(arg) + "'; see --help";
    }
  }
  // Two outputs into one regular file would leave only the last: refuse it up front.
  const std::pair<const char*, const std::string*> outputs[] = {{"--out", &o.out},
                                                                {"--report", &o.report},
                                                                {"--truth-out", &o.truth_out},
                                                                {"--error-out", &o.error_out}};
  for (size_t i = 0; i < std::size(outputs); ++i) {
    for (size_t j = i + 1; j < std::size(outputs); ++j) {
      const std::string &a = *outputs[i].second, &b = *outputs[j].second;
      if (a.empty() || b.empty() || isDevice(a)) continue;
      std::error_code ec;
      if (std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec)) {
        return std::string(outputs[i].first) + " and " + outputs[j].first +
               " name the same file '" + printable(a) + "'";
      }
    }
  }
  return {};
}

// ---------------------------------------------------------------- GPU state of the runner

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
  Program gbuffer, image, depth_inset;
  Texture shown;  // the error or truth image, uploaded for display
  GLuint empty_vao = 0;
  bool imgui = false;
  bool imgui_glfw = false;
  GLFWwindow* window = nullptr;

  ~Gpu() {
    if (imgui) {
      ImGui_ImplOpenGL3_Shutdown();
      if (imgui_glfw) ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
    if (empty_vao != 0) glDeleteVertexArrays(1, &empty_vao);
  }

  void ensureTargets(int w, int h) {
    if (w == size_w && h == size_h) return;
    size_w = w, size_h = h;
    target_color = Texture::color(w, h, GL_RGBA8);
    target_depth = Texture::depthStencil(w, h);
    target = std::make_unique<Framebuffer>();
    target->attachColor(target_color);
    target->attachDepthStencil(target_depth);
    target->check();
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

// ---------------------------------------------------------------- Frame helpers

void Frame::bindTarget() const {
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, width, height);
}

void Frame::clearTarget(glm::vec3 color) const {
  bindTarget();
  glClearColor(color.r, color.g, color.b, 1.0f);
  glClearStencil(0);
  glStencilMask(0xFF);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

void Frame::drawObjects(const Program& program, Objects which, const glm::mat4* cull) const {
  runner.drawObjects(*this, program, which, cull);
}

void Frame::setLightingUniforms(const Program& program, float dimming) const {
  program.set("uLightPos", light.position);
  program.set("uLightDir", light.direction);
  program.set("uLightDirectional", light.directional ? 1 : 0);
  program.set("uEye", eye);
  program.set("uDimming", dimming);
}

void Frame::drawDepthInset(const Texture& depth, float near, float far, bool perspective,
                           bool fullscreen) const {
  runner.drawInset(*this, depth, near, far, perspective, fullscreen);
}

void Frame::drawObject(const Program& program, size_t index) const {
  program.use();
  runner.drawObject(program, index);
}

void Frame::drawImageInset(const Texture& image, bool fullscreen) const {
  runner.drawImageInset(*this, image, fullscreen);
}

void Frame::drawFullscreen(const Program& program, bool inset) const {
  runner.drawFullscreen(*this, program, inset);
}

void Runner::drawFullscreen(const Frame& frame, const Program& program, bool inset) const {
  frame.bindTarget();
  const int side = std::max(16, std::min(frame.width, frame.height) / 4);
  if (inset) glViewport(frame.width - side - 8, 8, side, side);
  glDisable(GL_DEPTH_TEST);
  program.use();
  glBindVertexArray(gpu_->empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  countDrawCall();
  glEnable(GL_DEPTH_TEST);
  frame.bindTarget();
}

void Runner::drawImageInset(const Frame& frame, const Texture& image, bool fullscreen) const {
  const int side = std::max(16, std::min(frame.width, frame.height) / 4);
  const int wide = std::max(1, side * image.width() / std::max(image.height(), 1));
  frame.bindTarget();
  if (!fullscreen) glViewport(frame.width - wide - 8, 8, wide, side);
  glDisable(GL_DEPTH_TEST);
  image.bind(0);
  gpu_->image.use();
  gpu_->image.set("uImage", 0);
  glBindVertexArray(gpu_->empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  countDrawCall();
  glEnable(GL_DEPTH_TEST);
  frame.bindTarget();
}

void Runner::drawObjects(const Frame& frame, const Program& program, Objects which,
                         const glm::mat4* cull) const {
  program.use();
  for (size_t i = 0; i < scene_.objects.size(); ++i) {
    const SceneObject& object = scene_.objects[i];
    const Light& l = frame.light;
    if (which == Objects::Casters && !object.castsFrom(l.position, l.directional, l.direction)) {
      continue;
    }
    if (which == Objects::Receivers && !object.receiver) continue;
    if (cull != nullptr) {
      const Bounds b = object.worldBounds();
      if (sphereOutsideFrustum(*cull, b.center(), b.radius())) {
        frame.measure.count("culled_objects");
        continue;
      }
    }
    drawObject(program, i);
  }
}

void Runner::drawObject(const Program& program, size_t index) const {
  const SceneObject& object = scene_.objects.at(index);
  program.set("uModel", object.model);
  program.set("uNormalMatrix", glm::transpose(glm::inverse(object.model)));
  program.set("uColor", object.color);
  program.set("uObject", static_cast<int>(index));
  gpu_->meshes[index].draw();
}

void Runner::setObjectModel(size_t index, const glm::mat4& model) {
  SceneObject& object = scene_.objects.at(index);
  if (object.model == model) return;
  object.model = model;
  truth_.reset();  // the truth's triangles are in world space
  error_.valid = false;
  params_.markDirty(kDirtyShadowMap);  // a moved caster moves its shadow
}

void Runner::drawInset(const Frame& frame, const Texture& depth, float near, float far,
                       bool perspective, bool fullscreen) const {
  const int side = std::max(16, std::min(frame.width, frame.height) / 4);
  frame.bindTarget();
  if (!fullscreen) glViewport(frame.width - side - 8, 8, side, side);
  glDisable(GL_DEPTH_TEST);
  // The lesson samples this texture with a compare; a plain read needs the compare off.
  GLint compare_mode = GL_NONE;
  glBindTexture(GL_TEXTURE_2D, depth.id());
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &compare_mode);
  depth.setCompare(false);
  depth.bind(0);
  gpu_->depth_inset.use();
  gpu_->depth_inset.set("uDepth", 0);
  gpu_->depth_inset.set("uNear", near);
  gpu_->depth_inset.set("uFar", far);
  gpu_->depth_inset.set("uPerspective", perspective ? 1 : 0);
  glBindVertexArray(gpu_->empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  countDrawCall();
  depth.setCompare(compare_mode == GL_COMPARE_REF_TO_TEXTURE);
  glEnable(GL_DEPTH_TEST);
  frame.bindTarget();
}

// ---------------------------------------------------------------- Runner

Runner::Runner(const std::string& lessonName, std::unique_ptr<Lesson> lesson, RunOptions options)
    : name_(lessonName), lesson_(std::move(lesson)), options_(std::move(options)) {
  const std::vector<std::string> scenes = lesson_->scenes();
  params_.addChoice("scene", scenes, scenes.front(),
                    "scene preset (sets light and camera defaults)", kDirtyScene | kDirtyShadowMap);
  std::vector<std::string> views = {"shaded", "visibility"};
  for (const auto& v : lesson_->debugViews()) views.push_back(v);
  views.push_back("truth");
  views.push_back("error");
  params_.addChoice("view", views, "shaded",
                    "what to show: shaded, the shadow term alone, debug views, the ray-traced "
                    "truth, or the error against it");
  lesson_->declare(params_);
  declareShared();
  loadScene();
}

Runner::~Runner() {
  releaseGl();
  if (window_) glfwTerminate();
}

void Runner::declareShared() {
  // Sliders a lesson has no use for are not offered at all (a slider that does nothing
  // misleads), and --set rejects them.
  Params all;
  declareSharedInto(all);
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
  params.addFloat("light.fov", 60, 5, 160, "spot light field of view, degrees", kLight);
  params.addFloat("light.extent", 10, 0.5f, 50, "directional: half width of the light box", kLight);
  params.addFloat("light.near", 1, 0.001f, 100, "light frustum near plane", kLight).logarithmic =
      true;
  params.addFloat("light.far", 20, 0.01f, 1000, "light frustum far plane", kLight).logarithmic =
      true;
  params.addVec3("camera.pos", {0, 4, 8}, -100, 100, "eye position (drag in the window)");
  params.addVec3("camera.target", {0, 0, 0}, -100, 100, "what the eye looks at");
  params.addFloat("camera.fov", 45, 10, 120, "eye vertical field of view, degrees");
}

void Runner::loadScene() {
  scene_ = makeScene(params_.at("scene").choice());
  preset_models_.clear();
  for (const auto& object : scene_.objects) preset_models_.push_back(object.model);
  const LightSetup& l = scene_.light;
  params_.setDefaultChoice(params_.at("light.type"), l.directional ? "directional" : "spot");
  params_.setDefaultVec3(params_.at("light.pos"), l.position);
  params_.setDefaultVec3(params_.at("light.target"), l.target);
  const std::pair<const char*, float> frustum[] = {{"light.fov", l.fov},
                                                   {"light.extent", l.extent},
                                                   {"light.near", l.near},
                                                   {"light.far", l.far}};
  for (const auto& [name, value] : frustum) {
    if (Param* p = params_.find(name)) params_.setDefaultFloat(*p, value);
  }
  params_.setDefaultVec3(params_.at("camera.pos"), scene_.camera.position);
  params_.setDefaultVec3(params_.at("camera.target"), scene_.camera.target);
  params_.setDefaultFloat(params_.at("camera.fov"), scene_.camera.fov);
  params_.consume(kDirtyScene);
  truth_.reset();
  if (gpu_) {
    gpu_->meshes.clear();
    for (const auto& object : scene_.objects) gpu_->meshes.emplace_back(object.mesh);
  }
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
  return {};
}

Light Runner::currentLight() const {
  const Params& p = params_;
  Light l;
  l.directional = p.at("light.type").is("directional");
  l.position = p.at("light.pos").v();
  l.target = p.at("light.target").v();
  const glm::vec3 d = l.target - l.position;
  l.direction = glm::dot(d, d) > 1e-12f ? glm::normalize(d) : glm::vec3(0, -1, 0);
  // A lesson that does not offer a frustum slider gets the scene preset's value.
  auto value = [&](const char* name, float preset) {
    const Param* param = p.find(name);
    return param != nullptr ? param->f() : preset;
  };
  l.fov = value("light.fov", scene_.light.fov);
  l.extent = value("light.extent", scene_.light.extent);
  l.near = value("light.near", scene_.light.near);
  l.far = value("light.far", scene_.light.far);
  l.view = lookAtSafe(l.position, l.target);
  return l;
}

void Runner::initHeadless() {
  gpu_ = std::make_unique<Gpu>();
  gpu_->context = createHeadlessContext(options_.backend);
  initGl();
  if (options_.panel) {
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui_ImplOpenGL3_Init("#version 330 core");
    gpu_->imgui = true;
  }
}

void Runner::releaseGl() {
  // GL objects go while their context is still there: the lesson's, the timers', then the
  // runner's own, the context last (Gpu declares it first, so it is destroyed last).
  lesson_.reset();
  measure_.reset();
  gpu_.reset();
}

void Runner::initGl() {
  GlErrorLog::install();
  GlErrorLog::reset();
  measure_ = std::make_unique<Measure>();
  const auto dir = commonShaderDir();
  gpu_->gbuffer = Program(dir / "gbuffer.vert", dir / "gbuffer.frag");
  gpu_->image = Program(dir / "fullscreen.vert", dir / "image.frag");
  gpu_->depth_inset = Program(dir / "fullscreen.vert", dir / "depth_inset.frag");
  glGenVertexArrays(1, &gpu_->empty_vao);
  for (const auto& object : scene_.objects) gpu_->meshes.emplace_back(object.mesh);
  gpu_->ensureTargets(options_.width, options_.height);
  lesson_->init();
}

void Runner::setMouse(glm::vec2 position, bool leftDown) {
  mouse_ = position;
  mouse_down_ = leftDown;
}

int Runner::glErrors() const {
  return GlErrorLog::poll();
}

void Runner::renderFrame(bool timed) {
  const GLuint target = window_ ? 0 : gpu_->target->id();
  int w = options_.width, h = options_.height;
  if (window_) glfwGetFramebufferSize(gpu_->window, &w, &h);
  const bool panel = gpu_->imgui && (window_ || options_.panel);
  renderInto(target, w, h, params_.at("view").choice(), timed, panel);
  GlErrorLog::poll();
}

void Runner::renderInto(GLuint target, int width, int height, const std::string& mode, bool timed,
                        bool withPanel) {
  measure_->setEnabled(timed);
  if (params_.consume(kDirtyScene)) loadScene();
  Light light;
  Frame frame(*this, params_, scene_, *measure_, light);
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
  frame.mode = mode;

  if (withPanel) {
    ImGuiIO& io = ImGui::GetIO();
    if (!window_) {
      io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
      io.DeltaTime = 1.0f / 60.0f;
      io.MousePos = ImVec2(mouse_.x, mouse_.y);
      io.MouseDown[0] = mouse_down_;
    } else {
      ImGui_ImplGlfw_NewFrame();
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    drawPanel(frame);
    ImGui::Render();
    // A widget may have changed the scene, the light, the camera or the view this frame.
    if (params_.consume(kDirtyScene)) loadScene();
    readParams();
    frame.mode = params_.at("view").choice();
  }

  measure_->beginFrame();
  frame.bindTarget();
  resetGlState();  // every lesson starts from the same GL state
  if (frame.mode == "truth" || frame.mode == "error") {
    measure_->setEnabled(false);
    measureError();
    measure_->setEnabled(timed);
    showImage(frame, frame.mode == "truth" ? truth_image_ : error_image_);
  } else {
    lesson_->render(frame);
    light_frustum_ = frame.light_view_projection;
    truth_area_radius_ = frame.truth_area_radius;
    medium_ = frame.medium;
  }
  if (withPanel) {
    frame.bindTarget();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }
  measure_->endFrame();
  measure_->setEnabled(true);
}

glm::mat4 Runner::cameraView() const {
  return lookAtSafe(params_.at("camera.pos").v(), params_.at("camera.target").v());
}

glm::mat4 Runner::cameraProjection(int width, int height) const {
  const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
  return glm::perspective(glm::radians(params_.at("camera.fov").f()), aspect, scene_.camera.near,
                          scene_.camera.far);
}

void Runner::showImage(const Frame& frame, const Image& image) {
  if (image.width == 0) return;
  if (gpu_->shown.width() != image.width || gpu_->shown.height() != image.height) {
    gpu_->shown = Texture::color(image.width, image.height, GL_RGBA8);
  }
  glBindTexture(GL_TEXTURE_2D, gpu_->shown.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                  image.rgba.data());
  drawImageInset(frame, gpu_->shown, /*fullscreen=*/true);
}

std::vector<float> Runner::renderVisibility() {
  return renderRed("visibility");
}

std::vector<float> Runner::renderRed(const std::string& mode) {
  const int w = options_.width, h = options_.height;
  gpu_->ensureTargets(w, h);
  const GLuint fbo = gpu_->float_target->id();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  renderInto(fbo, w, h, mode, false, false);
  std::vector<glm::vec4> rgba(static_cast<size_t>(w) * h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  std::vector<float> red(rgba.size());
  for (size_t i = 0; i < rgba.size(); ++i) red[i] = rgba[i].r;
  return red;
}

void Runner::resetGlState() {
  PassState{}.apply();
  glDisable(GL_CLIP_DISTANCE0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

std::string Runner::errorKey() const {
  // Everything that can change the picture: every parameter but the view, and the size.
  std::string key = std::to_string(options_.width) + "x" + std::to_string(options_.height);
  char value[40];
  for (const auto& p : params_.all()) {
    if (p.name == "view") continue;
    // Full precision: text() rounds to 6 digits, and nearby values must not share a key.
    key += ";" + p.name + "=" + p.string_value;
    for (double v : p.value) {
      std::snprintf(value, sizeof value, ",%.17g", v);
      key += value;
    }
  }
  return key;
}

const ErrorState& Runner::measureError() {
  const std::string key = errorKey();
  if (error_.valid && key == error_key_) return error_;
  const int w = options_.width, h = options_.height;
  const size_t n = static_cast<size_t>(w) * h;
  const bool was_enabled = measure_->enabled();
  measure_->setEnabled(false);

  // The lesson's shadow term, and its shaded picture in float to catch NaN and Inf.
  std::vector<float> rendered = renderVisibility();
  const GLuint fbo = gpu_->float_target->id();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  renderInto(fbo, w, h, "shaded", false, false);
  std::vector<glm::vec4> shaded(n);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, shaded.data());

  // The surface seen by each pixel, from the runner's own geometry pass.
  SurfaceBuffer surface{w, h, std::vector<glm::vec4>(n), std::vector<glm::vec4>(n)};
  gpu_->surface->bind();
  glViewport(0, 0, w, h);
  const float clear_position[4] = {0, 0, 0, -1};
  const float clear_normal[4] = {0, 0, 0, 0};
  resetGlState();  // whatever the lesson left set must not shape the truth's surfaces
  glClearBufferfv(GL_COLOR, 0, clear_position);
  glClearBufferfv(GL_COLOR, 1, clear_normal);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  const Light light = currentLight();
  Frame frame(*this, params_, scene_, *measure_, light);
  // The very camera the lesson drew with, or truth and picture would not line up.
  gpu_->gbuffer.set("uViewProjection", cameraProjection(w, h) * cameraView());
  gpu_->gbuffer.set("uHasLightFrustum", light_frustum_ ? 1 : 0);
  gpu_->gbuffer.set("uLightViewProjection", light_frustum_.value_or(glm::mat4(1.0f)));
  drawObjects(frame, gpu_->gbuffer, Objects::All, nullptr);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, surface.position.data());
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, surface.normal.data());

  if (!truth_) {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;
    scene_.worldTriangles(positions, triangles);
    truth_ = std::make_unique<Truth>(positions, triangles, scene_.bounds().radius());
  }
  TruthLight truth_light;
  truth_light.position = light.position;
  truth_light.direction = light.direction;
  truth_light.directional = light.directional;
  truth_light.radius = truth_area_radius_;
  truth_light.samples = 64;
  const std::vector<float> truth = truth_->visibility(surface, truth_light);
  const std::vector<float> weight = Truth::facingWeight(surface, truth_light);

  error_.metrics = compareVisibility(rendered, truth, weight);
  error_.metrics.truth = light.directional ? "directional" : "point";
  if (truth_area_radius_ > 0.0f) {
    char name[64];
    std::snprintf(name, sizeof name, "area r=%g n=%d", truth_area_radius_, truth_light.samples);
    error_.metrics.truth = name;
  }
  // Non-finite pixels: where the visibility or any channel of the shaded picture is NaN or
  // Inf, each pixel counted once.
  long long nonfinite = 0;
  std::vector<std::uint8_t> shaded_bytes(n * 4);
  for (size_t i = 0; i < n; ++i) {
    bool finite = std::isfinite(rendered[i]);
    for (int c = 0; c < 4; ++c) {
      const float v = shaded[i][c];
      finite = finite && std::isfinite(v);
      shaded_bytes[i * 4 + static_cast<size_t>(c)] = static_cast<std::uint8_t>(
          std::lround(255.0f * std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f)));
    }
    if (!finite) ++nonfinite;
  }
  error_.metrics.nonfinite_pixels = nonfinite;
  error_image_ = {w, h, errorImage(shaded_bytes, rendered, truth)};
  truth_image_ = {w, h, std::vector<std::uint8_t>(n * 4)};
  for (size_t i = 0; i < n; ++i) {
    // Truth lit white, shadowed black, not counted (no surface, facing away) dark blue.
    const bool counted = truth[i] >= 0.0f;
    const auto grey = static_cast<std::uint8_t>(std::lround(255.0f * std::max(truth[i], 0.0f)));
    truth_image_.rgba[i * 4 + 0] = counted ? grey : 20;
    truth_image_.rgba[i * 4 + 1] = counted ? grey : 24;
    truth_image_.rgba[i * 4 + 2] = counted ? grey : 60;
    truth_image_.rgba[i * 4 + 3] = 255;
  }
  error_.metrics.air = AirMetrics{};
  if (medium_) measureAir(surface);
  error_.valid = true;
  error_key_ = key;
  measure_->setEnabled(was_enabled);
  return error_;
}

void Runner::measureAir(const SurfaceBuffer& surface) {
  // The lesson's air light alone, unscaled, against single scattering traced along the very
  // eye rays of its pixels. The truth and error views then show the air.
  const int w = options_.width, h = options_.height;
  const std::vector<float> rendered = renderRed("air");
  const glm::mat4 inverse_view_projection = glm::inverse(cameraProjection(w, h) * cameraView());
  air_truth_ = truth_->airLight(surface, params_.at("camera.pos").v(), inverse_view_projection,
                                scene_.camera.far, *medium_);
  error_.metrics.air = compareAir(rendered, air_truth_);
  error_.metrics.nonfinite_pixels += error_.metrics.air.nonfinite;
  error_image_ = {w, h, airErrorImage(rendered, air_truth_.light)};
  for (size_t i = 0; i < air_truth_.light.size(); ++i) {
    const auto grey = static_cast<std::uint8_t>(
        std::lround(255.0f * std::clamp(air_truth_.light[i], 0.0f, 1.0f)));
    truth_image_.rgba[i * 4 + 0] = truth_image_.rgba[i * 4 + 1] = grey;
    truth_image_.rgba[i * 4 + 2] = grey;
  }
}

Image Runner::readImage() const {
  const int w = options_.width, h = options_.height;
  Image image{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
  glBindFramebuffer(GL_FRAMEBUFFER, gpu_->target->id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  return image;
}

std::string Runner::costSummary() const {
  // The report's numbers (median of the timed frames so far), so panel and report agree.
  const size_t frames = measure_->timedFrames();
  if (frames == 0) return "frame: measuring...";
  char line[96];
  std::snprintf(line, sizeof line, "frame %.2f ms (median of %zu)", measure_->medianFrameMs(),
                frames);
  return line;
}

void Runner::drawPanel(Frame& frame) {
  // Narrow, in the top-left corner, in sections that fold away; folded whole on small
  // pictures, where it would hide everything.
  const float width = std::min(300.0f, 0.45f * static_cast<float>(frame.width));
  ImGui::SetNextWindowPos(ImVec2(6, 6), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(frame.height) - 12),
                           ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(frame.width < 600, ImGuiCond_FirstUseEver);
  ImGui::Begin(name_.c_str());
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 8.5f);  // room for the longest labels
  ImGui::TextWrapped("%s", lesson_->title().c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", lesson_->seeds().c_str());
  ImGui::PopStyleColor();
  params_.drawWidgets([](const Param& p) { return p.name == "view" || p.name == "scene"; });
  if (ImGui::Button("Screenshot (F12)")) screenshot_requested_ = true;

  const auto shared = [](const Param& p) {
    return p.name == "view" || p.name == "scene" || p.name.rfind("light.", 0) == 0 ||
           p.name.rfind("camera.", 0) == 0;
  };
  if (ImGui::CollapsingHeader("Technique", ImGuiTreeNodeFlags_DefaultOpen)) {
    params_.drawWidgets([&](const Param& p) { return !shared(p); });
    lesson_->panel(frame);
  }
  if (ImGui::CollapsingHeader("Light and camera", ImGuiTreeNodeFlags_DefaultOpen)) {
    params_.drawWidgets([](const Param& p) {
      return p.name.rfind("light.", 0) == 0 || p.name.rfind("camera.", 0) == 0;
    });
  }
  if (ImGui::CollapsingHeader("Cost", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::TextUnformatted(costSummary().c_str());
    // One line per pass ever run, so widgets never jump around.
    const auto& work = measure_->lastFrameWork();
    for (const auto& [pass, ms] : measure_->medianPassMs()) {
      const auto it = work.find(pass);
      if (it == work.end()) {
        ImGui::Text("  %-8s skipped this frame", pass.c_str());
      } else {
        ImGui::Text("  %-8s %6.2f ms %2lld draws", pass.c_str(), ms, it->second.draw_calls);
        ImGui::TextDisabled("           %lld fragments", it->second.fragment_invocations);
      }
    }
    std::string counts;
    for (const auto& [name, count] : measure_->lastFrameCounts()) {
      counts += (counts.empty() ? "" : ", ") + name + " " + std::to_string(count);
    }
    ImGui::TextWrapped("%s", counts.c_str());
  }
  if (options_.truth && ImGui::CollapsingHeader("Error", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (error_.valid) {
      const ErrorMetrics& e = error_.metrics;
      ImGui::TextWrapped("false shadow %.3f%%  false lit %.3f%%", e.false_shadow_pct,
                         e.false_lit_pct);
      ImGui::TextWrapped("vis_mae %.4f  non-finite %lld  counted %lld%s", e.vis_mae,
                         e.nonfinite_pixels, e.counted_pixels,
                         error_key_ == errorKey() ? "" : "  (stale: updating)");
      if (e.counted_pixels == 0) {
        ImGui::TextWrapped(
            "No pixel counted: no lit surface faces the eye in the light's "
            "frustum (is the eye inside an object?)");
      }
      if (e.air.valid) {
        ImGui::TextWrapped("air: mae %.4f  rel. RMSE %.1f%% (truth mean %.3f, noise %.4f)",
                           e.air.mae, 100.0 * e.air.rel_rmse, e.air.truth_mean, e.air.truth_noise);
      }
    } else {
      ImGui::TextDisabled("not measured yet");
    }
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

void Runner::writeReport(JsonWriter& json) {
  json.beginObject();
  json.value("lesson", name_);
  json.value("renderer", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  json.value("backend", window_ ? std::string("window") : HeadlessContext::current());
  json.beginArray("size");
  json.value("", options_.width);
  json.value("", options_.height);
  json.endArray();
  json.value("frames", options_.frames);
  params_.writeJson(json);
  json.value("frame_ms", measure_->medianFrameMs());
  json.beginObject("pass_ms");
  for (const auto& [pass, ms] : measure_->medianPassMs()) json.value(pass, ms);
  json.endObject();
  json.beginObject("counters");
  for (const auto& [pass, work] : measure_->lastFrameWork()) {
    json.beginObject(pass);
    json.value("draw_calls", work.draw_calls);
    json.value("fragment_invocations", work.fragment_invocations);
    json.endObject();
  }
  for (const auto& [name, count] : measure_->lastFrameCounts()) json.value(name, count);
  json.endObject();
  json.value("gl_errors", glErrors());
  lesson_->report(json);
  if (error_.valid) {
    const ErrorMetrics& e = error_.metrics;
    json.beginObject("error");
    json.value("truth", e.truth);
    json.value("false_shadow_pct", e.false_shadow_pct);
    json.value("false_lit_pct", e.false_lit_pct);
    json.value("vis_mae", e.vis_mae);
    json.value("shade_mae", e.shade_mae);
    json.value("nonfinite_pixels", e.nonfinite_pixels);
    json.value("counted_pixels", e.counted_pixels);
    if (e.air.valid) {
      json.value("air_mae", e.air.mae);
      json.value("air_rel_rmse", e.air.rel_rmse);
      json.value("air_truth_mean", e.air.truth_mean);
      json.value("air_truth_noise", e.air.truth_noise);
      json.value("air_pixels", e.air.pixels);
    }
    json.endObject();
  }
  json.endObject();
}

void Runner::saveScreenshot(int width, int height, const std::string& file) {
  Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  glBindFramebuffer(GL_FRAMEBUFFER, window_ ? 0 : gpu_->target->id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  const std::string path =
      file.empty() ? name_ + "_screenshot_" + std::to_string(++screenshots_taken_) + ".png" : file;
  if (writePng(path, image)) {
    std::printf("screenshot: %s\n", path.c_str());
  } else {
    std::fprintf(stderr, "screenshot: cannot write %s\n", path.c_str());
  }
}

int Runner::run() {
  const char* display = std::getenv("DISPLAY");
  const bool has_display = display != nullptr && *display != '\0';
  if (options_.headless || (!has_display && !options_.force_window)) {
    if (!options_.headless) std::printf("%s: no display, rendering headless\n", name_.c_str());
    return runHeadless();
  }
  const int result = runWindow();
  if (result != kNoWindow) return result;
  if (options_.force_window) return 1;
  // A DISPLAY that leads nowhere (a closed ssh tunnel, a stale variable): say so, go on.
  std::printf("%s: cannot open a window on DISPLAY=%s, rendering headless\n", name_.c_str(),
              has_display ? display : "");
  return runHeadless();
}

int Runner::runHeadless() {
  initHeadless();
  // Without --out the picture goes where ./run.sh puts them, out/<lesson>.png (git-ignored).
  std::string out = options_.out;
  if (out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories("out", ec);
    out = "out/" + name_ + ".png";
  }
  renderFrame();  // warm-up: shader JIT and the first shadow map land here
  // A snapshot with the panel should show the error numbers, so measure them first.
  if (options_.panel && options_.truth) measureError();
  measure_->clearHistory();
  for (int i = 0; i < options_.frames; ++i) renderFrame();
  // The panel shows the run's medians, the numbers the report gives: it is drawn once more,
  // untimed, after the last timed frame.
  if (options_.panel) renderFrame(/*timed=*/false);
  const Image image = readImage();
  // Asking for the truth or error picture asks for the truth, --no-truth or not.
  if (options_.truth || !options_.truth_out.empty() || !options_.error_out.empty()) {
    measureError();
  }
  if (!writeOutputs(out, image)) return 1;
  const int errors = glErrors();
  std::printf("%-30s %dx%d  frame %7.2f ms", out.c_str(), options_.width, options_.height,
              measure_->medianFrameMs());
  const auto& counts = measure_->lastFrameCounts();
  if (const auto it = counts.find("shadow_map_renders"); it != counts.end() && it->second == 0) {
    std::printf(" (map cached)");
  }
  if (error_.valid) {
    std::printf("  false shadow %6.2f%%  false lit %5.2f%%", error_.metrics.false_shadow_pct,
                error_.metrics.false_lit_pct);
  }
  std::printf("  gl_errors %d\n", errors);
  if (errors > 0) {
    std::fprintf(stderr, "%s: %d GL error(s), last: %s\n", name_.c_str(), errors,
                 GlErrorLog::last().c_str());
    return 1;
  }
  return 0;
}

bool Runner::writeOutputs(const std::string& out, const Image& image) {
  // Every output of the run, or none: a picture without its report is a half answer.
  OutputBatch batch;
  if (!out.empty()) batch.add(out, encodePng(image));
  if (!options_.truth_out.empty()) batch.add(options_.truth_out, encodePng(truth_image_));
  if (!options_.error_out.empty()) batch.add(options_.error_out, encodePng(error_image_));
  if (!options_.report.empty()) {
    JsonWriter json;
    writeReport(json);
    batch.add(options_.report, json.str() + "\n");
  }
  if (batch.commit()) return true;
  std::fprintf(stderr, "%s: %s\n", name_.c_str(), batch.failure().c_str());
  return false;
}

int Runner::runWindow() {
  glfwSetErrorCallback(
      [](int, const char* description) { std::fprintf(stderr, "GLFW: %s\n", description); });
  if (!glfwInit()) return kNoWindow;
  window_ = true;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_STENCIL_BITS, 8);
  GLFWwindow* window = glfwCreateWindow(
      options_.width, options_.height, (name_ + ": " + lesson_->title()).c_str(), nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "%s: cannot open a 4.5 core window\n", name_.c_str());
    glfwTerminate();
    window_ = false;
    return kNoWindow;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  if (gladLoadGL(glfwGetProcAddress) == 0) throw GlFailure("glad could not load GL");
  gpu_ = std::make_unique<Gpu>();
  gpu_->window = window;
  initGl();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  gpu_->imgui = gpu_->imgui_glfw = true;

  double last_x = 0, last_y = 0;
  bool dragging = false;
  auto changed_at = std::chrono::steady_clock::now();
  std::string last_key;
  // With --out, a windowed run renders --frames frames, saves the window and exits: that is
  // how the tests check the real window path under xvfb.
  int frames_left = options_.out.empty() ? -1 : options_.frames + 1;
  bool outputs_failed = false;
  while (!glfwWindowShouldClose(window) && frames_left != 0) {
    glfwPollEvents();
    const ImGuiIO& io = ImGui::GetIO();
    // Orbit the eye around its target with the left mouse button, zoom with the wheel.
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    const bool down = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    if (down && !io.WantCaptureMouse) {
      if (dragging) {
        Param& pos = params_.at("camera.pos");
        const glm::vec3 target = params_.at("camera.target").v();
        glm::vec3 offset = pos.v() - target;
        const float radius = glm::length(offset);
        float yaw = std::atan2(offset.x, offset.z) - 0.01f * static_cast<float>(x - last_x);
        float pitch = std::asin(std::clamp(offset.y / std::max(radius, 1e-6f), -1.0f, 1.0f)) +
                      0.01f * static_cast<float>(y - last_y);
        pitch = std::clamp(pitch, -1.5f, 1.5f);
        offset = radius * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                    std::cos(pitch) * std::cos(yaw));
        params_.setVec3(pos, target + offset);
      }
      dragging = true;
    } else {
      dragging = false;
    }
    last_x = x, last_y = y;
    if (io.MouseWheel != 0.0f && !io.WantCaptureMouse) {
      Param& pos = params_.at("camera.pos");
      const glm::vec3 target = params_.at("camera.target").v();
      params_.setVec3(pos, target + (pos.v() - target) * std::pow(0.9f, io.MouseWheel));
    }
    if (glfwGetKey(window, GLFW_KEY_F12) == GLFW_PRESS) screenshot_requested_ = true;

    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    if (w > 0 && h > 0) {
      options_.width = w, options_.height = h;
      gpu_->ensureTargets(w, h);
      // The truth is re-measured once the sliders rest (it costs a few hundred ms).
      const std::string key = errorKey();
      if (key != last_key) changed_at = std::chrono::steady_clock::now(), last_key = key;
      const bool resting =
          std::chrono::steady_clock::now() - changed_at > std::chrono::milliseconds(300);
      if (options_.truth && resting && key != error_key_ && !ImGui::IsAnyItemActive()) {
        measureError();
      }
      renderInto(0, w, h, params_.at("view").choice(), true, true);
      GlErrorLog::poll();
      if (screenshot_requested_) {
        screenshot_requested_ = false;
        saveScreenshot(w, h, {});
      }
      if (frames_left > 0 && --frames_left == 0) {
        // The same outputs as a headless run: the picture, and the report, truth and error
        // pictures asked for, all or none.
        Image image{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        if (options_.truth || !options_.truth_out.empty() || !options_.error_out.empty()) {
          measureError();
        }
        outputs_failed = !writeOutputs(options_.out, image);
      }
    }
    glfwSwapBuffers(window);
  }
  releaseGl();
  glfwDestroyWindow(window);
  return GlErrorLog::count() > 0 || outputs_failed ? 1 : 0;
}

int runLessonMain(int argc, char** argv) {
  const auto lessons = registeredLessons();
  if (lessons.size() != 1) {
    std::fprintf(stderr, "expected exactly one lesson in this binary\n");
    return 1;
  }
  RunOptions options;
  if (std::string e = parseCommandLine(argc, argv, options); !e.empty()) {
    std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.c_str());
    return 2;
  }
  if (options.help) {
    std::printf(kUsage, argv[0]);
    return 0;
  }
  try {
    Runner runner(lessons[0], makeLesson(lessons[0]), options);
    if (std::string e = runner.applySets(options.sets); !e.empty()) {
      std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.c_str());
      return 2;
    }
    if (std::string e = runner.checkConsistency(); !e.empty()) {
      std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.c_str());
      return 2;
    }
    if (options.list_params) {
      std::printf("%s", runner.params().listText().c_str());
      return 0;
    }
    return runner.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.what());
    return 1;
  }
}

}  // namespace shadows
