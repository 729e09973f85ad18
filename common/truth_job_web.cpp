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

#include "truth_job.hpp"

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

}  // namespace shadows

#endif  // __EMSCRIPTEN__
