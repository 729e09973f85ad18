// The runner's measure of a lesson against the ray-traced truth, the part without GL: what the
// GPU hands over (TruthInputs, gathered by Runner in error_measure.cpp), the trace and the
// metrics made of it on any thread (traceTruth), and what is kept of the last one
// (TruthMeasure) for the report, the panel and the truth and error views.
#pragma once

#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "lesson/lesson.hpp"
#include "truth/truth_job.hpp"

// Whether this build has the ray-traced truth (Embree, native); the browser's build has none
// of its own, and asks its page's worker instead.
#ifndef SHADOWS_HAVE_TRUTH
#define SHADOWS_HAVE_TRUTH 1
#endif

namespace shadows {

inline constexpr bool kHaveTruth = SHADOWS_HAVE_TRUTH != 0;

// Whether the truth and error views can show anything: the build has a tracer, and a page
// loaded its own; and why not when they cannot ("" when they can).
bool haveTruth();
std::string truthUnavailable();
// What the truth and error views say in a build without the truth (kHaveTruth).
inline constexpr const char* kNoTruthNote = "truth not available in this build";

// What the truth needs from the GPU, read back on the render thread (a few ms), so that the
// ray tracing can run anywhere.
struct TruthInputs {
  std::string key;
  int width = 0, height = 0;
  std::vector<float> rendered;    // the lesson's visibility view
  std::vector<glm::vec4> shaded;  // its shaded picture in float (NaN and Inf kept)
  std::string truth_name;
  TruthJob job;  // what the tracer traces: surfaces, light, triangles, lesson 08's air
  std::shared_ptr<const TruthTracer> truth;  // null: build one from the job's triangles
  std::optional<TruthTrace> given;           // --truth-from: the trace, already made
  bool keep_bytes = false;                   // --truth-job / --truth-result
  std::vector<float> air_rendered;           // lesson 08's air light
};

// What a traced truth installs.
struct TruthResult {
  std::string key;
  ErrorMetrics metrics;
  Image error_image, truth_image;
  Truth::AirResult air;
  std::shared_ptr<const TruthTracer> truth;
  std::vector<std::uint8_t> job_bytes, trace_bytes;  // when the outputs ask for them
  std::shared_ptr<const ErrorPixels> pixels;
};

// Traces the inputs' job (or takes the trace given with it) and measures the lesson's picture
// against it. Any thread: no GL, no runner state. Throws TruthMismatch when a given trace
// answers another job.
TruthResult traceTruth(TruthInputs inputs);

// The last truth measured, and the one being measured.
class TruthMeasure {
 public:
  // The result becomes the last error; its tracer is kept while `currentKey` (the settings
  // now) is still the key it was traced for.
  void install(TruthResult result, const std::string& currentKey);
  // No error and no pictures: the build cannot trace, or `key`'s trace failed on a page.
  void clear();
  void fail(const std::string& key);
  // The scene moved: its tracer and the error measured on it are stale.
  void forgetScene() {
    tracer_.reset();
    error_.valid = false;
  }
  void forgetTracer() { tracer_.reset(); }

  const ErrorState& error() const { return error_; }
  const std::string& key() const { return key_; }
  bool current(const std::string& key) const { return error_.valid && key == key_; }
  const Image& errorImage() const { return error_image_; }
  const Image& truthImage() const { return truth_image_; }
  const std::vector<std::uint8_t>& jobBytes() const { return job_bytes_; }
  const std::vector<std::uint8_t>& traceBytes() const { return trace_bytes_; }
  long long measured() const { return measured_; }
  bool failed() const { return failed_; }
  // The tracer for this job's scene, if the one kept was built for it.
  std::shared_ptr<const TruthTracer> tracerFor(const TruthJob& job) const {
    return tracer_ && tracer_->sceneId() == job.sceneId() ? tracer_ : nullptr;
  }

  std::optional<TruthTrace> given;  // --truth-from
  // A window's trace on a worker thread, or a page's: what its Web Worker's trace will be
  // compared with (no threads there).
  std::future<TruthResult> thread_job;
  std::shared_ptr<TruthInputs> page_job;
  bool running() const { return thread_job.valid() || page_job != nullptr; }

 private:
  // Embree (or a page's JavaScript) for the current scene, shared with a trace running on
  // another thread.
  std::shared_ptr<const TruthTracer> tracer_;
  std::vector<std::uint8_t> job_bytes_, trace_bytes_;  // --truth-job, --truth-result
  ErrorState error_;
  std::string key_;
  Image error_image_, truth_image_;
  long long measured_ = 0;
  bool failed_ = false;
};

}  // namespace shadows
