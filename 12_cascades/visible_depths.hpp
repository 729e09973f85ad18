// The nearest and farthest view depth the eye sees (Lauritzen, Salvi and Lefohn, "Sample
// Distribution Shadow Maps", 2010): the scene's depth from the eye, then the least and greatest
// of 4x4 blocks on the GPU (depth_range.frag) until at most 4x4 texels are left, read back (a
// few floats) and finished on the CPU. The cascades' slices then cover those depths only.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "lesson/lesson.hpp"

namespace shadows {

class VisibleDepths {
 public:
  void init(const std::filesystem::path& reduceShader) {
    depth_program_ = ProgramVariants(commonShaderDir() / "light_depth.vert",
                                     commonShaderDir() / "depth_only.frag");
    reduce_program_ = ProgramVariants(commonShaderDir() / "fullscreen.vert", reduceShader);
  }

  // The view depths (near, far) of the surfaces `view` sees through the frame's projection;
  // none where it sees no surface. passes() says how many it drew.
  std::optional<glm::vec2> measure(Frame& f, const glm::mat4& view) {
    ensure(f.width, f.height);
    depth_target_->bind();
    PassState{}.apply();
    glViewport(0, 0, f.width, f.height);
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    const Program& d = depth_program_.get({});
    const glm::mat4 eye = f.projection * view;
    d.set("uLightViewProjection", eye);
    f.drawObjects(d, Objects::All);  // unculled: culled_objects counts the cascades' culls
    passes_ = 1;
    // Each step a quarter of the last one's width and height, until at most 4x4 are left.
    const Texture* source = &depth_;
    for (size_t k = 0; k < steps_.size(); ++k) {
      Step& step = steps_[k];
      Frame pass = f;  // the step's target, as lesson 13's blur draws its passes
      pass.target = step.target->id();
      pass.width = step.texture.width();
      pass.height = step.texture.height();
      const Program& r = reduce_program_.get({define("FIRST_STEP", k == 0 ? 1 : 0)});
      source->bind(0);
      Sampler::unbind(0);
      r.set("uSource", 0);
      r.set("uSourceSize", glm::vec2(source->width(), source->height()));
      pass.drawFullscreen(r);  // leaves the step's target bound: the last one is read back
      ++passes_;
      source = &step.texture;
    }
    std::vector<float> rgba(static_cast<size_t>(source->width() * source->height()) * 4);
    glReadPixels(0, 0, source->width(), source->height(), GL_RGBA, GL_FLOAT, rgba.data());
    f.bindTarget();
    float lo = 1.0f, hi = 0.0f;
    for (size_t i = 0; i + 1 < rgba.size(); i += 4)
      lo = std::min(lo, rgba[i]), hi = std::max(hi, rgba[i + 1]);
    if (lo > hi) return std::nullopt;
    return glm::vec2(viewDepth(f.projection, lo), viewDepth(f.projection, hi));
  }

  int passes() const { return passes_; }

  // A window depth of the perspective `projection` back to the view depth: ndc = -P22 + P32/d.
  static float viewDepth(const glm::mat4& projection, float window) {
    return projection[3][2] / (2.0f * window - 1.0f + projection[2][2]);
  }

 private:
  struct Step {
    Texture texture;
    std::unique_ptr<Framebuffer> target;
  };

  void ensure(int width, int height) {
    if (depth_.width() == width && depth_.height() == height) return;
    depth_ = Texture::depth(width, height, 24);
    depth_target_ = std::make_unique<Framebuffer>();
    depth_target_->attachDepth(depth_);
    depth_target_->check();
    steps_.clear();
    for (int w = width, h = height; w > 4 || h > 4 || steps_.empty();) {
      w = (w + 3) / 4, h = (h + 3) / 4;
      Step step;
      step.texture = Texture::color(w, h, GL_RGBA32F);
      step.texture.setFilter(GL_NEAREST);
      step.target = std::make_unique<Framebuffer>();
      step.target->attachColor(step.texture);
      step.target->check();
      steps_.push_back(std::move(step));
    }
  }

  ProgramVariants depth_program_, reduce_program_;
  Texture depth_;
  std::unique_ptr<Framebuffer> depth_target_;
  std::vector<Step> steps_;
  int passes_ = 0;
};

}  // namespace shadows
