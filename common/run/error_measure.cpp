// The lesson's picture against the ray-traced truth: visibility, surfaces, air, metrics.
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

void Runner::drawTexels(const Frame& frame, bool heatmap) {
  if (!frame.shadow_sampling) return;  // no map this frame (shadow.off): the lesson's picture
  const ShadowSampling& map = *frame.shadow_sampling;
  resetGlState();
  if (heatmap) {
    frame.clearTarget();
  } else {
    frame.bindTarget();
    glClearColor(0, 0, 0, 0);  // z = 0: not counted
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }
  const Program& p = heatmap ? gpu_->texel_heatmap : gpu_->texel_raw;
  p.use();
  p.set("uViewProjection", frame.projection * frame.view);
  p.set("uShadowMatrix", map.texture_matrix);
  p.set("uMapSize", glm::vec2(map.map_size));
  p.set("uTolerance", kTexelTolerance);
  frame.setLightingUniforms(p, 0.0f);
  drawObjects(frame, p, Objects::All, nullptr);
  resetGlState();
}

const std::vector<TexelPixel>* Runner::measureTexels() {
  std::string key = errorKey();
  if (key != texel_key_) {
    const int w = options_.width, h = options_.height;
    gpu_->ensureTargets(w, h);
    const GLuint fbo = gpu_->float_target->id();
    if (!texel_measure_) texel_measure_ = std::make_unique<Measure>();
    std::swap(measure_, texel_measure_);
    renderInto(fbo, w, h, "texels", /*timed=*/true, false);
    std::swap(measure_, texel_measure_);
    texel_pixels_.clear();
    texel_stats_.reset();
    if (shadow_sampling_) {
      texel_pixels_.resize(static_cast<size_t>(w) * h);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glReadBuffer(GL_COLOR_ATTACHMENT0);
      glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, texel_pixels_.data());
      texel_stats_ = texelStats(texel_pixels_);
    }
    texel_key_ = std::move(key);
  }
  return texel_stats_ ? &texel_pixels_ : nullptr;
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

// What the truth needs from the GPU, read back on the render thread (a few ms), so that the
// ray tracing can run anywhere.
struct Runner::TruthInputs {
  std::string key;
  int width = 0, height = 0;
  std::vector<float> rendered;    // the lesson's visibility view
  std::vector<glm::vec4> shaded;  // its shaded picture in float (NaN and Inf kept)
  std::string truth_name;
  TruthJob job;  // what the tracer traces: surfaces, light, triangles, lesson 08's air
  std::shared_ptr<const TruthTracer> truth;  // null: build one from the job's triangles
  std::optional<TruthTrace> given;           // --truth-from: the trace, already made
  bool keep_bytes = false;                   // --truth-job / --truth-result
  std::vector<float> air_rendered;           // lesson 08's air light
};

Runner::TruthInputs Runner::gatherTruthInputs() {
  TruthInputs in;
  in.key = errorKey();
  const int w = options_.width, h = options_.height;
  const size_t n = static_cast<size_t>(w) * h;
  in.width = w, in.height = h;
  const bool was_enabled = measure_->enabled();
  measure_->setEnabled(false);

  measureTexels();  // what the panel shows next to the error, measured when it is
  // The lesson's shadow term, and its shaded picture in float to catch NaN and Inf.
  in.rendered = renderVisibility();
  const GLuint fbo = gpu_->float_target->id();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  renderInto(fbo, w, h, "shaded", false, false);
  in.shaded.resize(n);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, in.shaded.data());

  // The surface seen by each pixel, from the runner's own geometry pass.
  TruthJob& job = in.job;
  job.surface = {w, h, std::vector<glm::vec4>(n), std::vector<glm::vec4>(n)};
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
  frame.eye = params_.at("camera.pos").v();  // drawn in the order the lesson's eye pass was
  // The very camera the lesson drew with, or truth and picture would not line up.
  gpu_->gbuffer.set("uViewProjection", cameraProjection(w, h) * cameraView());
  gpu_->gbuffer.set("uHasLightFrustum", light_frustum_ ? 1 : 0);
  gpu_->gbuffer.set("uLightViewProjection", light_frustum_.value_or(glm::mat4(1.0f)));
  drawObjects(frame, gpu_->gbuffer, Objects::All, nullptr);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, job.surface.position.data());
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, job.surface.normal.data());

  // The triangles always travel with the job (a tracer built for them is kept in truth_
  // while the scene stays): a job is whole wherever it is traced.
  scene_.worldTriangles(job.positions, job.triangles);
  job.scene_radius = scene_.bounds().radius();
  if (truth_ && truth_->sceneId() == job.sceneId()) in.truth = truth_;
  in.given = given_trace_;
  in.keep_bytes = !options_.truth_job.empty() || !options_.truth_result.empty();
  job.light.position = light.position;
  job.light.direction = light.direction;
  job.light.directional = light.directional;
  job.light.radius = truth_area_radius_;
  job.light.samples = 64;
  in.truth_name = light.directional ? "directional" : "point";
  if (truth_area_radius_ > 0.0f) {
    char name[64];
    std::snprintf(name, sizeof name, "area r=%g n=%d", truth_area_radius_, job.light.samples);
    in.truth_name = name;
  }
  if (medium_) {
    // The lesson's air light alone, unscaled, against single scattering traced along the
    // very eye rays of its pixels.
    TruthJob::Air air;
    air.medium = *medium_;
    air.medium.spot = nullptr;
    // A copy of the spot texture: the lesson may load another while the truth is traced.
    if (medium_->spot != nullptr) air.spot = *medium_->spot;
    air.eye = params_.at("camera.pos").v();
    air.inverse_view_projection = glm::inverse(cameraProjection(w, h) * cameraView());
    job.air = std::move(air);
    in.air_rendered = renderRed("air");
  }
  measure_->setEnabled(was_enabled);
  return in;
}

