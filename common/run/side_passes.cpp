#include "run/side_passes.hpp"

#include "run/error_measure.hpp"
#include "run/run_options.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadows {

void BaselineFrames::render() {
  Param* off = params_.find("shadow.off");
  const View view = frames_.currentView();
  if (off == nullptr || off->b() || view == views::kTruth || view == views::kError) return;
  const int w = options_.width, h = options_.height;  // the picture's, as renderFrame's
  target_.ensure(w, h);
  // What the lesson's frame has still to do (a dirty map must still be rendered by the next
  // real frame) survives the baseline frame, exception or not. A scene reload it has done is
  // not done again.
  struct Restore {
    BaselineFrames& b;
    Param& off;
    std::uint32_t dirty;
    ~Restore() {
      off.value[0] = 0.0;
      b.running_ = false;
      b.params_.markDirty(dirty & ~kDirtyScene);
    }
  } restore{*this, *off, params_.dirty()};
  running_ = true;
  off->value[0] = 1.0;  // not through Params::set: nothing is dirtied
  // The first one compiles the unshadowed variants: not timed. The panel, if shown, is laid
  // over it as over the lesson's frames (never drawn anew: it takes no input here).
  frames_.render({target_.id(), w, h, view, /*timed=*/frames_drawn_++ > 0, frames_.panelShown(),
                  measure_.get()});
}

double BaselineFrames::overhead() const {
  const double base = measure_ ? measure_->medianFrameMs() : 0.0;
  return base > 0.0 ? frames_.lessonMeasure().medianFrameMs() / base : 0.0;
}

std::optional<double> BaselineFrames::measuredOverhead() const {
  if (timedFrames() < kFramesForRatio || frames_.lessonMeasure().timedFrames() < kFramesForRatio) {
    return std::nullopt;
  }
  const double ratio = overhead();
  return ratio > 0.0 ? std::optional<double>(ratio) : std::nullopt;
}

void TexelPass::initGl() {
  const auto dir = commonShaderDir();
  heatmap_ = Program(dir / "shadow_coord.vert", dir / "texel_density.frag", {"TEXEL_HEATMAP 1"});
  raw_ = Program(dir / "shadow_coord.vert", dir / "texel_density.frag", {"TEXEL_HEATMAP 0"});
}

void TexelPass::releaseGl() {
  heatmap_ = Program();
  raw_ = Program();
  measure_.reset();
}

const std::vector<TexelPixel>* TexelPass::measure() {
  std::string key = pictureKey(options_, params_, host_);
  if (key != key_) {
    const int w = options_.width, h = options_.height;
    floats_.ensure(w, h);
    const GLuint fbo = floats_.id();
    if (!measure_) measure_ = std::make_unique<Measure>();
    const FrameOutputs told =
        frames_.render({fbo, w, h, views::kTexels, /*timed=*/true, false, measure_.get()});
    pixels_.clear();
    stats_.reset();
    if (told.shadow_sampling) {
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
  return key_ == pictureKey(options_, params_, host_);
}

void TexelPass::draw(const Frame& frame, bool heatmap) const {
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
  const Program& p = heatmap ? heatmap_ : raw_;
  p.use();
  p.set("uViewProjection", frame.projection * frame.view);
  p.set("uShadowMatrix", map.texture_matrix);
  p.set("uMapSize", glm::vec2(map.map_size));
  p.set("uTolerance", kTexelTolerance);
  frame.setLightingUniforms(p, 0.0f);
  frame.drawObjects(p, Objects::All, nullptr);
  resetGlState();
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
