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

// The workers' side (web/truth/page.mjs), for one of its two pools: `bake` 0 the truth's
// (Module.shadowsPostTruthJob, ...), 1 lesson 15's bakes (Module.shadowsPostBakeJob, ...).
// Post a copy of the job; take the answer as malloc'ed bytes at *out (its size), -1 while none
// is there, -2 when the workers failed.
EM_JS(int, shadows_post_job_js, (int bake, const unsigned char* job, int size), {
  const post = bake ? Module.shadowsPostBakeJob : Module.shadowsPostTruthJob;
  if (typeof post !== 'function') return 0;
  return post(HEAPU8.slice(job, job + size)) ? 1 : 0;
});
EM_JS(int, shadows_take_trace_js, (int bake, unsigned char** out), {
  const take = bake ? Module.shadowsTakeBakeTrace : Module.shadowsTakeTruthTrace;
  const answer = typeof take === 'function' ? take() : null;
  if (answer === null) return -1;
  if (!answer.trace) {
    console.error('shadows: the ' + (bake ? 'bake' : 'truth') + ' worker failed: ' + answer.error);
    return -2;
  }
  const at = _malloc(answer.trace.length);
  HEAPU8.set(answer.trace, at);
  HEAPU32[out >> 2] = at;
  return answer.trace.length;
});
EM_JS(double, shadows_progress_js, (int bake), {
  const progress = bake ? Module.shadowsBakeProgress : Module.shadowsTruthProgress;
  return typeof progress === 'number' ? progress : -1;
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

namespace {
constexpr int kTruthPool = 0, kBakePool = 1;  // shadows_*_js's `bake`

bool postJob(int pool, const std::vector<std::uint8_t>& job_bytes) {
  return shadows_post_job_js(pool, job_bytes.data(), static_cast<int>(job_bytes.size())) != 0;
}

PageTraceAnswer takeAnswer(int pool) {
  unsigned char* at = nullptr;
  const int size = shadows_take_trace_js(pool, &at);
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

bool postTruthJob(const std::vector<std::uint8_t>& job_bytes) {
  return postJob(kTruthPool, job_bytes);
}

PageTraceAnswer takeTruthTrace() {
  return takeAnswer(kTruthPool);
}

double truthTraceProgress() {
  return shadows_progress_js(kTruthPool);
}

bool postBakeJob(const std::vector<std::uint8_t>& job_bytes) {
  return postJob(kBakePool, job_bytes);
}

PageTraceAnswer takeBakeTrace() {
  return takeAnswer(kBakePool);
}

double bakeTraceProgress() {
  return shadows_progress_js(kBakePool);
}

}  // namespace shadows

#endif  // __EMSCRIPTEN__
