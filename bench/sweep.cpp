// bench_sweep: the time-vs-error benchmark. For one lesson (or all that have a sweep) it renders
// every configuration of a sweep (scenes x the Cartesian product of parameter axes) headless,
// times N frames after a warm-up, measures the error against the ray-traced truth, and writes
// DIR/<lesson>.csv, DIR/<lesson>.json and a gnuplot plot DIR/<lesson>.png.
//
// Google Benchmark drives the runs: one registered benchmark per configuration with a fixed
// iteration count (= frames) and manual time (= the runner's glFinish-bracketed frame time), the
// error metrics as counters. Warm-up and the truth happen outside the timing loop.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app.hpp"
#include "json.hpp"

#ifndef BENCH_DIR
#error "BENCH_DIR (the directory of plot.gp) must be defined by the build"
#endif

extern char** environ;

namespace shadows {
namespace {

// ---- Sweep definitions ---------------------------------------------------------------------

// A value is either plain (the setting is name=value) or a bundle "label:a=1 b=2" that sets
// several parameters at once, for knobs that only make sense together (a PCF mode and its
// tap count); the label names the point in the CSV and on the plot.
struct Axis {
  std::string name;
  std::vector<std::string> values;
};

// The label of a value and the --set assignments it stands for.
std::pair<std::string, std::vector<std::string>> settingsOf(const Axis& axis,
                                                            const std::string& value) {
  const auto colon = value.find(':');
  if (colon == std::string::npos) return {value, {axis.name + "=" + value}};
  std::vector<std::string> sets;
  std::istringstream words(value.substr(colon + 1));
  for (std::string w; words >> w;) sets.push_back(w);
  return {value.substr(0, colon), sets};
}

// scenes x axes. axes[0] is the knob that runs along each plotted series (it also varies fastest,
// so the points of one series are measured back to back); the other axes pick the series.
struct Sweep {
  std::vector<std::string> scenes;
  std::vector<Axis> axes;
  std::vector<std::string> fixed;  // --set values every configuration shares
  // The error metrics plotted against time, one row of panels each: any of vis_mae,
  // false_shadow_pct, false_lit_pct, shade_mae, air_rel_rmse_pct, air_mae.
  std::vector<std::string> plot_metrics = {"vis_mae"};
  // Plot against axes[0]'s (numeric) value instead of time, for knobs that cost nothing
  // (a bias): there the question is how error moves with the knob.
  bool plot_along = false;
  // A study across lessons: its name is no lesson, and its bundles say `lesson=NAME`.
  bool study = false;
};

// Lessons 06 and 07: the copy paths against map size and the light pass's depth bits.
Sweep copyCostSweep() {
  return {.scenes = {"torus_pyramid", "dueling"},
          .axes = {{"shadow.size", {"256", "512", "1024", "2048"}},
                   {"map.path", {"read_pixels", "copy_texture", "render_to_texture"}},
                   {"map.depth_bits", {"24", "16"}}},
          .fixed = {"shadow.cache=false", "inset=false"},
          .plot_metrics = {"false_shadow_pct", "false_lit_pct"}};
}

// What a shadow costs (issue 10): every lesson with a shadow.off baseline, at its defaults,
// its frame against the same frame with no shadow work, interleaved in one run, with the map
// cached (a static scene) and re-rendered every frame. A new lesson with the baseline joins by
// itself; instrumentation (a `*.count` switch) is off, since it is not the shadow.
Sweep shadowCostSweep() {
  Axis lessons{"lesson_tag", {}};
  for (const std::string& name : registeredLessons()) {
    Runner probe(name, makeLesson(name), RunOptions{});  // parameters only, no GL
    if (probe.params().find("shadow.off") == nullptr) continue;
    std::string bundle = name.substr(0, 2) + ":lesson=" + name;
    for (const Param& p : probe.params().all()) {
      if (p.kind == ParamKind::Bool && p.name.ends_with(".count"))
        bundle += " " + p.name + "=false";
    }
    lessons.values.push_back(bundle);
  }
  return {.scenes = {"torus_pyramid", "grazing", "dueling", "cubes"},
          .axes = {{"shadow.off", {"false", "true"}}, lessons, {"shadow.cache", {"true", "false"}}},
          .fixed = {"inset=false"},
          .plot_metrics = {"vis_mae"},
          .study = true};
}

// One entry per lesson. Adding a lesson's sweep is one entry here, e.g. for 04:
//   {"04_...", {.scenes = {...}, .axes = {{"bias.units", {...}}, {"bias.factor", {...}}}, ...}}
const std::map<std::string, Sweep>& sweeps() {
  static const std::map<std::string, Sweep> table = {
      {"03_shadow_map_basic",
       {.scenes = {"torus_pyramid", "cubes"},
        .axes = {{"shadow.size", {"128", "256", "512", "1024", "2048", "4096"}},
                 {"shadow.format", {"16", "24", "32f"}},
                 {"shadow.filter", {"nearest", "linear"}}},
        // No cache: a static frame would otherwise skip the shadow pass and not pay for it.
        // No inset: the corner depth view is a teaching aid, not part of the technique.
        .fixed = {"shadow.cache=false", "inset=false"},
        // Split by failure mode: with no bias, acne (false shadow) does not depend on the map
        // at all, while aliasing at shadow edges (false lit) falls with its size.
        .plot_metrics = {"false_shadow_pct", "false_lit_pct"}}},
      {"04_bias_offset",
       // Bias costs nothing: the plot is about error, along the constant bias from none to
       // far too much (acne falls, then peter panning rises), one series per method.
       {.scenes = {"torus_pyramid", "grazing"},
        .axes = {{"bias.units", {"0", "1", "4", "64", "1000", "10000", "100000", "1000000"}},
                 {"bias.mode",
                  {"constant_only", "polygon_offset", "clip_translate", "back_faces",
                   "normal_offset"}},
                 {"bias.factor", {"1.1", "2"}}},
        .fixed = {"shadow.size=2048", "shadow.cache=false", "inset=false"},
        .plot_metrics = {"false_shadow_pct", "false_lit_pct"},
        .plot_along = true}},
      {"05_pcf_dithered",
       // Along a series, kernels from cheapest to dearest, so the plot shows where 001's
       // 4-tap dither sits against 64 taps. All points of a series share the radius and the
       // map size, hence the same area-light truth ("none" and hw2x2 have their own and are
       // left out); early_out=false shows what skipping settled neighbourhoods saves.
       {.scenes = {"torus_pyramid", "dueling"},
        .axes = {{"kernel",
                  {"dithered4:pcf.mode=dithered", "grid4:pcf.mode=grid pcf.taps=4",
                   "poisson16:pcf.mode=poisson pcf.taps=16", "grid16:pcf.mode=grid pcf.taps=16",
                   "poisson64:pcf.mode=poisson pcf.taps=64", "grid64:pcf.mode=grid pcf.taps=64",
                   "grid64_all_taps:pcf.mode=grid pcf.taps=64 pcf.early_out=false"}},
                 {"pcf.radius", {"1", "2", "4"}},
                 {"shadow.size", {"1024", "2048"}}},
        .fixed = {"shadow.cache=false", "inset=false", "pcf.count=false"},
        .plot_metrics = {"vis_mae", "false_lit_pct"}}},
      // Seed 000's copy claims, timed as the `readback` pass: "512x512 takes 4 times longer to
      // copy than 256x256", "16-bit depth values copy twice as fast as 24-bit".
      {"06_dual_texture_8bit", copyCostSweep()},
      {"07_multidigit_16bit", copyCostSweep()},
      {"precision_study",
       // Seed 000's claim in numbers: error against the light frustum's far/near ratio, from
       // about the casters' own (6) to "expanded out considerably" (5000) and past it. Every
       // point sets near and far itself (no fit), every map is 1024², every technique keeps
       // its own lesson's default bias (04's back faces + (1.1, 4) for the depth textures).
       {.scenes = {"torus_pyramid", "dueling"},
        .axes = {{"far_over_near",
                  {"6:shadow.fit=false light.near=4 light.far=24",
                   "20:shadow.fit=false light.near=1.2 light.far=24",
                   "100:shadow.fit=false light.near=0.5 light.far=50",
                   "1000:shadow.fit=false light.near=0.1 light.far=100",
                   "5000:shadow.fit=false light.near=0.1 light.far=500",
                   "100000:shadow.fit=false light.near=0.01 light.far=1000"}},
                 {"map",
                  {"8bit_projective:lesson=06_dual_texture_8bit",
                   "8bit_linear:lesson=06_dual_texture_8bit map.encoding=linear",
                   "16bit_two_digits:lesson=07_multidigit_16bit",
                   "D16:lesson=04_bias_offset shadow.format=16",
                   "D24:lesson=04_bias_offset shadow.format=24",
                   "D32F:lesson=04_bias_offset shadow.format=32f"}}},
        .fixed = {"shadow.cache=false", "inset=false", "shadow.size=1024"},
        .plot_metrics = {"false_shadow_pct", "false_lit_pct"},
        .plot_along = true,
        .study = true}},
      {"shadow_cost", shadowCostSweep()},
      {"08_atmospherics",
       // Slices against the air's error: where more slices stop paying (the map's resolution
       // or the truth's own noise), with and without jitter, on two map sizes.
       {.scenes = {"room"},
        .axes = {{"air.slices", {"4", "8", "16", "32", "48", "64", "96", "128"}},
                 {"air.jitter", {"false", "true"}},
                 {"shadow.size", {"256", "1024"}}},
        .fixed = {"shadow.cache=false", "inset=false"},
        .plot_metrics = {"air_rel_rmse_pct", "air_mae"}}},
  };
  return table;
}

// ---- Configurations and their results ------------------------------------------------------

struct Config {
  std::string sweep;  // the table entry it belongs to: a lesson, or a study across lessons
  std::string lesson, scene;
  std::vector<std::string> axis_names, values;  // values[i] belongs to axis_names[i]
  std::vector<size_t> value_index;              // index of values[i] in the axis' list
  std::vector<std::string> sets;

