// The runner's error against the ray-traced truth for its current settings: measured now
// (measure()) or off the frame's critical path (begin / poll: a window's worker thread, a
// page's Web Worker). It gathers what the truth needs of the GPU on the render thread
// (error_measure.cpp) and keeps the last result (TruthMeasure, truth_measure.hpp).
#pragma once

#include <string>

#include "run/truth_measure.hpp"

namespace shadows {

class Runner;

class ErrorMeasure {
 public:
  explicit ErrorMeasure(Runner& runner) : r_(runner) {}
  // Computes visibility, truth and metrics for the current parameters; waits for a running job.
  const ErrorState& measure();
  // begin renders what the truth needs (a few ms of GL) and traces it elsewhere; poll installs
  // the result once it is there (true then). One job at a time.
  void begin();
  bool poll();
  // The running job's progress in [0, 1], or -1 when not known (natively) or none runs.
  double progress() const;
  // Everything that can change the picture: every parameter but the view, and the size.
  std::string key() const;
  // The last truth and its error: running(), measured() (a page's tests wait on it), failed().
  const TruthMeasure& truth() const { return truth_; }
  TruthMeasure& truth() { return truth_; }

 private:
  TruthInputs gatherInputs();  // render thread: what traceTruth needs of the GPU
  void install(TruthResult result);
  bool bakeBegan() const;  // a light-map bake runs (lesson 15): trace once it is in

  Runner& r_;
  TruthMeasure truth_;
};

}  // namespace shadows
