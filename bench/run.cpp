// Running: one round of one configuration (Bench), and the console table (Reporter).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "bench.hpp"
#include "core/json.hpp"

namespace shadows::bench {

Bench::Bench(Options options, std::vector<Config> configs)
    : options_(std::move(options)),
      configs_(std::move(configs)),
      results_(configs_.size()),
      tty_(isatty(STDERR_FILENO) != 0) {}

void Bench::run(benchmark::State& state, size_t index) {
  const Config& c = configs_[index];
  Result& result = results_[index];
  try {
    Runner& r = runnerFor(c.lesson);
    // The runner is reused: start every configuration from the defaults, so a setting one
    // configuration made (a bundle's pcf.early_out=false, say) does not leak into the next.
    r.params().resetToDefaults();
    if (std::string e = r.applySets(c.sets); !e.empty()) {
      fail(state, index, "bad sweep value: " + e);
      return;
    }
    const int errors_before = r.glErrors();
    r.renderFrame();  // warm-up: shader JIT and the new map's allocation land here
    for (auto _ : state) {
      r.measure().clearHistory();  // one frame of history: its pass times are this frame's
      r.renderFrame();
      const double ms = r.measure().lastFrameMs();
      state.SetIterationTime(ms / 1000.0);
      result.frame_samples.push_back(ms);
      for (const auto& [pass, pass_ms] : r.measure().medianPassMs()) {
        result.pass_samples[pass].push_back(pass_ms);
      }
    }
    result.frame_ms = median(result.frame_samples);
    result.frame_min_ms =
        *std::min_element(result.frame_samples.begin(), result.frame_samples.end());
    for (const auto& [pass, samples] : result.pass_samples) result.pass_ms[pass] = median(samples);
    result.work = r.measure().lastFrameWork();
    result.counts = r.measure().lastFrameCounts();
    if (!result.error_valid) {
      const ErrorState& e = r.measureError();
      result.error = e.metrics;
      result.error_valid = e.valid;
      // A caster moved off its preset's place (lesson 16's move.x) is another truth, though
      // the light is the same: its rows must not share a front with the unmoved scene's.
      for (size_t k = 0; k < r.scene().objects.size(); ++k) {
        const glm::vec3 d = glm::vec3(r.scene().objects[k].model[3] - r.host().presetModel(k)[3]);
        if (r.scene().objects[k].model == r.host().presetModel(k)) continue;
        char moved[128];
        std::snprintf(moved, sizeof moved, ", %s moved by (%g, %g, %g)",
                      r.scene().objects[k].name.c_str(), d.x, d.y, d.z);
        result.error.truth += moved;
      }
      if (const auto* texels = r.texels().measure()) {
        result.undersampled_pct = texelStats(*texels).undersampled_pct;
      }
      const std::vector<std::string>& numbers = allSweeps().at(c.sweep).report_numbers;
      if (!numbers.empty()) {
        JsonWriter json;
        r.writeReport(json);
        for (const std::string& name : numbers) {
          // JsonWriter keeps every number it wrote by its JSON pointer (as --grade reads them).
          const std::optional<double> v = json.number("/" + name);
          if (!v) throw std::runtime_error("the report has no number " + name);
          result.report_numbers[name] = *v;
        }
      }
    }
    result.gl_errors += r.glErrors() - errors_before;
    result.renderer = renderer_;
    result.done = result.failure.empty();
    ++result.rounds;
    state.counters["median_ms"] = result.frame_ms;
    for (const auto& [pass, ms] : result.pass_ms) state.counters[pass + "_ms"] = ms;
    state.counters["false_shadow_pct"] = result.error.false_shadow_pct;
    state.counters["false_lit_pct"] = result.error.false_lit_pct;
    // x1000 so the console's SI formatting does not print it as "12.3m".
    state.counters["vis_mae_x1000"] = 1000.0 * result.error.vis_mae;
    progress(index);
  } catch (const std::exception& e) {
    fail(state, index, e.what());
  }
}

void Bench::progress(size_t index) {
  const Config& c = configs_[index];
  const Result& result = results_[index];
  char line[512];
  const std::string who = options_.lessons.size() > 1 ? c.lesson + " " + c.label() : c.label();
  const size_t total = expected_ * static_cast<size_t>(options_.rounds);
  if (result.failure.empty()) {
    std::snprintf(line, sizeof line, "[%zu/%zu] %s  frame %.1f ms  false shadow %.2f%%",
                  ++runs_done_, total, who.c_str(), result.frame_ms, result.error.false_shadow_pct);
  } else {
    std::snprintf(line, sizeof line, "[%zu/%zu] %s  FAILED: %s", ++runs_done_, total, who.c_str(),
                  result.failure.c_str());
  }
  std::fprintf(stderr, "%s%s%s", tty_ ? "\r\033[K" : "", line, tty_ ? "" : "\n");
  std::fflush(stderr);
  last_line_ = line;
}

void Bench::clearProgress() const {
  if (tty_ && !last_line_.empty()) std::fprintf(stderr, "\r\033[K");
}

void Bench::redrawProgress() const {
  if (tty_ && !last_line_.empty()) std::fprintf(stderr, "%s", last_line_.c_str());
  std::fflush(stderr);
}

void Bench::endProgress() const {
  if (tty_ && !last_line_.empty()) std::fprintf(stderr, "\n");
}

Runner& Bench::runnerFor(const std::string& lesson) {
  if (!runner_ || runner_lesson_ != lesson) {
    runner_.reset();  // one GL context at a time
    RunOptions o;
    o.headless = true;
    o.width = options_.width;
    o.height = options_.height;
    o.frames = options_.frames;
    o.backend = options_.backend;
    o.device = options_.device;
    runner_ = std::make_unique<Runner>(lesson, makeLesson(lesson), o);
    runner_->initHeadless();
    renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    runner_lesson_ = lesson;
  }
  return *runner_;
}

void Bench::fail(benchmark::State& state, size_t index, const std::string& why) {
  Result& result = results_[index];
  result.done = false;
  if (result.failure.empty()) result.failure = why;
  state.SkipWithError(why.c_str());
  progress(index);
}

void Reporter::ReportRuns(const std::vector<Run>& runs) {
  const bool rounds = runs.size() > 1;  // then there are aggregates: show only the median
  std::vector<Run> shown;
  double cpu_ms = 0.0;
  int measured = 0;
  for (const Run& run : runs) {
    if (run.run_type == Run::RT_Iteration && !run.error_occurred) {
      // Unit(kMillisecond), so the adjusted CPU time is ms per frame.
      cpu_ms += run.GetAdjustedCPUTime();
      ++measured;
    }
    const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
    if (run.error_occurred || (rounds ? median : run.run_type == Run::RT_Iteration)) {
      shown.push_back(run);
    }
  }
  if (!runs.empty()) {
    const auto it = index_of_.find(runs.front().run_name.function_name);
    if (it != index_of_.end() && measured > 0) bench_.setCpuMs(it->second, cpu_ms / measured);
  }
  bench_.clearProgress();
  if (!shown.empty()) ConsoleReporter::ReportRuns(shown);
  std::cout.flush();
  bench_.redrawProgress();
}

}  // namespace shadows::bench
