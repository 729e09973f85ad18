// A run's outputs, all or nothing: the headless run (frames, then the picture, the report and
// the truth's pictures asked for), and the same outputs and screenshots for a window
// (outputs.cpp). The report itself is Runner::writeReport.
#pragma once

#include <string>

#include "core/image.hpp"

namespace shadows {

class Runner;

class HeadlessRun {
 public:
  explicit HeadlessRun(Runner& runner) : r_(runner) {}
  // The whole run without a window; the exit code (2: an output names the default picture).
  int run();
  // The picture (to `out`) and the --report, --truth-out, --error-out, --truth-job and
  // --truth-result asked for; false (and one line on stderr) when any cannot be written.
  bool writeOutputs(const std::string& out, const Image& image);
  // What is on the target (or the window) as a PNG: out/screenshots/<lesson>_N.png, N the
  // first number not taken; the line saying where (or why not) goes to stderr and to
  // RunnerWindow::screenshot_said, under the panel's button.
  void saveScreenshot(int width, int height);
  static constexpr const char* kScreenshotFolder = "out/screenshots";

 private:
  Runner& r_;
};

}  // namespace shadows