  std::string label() const {
    std::string s = scene;
    for (size_t i = 0; i < values.size(); ++i) s += " " + axis_names[i] + "=" + values[i];
    return s;
  }
};

struct Result {
  bool done = false;    // at least one round measured, none failed
  std::string failure;  // why the configuration could not be measured
  int rounds = 0;
  std::vector<double> frame_samples;  // every timed frame of every round
  std::map<std::string, std::vector<double>> pass_samples;
  double frame_ms = 0.0;      // medians of the samples
  double frame_min_ms = 0.0;  // the fastest frame: what a busy machine disturbs least
  std::map<std::string, double> pass_ms;
  double cpu_ms = 0.0;  // process CPU time per frame (all llvmpipe threads), from the benchmark
  std::map<std::string, PassWork> work;  // deterministic: the last frame's
  std::map<std::string, long long> counts;
  ErrorMetrics error;
  bool error_valid = false;
  int gl_errors = 0;
  std::string renderer;
};

struct Options {
  std::vector<std::string> lessons;
  std::filesystem::path out_dir = "bench/results";
  int width = 640, height = 480, frames = 5, rounds = 3;
  bool frames_given = false, size_given = false, rounds_given = false;
  bool smoke = false, quick = false, plot = true;
  // The plot's time. CPU time per frame by default: on the shared 2-core machine other jobs
  // stretch wall times (median or fastest frame) 2-3x more than CPU times (see README.md).
  std::string plot_x = "cpu";
};

std::vector<Config> expand(const std::string& lesson, const Sweep& sweep, const Options& o) {
  std::vector<Axis> axes = sweep.axes;
  std::vector<std::string> scenes = sweep.scenes;
  if (o.quick && !axes.empty()) {
    // Every other value along the series, and always the last one.
    std::vector<std::string> thinned;
    const auto& v = axes[0].values;
    for (size_t i = 0; i < v.size(); i += 2) thinned.push_back(v[i]);
    if (thinned.back() != v.back()) thinned.push_back(v.back());
    axes[0].values = thinned;
  }
  // The odometer over value indices, axes[0] fastest.
  auto make = [&](const std::string& scene, const std::vector<size_t>& index) {
    Config c{lesson, lesson, scene, {}, {}, index, {"scene=" + scene}};
    for (size_t a = 0; a < axes.size(); ++a) {
      c.axis_names.push_back(axes[a].name);
      const auto [label, sets] = settingsOf(axes[a], axes[a].values[index[a]]);
      c.values.push_back(label);
      for (const std::string& set : sets) {
        // A study's bundle picks the lesson that renders it.
        if (set.rfind("lesson=", 0) == 0) {
          c.lesson = set.substr(7);
        } else {
          c.sets.push_back(set);
        }
      }
    }
    c.sets.insert(c.sets.end(), sweep.fixed.begin(), sweep.fixed.end());
    // The index into the full (unthinned) axis, so the plot's series keep their identity.
    for (size_t a = 0; a < axes.size(); ++a) {
      const auto& full = sweep.axes[a].values;
      c.value_index[a] = static_cast<size_t>(
          std::find_if(full.begin(), full.end(),
                       [&](const std::string& v) {
                         return settingsOf(sweep.axes[a], v).first == c.values[a];
                       }) -
          full.begin());
    }
    return c;
  };
  std::vector<Config> configs;
  if (o.smoke) {
    // Three tiny runs that still touch both ends of every axis and two scenes.
    std::vector<size_t> first(axes.size(), 0), last(axes.size());
    for (size_t a = 0; a < axes.size(); ++a) last[a] = axes[a].values.size() - 1;
    std::vector<size_t> first_but_along = first;
    if (!axes.empty()) first_but_along[0] = last[0];
    configs.push_back(make(scenes.front(), first));
    configs.push_back(make(scenes.front(), first_but_along));
    configs.push_back(make(scenes.size() > 1 ? scenes[1] : scenes.front(), last));
    return configs;
  }
  for (const auto& scene : scenes) {
    std::vector<size_t> index(axes.size(), 0);
    for (;;) {
      configs.push_back(make(scene, index));
      size_t a = 0;
      while (a < axes.size() && ++index[a] == axes[a].values.size()) index[a++] = 0;
      if (a == axes.size()) break;
    }
  }
  return configs;
}

// ---- Running -------------------------------------------------------------------------------

class Bench {
 public:
  Bench(Options options, std::vector<Config> configs)
      : options_(std::move(options)), configs_(std::move(configs)), results_(configs_.size()) {}

