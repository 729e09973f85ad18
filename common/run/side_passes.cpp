#include "run/side_passes.hpp"

#include "run/runner.hpp"
#include "run/runner_gpu.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadows {

void BaselineFrames::render() {
  Runner& r = r_;
  Param* off = r.params_.find("shadow.off");
  const View view = r.currentView();
  if (off == nullptr || off->b() || view == views::kTruth || view == views::kError) return;
  const int w = r.options_.width, h = r.options_.height;  // the picture's, as renderFrame's
  r.gpu_->ensureTargets(w, h);
  // What the lesson's frame told the runner, and what it has still to do (a dirty map must
  // still be rendered by the next real frame), survive the baseline frame, exception or not.
  // A scene reload it has done is not done again.
  struct Restore {
    BaselineFrames& b;
    Param& off;
    std::uint32_t dirty;
    FrameOutputs told;
    ~Restore() {
      off.value[0] = 0.0;
      std::swap(b.r_.measure_, b.measure_);
      b.running_ = false;
      b.r_.params_.markDirty(dirty & ~kDirtyScene);
      b.r_.told_ = told;
    }
  } restore{*this, *off, r.params_.dirty(), r.told_};
  std::swap(r.measure_, measure_);
  running_ = true;
  off->value[0] = 1.0;  // not through Params::set: nothing is dirtied
  // The first one compiles the unshadowed variants: not timed. The panel, if shown, is laid
  // over it as over the lesson's frames (never drawn anew: it takes no input here).
  const bool panel =
      r.gpu_->imgui && (r.window_.is_open ? !r.options_.hide_panel : r.options_.panel);
  r.renderInto(r.gpu_->target->id(), w, h, view, /*timed=*/frames_++ > 0, panel);
}

double BaselineFrames::overhead() const {
  const double base = measure_ ? measure_->medianFrameMs() : 0.0;
  return base > 0.0 ? r_.measure_->medianFrameMs() / base : 0.0;
}

std::optional<double> BaselineFrames::measuredOverhead() const {
  if (timedFrames() < kFramesForRatio || r_.measure_->timedFrames() < kFramesForRatio) {
    return std::nullopt;
  }
  const double ratio = overhead();
  return ratio > 0.0 ? std::optional<double>(ratio) : std::nullopt;
}

const std::vector<TexelPixel>* TexelPass::measure() {
  Runner& r = r_;
  std::string key = r.errors().key();
  if (key != key_) {
    const int w = r.options_.width, h = r.options_.height;
    r.gpu_->ensureFloatTargets(w, h);
    const GLuint fbo = r.gpu_->float_target->id();
    if (!measure_) measure_ = std::make_unique<Measure>();
    std::swap(r.measure_, measure_);
    r.renderInto(fbo, w, h, views::kTexels, /*timed=*/true, false);
    std::swap(r.measure_, measure_);
    pixels_.clear();
    stats_.reset();
    if (r.told_.shadow_sampling) {
      pixels_.resize(static_cast<size_t>(w) * h);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glReadBuffer(GL_COLOR_ATTACHMENT0);
      glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, pixels_.data());
      stats_ = texelStats(pixels_);
    }
    key_ = std::move(key);
  }
  return stats_ ? &pixels_ : nullptr;
}

bool TexelPass::current() const {
  return key_ == r_.errors_.key();
}

void TexelPass::draw(const Frame& frame, bool heatmap) const {
  if (!frame.shadow_sampling) return;  // no map this frame (shadow.off): the lesson's picture
  const ShadowSampling& map = *frame.shadow_sampling;
  Runner::resetGlState();
  if (heatmap) {
    frame.clearTarget();
  } else {
    frame.bindTarget();
    glClearColor(0, 0, 0, 0);  // z = 0: not counted
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }
  const Program& p = heatmap ? r_.gpu_->texel_heatmap : r_.gpu_->texel_raw;
  p.use();
  p.set("uViewProjection", frame.projection * frame.view);
  p.set("uShadowMatrix", map.texture_matrix);
  p.set("uMapSize", glm::vec2(map.map_size));
  p.set("uTolerance", kTexelTolerance);
  frame.setLightingUniforms(p, 0.0f);
  frame.drawObjects(p, Objects::All, nullptr);
  Runner::resetGlState();
}

void TexelPass::drawLegend() {
  // The aliasing view's colours (common/shaders/texel_density.frag's TEXEL_HEATMAP, mirrored
  // here) along texels per pixel on the least sampled axis, 1/8 to 8 on a log scale.
  const auto colour = [](float e) {  // e = log2(texels per pixel)
    const float t = std::clamp(std::abs(e) / 3.0f, 0.0f, 1.0f);
    const glm::vec3 c =
        std::abs(std::exp2(e) - 1.0f) <= kTexelTolerance ? glm::vec3(0.15f, 0.8f, 0.25f)
        : e < 0.0f ? glm::mix(glm::vec3(1.0f, 0.85f, 0.8f), glm::vec3(0.85f, 0.05f, 0.05f), t)
                   : glm::mix(glm::vec3(0.8f, 0.85f, 1.0f), glm::vec3(0.05f, 0.2f, 0.9f), t);
    return ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1.0f));
  };
  ImGui::TextWrapped("the aliasing view: texels per pixel, least axis (grey: not counted)");
  const float width = ImGui::GetContentRegionAvail().x, height = ImGui::GetFontSize();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr int kSteps = 60;
  for (int i = 0; i < kSteps; ++i) {
    const float e = -3.0f + 6.0f * (static_cast<float>(i) + 0.5f) / kSteps;
    const float x0 = at.x + width * static_cast<float>(i) / kSteps;
    draw->AddRectFilled(ImVec2(x0, at.y), ImVec2(x0 + width / kSteps + 1.0f, at.y + height),
                        colour(e));
  }
  // One texel per pixel (green) is a hair's width on this scale: a tick marks it.
  const float one = at.x + 0.5f * width;
  draw->AddRectFilled(ImVec2(one - 1.5f, at.y - 2.0f), ImVec2(one + 1.5f, at.y + height + 2.0f),
                      colour(0.0f));
  ImGui::Dummy(ImVec2(width, height + 2.0f));
  // The scale's ends and middle under the bar, then what the colours mean.
  const float x0 = ImGui::GetCursorPosX();
  ImGui::TextUnformatted("1/8");
  ImGui::SameLine(x0 + 0.5f * width - 0.5f * ImGui::CalcTextSize("1").x);
  ImGui::TextUnformatted("1");
  ImGui::SameLine(x0 + width - ImGui::CalcTextSize("8").x);
  ImGui::TextUnformatted("8");
  ImGui::TextWrapped("red: under-sampled (blocky), green: one texel a pixel, blue: over");
}

}  // namespace shadows
