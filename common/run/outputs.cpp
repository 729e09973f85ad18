// Running headless, the report, and every output of a run, all or nothing.
#include "run/headless_run.hpp"

#include "run/runner.hpp"

#include "run/runner_gpu.hpp"

#include "core/json.hpp"
#include "core/output_files.hpp"
#include "gl/context.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <set>

namespace shadows {

void Runner::writeReport(JsonWriter& json) {
  // Where the map's texels land (texel_density.hpp), for lessons with a map this frame:
  // measured first, so the GL errors and compiled variants below include its frame.
  const bool texels = texels_.measure() != nullptr;
  json.beginObject();
  json.value("lesson", name_);
  json.value("renderer", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  json.value("flavour", caps().flavour);  // the API this build speaks: gl45, gl41 or gles30
  json.value("vendor", reinterpret_cast<const char*>(glGetString(GL_VENDOR)));
  json.value("backend", window_.is_open ? std::string("window") : HeadlessContext::current());
  // Which EGL device rendered it (--backend egl-device), of how many there were.
  if (const EglDeviceChoice device = currentEglDevice(); device.index >= 0 && !window_.is_open) {
    json.beginObject("device");
    json.value("index", device.index);
    json.value("name", device.name);
    json.value("count", static_cast<int>(device.count));
    json.endObject();
  }
  json.beginArray("size");
  json.value("", options_.width);
  json.value("", options_.height);
  json.endArray();
  json.value("frames", options_.frames);
  params_.writeJson(json);
  json.value("light_on_surface", lightOnSurface());
  json.value("frame_ms", measure_->medianFrameMs());
  // What the shadow costs: the same frame with shadow.off, timed in the same run.
  if (baseline_.timedFrames() > 0) {
    json.value("baseline_frame_ms", baseline_.measure().medianFrameMs());
    json.figure("shadow_overhead", baseline_.measuredOverhead(),
                "rests on fewer than " + std::to_string(BaselineFrames::kFramesForRatio) +
                    " timed frames: give --frames 3 or more");
  }
  json.beginObject("pass_ms");
  for (const auto& [pass, ms] : measure_->medianPassMs()) json.value(pass, ms);
  json.endObject();
  // Counters this context cannot count are null, and "unavailable" says so, once per name.
  std::set<std::string> unavailable = measure_->lastFrameUnavailable();
  json.beginObject("counters");
  for (const auto& [pass, work] : measure_->lastFrameWork()) {
    json.beginObject(pass);
    json.value("draw_calls", work.draw_calls);
    json.value("fragment_invocations", work.fragment_invocations);
    if (!work.fragment_invocations) unavailable.insert("fragment_invocations");
    if (work.counts_passed) json.value("fragments_passed", work.fragments_passed);
    if (work.counts_passed && !work.fragments_passed) unavailable.insert("fragments_passed");
    json.endObject();
  }
  for (const auto& [name, count] : measure_->lastFrameCounts()) json.value(name, count);
  for (const std::string& name : measure_->lastFrameUnavailable()) {
    json.value(name, std::optional<long long>());
  }
  json.endObject();
  if (!unavailable.empty()) {
    json.beginObject("unavailable");
    for (const std::string& name : unavailable) json.value(name, caps().unavailable());
    json.endObject();
  }
  json.value("gl_errors", glErrors());
  // Which compiled variant each pass ran, and how many programs this run compiled.
  json.beginArray("shader_variants");
  for (const std::string& used : measure_->lastFrameVariants()) json.value("", used);
  json.endArray();
  json.value("shader_variants_compiled", ProgramVariants::compiledTotal() - compiled_at_start_);
  lesson_->report(json);
  if (texels) {
    const TexelStats& t = *texels_.stats();
    writeTexelsPerPixel(json, t);
    json.value("undersampled_pct", t.pixels > 0 ? t.undersampled_pct : kNoFigure);
  }
  if (errors_.truth().error().valid) {
    const ErrorMetrics& e = errors_.truth().error().metrics;
    json.beginObject("error");
    json.value("truth", e.truth);
    // A share of no pixel is no figure: null, and why (a zero would read as "no error").
    const bool counted = e.counted_pixels > 0;
    json.value("false_shadow_pct", counted ? e.false_shadow_pct : kNoFigure);
    json.value("false_lit_pct", counted ? e.false_lit_pct : kNoFigure);
    json.value("vis_mae", counted ? e.vis_mae : kNoFigure);
    json.value("shade_mae", counted ? e.shade_mae : kNoFigure);
    if (!counted) json.value("not_counted", notCountedReason(e));
    json.value("nonfinite_pixels", e.nonfinite_pixels);
    json.value("counted_pixels", e.counted_pixels);
    json.value("covered_pixels", e.covered_pixels);
    json.value("grazing_pixels", e.grazing_pixels);
    if (e.air.valid) {
      json.value("air_mae", e.air.mae);
      json.value("air_rel_rmse", e.air.rel_rmse);
      json.value("air_truth_mean", e.air.truth_mean);
      json.value("air_truth_noise", e.air.truth_noise);
      json.value("air_pixels", e.air.pixels);
      if (!e.air.note.empty()) json.value("air_note", e.air.note);
      if (!e.air.rel_rmse_note.empty()) json.value("air_rel_rmse_note", e.air.rel_rmse_note);
    }
    // The lesson's regions, after the whole frame's figures so that a first match of a
    // metric's name is the frame's; only from pixels of this very frame (a window's error may
    // be stale while the lesson's regions are not).
    if (errors_.truth().error().pixels && errors_.truth().key() == errors_.key()) {
      for (const ErrorRegion& region : lesson_->errorRegions()) {
        const ErrorMetrics r = compareVisibilityIn(*errors_.truth().error().pixels, region.inside,
                                                   region.pixel_inside);
        json.beginObject(region.name);
        json.value("counted_pixels", r.counted_pixels);
        json.value("false_shadow_pct", r.counted_pixels > 0 ? r.false_shadow_pct : kNoFigure);
        json.value("false_lit_pct", r.counted_pixels > 0 ? r.false_lit_pct : kNoFigure);
        json.value("vis_mae", r.counted_pixels > 0 ? r.vis_mae : kNoFigure);
        // The region's share of the frame's counted pixels (lesson 13: how much light bleeds).
        json.value("share_pct", e.counted_pixels > 0
                                    ? 100.0 * static_cast<double>(r.counted_pixels) /
                                          static_cast<double>(e.counted_pixels)
                                    : kNoFigure);
        json.endObject();
      }
    }
    json.endObject();
  }
  lesson_->reportPixels(json, {options_.width, options_.height, texels_.measure()});
  // The exercise's verdict on these very numbers (lesson/exercise.hpp), last: it reads them.
  if (exercise_.chosen() && errors_.truth().error().valid) {
    const Exercise& ex = *exercise_.chosen();
    const Verdict v = evaluate(ex, json);
    json.beginObject("exercise");
    json.value("number", options_.exercise);
    json.value("title", ex.title);
    json.value("goal", ex.goal);
    json.beginObject("measured");
    for (const FigureResult& f : v.figures) {
      json.value(f.figure->pointer, f.measured.value_or(kNoFigure));
    }
    json.endObject();
    json.value("met", v.met);
    json.endObject();
  }
  json.endObject();
}

int Runner::run() {
  if (!options_.truth_from.empty()) {
    try {
      errors_.truth().given = readTruthTrace(options_.truth_from);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "%s: --truth-from: %s\n", name_.c_str(), printable(e.what()).c_str());
      return 2;
    }
  }
  try {
    return options_.grade ? exercise_.grade() : runHeadlessOrWindow();
  } catch (const TruthMismatch& e) {
    std::fprintf(stderr, "%s: %s\n", name_.c_str(), printable(e.what()).c_str());
    return 2;
  }
}

int Runner::runHeadlessOrWindow() {
  const char* display = std::getenv("DISPLAY");
  const bool has_display = display != nullptr && *display != '\0';
  if (options_.headless || (!has_display && !options_.force_window)) {
    // Said on stderr, as every diagnostic: `--report /dev/stdout` stays the report alone.
    if (!options_.headless)
      std::fprintf(stderr, "%s: no display, rendering headless\n", name_.c_str());
    return headless_.run();
  }
  const int result = window_.run();
  if (result != RunnerWindow::kNoWindow) return result;
  const std::string why = printable(window_.error.empty() ? "unknown reason" : window_.error);
  if (options_.force_window) {
    std::fprintf(stderr, "%s: cannot open a window (%s)\n", name_.c_str(), why.c_str());
    return 1;
  }
  // A DISPLAY that leads nowhere (a closed ssh tunnel, a stale variable): say so once, go on.
  std::fprintf(stderr, "%s: cannot open a window on DISPLAY=%s (%s), rendering headless\n",
               name_.c_str(), has_display ? printable(display).c_str() : "", why.c_str());
  return headless_.run();
}

void HeadlessRun::saveScreenshot(int width, int height) {
  Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  glBindFramebuffer(GL_FRAMEBUFFER, r_.window_.is_open ? 0 : r_.gpu_->target->id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // Beside the headless pictures (out/, ignored by git), never over an earlier one.
  std::error_code ec;
  std::filesystem::create_directories(kScreenshotFolder, ec);
  std::string path;
  do {
    path = std::string(kScreenshotFolder) + "/" + r_.name_ + "_" +
           std::to_string(++r_.window_.screenshots_taken) + ".png";
  } while (std::filesystem::exists(path, ec));
  // Said under the panel's button, and on the terminal with the folder it is in.
  r_.window_.screenshot_said =
      writePng(path, image) ? "screenshot: " + path : "screenshot: cannot write " + path;
  std::fprintf(stderr, "%s (in %s)\n", r_.window_.screenshot_said.c_str(),
               std::filesystem::current_path(ec).string().c_str());
}

int HeadlessRun::run() {
  // Without --out the picture goes where ./run.sh puts them, out/<lesson>.png (git-ignored):
  // checked against the other outputs like a given --out, before anything is rendered.
  std::string out = r_.options_.out;
  // A grade writes only what it was asked for: no default picture.
  if (out.empty() && !r_.options_.grade) {
    std::error_code ec;
    std::filesystem::create_directories("out", ec);
    out = "out/" + r_.name_ + ".png";
    OutputTarget picture, other;
    if (const std::string why = resolveOutput(out, picture); !why.empty()) {
      std::fprintf(stderr, "%s: cannot write '%s' (%s)\n", r_.name_.c_str(), out.c_str(),
                   why.c_str());
      return 2;
    }
    for (const auto& [flag, path] :
         {std::pair<const char*, const std::string*>{"--report", &r_.options_.report},
          {"--truth-out", &r_.options_.truth_out},
          {"--error-out", &r_.options_.error_out},
          {"--truth-job", &r_.options_.truth_job},
          {"--truth-result", &r_.options_.truth_result}}) {
      if (path->empty() || !resolveOutput(*path, other).empty()) continue;
      if (picture.sameFileAs(other)) {
        std::fprintf(stderr, "%s: %s names the default picture %s; give --out\n", r_.name_.c_str(),
                     flag, out.c_str());
        return 2;
      }
    }
  }
  r_.initHeadless();
  r_.renderFrame();  // warm-up: shader JIT and the first shadow map land here
  r_.baseline_.render();
  // A snapshot with the panel should show the error numbers, so measure them first.
  if (r_.options_.panel && r_.options_.truth) r_.measureError();
  r_.measure_->clearHistory();
  r_.baseline_.measure().clearHistory();
  for (int i = 0; i < r_.options_.frames; ++i) {
    r_.baseline_.render();  // interleaved with the frames it is compared with; first, as the
    r_.renderFrame();       // picture is read from the same target
  }
  // The panel shows the run's medians, the numbers the report gives: it is drawn once more,
  // untimed, after the last timed frame.
  if (r_.options_.panel) r_.renderFrame(/*timed=*/false);
  const Image image = r_.readImage();
  // Asking for the truth or error picture (or its job) asks for the truth, --no-truth or not.
  if (r_.options_.truthAsked()) r_.measureError();
  if (!writeOutputs(out, image)) return 1;
  const int errors = r_.glErrors();
  std::printf("%-30s %dx%d  frame %7.2f ms", out.empty() ? r_.name_.c_str() : out.c_str(),
              r_.options_.width, r_.options_.height, r_.measure_->medianFrameMs());
  const auto& counts = r_.measure_->lastFrameCounts();
  if (const auto it = counts.find("shadow_map_renders"); it != counts.end() && it->second == 0) {
    std::printf(" (map cached)");
  }
  if (const std::optional<double> overhead = r_.baseline_.measuredOverhead()) {
    std::printf(", %.2fx without shadow", *overhead);
  }
  const ErrorState& error = r_.errors().truth().error();
  if (error.valid && error.metrics.counted_pixels == 0) {
    std::printf("  error: none counted (%s)", notCountedReason(error.metrics).c_str());
  } else if (error.valid) {
    std::printf("  false shadow %6.2f%%  false lit %5.2f%%", error.metrics.false_shadow_pct,
                error.metrics.false_lit_pct);
  }
  std::printf("  gl_errors %d\n", errors);
  if (errors > 0) {
    std::fprintf(stderr, "%s: %d GL error(s), last: %s\n", r_.name_.c_str(), errors,
                 GlErrorLog::last().c_str());
    return 1;
  }
  return 0;
}

bool HeadlessRun::writeOutputs(const std::string& out, const Image& image) {
  // Every output of the run, or none: a picture without its report is a half answer.
  OutputBatch batch;
  const TruthMeasure& truth = r_.errors().truth();
  // A picture sent to /dev/null is neither encoded nor written (the tests' runs: a tenth of a
  // short one).
  const auto picture = [&batch](const std::string& path, const Image& shown) {
    if (!path.empty() && !discardsWhatIsWritten(path)) batch.add(path, encodePng(shown));
  };
  picture(out, image);
  picture(r_.options_.truth_out, truth.truthImage());
  picture(r_.options_.error_out, truth.errorImage());
  if (!r_.options_.truth_job.empty())
    batch.add(r_.options_.truth_job, {truth.jobBytes().begin(), truth.jobBytes().end()});
  if (!r_.options_.truth_result.empty()) {
    batch.add(r_.options_.truth_result, {truth.traceBytes().begin(), truth.traceBytes().end()});
  }
  if (!r_.options_.report.empty()) {
    JsonWriter json;
    r_.writeReport(json);
    batch.add(r_.options_.report, json.str() + "\n");
  }
  if (batch.commit()) return true;
  std::fprintf(stderr, "%s: %s\n", r_.name_.c_str(), batch.failure().c_str());
  return false;
}

}  // namespace shadows
