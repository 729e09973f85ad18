// What the runner's pieces ask of the frame, and no more (Runner implements it): draw one into
// a target of theirs, timed in a Measure of theirs, and what the lesson told; the light and
// the eye as the parameters give them. The truth's passes, the frames without shadow and the
// texel pass draw through it, never through the Runner.
#pragma once

#include <optional>

#include "gl/measure.hpp"
#include "lesson/lesson.hpp"

namespace shadows {

// What a lesson's frame told the runner (Frame's outputs).
struct FrameOutputs {
  std::optional<glm::mat4> light_frustum;
  std::optional<Frame::LightReach> light_reach;
  float truth_area_radius = 0.0f;
  std::optional<AirMedium> medium;
  std::optional<ShadowSampling> shadow_sampling;
};

struct FrameRequest {
  GLuint target = 0;
  int width = 0, height = 0;
  View view = views::kShaded;
  bool timed = false;
  bool panel = false;          // the ImGui panel over it
  Measure* measure = nullptr;  // timed and counted there (null: the lesson's own Measure)
};

class FrameSource {
 public:
  // Draws one frame as asked; what the lesson told in it (nothing where the view is the
  // runner's truth or error picture, which the lesson does not draw).
  virtual FrameOutputs render(const FrameRequest& request) = 0;
  // The lesson's frames' Measure: the report's and the panel's numbers.
  virtual Measure& lessonMeasure() = 0;
  virtual View currentView() const = 0;  // the view the `view` parameter chooses
  virtual Light currentLight() const = 0;
  // The eye's matrices from camera.*: one definition for the lesson and the truth's passes.
  virtual glm::mat4 cameraView() const = 0;
  virtual glm::mat4 cameraProjection(int width, int height) const = 0;
  // Whether the panel is drawn over the frames (a window's, unless hidden; headless --panel).
  virtual bool panelShown() const = 0;

 protected:
  ~FrameSource() = default;
};

}  // namespace shadows
