// The trace and the metrics of a truth measure, and what is kept of the last one. No GL.
#include "run/truth_measure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>

namespace shadows {

#if SHADOWS_HAVE_TRUTH
namespace {

// The suite's memo of traces (SHADOWS_TRUTH_MEMO, a folder; tests/README.md, "The suite's
// budget"): a job traced again within one ctest run (a README's claim and an exercise of the
// same defaults) is read back, byte for byte the trace, not traced anew. ctest empties the
// folder as the run starts (the truth_memo fixture), so no trace is older than the tracer
// that answered it. Unset, as for everyone but the suite, nothing is kept (and no job's id
// is taken for it).
struct Memo {
  std::string path;
  std::uint64_t job_id = 0;
};

std::optional<Memo> memoFor(const TruthJob& job) {
  const char* dir = std::getenv("SHADOWS_TRUTH_MEMO");
  if (dir == nullptr || *dir == '\0') return std::nullopt;
  Memo memo{dir, job.id()};
  char name[40];
  std::snprintf(name, sizeof name, "/%016llx.trace", static_cast<unsigned long long>(memo.job_id));
  memo.path += name;
  return memo;
}

std::optional<TruthTrace> readMemo(const Memo& memo, const TruthJob& job) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(memo.path, ec)) return std::nullopt;
  try {
    TruthTrace trace = readTruthTrace(memo.path);
    if (trace.job_id == memo.job_id && trace.width == job.surface.width &&
        trace.height == job.surface.height && trace.air.has_value() == job.air.has_value()) {
      return trace;
    }
  } catch (const std::exception&) {  // half a file (a full disk): traced anew
  }
  return std::nullopt;
}

// The job's trace: another tracer's answer given for it, the suite's memo of it, or traced
// here (the tracer kept in `out` for the next job on the same scene).
TruthTrace obtainTrace(TruthInputs& in, TruthResult& out) {
  const TruthJob& job = in.job;
  if (in.given) {
    // Another tracer's answer: only to this very job (the same scene, view, light, size).
    if (in.given->job_id != job.id()) {
      throw TruthMismatch(
          "--truth-from: the trace answers another job (other parameters, "
          "size or scene); write the job again with --truth-job");
    }
    TruthTrace trace = std::move(*in.given);
    if (trace.width != job.surface.width || trace.height != job.surface.height ||
        trace.air.has_value() != job.air.has_value()) {
      throw TruthMismatch("--truth-from: the trace does not fit its job (size or air)");
    }
    return trace;
  }
  const std::optional<Memo> memo = memoFor(job);  // the suite's only
  if (std::optional<TruthTrace> kept = memo ? readMemo(*memo, job) : std::nullopt) {
    return std::move(*kept);
  }
  out.truth = in.truth ? in.truth : makeTruthTracer(job);
  TruthTrace trace = out.truth->trace(job);
  if (memo) {
    trace.job_id = memo->job_id;
    keepTruthTrace(memo->path, trace);
  }
  return trace;
}

}  // namespace
#endif

