// The runner's error against the ray-traced truth for its current settings: measured now
// (measure()) or off the frame's critical path (begin / poll: a window's worker thread, a
// page's Web Worker). It gathers what the truth needs of the GPU on the render thread
// (error_measure.cpp: the lesson's visibility and shaded picture through the FrameSource, the
// surfaces from a geometry pass of its own) and keeps the last result (TruthMeasure,
// truth_measure.hpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "run/frame_source.hpp"
#include "run/gl_targets.hpp"
#include "run/truth_measure.hpp"

namespace shadows {

struct RunOptions;
class SceneHost;
class TexelPass;

// Everything that can change the picture: every parameter but the view, the picture's size,
// and a light map baked (lesson 15). A truth or a texel measure is current while it holds.
std::string pictureKey(const RunOptions& options, const Params& params, const SceneHost& host);

class ErrorMeasure {
 public:
  // `params` and `host`: what a Frame of the geometry pass draws with.
  ErrorMeasure(FrameSource& frames, const RunOptions& options, Params& params, SceneHost& host,
               TexelPass& texels, FloatTarget& floats)
      : frames_(frames),
        options_(options),
        params_(params),
        host_(host),
        texels_(texels),
        floats_(floats) {}
  // Computes visibility, truth and metrics for the current parameters; waits for a running job.
  const ErrorState& measure();
  // begin renders what the truth needs (a few ms of GL) and traces it elsewhere; poll installs
  // the result once it is there (true then). One job at a time.
  void begin();
  bool poll();
  // The running job's progress in [0, 1], or -1 when not known (natively) or none runs.
  double progress() const;
  std::string key() const { return pictureKey(options_, params_, host_); }
  // The last truth and its error: running(), measured() (a page's tests wait on it), failed().
  const TruthMeasure& truth() const { return truth_; }
  TruthMeasure& truth() { return truth_; }
  // Called each time a truth is current after measure() or an install: the exercise's verdict.
  void onMeasured(std::function<void()> call) { on_measured_ = std::move(call); }
  // Renders `view` into the float target and returns its red channel (visibility, air).
  std::vector<float> renderRed(View view);
  void initGl();  // the geometry pass's program; its targets when first measured
  void releaseGl();

 private:
  TruthInputs gatherInputs();  // render thread: what traceTruth needs of the GPU
  void install(TruthResult result);
  bool bakeBegan() const;  // a light-map bake runs (lesson 15): trace once it is in
  void measured() const {
    if (on_measured_) on_measured_();
  }

  FrameSource& frames_;
  const RunOptions& options_;
  Params& params_;
  SceneHost& host_;
  TexelPass& texels_;
  FloatTarget& floats_;
  std::function<void()> on_measured_;
  TruthMeasure truth_;
  // The surface each pixel sees (position, normal), from gbuffer.vert/frag.
  Program gbuffer_;
  Texture surface_position_, surface_normal_, surface_depth_;
  std::unique_ptr<Framebuffer> surface_;
  int surface_w_ = 0, surface_h_ = 0;
  void ensureSurface(int width, int height);
};

}  // namespace shadows
