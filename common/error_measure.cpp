// The lesson's picture against the ray-traced truth: visibility, surfaces, air, metrics.
#include "app.hpp"

#include "runner_gpu.hpp"

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
  frame.eye = params_.at("camera.pos").v();  // drawn in the order the lesson's eye pass was
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
  // Every surface the eye sees writes its normal, counted or not; the sky keeps the clear 0.
  error_.metrics.covered_pixels =
      std::count_if(surface.normal.begin(), surface.normal.end(),
                    [](const glm::vec4& normal) { return glm::dot(normal, normal) > 0.0f; });
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

}  // namespace shadows
