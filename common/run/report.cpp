// The report (--report, and what an exercise's verdict reads): the run and its cost, the
// error against the truth and the lesson's regions, the exercise's verdict; docs/CONTRACTS.md
// names every field.
#include <set>

#include "core/json.hpp"
#include "run/runner.hpp"

namespace shadows {

namespace {

// What the frame costs: its time, the shadow's over the frame without it, each pass's time and
// work, the counters, the GL errors, the shader variants that ran.
void reportCost(JsonWriter& json, const Measure& measure, const BaselineFrames& baseline,
                long long compiled) {
  json.value("frame_ms", measure.medianFrameMs());
  // What the shadow costs: the same frame with shadow.off, timed in the same run.
  if (baseline.timedFrames() > 0) {
    json.value("baseline_frame_ms", baseline.measure().medianFrameMs());
    json.figure("shadow_overhead", baseline.measuredOverhead(),
                "rests on fewer than " + std::to_string(BaselineFrames::kFramesForRatio) +
                    " timed frames: give --frames 3 or more");
  }
  json.beginObject("pass_ms");
  for (const auto& [pass, ms] : measure.medianPassMs()) json.value(pass, ms);
  json.endObject();
  // Counters this context cannot count are null, and "unavailable" says so, once per name.
  std::set<std::string> unavailable = measure.lastFrameUnavailable();
  json.beginObject("counters");
  for (const auto& [pass, work] : measure.lastFrameWork()) {
    json.beginObject(pass);
    json.value("draw_calls", work.draw_calls);
    json.value("fragment_invocations", work.fragment_invocations);
    if (!work.fragment_invocations) unavailable.insert("fragment_invocations");
    if (work.counts_passed) json.value("fragments_passed", work.fragments_passed);
    if (work.counts_passed && !work.fragments_passed) unavailable.insert("fragments_passed");
    json.endObject();
  }
  for (const auto& [name, count] : measure.lastFrameCounts()) json.value(name, count);
  for (const std::string& name : measure.lastFrameUnavailable()) {
    json.value(name, std::optional<long long>());
  }
  json.endObject();
  if (!unavailable.empty()) {
    json.beginObject("unavailable");
    for (const std::string& name : unavailable) json.value(name, caps().unavailable());
    json.endObject();
  }
  json.value("gl_errors", GlErrorLog::poll());
  // Which compiled variant each pass ran, and how many programs this run compiled.
  json.beginArray("shader_variants");
  for (const std::string& used : measure.lastFrameVariants()) json.value("", used);
  json.endArray();
  json.value("shader_variants_compiled", compiled);
}

// The error against the truth over the whole frame, then over each of the lesson's regions.
void reportError(JsonWriter& json, const ErrorMeasure& errors, const Lesson& lesson) {
  const ErrorMetrics& e = errors.truth().error().metrics;
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
  if (errors.truth().error().pixels && errors.truth().key() == errors.key()) {
    for (const ErrorRegion& region : lesson.errorRegions()) {
      const ErrorMetrics r =
          compareVisibilityIn(*errors.truth().error().pixels, region.inside, region.pixel_inside);
      json.beginObject(region.name);
      json.value("counted_pixels", r.counted_pixels);
      json.value("false_shadow_pct", r.counted_pixels > 0 ? r.false_shadow_pct : kNoFigure);
      json.value("false_lit_pct", r.counted_pixels > 0 ? r.false_lit_pct : kNoFigure);
      json.value("vis_mae", r.counted_pixels > 0 ? r.vis_mae : kNoFigure);
      // The region's share of the frame's counted pixels (lesson 13: how much light bleeds).
      json.value("share_pct", e.counted_pixels > 0 ? 100.0 * static_cast<double>(r.counted_pixels) /
                                                         static_cast<double>(e.counted_pixels)
                                                   : kNoFigure);
      json.endObject();
    }
  }
  json.endObject();
}

// The chosen exercise's figures and verdict on the numbers above.
void reportExercise(JsonWriter& json, const ExerciseRun& exercise) {
  const Exercise& ex = *exercise.chosen();
  const Verdict v = evaluate(ex, json);
  json.beginObject("exercise");
  json.value("number", exercise.number());
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

}  // namespace

void Runner::writeReport(JsonWriter& json) {
  // Where the map's texels land (texel_density.hpp), for lessons with a map this frame:
  // measured first, so the GL errors and compiled variants below include its frame.
  const bool texels = texels_.measure() != nullptr;
  json.beginObject();
  reportRun(json);
  reportCost(json, *measure_, baseline_, ProgramVariants::compiledTotal() - compiled_at_start_);
  lesson_->report(json);
  if (texels) {
    const TexelStats& t = *texels_.stats();
    writeTexelsPerPixel(json, t);
    json.value("undersampled_pct", t.pixels > 0 ? t.undersampled_pct : kNoFigure);
  }
  if (errors_.truth().error().valid) reportError(json, errors_, *lesson_);
  lesson_->reportPixels(json, {options_.width, options_.height, texels_.measure()});
  // The exercise's verdict on these very numbers (lesson/exercise.hpp), last: it reads them.
  if (exercise_.chosen() && errors_.truth().error().valid) reportExercise(json, exercise_);
  json.endObject();
}

// What ran, where, at what size, with which settings.
void Runner::reportRun(JsonWriter& json) {
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
}

}  // namespace shadows
