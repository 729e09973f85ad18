// Two passes the runner makes beside a lesson's frame, each an object of its own, handed what
// it draws with: the frame without shadow that the shadow's cost is measured against
// (BaselineFrames, side_passes.cpp) and the texel-density pass that says how many map texels
// fall on a pixel (TexelPass). Both draw through the FrameSource into a Measure of their own,
// so the report's counters stay the lesson's frame's.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/measure.hpp"
#include "math/texel_density.hpp"
#include "run/frame_source.hpp"
#include "run/gl_targets.hpp"

namespace shadows {

struct RunOptions;
class SceneHost;

class BaselineFrames {
 public:
  // `target`: where its frames go, never seen (the picture's target: same size, same format).
  BaselineFrames(FrameSource& frames, Params& params, const RunOptions& options,
                 PictureTarget& target)
      : frames_(frames), params_(params), options_(options), target_(target) {}
  // The same frame with no shadow work (shadow.off), timed on its own and off-screen, so the
  // report and the panel can say what the shadow costs over it, measured in the same run. The
  // map and every dirty bit are left as they were. Nothing for lessons without shadow.off.
  void render();
  // Median frame over median baseline frame (0 before any baseline frame).
  double overhead() const;
  // The report's and the summary line's ratio: only where both medians rest on at least
  // kFramesForRatio timed frames (one frame at load is no cost: 0.002 was seen); else none.
  static constexpr size_t kFramesForRatio = 3;
  std::optional<double> measuredOverhead() const;
  const Measure& measure() const { return *measure_; }
  Measure& measure() { return *measure_; }
  size_t timedFrames() const { return measure_ ? measure_->timedFrames() : 0; }
  bool running() const { return running_; }  // the frame being drawn is a baseline one
  void init() { measure_ = std::make_unique<Measure>(); }
  void release() { measure_.reset(); }

 private:
  FrameSource& frames_;
  Params& params_;
  const RunOptions& options_;
  PictureTarget& target_;
  std::unique_ptr<Measure> measure_;
  long long frames_drawn_ = 0;
  bool running_ = false;
};

class TexelPass {
 public:
  // `floats`: the float target it reads back (the truth's, at the same size).
  TexelPass(FrameSource& frames, const RunOptions& options, const Params& params,
            const SceneHost& host, FloatTarget& floats)
      : frames_(frames), options_(options), params_(params), host_(host), floats_(floats) {}
  // Texels per pixel (texel_density.hpp) for the current parameters, read back from the pass
  // over the lesson's map; null when the last frame had no map. Cached until a parameter or
  // the size changes. Its frame draws into its own Measure, enabled: the lesson draws with the
  // very variants a timed frame uses (05's counted kernel, not an uncounted twin).
  const std::vector<TexelPixel>* measure();
  // The last measure's figures (none before one, or without a map), and whether they are for
  // the current parameters.
  const std::optional<TexelStats>& stats() const { return stats_; }
  bool current() const;
  // The pass over the frame the lesson just drew (the `aliasing` view, or raw for measure()).
  void draw(const Frame& frame, bool heatmap) const;
  // The aliasing view's colour bar, in the panel while that view shows.
  static void drawLegend();
  void initGl();  // texel_density.frag's two variants
  void releaseGl();

 private:
  FrameSource& frames_;
  const RunOptions& options_;
  const Params& params_;
  const SceneHost& host_;
  FloatTarget& floats_;
  Program heatmap_, raw_;  // texel_density.frag: the aliasing view's colours, its numbers
  std::vector<TexelPixel> pixels_;
  std::optional<TexelStats> stats_;
  std::string key_;
  std::unique_ptr<Measure> measure_;
};

}  // namespace shadows
