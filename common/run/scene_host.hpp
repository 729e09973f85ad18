// The scene a lesson draws and the runner's half of Frame's draw helpers (LessonHost): the
// scene's meshes, the insets and full-screen passes, one object's placement, the last error.
// The runner owns one; every Frame it builds draws through it.
#pragma once

#include <vector>

#include "core/scene.hpp"
#include "lesson/lesson.hpp"
#include "run/light_map_bake.hpp"

namespace shadows {

class Runner;

class SceneHost final : public LessonHost {
 public:
  explicit SceneHost(Runner& runner) : r_(runner) {}
  const Scene& scene() const { return scene_; }
  // A scene preset: its objects, and their matrices as presetModel's answers.
  void load(Scene scene);

  const ErrorState& lastError() const override;
  void setObjectModel(size_t index, const glm::mat4& model) override;
  const glm::mat4& presetModel(size_t index) const override { return preset_models_.at(index); }
  void bake(BakeRequest request) override;
  const BakeState& bakeState() const override { return baker_.poll(); }
  void cancelBake() override { baker_.cancel(); }

 private:
  void drawObjects(const Frame& frame, const Program& program, Objects which,
                   const glm::mat4* cull) const override;
  void drawObject(const Program& program, size_t index) const override;
  void drawInset(const Frame& frame, const Texture& depth, float near, float far, bool perspective,
                 bool fullscreen) const override;
  void drawImageInset(const Frame& frame, const Texture& image, bool fullscreen) const override;
  void drawFullscreen(const Frame& frame, const Program& program, bool inset) const override;

  Runner& r_;
  Scene scene_;
  std::vector<glm::mat4> preset_models_;
  mutable LightMapBaker baker_;  // polled where its state is asked for
};

}  // namespace shadows