Runner::TruthResult Runner::traceTruth(TruthInputs in) {
#if !SHADOWS_HAVE_TRUTH
  // This build has no ray tracer: nothing calls this (measureError says so first).
  (void)in;
  throw std::logic_error("no ray-traced truth in this build");
#else
  TruthResult out;
  out.key = in.key;
  const TruthJob& job = in.job;
  TruthTrace trace;
  if (in.given) {
    // Another tracer's answer: only to this very job (the same scene, view, light, size).
    if (in.given->job_id != job.id()) {
      throw TruthMismatch(
          "--truth-from: the trace answers another job (other parameters, "
          "size or scene); write the job again with --truth-job");
    }
    trace = std::move(*in.given);
    if (trace.width != job.surface.width || trace.height != job.surface.height ||
        trace.air.has_value() != job.air.has_value()) {
      throw TruthMismatch("--truth-from: the trace does not fit its job (size or air)");
    }
  } else {
    out.truth = in.truth ? in.truth : makeTruthTracer(job);
    trace = out.truth->trace(job);
  }
  if (in.keep_bytes) {
    trace.job_id = job.id();
    out.job_bytes = serializeTruthJob(job);
    out.trace_bytes = serializeTruthTrace(trace);
  }
  const int w = in.width, h = in.height;
  const size_t n = static_cast<size_t>(w) * h;
  const std::vector<float>& truth = trace.visibility;
  long long grazing = 0;
  const std::vector<float> weight = Truth::facingWeight(job.surface, job.light, &grazing);
  ErrorMetrics& m = out.metrics;
  m = compareVisibility(in.rendered, truth, weight);
  m.grazing_pixels = grazing;
  // Every surface the eye sees writes its normal, counted or not; the sky keeps the clear 0.
  m.covered_pixels =
      std::count_if(job.surface.normal.begin(), job.surface.normal.end(),
                    [](const glm::vec4& normal) { return glm::dot(normal, normal) > 0.0f; });
  m.truth = in.truth_name;
  // Non-finite pixels: where the visibility or any channel of the shaded picture is NaN or
  // Inf, each pixel counted once.
  long long nonfinite = 0;
  std::vector<std::uint8_t> shaded_bytes(n * 4);
  for (size_t i = 0; i < n; ++i) {
    bool finite = std::isfinite(in.rendered[i]);
    for (int c = 0; c < 4; ++c) {
      const float v = in.shaded[i][c];
      finite = finite && std::isfinite(v);
      shaded_bytes[i * 4 + static_cast<size_t>(c)] = static_cast<std::uint8_t>(
          std::lround(255.0f * std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f)));
    }
    if (!finite) ++nonfinite;
  }
  m.nonfinite_pixels = nonfinite;
  out.error_image = {w, h, errorImage(shaded_bytes, in.rendered, truth)};
  out.pixels = std::make_shared<const ErrorPixels>(
      ErrorPixels{in.rendered, truth, weight, job.surface.position});
  out.truth_image = {w, h, std::vector<std::uint8_t>(n * 4)};
  for (size_t i = 0; i < n; ++i) {
    // Truth lit white, shadowed black, not counted (no surface, facing away) dark blue.
    const bool counted = truth[i] >= 0.0f;
    const auto grey = static_cast<std::uint8_t>(std::lround(255.0f * std::max(truth[i], 0.0f)));
    out.truth_image.rgba[i * 4 + 0] = counted ? grey : 20;
    out.truth_image.rgba[i * 4 + 1] = counted ? grey : 24;
    out.truth_image.rgba[i * 4 + 2] = counted ? grey : 60;
    out.truth_image.rgba[i * 4 + 3] = 255;
  }
  m.air = AirMetrics{};
  if (trace.air) {
    // The truth and error views then show the air.
    out.air = std::move(*trace.air);
    m.air = compareAir(in.air_rendered, out.air);
    m.nonfinite_pixels += m.air.nonfinite;
    out.error_image = {w, h, airErrorImage(in.air_rendered, out.air.light)};
    for (size_t i = 0; i < out.air.light.size(); ++i) {
      const auto grey =
          static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(out.air.light[i], 0.0f, 1.0f)));
      out.truth_image.rgba[i * 4 + 0] = out.truth_image.rgba[i * 4 + 1] = grey;
      out.truth_image.rgba[i * 4 + 2] = grey;
    }
  }
  return out;
