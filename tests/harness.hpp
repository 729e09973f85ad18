// Drives a lesson in-process, headless, exactly as its binary would.
#pragma once

#include "app.hpp"
#include "image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace shadows::testing {

inline std::unique_ptr<Runner> startLesson(const std::string& lesson,
                                           const std::vector<std::string>& sets, int width = 320,
                                           int height = 240, bool panel = false,
                                           const std::string& backend = "osmesa") {
  RunOptions options;
  options.headless = true;
  options.width = width;
  options.height = height;
  options.panel = panel;
  options.backend = backend;
  auto runner = std::make_unique<Runner>(lesson, makeLesson(lesson), options);
  const std::string error = runner->applySets(sets);
  EXPECT_EQ(error, "");
  runner->initHeadless();
  return runner;
}

// Fraction of pixels whose largest channel difference exceeds `threshold` levels.
inline double fractionDiffering(const Image& a, const Image& b, int threshold) {
  if (a.width != b.width || a.height != b.height) return 1.0;
  size_t differing = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.rgba[i + c] - b.rgba[i + c]));
    if (worst > threshold) ++differing;
  }
  return static_cast<double>(differing) / static_cast<double>(a.rgba.size() / 4);
}

inline double meanAbsDifference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) sum += std::abs(a.rgba[i] - b.rgba[i]);
  return sum / static_cast<double>(a.rgba.size());
}

}  // namespace shadows::testing
