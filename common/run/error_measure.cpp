// What the truth needs of the GPU, read back on the render thread (the lesson's visibility and
// shaded picture, the surfaces, 08's air, the texel pass), and the measure run on a thread or a
// page's worker; truth_measure.cpp traces and compares.
#include "run/error_measure.hpp"

#include "run/runner.hpp"

#include "core/spotlight.hpp"
#include "run/runner_gpu.hpp"

#include "core/json.hpp"
#include "gl/context.hpp"

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

std::vector<float> Runner::renderVisibility() {
  return renderRed(views::kVisibility);
}

std::vector<float> Runner::renderRed(View view) {
  const int w = options_.width, h = options_.height;
  gpu_->ensureFloatTargets(w, h);
  const GLuint fbo = gpu_->float_target->id();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  renderInto(fbo, w, h, view, false, false);
  std::vector<glm::vec4> rgba(static_cast<size_t>(w) * h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  std::vector<float> red(rgba.size());
  for (size_t i = 0; i < rgba.size(); ++i) red[i] = rgba[i].r;
  return red;
}

std::string ErrorMeasure::key() const {
  // Everything that can change the picture: every parameter but the view, and the size.
  std::string key = std::to_string(r_.options_.width) + "x" + std::to_string(r_.options_.height);
  char value[40];
  for (const auto& p : r_.params_.all()) {
    if (p.name == "view") continue;
    // Full precision: text() rounds to 6 digits, and nearby values must not share a key.
    key += ";" + p.name + "=" + p.string_value;
    for (double v : p.value) {
      std::snprintf(value, sizeof value, ",%.17g", v);
      key += value;
    }
  }
  // A light map finished baking (lesson 15) changes the picture with no parameter moved.
  const BakeState& bake = r_.host_.bakeState();
  if (bake.stage != BakeState::Stage::kNone) {
    key += ";bake=" + std::to_string(bake.id) + "," + std::to_string(static_cast<int>(bake.stage));
  }
  return key;
}

TruthInputs ErrorMeasure::gatherInputs() {
  TruthInputs in;
  in.key = key();
  const int w = r_.options_.width, h = r_.options_.height;
  const size_t n = static_cast<size_t>(w) * h;
  in.width = w, in.height = h;
  const bool was_enabled = r_.measure_->enabled();
  r_.measure_->setEnabled(false);

  r_.texels_.measure();  // what the panel shows next to the error, measured when it is
  // The lesson's shadow term, and its shaded picture in float to catch NaN and Inf.
  in.rendered = r_.renderVisibility();  // ensures the float targets at this size
  const GLuint fbo = r_.gpu_->float_target->id();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  r_.renderInto(fbo, w, h, views::kShaded, false, false);
  in.shaded.resize(n);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, in.shaded.data());

  // The surface seen by each pixel, from the runner's own geometry pass.
  TruthJob& job = in.job;
  job.surface = {w, h, std::vector<glm::vec4>(n), std::vector<glm::vec4>(n)};
  r_.gpu_->surface->bind();
  glViewport(0, 0, w, h);
  const float clear_position[4] = {0, 0, 0, -1};
  const float clear_normal[4] = {0, 0, 0, 0};
  r_.resetGlState();  // whatever the lesson left set must not shape the truth's surfaces
  glClearBufferfv(GL_COLOR, 0, clear_position);
  glClearBufferfv(GL_COLOR, 1, clear_normal);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  const Light light = r_.currentLight();
  Frame frame(r_.host_, r_.params_, r_.scene(), *r_.measure_, light);
  frame.eye = r_.params_.at("camera.pos").v();  // drawn in the order the lesson's eye pass was
  // The very camera the lesson drew with, or truth and picture would not line up.
  r_.gpu_->gbuffer.set("uViewProjection", r_.cameraProjection(w, h) * r_.cameraView());
  r_.gpu_->gbuffer.set("uHasLightFrustum", r_.told_.light_frustum ? 1 : 0);
  r_.gpu_->gbuffer.set("uLightViewProjection", r_.told_.light_frustum.value_or(glm::mat4(1.0f)));
  const Frame::LightReach reach = r_.told_.light_reach.value_or(Frame::LightReach{});
  r_.gpu_->gbuffer.set("uHasLightReach", r_.told_.light_reach ? 1 : 0);
  r_.gpu_->gbuffer.set("uReachLight", reach.position);
  r_.gpu_->gbuffer.set("uReach",
                       glm::vec3(reach.near, reach.far, reach.far_along_axis ? 1.0f : 0.0f));
  frame.drawObjects(r_.gpu_->gbuffer, Objects::All, nullptr);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, job.surface.position.data());
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, job.surface.normal.data());

  // The triangles always travel with the job (a tracer built for them is kept in truth_
  // while the scene stays): a job is whole wherever it is traced.
  r_.scene().worldTriangles(job.positions, job.triangles);
  job.scene_radius = r_.scene().bounds().radius();
  in.truth = truth_.tracerFor(job);
  in.given = truth_.given;
  in.keep_bytes = !r_.options_.truth_job.empty() || !r_.options_.truth_result.empty();
  job.light.position = light.position;
  job.light.direction = light.direction;
  job.light.directional = light.directional;
  job.light.radius = r_.told_.truth_area_radius;
  job.light.samples = 64;
  in.truth_name = light.directional ? "directional" : "point";
  if (r_.told_.truth_area_radius > 0.0f) {
    char name[64];
    std::snprintf(name, sizeof name, "area r=%g n=%d", r_.told_.truth_area_radius,
                  job.light.samples);
    in.truth_name = name;
  }
  if (r_.told_.medium) {
    // The lesson's air light alone, unscaled, against single scattering traced along the
    // very eye rays of its pixels.
    TruthJob::Air air;
    air.medium = *r_.told_.medium;
    air.medium.spot = nullptr;
    // A copy of the spot texture: the lesson may load another while the truth is traced.
    if (r_.told_.medium->spot != nullptr) air.spot = *r_.told_.medium->spot;
    air.eye = r_.params_.at("camera.pos").v();
    air.inverse_view_projection = glm::inverse(r_.cameraProjection(w, h) * r_.cameraView());
    job.air = std::move(air);
    in.air_rendered = r_.renderRed(views::kAir);
  }
  r_.measure_->setEnabled(was_enabled);
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
    r_.exercise_.judge();
    return truth_.error();
  }
  install(traceTruth(gatherInputs()));
  return truth_.error();
}

// Rendering the truth's inputs may have started a light-map bake (lesson 15, a view such as
// `truth` that draws none of the lesson's own frames): the picture is about to change, so the
// window traces once the bake is in.
bool ErrorMeasure::bakeBegan() const {
  return r_.host_.bakeState().stage == BakeState::Stage::kRunning;
}

void ErrorMeasure::install(TruthResult result) {
  truth_.install(std::move(result), key());
  r_.exercise_.judge();
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