#endif
}

void Runner::installTruth(TruthResult result) {
  // A truth built for a scene that has changed since is not kept (its key says so).
  if (result.truth && result.key == errorKey()) truth_ = std::move(result.truth);
  job_bytes_ = std::move(result.job_bytes);
  trace_bytes_ = std::move(result.trace_bytes);
  error_.metrics = std::move(result.metrics);
  error_.valid = true;
  error_.pixels = std::move(result.pixels);
  error_key_ = std::move(result.key);
  error_image_ = std::move(result.error_image);
  truth_image_ = std::move(result.truth_image);
  air_truth_ = std::move(result.air);
  ++truths_measured_;
  truth_failed_ = false;
}

bool Runner::haveTruth() {
  return kHaveTruth && truthTracerAvailable();
}

const ErrorState& Runner::measureError() {
  if (!haveTruth()) {  // nothing to measure against: the views and the panel say so
    error_ = {};
    truth_image_ = error_image_ = {};
    return error_;
  }
  if (truth_job_.valid()) installTruth(truth_job_.get());  // a window's job: wait for it
  // A page cannot wait for its worker; its answer, when it comes, answers no job any more.
  page_job_.reset();
  if (error_.valid && errorKey() == error_key_) return error_;
  installTruth(traceTruth(gatherTruthInputs()));
  return error_;
}

#ifndef __EMSCRIPTEN__

void Runner::beginErrorMeasure() {
  if (errorMeasureRunning() || !haveTruth()) return;
  truth_job_ = std::async(std::launch::async, &Runner::traceTruth, gatherTruthInputs());
}

bool Runner::pollErrorMeasure() {
  if (!truth_job_.valid() ||
      truth_job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return false;
  }
  installTruth(truth_job_.get());
  return true;
}

double Runner::errorMeasureProgress() const {
  return -1.0;
}

#else  // a page: no threads, so the rays are traced by its Web Worker (web/truth/page.mjs)

void Runner::beginErrorMeasure() {
  if (errorMeasureRunning() || !haveTruth()) return;
  auto inputs = std::make_shared<TruthInputs>(gatherTruthInputs());
  if (postTruthJob(serializeTruthJob(inputs->job))) {
    page_job_ = std::move(inputs);
  } else {
    installTruth(traceTruth(std::move(*inputs)));  // no worker: on this thread, the page waits
  }
}

bool Runner::pollErrorMeasure() {
  if (!page_job_) return false;
  PageTraceAnswer answer = takeTruthTrace();
  if (answer.state == PageTraceAnswer::State::kNone) return false;
  std::shared_ptr<TruthInputs> inputs = std::move(page_job_);
  if (answer.state == PageTraceAnswer::State::kFailed) {
    // Not again for the same settings (the console says why); the panel says it failed.
    error_ = {};
    error_key_ = inputs->key;
    truth_image_ = error_image_ = {};
    truth_failed_ = true;
    return false;
  }
  inputs->given = parseTruthTrace(answer.trace_bytes);
  installTruth(traceTruth(std::move(*inputs)));
  return true;
}

double Runner::errorMeasureProgress() const {
  return page_job_ ? std::max(truthTraceProgress(), 0.0) : -1.0;
}

#endif

}  // namespace shadows
