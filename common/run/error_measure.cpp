// What the truth needs of the GPU, read back on the render thread (the lesson's visibility and
// shaded picture, the surfaces, 08's air, the texel pass), and the measure run on a thread or a
// page's worker; truth_measure.cpp traces and compares.
#include "run/error_measure.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "run/run_options.hpp"
#include "run/scene_host.hpp"
#include "run/side_passes.hpp"

namespace shadows {

std::vector<float> ErrorMeasure::renderRed(View view) {
  const int w = options_.width, h = options_.height;
  floats_.ensure(w, h);
  const GLuint fbo = floats_.id();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  frames_.render({fbo, w, h, view, /*timed=*/false, /*panel=*/false});
  std::vector<glm::vec4> rgba(static_cast<size_t>(w) * h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  std::vector<float> red(rgba.size());
  for (size_t i = 0; i < rgba.size(); ++i) red[i] = rgba[i].r;
  return red;
}

void ErrorMeasure::initGl() {
  const auto dir = commonShaderDir();
  gbuffer_ = Program(dir / "gbuffer.vert", dir / "gbuffer.frag");
}

void ErrorMeasure::releaseGl() {
  gbuffer_ = Program();
  surface_.reset();
  surface_position_ = Texture();
  surface_normal_ = Texture();
  surface_depth_ = Texture();
  surface_w_ = surface_h_ = 0;
}

void ErrorMeasure::ensureSurface(int width, int height) {
  if (width == surface_w_ && height == surface_h_) return;
  surface_w_ = width, surface_h_ = height;
  surface_position_ = Texture::color(width, height, GL_RGBA32F);
  surface_normal_ = Texture::color(width, height, GL_RGBA32F);
  surface_depth_ = Texture::depthStencil(width, height);
  surface_ = std::make_unique<Framebuffer>();
  surface_->attachColor(surface_position_, 0);
  surface_->attachColor(surface_normal_, 1);
  surface_->attachDepthStencil(surface_depth_);
  surface_->check();
}

std::string pictureKey(const RunOptions& options, const Params& params, const SceneHost& host) {
  std::string key = std::to_string(options.width) + "x" + std::to_string(options.height);
  char value[40];
  for (const auto& p : params.all()) {
    if (p.name == "view") continue;
    // Full precision: text() rounds to 6 digits, and nearby values must not share a key.
    key += ";" + p.name + "=" + p.string_value;
    for (double v : p.value) {
      std::snprintf(value, sizeof value, ",%.17g", v);
      key += value;
    }
  }
  // A light map finished baking (lesson 15) changes the picture with no parameter moved.
  const BakeState& bake = host.bakeState();
  if (bake.stage != BakeState::Stage::kNone) {
    key += ";bake=" + std::to_string(bake.id) + "," + std::to_string(static_cast<int>(bake.stage));
  }
  return key;
}

TruthInputs ErrorMeasure::gatherInputs() {
  TruthInputs in;
  in.key = key();
  const int w = options_.width, h = options_.height;
  const size_t n = static_cast<size_t>(w) * h;
  in.width = w, in.height = h;
  Measure& lesson_measure = frames_.lessonMeasure();
  const bool was_enabled = lesson_measure.enabled();
  lesson_measure.setEnabled(false);

  texels_.measure();  // what the panel shows next to the error, measured when it is
  // The lesson's shadow term, and its shaded picture in float to catch NaN and Inf.
  in.rendered = renderRed(views::kVisibility);  // ensures the float target at this size
  const GLuint fbo = floats_.id();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  const FrameOutputs told = frames_.render({fbo, w, h, views::kShaded, false, false});
  in.shaded.resize(n);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, in.shaded.data());

  // The surface seen by each pixel, from the runner's own geometry pass.
  TruthJob& job = in.job;
  job.surface = {w, h, std::vector<glm::vec4>(n), std::vector<glm::vec4>(n)};
  ensureSurface(w, h);
  surface_->bind();
  glViewport(0, 0, w, h);
  const float clear_position[4] = {0, 0, 0, -1};
  const float clear_normal[4] = {0, 0, 0, 0};
  resetGlState();  // whatever the lesson left set must not shape the truth's surfaces
  glClearBufferfv(GL_COLOR, 0, clear_position);
  glClearBufferfv(GL_COLOR, 1, clear_normal);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  const Light light = frames_.currentLight();
  const Scene& scene = host_.scene();
  Frame frame(host_, params_, scene, lesson_measure, light);
  frame.eye = params_.at("camera.pos").v();  // drawn in the order the lesson's eye pass was
  // The very camera the lesson drew with, or truth and picture would not line up.
  const glm::mat4 view_projection = frames_.cameraProjection(w, h) * frames_.cameraView();
  gbuffer_.set("uViewProjection", view_projection);
  gbuffer_.set("uHasLightFrustum", told.light_frustum ? 1 : 0);
  gbuffer_.set("uLightViewProjection", told.light_frustum.value_or(glm::mat4(1.0f)));
  const Frame::LightReach reach = told.light_reach.value_or(Frame::LightReach{});
  gbuffer_.set("uHasLightReach", told.light_reach ? 1 : 0);
  gbuffer_.set("uReachLight", reach.position);
  gbuffer_.set("uReach", glm::vec3(reach.near, reach.far, reach.far_along_axis ? 1.0f : 0.0f));
  frame.drawObjects(gbuffer_, Objects::All, nullptr);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, job.surface.position.data());
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, job.surface.normal.data());

  // The triangles always travel with the job (a tracer built for them is kept in truth_
  // while the scene stays): a job is whole wherever it is traced.
  scene.worldTriangles(job.positions, job.triangles);
  job.scene_radius = scene.bounds().radius();
  in.truth = truth_.tracerFor(job);
  in.given = truth_.given;
  in.keep_bytes = !options_.truth_job.empty() || !options_.truth_result.empty();
  job.light.position = light.position;
  job.light.direction = light.direction;
  job.light.directional = light.directional;
  job.light.radius = told.truth_area_radius;
  job.light.samples = 64;
  in.truth_name = light.directional ? "directional" : "point";
  if (told.truth_area_radius > 0.0f) {
    char name[64];
    std::snprintf(name, sizeof name, "area r=%g n=%d", told.truth_area_radius, job.light.samples);
    in.truth_name = name;
  }
  if (told.medium) {
    // The lesson's air light alone, unscaled, against single scattering traced along the
    // very eye rays of its pixels.
    TruthJob::Air air;
    air.medium = *told.medium;
    air.medium.spot = nullptr;
    // A copy of the spot texture: the lesson may load another while the truth is traced.
    if (told.medium->spot != nullptr) air.spot = *told.medium->spot;
    air.eye = params_.at("camera.pos").v();
    air.inverse_view_projection = glm::inverse(view_projection);
    job.air = std::move(air);
    in.air_rendered = renderRed(views::kAir);
  }
  lesson_measure.setEnabled(was_enabled);
  return in;
}

