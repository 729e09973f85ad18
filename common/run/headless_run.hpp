// A run's outputs, all or nothing: the headless run (frames, then the picture, the report and
// the truth's pictures asked for), and the same outputs and screenshots for a window
// (headless_run.cpp). It owns the picture's off-screen target, what a headless run draws into and
// reads back. It drives the Runner through its public interface, as a window does.
#pragma once

#include <string>

#include "core/image.hpp"
#include "run/gl_targets.hpp"

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
  // What is on the target (or the window, `window`) as a PNG: out/screenshots/<lesson>_N.png,
  // N the first number not taken; the line saying where (or why not) goes to stderr and to
  // screenshotSaid(), under the panel's button.
  void saveScreenshot(int width, int height, bool window);
  const std::string& screenshotSaid() const { return screenshot_said_; }
  static constexpr const char* kScreenshotFolder = "out/screenshots";
  // What the lesson draws into without a window.
  PictureTarget& target() { return target_; }
  const PictureTarget& target() const { return target_; }

 private:
  Runner& r_;
  PictureTarget target_;
  int screenshots_taken_ = 0;
  std::string screenshot_said_;  // the last screenshot: where it went, or why not
};

}  // namespace shadows
