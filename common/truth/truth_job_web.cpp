// The truth in a browser (a WebGL2 page built with emscripten, where Embree is not): the
// page's JavaScript traces the job with three-mesh-bvh (web/truth/truth.mjs). This file is
// the seam: makeTruthTracer hands the job's bytes to JavaScript as a view of the wasm heap and
// takes the trace's bytes back, and the runner computes the metrics and the truth and error
// pictures from them as natively. The page installs the JavaScript half before main() runs:
//   import { installTruth } from './truth/page.mjs';  installTruth(Module);
// (web/truth/README.md). Native builds compile nothing here; truth.cpp is their tracer.
#ifdef __EMSCRIPTEN__

#include <emscripten.h>

#include <cstdlib>
#include <stdexcept>

#include "truth/truth_job.hpp"

namespace {

// Traces `size` bytes of job at `job` with Module.shadowsTraceTruth (a Uint8Array of the
// job in, of its trace out); the trace is copied into malloc'ed memory at *out. Returns its
// size, or -1 (the reason on the console) when the page installed no tracer or it threw.
// Synchronous: call it where the page may block (the browser's main thread, between frames).
// clang-format off
EM_JS(int, shadows_trace_truth_js, (const unsigned char* job, int size, unsigned char** out), {
  if (typeof Module.shadowsTraceTruth !== 'function') {
    console.error('shadows: no truth tracer installed (web/truth/page.mjs installTruth)');
    return -1;
  }
  let trace;
  try {
    trace = Module.shadowsTraceTruth(HEAPU8.subarray(job, job + size));
  } catch (e) {
    console.error('shadows: the truth tracer failed: ' + e);
    return -1;
  }
  const at = _malloc(trace.length);
  HEAPU8.set(trace, at);
  HEAPU32[out >> 2] = at;
  return trace.length;
});

// The worker's side (web/truth/page.mjs): post a copy of the job; take the answer as malloc'ed
// bytes at *out (its size), -1 while none is there, -2 when the worker failed.
EM_JS(int, shadows_post_truth_job_js, (const unsigned char* job, int size), {
  if (typeof Module.shadowsPostTruthJob !== 'function') return 0;
  return Module.shadowsPostTruthJob(HEAPU8.slice(job, job + size)) ? 1 : 0;
});
EM_JS(int, shadows_take_truth_trace_js, (unsigned char** out), {
  const answer = typeof Module.shadowsTakeTruthTrace === 'function' ? Module.shadowsTakeTruthTrace() : null;
  if (answer === null) return -1;
  if (!answer.trace) {
    console.error('shadows: the truth worker failed: ' + answer.error);
    return -2;
  }
  const at = _malloc(answer.trace.length);
  HEAPU8.set(answer.trace, at);
  HEAPU32[out >> 2] = at;
  return answer.trace.length;
});
EM_JS(double, shadows_truth_progress_js, (), {
  return typeof Module.shadowsTruthProgress === 'number' ? Module.shadowsTruthProgress : -1;
});
EM_JS(int, shadows_post_bake_job_js, (const unsigned char* job, int size), {
  if (typeof Module.shadowsPostBakeJob !== 'function') return 0;
  return Module.shadowsPostBakeJob(HEAPU8.slice(job, job + size)) ? 1 : 0;
});
EM_JS(int, shadows_take_bake_trace_js, (unsigned char** out), {
  const answer = typeof Module.shadowsTakeBakeTrace === 'function' ? Module.shadowsTakeBakeTrace() : null;
  if (answer === null) return -1;
  if (!answer.trace) {
    console.error('shadows: the bake worker failed: ' + answer.error);
    return -2;
  }
  const at = _malloc(answer.trace.length);
  HEAPU8.set(answer.trace, at);
  HEAPU32[out >> 2] = at;
  return answer.trace.length;
});
EM_JS(double, shadows_bake_progress_js, (), {
  return typeof Module.shadowsBakeProgress === 'number' ? Module.shadowsBakeProgress : -1;
});
EM_JS(int, shadows_truth_installed_js, (), {
  return typeof Module.shadowsTraceTruth === 'function' ? 1 : 0;
});
// clang-format on

class PageTracer final : public shadows::TruthTracer {
 public:
  explicit PageTracer(std::uint64_t scene) : scene_id_(scene) {}

  shadows::TruthTrace trace(const shadows::TruthJob& job) const override {
    const std::vector<std::uint8_t> bytes = shadows::serializeTruthJob(job);
    unsigned char* at = nullptr;
    const int size = shadows_trace_truth_js(bytes.data(), static_cast<int>(bytes.size()), &at);
    if (size < 0) throw std::runtime_error("the page's truth tracer failed (see the console)");
    std::vector<std::uint8_t> trace_bytes(at, at + size);
    std::free(at);
    shadows::TruthTrace trace = shadows::parseTruthTrace(trace_bytes);
    if (trace.job_id != job.id()) {
      throw std::runtime_error("the page's truth tracer answered another job");
    }
    return trace;
  }
  std::uint64_t sceneId() const override { return scene_id_; }

 private:
  std::uint64_t scene_id_;
};

}  // namespace

namespace shadows {

// The page keeps its own BVH per scene (truth.mjs caches it by the job's scene id).
std::shared_ptr<const TruthTracer> makeTruthTracer(const TruthJob& job) {
  return std::make_shared<PageTracer>(job.sceneId());
}

bool truthTracerAvailable() {
  return shadows_truth_installed_js() != 0;
}

bool postTruthJob(const std::vector<std::uint8_t>& job_bytes) {
  return shadows_post_truth_job_js(job_bytes.data(), static_cast<int>(job_bytes.size())) != 0;
}

namespace {
PageTraceAnswer takeAnswer(int (*take)(unsigned char**)) {
  unsigned char* at = nullptr;
  const int size = take(&at);
  PageTraceAnswer answer;
  if (size == -1) return answer;
  if (size < 0) {
    answer.state = PageTraceAnswer::State::kFailed;
    return answer;
  }
  answer.state = PageTraceAnswer::State::kDone;
  answer.trace_bytes.assign(at, at + size);
  std::free(at);
  return answer;
}
}  // namespace

bool postBakeJob(const std::vector<std::uint8_t>& job_bytes) {
  return shadows_post_bake_job_js(job_bytes.data(), static_cast<int>(job_bytes.size())) != 0;
}

PageTraceAnswer takeBakeTrace() {
  return takeAnswer(&shadows_take_bake_trace_js);
}

double bakeTraceProgress() {
  return shadows_bake_progress_js();
}

PageTraceAnswer takeTruthTrace() {
  return takeAnswer(&shadows_take_truth_trace_js);
}

double truthTraceProgress() {
  return shadows_truth_progress_js();
}

}  // namespace shadows

#endif  // __EMSCRIPTEN__
