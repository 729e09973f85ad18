// The scene a lesson draws and the runner's half of Frame's draw helpers (LessonHost): the
// scene's meshes, the insets and full-screen passes and their programs, one object's
// placement, the last error, the light-map bake. The runner owns one; every Frame it builds
// draws through it.
#pragma once

#include <vector>

#include "core/image.hpp"
#include "core/scene.hpp"
#include "lesson/lesson.hpp"
#include "run/light_map_bake.hpp"

namespace shadows {

class TruthMeasure;

class SceneHost final : public LessonHost {
 public:
  // `params`: a moved object dirties the map; `truth`: its last error, its scene forgotten.
  SceneHost(Params& params, TruthMeasure& truth) : params_(params), truth_(truth) {}
  const Scene& scene() const { return scene_; }
  // A scene preset: its objects, and their matrices as presetModel's answers (its meshes
  // uploaded too, once the GL is up).
  void load(Scene scene);
  // The meshes and the programs of the insets, once a context is current; released before it.
  void initGl();
  void releaseGl();
  // A CPU picture (the truth, the error) over the whole frame.
  void showImage(const Frame& frame, const Image& image);
  // The one triangle over the viewport, with no vertex data (the panel's texture laid over).
  void drawCovering() const;
  // A light map is baked on a thread while a window runs until closed; anything that writes
  // what it rendered (headless, a window's --frames run) waits for it.
  void setBakeInBackground(bool background) { bake_in_background_ = background; }

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

  Params& params_;
  TruthMeasure& truth_;
  Scene scene_;
  std::vector<glm::mat4> preset_models_;
  mutable LightMapBaker baker_;  // polled where its state is asked for
  bool bake_in_background_ = false;
  bool gl_ = false;  // initGl has run
  std::vector<Mesh> meshes_;
  Program image_, depth_inset_;
  Texture shown_;  // the CPU picture showImage uploads
  GLuint empty_vao_ = 0;
};

}  // namespace shadows
