// Lesson 15's bake behind LessonHost::bake: the truth's tracer over a light map's texels, on a
// thread with its progress and a cancel (Truth's TraceControl), or from the disk cache, keyed
// by the hash of every input (TruthJob::id). A page bakes in Web Workers of its own
// (postBakeJob, web/truth/page.mjs), or on its main thread where it has none.
#pragma once

#include <chrono>
#include <future>
#include <memory>
#include <string>

#include "lesson/lesson.hpp"

namespace shadows {

class LightMapBaker {
 public:
  LightMapBaker();
  ~LightMapBaker();
  LightMapBaker(const LightMapBaker&) = delete;
  LightMapBaker& operator=(const LightMapBaker&) = delete;
  // `wait`: trace now, with a progress line on a terminal (a headless run, a scripted window).
  void start(BakeRequest request, bool wait);
  // Takes a finished thread's answer (a window's frame calls it) and prints progress.
  const BakeState& poll();
  const BakeState& state() const { return state_; }
  void cancel();
  // Where bakes are kept: $SHADOWS_CACHE (made if missing: it was asked for), else
  // $XDG_CACHE_HOME/shadows, else ~/.cache/shadows, where that folder (XDG_CACHE_HOME, HOME)
  // exists and can be written: a missing or read-only home is never created or written into.
  // `path` "" when none: `why` says why (a page, SHADOWS_CACHE=off, no usable home).
  struct CacheDirectory {
    std::string path, why;
  };
  static CacheDirectory cacheDirectory();

 private:
  struct Running;
  void finish();
  BakeState state_;
  std::unique_ptr<Running> running_;
  std::chrono::steady_clock::time_point printed_{};
};

}  // namespace shadows