  std::vector<Result>& results() { return results_; }

  // One round of one configuration: a warm-up frame, then `frames` timed frames. The truth is
  // measured once per configuration, outside the timing loop.
  void run(benchmark::State& state, size_t index) {
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
      for (const auto& [pass, samples] : result.pass_samples)
        result.pass_ms[pass] = median(samples);
      result.work = r.measure().lastFrameWork();
      result.counts = r.measure().lastFrameCounts();
      if (!result.error_valid) {
        const ErrorState& e = r.measureError();
        result.error = e.metrics;
        result.error_valid = e.valid;
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

  // The benchmark library's mean process CPU time per frame over the rounds.
  void setCpuMs(size_t index, double cpu_ms) { results_[index].cpu_ms = cpu_ms; }

  void progress(size_t index) {
    const Config& c = configs_[index];
    const Result& result = results_[index];
    char line[512];
    const std::string who = options_.lessons.size() > 1 ? c.lesson + " " + c.label() : c.label();
    const size_t total = expected_ * static_cast<size_t>(options_.rounds);
    if (result.failure.empty()) {
      std::snprintf(line, sizeof line, "[%zu/%zu] %s  frame %.1f ms  false shadow %.2f%%",
                    ++runs_done_, total, who.c_str(), result.frame_ms,
                    result.error.false_shadow_pct);
    } else {
      std::snprintf(line, sizeof line, "[%zu/%zu] %s  FAILED: %s", ++runs_done_, total, who.c_str(),
                    result.failure.c_str());
    }
    std::fprintf(stderr, "%s%s%s", tty_ ? "\r\033[K" : "", line, tty_ ? "" : "\n");
    std::fflush(stderr);
    last_line_ = line;
  }
  // The console table scrolls above; the progress line stays at the bottom of a terminal.
  void clearProgress() const {
    if (tty_ && !last_line_.empty()) std::fprintf(stderr, "\r\033[K");
  }
  void redrawProgress() const {
    if (tty_ && !last_line_.empty()) std::fprintf(stderr, "%s", last_line_.c_str());
    std::fflush(stderr);
  }
  void endProgress() const {
    if (tty_ && !last_line_.empty()) std::fprintf(stderr, "\n");
  }

  void closeRunner() { runner_.reset(); }
  // How many configurations --benchmark_filter lets through, for the progress count.
  void setExpected(size_t n) { expected_ = n; }

 private:
  Runner& runnerFor(const std::string& lesson) {
    if (!runner_ || runner_lesson_ != lesson) {
      runner_.reset();  // one GL context at a time
      RunOptions o;
      o.headless = true;
      o.width = options_.width;
      o.height = options_.height;
      o.frames = options_.frames;
      runner_ = std::make_unique<Runner>(lesson, makeLesson(lesson), o);
      runner_->initHeadless();
      renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
      runner_lesson_ = lesson;
    }
    return *runner_;
  }

  void fail(benchmark::State& state, size_t index, const std::string& why) {
    Result& result = results_[index];
    result.done = false;
    if (result.failure.empty()) result.failure = why;
    state.SkipWithError(why.c_str());
    progress(index);
  }

  Options options_;
  std::vector<Config> configs_;
  std::vector<Result> results_;
  std::unique_ptr<Runner> runner_;
  std::string runner_lesson_, renderer_;
  size_t runs_done_ = 0, expected_ = configs_.size();
  bool tty_ = isatty(STDERR_FILENO) != 0;
  std::string last_line_;
};

// The library's console table on stdout, one row per configuration (the median over its rounds),
// with our progress line kept below it; and the CPU time per frame for the CSV.
class Reporter : public benchmark::ConsoleReporter {
 public:
  Reporter(Bench& bench, std::map<std::string, size_t> index_of, OutputOptions options)
      : ConsoleReporter(options), bench_(bench), index_of_(std::move(index_of)) {}

  // The library calls this once per configuration, after its last round.
  void ReportRuns(const std::vector<Run>& runs) override {
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

 private:
  Bench& bench_;
  std::map<std::string, size_t> index_of_;
};

// ---- Output --------------------------------------------------------------------------------

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> numeric;  // per column: written unquoted in JSON
};

std::string number(double v) {
  if (!std::isfinite(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Columns: lesson, scene, each axis, size and frames, timings, work, error, renderer. Passes and
// counters are the union over all rows, so a lesson with more passes gets more columns.
Table makeTable(const std::vector<const Config*>& configs,
                const std::vector<const Result*>& results, const Options& o) {
  std::set<std::string> passes, counts;
  for (const Result* r : results) {
    for (const auto& [p, ms] : r->pass_ms) passes.insert(p);
    for (const auto& [p, w] : r->work) passes.insert(p);
    for (const auto& [name, n] : r->counts) counts.insert(name);
  }
  Table t;
  auto column = [&](const std::string& name, bool numeric) {
    t.header.push_back(name);
    t.numeric.push_back(numeric);
  };
  column("lesson", false);
  column("scene", false);
  // A swept column is numeric in the JSON when all its values are numbers (shadow.size is,
  // shadow.format with its "32f" is not).
  for (size_t a = 0; a < configs.front()->axis_names.size(); ++a) {
    const bool numeric = std::all_of(configs.begin(), configs.end(), [a](const Config* c) {
      char* end = nullptr;
      std::strtod(c->values[a].c_str(), &end);
      return !c->values[a].empty() && *end == '\0';
    });
    column(configs.front()->axis_names[a], numeric);
  }
  column("width", true);
  column("height", true);
  column("frames", true);
  column("rounds", true);
  column("frame_ms", true);
  column("frame_min_ms", true);
  column("cpu_ms", true);
  for (const auto& p : passes) column("pass_ms." + p, true);
  for (const auto& p : passes) {
    column("draw_calls." + p, true);
    column("fragment_invocations." + p, true);
  }
  for (const auto& name : counts) column(name, true);
  for (const char* name :
       {"false_shadow_pct", "false_lit_pct", "vis_mae", "shade_mae", "nonfinite_pixels",
        "counted_pixels", "air_mae", "air_rel_rmse", "air_truth_noise"}) {
    column(name, true);
  }
  column("truth", false);
  column("gl_errors", true);
  column("renderer", false);
  column("status", false);

  for (size_t i = 0; i < configs.size(); ++i) {
    const Config& c = *configs[i];
    const Result& r = *results[i];
    std::vector<std::string> row = {c.lesson, c.scene};
    row.insert(row.end(), c.values.begin(), c.values.end());
    row.push_back(std::to_string(o.width));
    row.push_back(std::to_string(o.height));
    row.push_back(std::to_string(o.frames));
    row.push_back(std::to_string(r.rounds));
    row.push_back(number(r.frame_ms));
    row.push_back(number(r.frame_min_ms));
    row.push_back(number(r.cpu_ms));
    for (const auto& p : passes) {
      const auto it = r.pass_ms.find(p);
      row.push_back(it == r.pass_ms.end() ? "" : number(it->second));
    }
    for (const auto& p : passes) {
      const auto it = r.work.find(p);
      row.push_back(it == r.work.end() ? "" : std::to_string(it->second.draw_calls));
      row.push_back(it == r.work.end() ? "" : std::to_string(it->second.fragment_invocations));
    }
    for (const auto& name : counts) {
      const auto it = r.counts.find(name);
      row.push_back(it == r.counts.end() ? "" : std::to_string(it->second));
    }
    const bool e = r.error_valid;
    row.push_back(e ? number(r.error.false_shadow_pct) : "");
    row.push_back(e ? number(r.error.false_lit_pct) : "");
    row.push_back(e ? number(r.error.vis_mae) : "");
    row.push_back(e ? number(r.error.shade_mae) : "");
    row.push_back(e ? std::to_string(r.error.nonfinite_pixels) : "");
    row.push_back(e ? std::to_string(r.error.counted_pixels) : "");
    const bool air = e && r.error.air.valid;  // lesson 08's air light
    row.push_back(air ? number(r.error.air.mae) : "");
    row.push_back(air ? number(r.error.air.rel_rmse) : "");
    row.push_back(air ? number(r.error.air.truth_noise) : "");
    row.push_back(e ? r.error.truth : "");
    row.push_back(std::to_string(r.gl_errors));
    row.push_back(r.renderer);
    row.push_back(r.done ? "ok" : "failed: " + r.failure);
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

std::string csvLine(const std::vector<std::string>& fields) {
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csvField(fields[i]);
  }
  return line;
}

std::string toCsv(const Table& t) {
  std::string out = csvLine(t.header) + "\n";
  for (const auto& row : t.rows) out += csvLine(row) + "\n";
  return out;
}

std::string toJson(const Table& t, const std::string& lesson, const Options& o) {
  JsonWriter json;
  json.beginObject();
  json.value("lesson", lesson);
  json.beginArray("size");
  json.value("", o.width);
  json.value("", o.height);
  json.endArray();
  json.value("frames", o.frames);
  json.value("rounds", o.rounds);
  // Rows carry the CSV's columns under the same names; empty cells are null.
  json.beginArray("rows");
  for (const auto& row : t.rows) {
    json.beginObject();
    for (size_t i = 0; i < row.size(); ++i) {
      if (!t.numeric[i]) {
        json.value(t.header[i], row[i]);
      } else if (row[i].empty() || row[i] == "nan") {
        json.value(t.header[i], std::nan(""));
      } else {
        json.value(t.header[i], std::stod(row[i]));
      }
    }
    json.endObject();
  }
  json.endArray();
  json.endObject();
  return json.str() + "\n";
}

// Written next to the final name, then renamed: a reader never sees half a file.
bool writeFile(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) return false;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  return !ec;
}

std::string gnuplotString(const std::string& s) {
  std::string q = "'";  // single-quoted: only ' itself needs escaping, by doubling
  for (char ch : s) q += ch == '\'' ? std::string("''") : std::string(1, ch);
  return q + "'";
}

// The plot's data: one block per (scene, series), blocks separated by two blank lines so
// gnuplot's `index` picks them; rows along axes[0]. Returns the -e variables for plot.gp.
std::string writePlotData(const std::filesystem::path& path, const std::string& lesson,
                          const Sweep& sweep, const std::vector<const Config*>& configs,
                          const std::vector<const Result*>& results, const Options& o) {
  // Series = combinations of axes[1..] (every value, so colours stay stable across runs).
  std::vector<std::vector<size_t>> series(1);
  for (size_t a = 1; a < sweep.axes.size(); ++a) {
    std::vector<std::vector<size_t>> next;
    for (size_t v = 0; v < sweep.axes[a].values.size(); ++v) {
      for (const auto& s : series) {
        next.push_back(s);
        next.back().push_back(v);
      }
    }
    series = next;
  }
  // Log axes cannot show 0: an error below what one pixel can show is drawn at half a pixel,
  // the floor of what this image size can measure.
  auto floored = [](double v, double half_pixel) { return number(std::max(v, half_pixel)); };
  // axes[0] as a number for plot_along; 0 is drawn at half the smallest positive value so a
  // log axis can hold it.
  double smallest_positive = 1e300;
  for (const auto& v : sweep.axes[0].values) {
    const double x = std::strtod(settingsOf(sweep.axes[0], v).first.c_str(), nullptr);
    if (x > 0) smallest_positive = std::min(smallest_positive, x);
  }
  auto alongValue = [&](const std::string& label) {
    char* end = nullptr;
    const double x = std::strtod(label.c_str(), &end);
    if (end == label.c_str() || *end != '\0') return std::string("nan");
    return number(x > 0 ? x : 0.5 * smallest_positive);
  };
  std::ostringstream data;
  data << "# " << lesson
       << ": frame_ms cpu_ms frame_min_ms vis_mae false_shadow_pct false_lit_pct shade_mae "
       << sweep.axes[0].name << " (0 drawn as half a pixel)\n";
  std::string present;  // per scene, the series numbers that have points
  for (const auto& scene : sweep.scenes) {
    std::string here;
    for (size_t k = 0; k < series.size(); ++k) {
      data << "# " << scene << "\n";
      bool any = false;
      for (size_t i = 0; i < configs.size(); ++i) {
        const Config& c = *configs[i];
        const Result& r = *results[i];
        if (c.scene != scene || !r.done || !r.error_valid) continue;
        if (!std::equal(series[k].begin(), series[k].end(), c.value_index.begin() + 1)) continue;
        const ErrorMetrics& e = r.error;
        const double pixel = 1.0 / static_cast<double>(std::max(e.counted_pixels, 1LL));
        // A time that was not measured is missing, not 0, which no log axis can hold.
        auto time = [](double ms) { return ms > 0.0 ? number(ms) : std::string("nan"); };
        data << time(r.frame_ms) << " " << time(r.cpu_ms) << " " << time(r.frame_min_ms) << " "
             << floored(e.vis_mae, 0.5 * pixel) << " " << floored(e.false_shadow_pct, 50.0 * pixel)
             << " " << floored(e.false_lit_pct, 50.0 * pixel) << " "
             << floored(e.shade_mae, 0.5 * pixel) << " \"" << c.values[0] << "\" "
             << alongValue(c.values[0]) << " "
             << (e.air.valid ? number(100.0 * e.air.rel_rmse) : std::string("nan")) << " "
             << (e.air.valid ? number(e.air.mae) : std::string("nan")) << "\n";
        any = true;
      }
      // gnuplot does not count a block without records: keep every index in its place.
      if (!any) data << "nan nan nan nan nan nan nan \"\" nan nan nan\n";
      data << "\n\n";
      if (any) here += std::to_string(k + 1) + " ";
    }
    present += "\"" + here + "\" ";
  }
  if (!writeFile(path, data.str())) return {};

  // Titles, colours (by axes[1]) and dash types (by axes[2]) as word lists for plot.gp.
  std::string titles, colors, dashes, scenes;
  for (const auto& s : series) {
    std::string title;
    for (size_t a = 1; a < sweep.axes.size(); ++a) {
      if (a > 1) title += ' ';
      const std::string& axis = sweep.axes[a].name;
      title += axis.substr(axis.rfind('.') + 1) + "=" +
               settingsOf(sweep.axes[a], sweep.axes[a].values[s[a - 1]]).first;
    }
    titles += "\"" + (title.empty() ? lesson : title) + "\" ";
    colors += std::to_string(s.empty() ? 1 : s[0] + 1) + " ";
    dashes += std::to_string(s.size() < 2 ? 1 : s[1] + 1) + " ";
  }
  for (const auto& scene : sweep.scenes) scenes += scene + " ";
  // The data columns above, and an axis label for each.
  static const std::map<std::string, std::pair<int, std::string>> metric_columns = {
      {"vis_mae", {4, "vis_mae: mean |visibility - truth|"}},
      {"false_shadow_pct", {5, "false shadow: % of counted pixels"}},
      {"false_lit_pct", {6, "false lit: % of counted pixels"}},
      {"shade_mae", {7, "shade_mae: mean |vis - truth| x N.L"}},
      {"air_rel_rmse_pct", {10, "air light: relative RMSE against the truth, %"}},
      {"air_mae", {11, "air light: mean |rendered - truth|"}}};
  std::string ycols, ylabels;
  for (const auto& metric : sweep.plot_metrics) {
    const auto it = metric_columns.find(metric);
    if (it == metric_columns.end()) return {};
    ycols += std::to_string(it->second.first) + " ";
    ylabels += "\"" + it->second.second + "\" ";
  }
  char size[64];
  std::snprintf(size, sizeof size, "%dx%d, %d round%s x %d frame%s", o.width, o.height, o.rounds,
                o.rounds == 1 ? "" : "s", o.frames, o.frames == 1 ? "" : "s");
  const int xcol = sweep.plot_along ? 9 : o.plot_x == "cpu" ? 2 : o.plot_x == "min" ? 3 : 1;
  const std::string xlabel = xcol == 9   ? sweep.axes[0].name + " (0 drawn at the left edge)"
                             : xcol == 2 ? "CPU time per frame, all threads, ms"
                             : xcol == 3 ? "frame time, ms (fastest frame)"
                                         : "frame time, ms (median)";
  return "data=" + gnuplotString(path.string()) + "; xcol=" + std::to_string(xcol) +
         "; xlabel=" + gnuplotString(xlabel) + "; scenes=" + gnuplotString(scenes) +
         "; nseries=" + std::to_string(series.size()) + "; titles=" + gnuplotString(titles) +
         "; present=" + gnuplotString(present) + "; colors=" + gnuplotString(colors) +
         "; dashes=" + gnuplotString(dashes) + "; along=" + gnuplotString(sweep.axes[0].name) +
         "; ycols=" + gnuplotString(ycols) + "; ylabels=" + gnuplotString(ylabels) +
         "; title=" + gnuplotString(lesson + " (" + size + ", " + results.front()->renderer + ")");
}

// 0 plotted, 1 gnuplot failed, -1 no gnuplot (a note, not a failure). gnuplot's chatter goes
// to `log`, shown only when it fails.
int runGnuplot(const std::string& variables, const std::filesystem::path& png,
               const std::filesystem::path& log) {
  const std::string script = std::string(BENCH_DIR) + "/plot.gp";
  // Drawn next to the final name and renamed, so a failed plot leaves no stale or half picture.
  const std::filesystem::path temporary = png.string() + ".partial";
  std::error_code ec;
  std::filesystem::remove(png, ec);
  const std::string e = variables + "; out=" + gnuplotString(temporary.string());
  std::vector<std::string> args = {"gnuplot", "-e", e, script};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    std::filesystem::rename(temporary, png, ec);
    return ec ? 1 : 0;
  }
  std::filesystem::remove(temporary, ec);
  std::ifstream in(log);
  std::cerr << in.rdbuf();
  return 1;
}

// ---- Checks (every run; --smoke also re-reads what was written) ------------------------------

std::vector<std::string> checkResults(const std::vector<const Config*>& configs,
                                      const std::vector<const Result*>& results) {
  // The passes every configuration of a lesson ran (some skip one on purpose: no readback
  // without a copy), each of which must have a time; and every time present must be > 0.
  std::map<std::string, std::set<std::string>> passes;
  std::set<std::string> seen;
  for (size_t i = 0; i < configs.size(); ++i) {
    if (!results[i]->done) continue;
    std::set<std::string> here;
    for (const auto& [p, ms] : results[i]->pass_ms) here.insert(p);
    const std::string& lesson = configs[i]->lesson;
    if (seen.insert(lesson).second) {
      passes[lesson] = here;
    } else {
      std::erase_if(passes[lesson], [&](const std::string& p) { return !here.contains(p); });
    }
  }
  std::vector<std::string> problems;
  for (size_t i = 0; i < configs.size(); ++i) {
    const Result& r = *results[i];
    const std::string who = configs[i]->lesson + " " + configs[i]->label() + ": ";
    if (!r.done) {
      problems.push_back(who + "failed: " + r.failure);
      continue;
    }
    if (r.gl_errors > 0) problems.push_back(who + std::to_string(r.gl_errors) + " GL error(s)");
    if (!(r.frame_ms > 0.0) || !std::isfinite(r.frame_ms)) {
      problems.push_back(who + "frame_ms " + number(r.frame_ms));
    }
    for (const auto& p : passes[configs[i]->lesson]) {
      if (!r.pass_ms.contains(p)) problems.push_back(who + "no pass_ms." + p);
    }
    for (const auto& [p, ms] : r.pass_ms) {
      if (!(ms > 0.0)) problems.push_back(who + "pass_ms." + p + " " + number(ms));
    }
    const ErrorMetrics& e = r.error;
    if (!r.error_valid || e.counted_pixels <= 0) {
      problems.push_back(who + "no error metrics");
    } else {
      if (e.nonfinite_pixels > 0) {
        problems.push_back(who + std::to_string(e.nonfinite_pixels) + " non-finite pixel(s)");
      }
      for (double v : {e.false_shadow_pct, e.false_lit_pct, e.vis_mae, e.shade_mae}) {
        if (!std::isfinite(v) || v < 0.0) problems.push_back(who + "a metric is " + number(v));
      }
    }
  }
  return problems;
}

std::vector<std::string> checkFiles(const std::filesystem::path& csv,
                                    const std::filesystem::path& json, const Table& t) {
  std::vector<std::string> problems;
  std::ifstream in(csv);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  if (lines.empty() || lines[0] != csvLine(t.header)) {
    problems.push_back(csv.string() + ": missing or unexpected header");
  }
  if (lines.size() != t.rows.size() + 1) {
    problems.push_back(csv.string() + ": " + std::to_string(lines.size()) + " lines, expected " +
                       std::to_string(t.rows.size() + 1));
  }
  for (const char* required : {"lesson", "scene", "frame_ms", "false_shadow_pct", "false_lit_pct",
                               "vis_mae", "shade_mae", "nonfinite_pixels", "gl_errors"}) {
    if (std::find(t.header.begin(), t.header.end(), required) == t.header.end()) {
      problems.push_back(csv.string() + ": no column " + required);
    }
  }
  std::ifstream jin(json);
  const std::string text((std::istreambuf_iterator<char>(jin)), std::istreambuf_iterator<char>());
  size_t rows = 0;
  for (size_t at = text.find("\"frame_ms\""); at != std::string::npos;
       at = text.find("\"frame_ms\"", at + 1)) {
    ++rows;
  }
  if (text.empty() || text.front() != '{' || rows != t.rows.size()) {
    problems.push_back(json.string() + ": " + std::to_string(rows) + " rows, expected " +
                       std::to_string(t.rows.size()));
  }
  return problems;
}

// ---- Command line --------------------------------------------------------------------------

const char* kUsage =
    "usage: bench_sweep [--lesson NAME | --all] [--out-dir DIR] [--size WxH] [--frames N]\n"
    "                   [--rounds R] [--smoke] [--quick] [--plot-x cpu|min|median] [--no-plot]\n"
    "                   [--benchmark_... flags]\n"
    "  --lesson NAME  the lesson to sweep (default 03_shadow_map_basic); --all: every lesson\n"
    "                 with a sweep\n"
    "  --out-dir DIR  where <lesson>.csv, .json and .png go (default bench/results)\n"
    "  --size WxH     render size (default 640x480; --smoke: 160x120)\n"
    "  --frames N     timed frames per round after one warm-up (default 5; --smoke 1; --quick 3)\n"
    "  --rounds R     visits per configuration, in shuffled order; the CSV has the median over\n"
    "                 all R x N frames (default 3; --smoke, --quick 1)\n"
    "  --smoke        three tiny configurations per lesson; exit 1 on any problem (a CTest)\n"
    "  --quick        every other value along each series, one round of 3 frames\n"
    "  --plot-x cpu|min|median  the plot's time: process CPU time per frame, all threads\n"
    "                 (default: the least disturbed by other jobs), or the fastest or the median\n"
    "                 frame's wall time\n"
    "  --no-plot      skip gnuplot\n"
    "Google Benchmark's own flags (e.g. --benchmark_filter=cubes) are passed through.\n";

// Returns "" or what was wrong (exit 2).
std::string parse(int argc, char** argv, Options& o, bool& all) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto next = [&](std::string& value) {
      if (i + 1 >= argc) return false;
      value = argv[++i];
      return true;
    };
    std::string v;
    if (arg == "--lesson") {
      if (!next(v)) return "--lesson needs a name";
      o.lessons.push_back(v);
    } else if (arg == "--all") {
      all = true;
    } else if (arg == "--out-dir") {
      if (!next(v) || v.empty()) return "--out-dir needs a directory";
      o.out_dir = v;
    } else if (arg == "--size") {
      int w = 0, h = 0;
      char tail = 0;
      if (!next(v) || std::sscanf(v.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 ||
          w > 8192 || h > 8192) {
        return "--size wants WxH with 16 <= W, H <= 8192, e.g. 640x480 (got '" + v + "')";
      }
      o.width = w, o.height = h, o.size_given = true;
    } else if (arg == "--frames") {
      int n = 0;
      char tail = 0;
      if (!next(v) || std::sscanf(v.c_str(), "%d%c", &n, &tail) != 1 || n < 1 || n > 10000) {
        return "--frames wants an integer in [1, 10000] (got '" + v + "')";
      }
      o.frames = n, o.frames_given = true;
    } else if (arg == "--rounds") {
      int n = 0;
      char tail = 0;
      if (!next(v) || std::sscanf(v.c_str(), "%d%c", &n, &tail) != 1 || n < 1 || n > 100) {
        return "--rounds wants an integer in [1, 100] (got '" + v + "')";
      }
      o.rounds = n, o.rounds_given = true;
    } else if (arg == "--smoke") {
      o.smoke = true;
    } else if (arg == "--quick") {
      o.quick = true;
    } else if (arg == "--plot-x") {
      if (!next(v) || (v != "median" && v != "min" && v != "cpu")) {
        return "--plot-x wants cpu, min or median (got '" + v + "')";
      }
      o.plot_x = v;
    } else if (arg == "--no-plot") {
      o.plot = false;
    } else {
      return "unknown argument '" + arg + "' (see --help)";
    }
  }
  if (all && !o.lessons.empty()) return "--all and --lesson exclude each other";
  if (o.smoke && o.quick) return "--smoke and --quick exclude each other";
  if (o.smoke && !o.size_given) o.width = 160, o.height = 120;
  if (!o.frames_given) o.frames = o.smoke ? 1 : o.quick ? 3 : 5;
  if (!o.rounds_given) o.rounds = o.smoke || o.quick ? 1 : 3;
  return {};
}

// Whether the library's --benchmark_filter (a regular expression, "-" in front negates) lets a
// benchmark through; approximate (std::regex, not the library's), and true when in doubt.
bool passesFilter(const std::string& name) {
  std::string filter = benchmark::GetBenchmarkFilter();
  if (filter.empty() || filter == "all") return true;
  const bool negative = filter.front() == '-';
  if (negative) filter.erase(0, 1);
  try {
    return std::regex_search(name, std::regex(filter, std::regex::extended)) != negative;
  } catch (const std::regex_error&) {
    return true;
  }
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

int sweepMain(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::printf("%s", kUsage);
      return 0;
    }
  }
  // Rounds of different configurations are shuffled, so a burst of load on this shared machine
  // spreads over all of them instead of bending one series. Flags the user gives come later
  // and win.
  std::vector<char*> args(argv, argv + argc);
  std::string interleave = "--benchmark_enable_random_interleaving=true";
  args.insert(args.begin() + 1, interleave.data());
  int count = static_cast<int>(args.size());
  args.push_back(nullptr);
  benchmark::Initialize(&count, args.data());  // takes its --benchmark_* flags out of args
  argc = count;
  argv = args.data();
  Options o;
  bool all = false;
  if (std::string e = parse(argc, argv, o, all); !e.empty()) {
    std::fprintf(stderr, "bench_sweep: %s\n", e.c_str());
    return 2;
  }
  const auto registered = registeredLessons();
  std::vector<std::string> with_sweep;
  for (const auto& [name, sweep] : sweeps()) {
    if (sweep.study || std::find(registered.begin(), registered.end(), name) != registered.end()) {
      with_sweep.push_back(name);
    }
  }
  if (all) o.lessons = with_sweep;
  if (o.lessons.empty()) o.lessons = {"03_shadow_map_basic"};
  for (const auto& lesson : o.lessons) {
    if (std::find(with_sweep.begin(), with_sweep.end(), lesson) == with_sweep.end()) {
      std::fprintf(stderr, "bench_sweep: no sweep for lesson '%s'; lessons with one: %s\n",
                   lesson.c_str(), joined(with_sweep).c_str());
      return 2;
    }
  }
  // Fail on an unwritable directory now, not after minutes of rendering.
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  const auto probe = o.out_dir / ".bench_sweep_probe";
  if (ec || !std::ofstream(probe)) {
    std::fprintf(stderr, "bench_sweep: cannot write into %s\n", o.out_dir.string().c_str());
    return 2;
  }
  std::filesystem::remove(probe, ec);

  std::vector<Config> configs;
  for (const auto& lesson : o.lessons) {
    auto c = expand(lesson, sweeps().at(lesson), o);
    configs.insert(configs.end(), c.begin(), c.end());
  }
  Bench bench(o, configs);
  std::map<std::string, size_t> index_of;
  size_t expected = 0;
  for (size_t i = 0; i < configs.size(); ++i) {
    // The library's "family/arg:value" convention, axis names without their prefix ("size:512"),
    // to keep the console table narrow.
    std::string name = configs[i].sweep + "/" + configs[i].scene;
    for (size_t a = 0; a < configs[i].values.size(); ++a) {
      const std::string& axis = configs[i].axis_names[a];
      name += "/" + axis.substr(axis.rfind('.') + 1) + ":" + configs[i].values[a];
    }
    index_of[name] = i;
    if (passesFilter(name)) ++expected;
    benchmark::RegisterBenchmark(name.c_str(),
                                 [&bench, i](benchmark::State& state) { bench.run(state, i); })
        ->Iterations(o.frames)
        ->Repetitions(o.rounds)
        ->UseManualTime()
        ->MeasureProcessCPUTime()  // llvmpipe rasterizes on worker threads
        ->Unit(benchmark::kMillisecond);
  }

  bench.setExpected(expected);

  const auto start = std::chrono::steady_clock::now();
  const bool color = isatty(STDOUT_FILENO) != 0;
  Reporter reporter(
      bench, index_of,
      color ? benchmark::ConsoleReporter::OO_ColorTabular : benchmark::ConsoleReporter::OO_Tabular);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  bench.endProgress();
  bench.closeRunner();
  benchmark::Shutdown();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  int status = 0;
  for (const auto& lesson : o.lessons) {
    // The configurations that ran (a --benchmark_filter may have skipped some).
    std::vector<const Config*> cs;
    std::vector<const Result*> rs;
    for (size_t i = 0; i < configs.size(); ++i) {
      const Result& r = bench.results()[i];
      if (configs[i].sweep == lesson && (r.done || !r.failure.empty())) {
        cs.push_back(&configs[i]);
        rs.push_back(&r);
      }
    }
    if (cs.empty()) continue;
    const Table table = makeTable(cs, rs, o);
    const auto csv = o.out_dir / (lesson + ".csv");
    const auto json = o.out_dir / (lesson + ".json");
    const auto png = o.out_dir / (lesson + ".png");
    if (!writeFile(csv, toCsv(table)) || !writeFile(json, toJson(table, lesson, o))) {
      std::fprintf(stderr, "bench_sweep: cannot write %s\n", csv.string().c_str());
      return 1;
    }
    std::vector<std::string> problems = checkResults(cs, rs);
    if (o.smoke) {
      auto file_problems = checkFiles(csv, json, table);
      problems.insert(problems.end(), file_problems.begin(), file_problems.end());
    }
    std::string plotted;
    if (o.plot && std::any_of(rs.begin(), rs.end(), [](const Result* r) { return r->done; })) {
      const auto dat = o.out_dir / (lesson + ".plot.dat");
      const std::string vars = writePlotData(dat, lesson, sweeps().at(lesson), cs, rs, o);
      const auto log = o.out_dir / (lesson + ".plot.log");
      const int plot = vars.empty() ? 1 : runGnuplot(vars, png, log);
      if (plot < 0) {
        std::fprintf(stderr,
                     "bench_sweep: note: gnuplot not found, no plot (apt install "
                     "gnuplot-nox); the CSV and JSON are complete\n");
      } else if (plot > 0) {
        problems.push_back("no plot: gnuplot or plot.gp failed on " + dat.string());
      } else {
        plotted = ", " + png.string();
      }
    }
    std::fprintf(stderr, "%s: %zu configurations -> %s, %s%s\n", lesson.c_str(), cs.size(),
                 csv.string().c_str(), json.string().c_str(), plotted.c_str());
    for (const auto& p : problems) std::fprintf(stderr, "bench_sweep: FAIL %s\n", p.c_str());
    if (!problems.empty()) status = 1;
  }
  const bool ran = std::any_of(bench.results().begin(), bench.results().end(),
                               [](const Result& r) { return r.done || !r.failure.empty(); });
  if (!ran) {
    std::fprintf(stderr, "bench_sweep: no configuration ran (see --benchmark_filter)\n");
    status = 1;
  }
  std::fprintf(stderr, "bench_sweep: %.1f s\n", seconds);
  return status;
}

}  // namespace
}  // namespace shadows

int main(int argc, char** argv) {
  return shadows::sweepMain(argc, argv);
}