const ErrorState& ErrorMeasure::measure() {
  if (!haveTruth()) {  // nothing to measure against: the views and the panel say so
    truth_.clear();
    return truth_.error();
  }
  // A window's job: wait for it.
  if (truth_.thread_job.valid()) truth_.install(truth_.thread_job.get(), key());
  // A page cannot wait for its worker; its answer, when it comes, answers no job any more.
  truth_.page_job.reset();
  if (truth_.current(key())) {
    measured();
    return truth_.error();
  }
  install(traceTruth(gatherInputs()));
  return truth_.error();
}

// Rendering the truth's inputs may have started a light-map bake (lesson 15, a view such as
// `truth` that draws none of the lesson's own frames): the picture is about to change, so the
// window traces once the bake is in.
bool ErrorMeasure::bakeBegan() const {
  return host_.bakeState().stage == BakeState::Stage::kRunning;
}

void ErrorMeasure::install(TruthResult result) {
  truth_.install(std::move(result), key());
  measured();
}

#ifndef __EMSCRIPTEN__

void ErrorMeasure::begin() {
  if (truth_.running() || !haveTruth()) return;
  TruthInputs inputs = gatherInputs();
  if (bakeBegan()) return;
  truth_.thread_job = std::async(std::launch::async, &traceTruth, std::move(inputs));
}

bool ErrorMeasure::poll() {
  if (!truth_.thread_job.valid() ||
      truth_.thread_job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return false;
  }
  install(truth_.thread_job.get());
  return true;
}

double ErrorMeasure::progress() const {
  return -1.0;
}

#else  // a page: no threads, so the rays are traced by its Web Worker (web/truth/page.mjs)

void ErrorMeasure::begin() {
  if (truth_.running() || !haveTruth()) return;
  auto inputs = std::make_shared<TruthInputs>(gatherInputs());
  if (bakeBegan()) return;
  if (postTruthJob(serializeTruthJob(inputs->job))) {
    truth_.page_job = std::move(inputs);
  } else {
    // No worker: on this thread, the page waits.
    install(traceTruth(std::move(*inputs)));
  }
}

bool ErrorMeasure::poll() {
  if (!truth_.page_job) return false;
  PageTraceAnswer answer = takeTruthTrace();
  if (answer.state == PageTraceAnswer::State::kNone) return false;
  std::shared_ptr<TruthInputs> inputs = std::move(truth_.page_job);
  if (answer.state == PageTraceAnswer::State::kFailed) {
    // Not again for the same settings (the console says why); the panel says it failed.
    truth_.fail(inputs->key);
    return false;
  }
  inputs->given = parseTruthTrace(answer.trace_bytes);
  install(traceTruth(std::move(*inputs)));
  return true;
}

double ErrorMeasure::progress() const {
  return truth_.page_job ? std::max(truthTraceProgress(), 0.0) : -1.0;
}

#endif

}  // namespace shadows