TruthResult traceTruth(TruthInputs in) {
#if !SHADOWS_HAVE_TRUTH
  // This build has no ray tracer: nothing calls this (measureError says so first).
  (void)in;
  throw std::logic_error("no ray-traced truth in this build");
#else
  TruthResult out;
  out.key = in.key;
  const TruthJob& job = in.job;
  TruthTrace trace = obtainTrace(in, out);
  if (in.keep_bytes) {
    trace.job_id = job.id();
    out.job_bytes = serializeTruthJob(job);
    out.trace_bytes = serializeTruthTrace(trace);
  }
  const int w = in.width, h = in.height;
  const size_t n = static_cast<size_t>(w) * h;
  const std::vector<float>& truth = trace.visibility;
  long long grazing = 0;
  const std::vector<float> weight = Truth::facingWeight(job.surface, job.light, &grazing);
  ErrorMetrics& m = out.metrics;
  m = compareVisibility(in.rendered, truth, weight);
  m.grazing_pixels = grazing;
  // Every surface the eye sees writes its normal, counted or not; the sky keeps the clear 0.
  m.covered_pixels =
      std::count_if(job.surface.normal.begin(), job.surface.normal.end(),
                    [](const glm::vec4& normal) { return glm::dot(normal, normal) > 0.0f; });
  m.truth = in.truth_name;
  // Non-finite pixels: where the visibility or any channel of the shaded picture is NaN or
  // Inf, each pixel counted once.
  long long nonfinite = 0;
  std::vector<std::uint8_t> shaded_bytes(n * 4);
  for (size_t i = 0; i < n; ++i) {
    bool finite = std::isfinite(in.rendered[i]);
    for (int c = 0; c < 4; ++c) {
      const float v = in.shaded[i][c];
      finite = finite && std::isfinite(v);
      shaded_bytes[i * 4 + static_cast<size_t>(c)] = static_cast<std::uint8_t>(
          std::lround(255.0f * std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f)));
    }
    if (!finite) ++nonfinite;
  }
  m.nonfinite_pixels = nonfinite;
  out.error_image = {w, h, errorImage(shaded_bytes, in.rendered, truth)};
  out.pixels = std::make_shared<const ErrorPixels>(
      ErrorPixels{in.rendered, truth, weight, job.surface.position});
  out.truth_image = {w, h, std::vector<std::uint8_t>(n * 4)};
  for (size_t i = 0; i < n; ++i) {
    // Truth lit white, shadowed black, not counted (no surface, facing away) dark blue.
    const bool counted = truth[i] >= 0.0f;
    const auto grey = static_cast<std::uint8_t>(std::lround(255.0f * std::max(truth[i], 0.0f)));
    out.truth_image.rgba[i * 4 + 0] = counted ? grey : 20;
    out.truth_image.rgba[i * 4 + 1] = counted ? grey : 24;
    out.truth_image.rgba[i * 4 + 2] = counted ? grey : 60;
    out.truth_image.rgba[i * 4 + 3] = 255;
  }
  m.air = AirMetrics{};
  if (trace.air) {
    // The truth and error views then show the air.
    out.air = std::move(*trace.air);
    m.air = compareAir(in.air_rendered, out.air);
    m.nonfinite_pixels += m.air.nonfinite;
    out.error_image = {w, h, airErrorImage(in.air_rendered, out.air.light)};
    for (size_t i = 0; i < out.air.light.size(); ++i) {
      const auto grey =
          static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(out.air.light[i], 0.0f, 1.0f)));
      out.truth_image.rgba[i * 4 + 0] = out.truth_image.rgba[i * 4 + 1] = grey;
      out.truth_image.rgba[i * 4 + 2] = grey;
    }
  }
  return out;
#endif
}

void TruthMeasure::install(TruthResult result, const std::string& currentKey) {
  // A truth built for a scene that has changed since is not kept (its key says so).
  if (result.truth && result.key == currentKey) tracer_ = std::move(result.truth);
  job_bytes_ = std::move(result.job_bytes);
  trace_bytes_ = std::move(result.trace_bytes);
  error_.metrics = std::move(result.metrics);
  error_.valid = true;
  error_.pixels = std::move(result.pixels);
  key_ = std::move(result.key);
  error_image_ = std::move(result.error_image);
  truth_image_ = std::move(result.truth_image);
  ++measured_;
  failed_ = false;
}

void TruthMeasure::clear() {
  error_ = {};
  truth_image_ = error_image_ = {};
}

void TruthMeasure::fail(const std::string& key) {
  clear();
  key_ = key;
  failed_ = true;
}

bool haveTruth() {
  return kHaveTruth && truthTracerAvailable();
}

std::string truthUnavailable() {
  if (!kHaveTruth) return std::string(kNoTruthNote) + ": the truth and error views are empty";
  if (!truthTracerAvailable()) {
    return "the page could not load its ray tracer (web/truth): the truth and error views are "
           "empty";
  }
  return "";
}

}  // namespace shadows
