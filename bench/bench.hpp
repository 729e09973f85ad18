// bench_sweep's engine, private to bench/: what it runs (Config), what it measured (Result), and
// the files that hold each step. The sweeps themselves are data: every lesson's in
// NN_name/sweep.cpp (common/lesson/sweep_spec.hpp), the studies across lessons in studies.cpp.
//
//   sweep_main.cpp  command line, main(): which sweeps, the benchmarks, the files per sweep
//   configs.cpp     a sweep -> its configurations; the catalogue of sweeps; --set checks
//   run.cpp         Bench (one round of one configuration), Reporter (the console table)
//   tables.cpp      the CSV/JSON table, writing files, the checks on results and files
//   front.cpp       the table as CSV, read back; its Pareto fronts (front.hpp)
//   plot.cpp        the plots' data, label placement and gnuplot (plot.gp, plot_along.gp)
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "front.hpp"
#include "lesson/sweep_spec.hpp"
#include "run/runner.hpp"

namespace shadows::bench {

struct Options {
  std::vector<std::string> lessons;
  std::filesystem::path out_dir = "bench/results";
  int width = 640, height = 480, frames = 5, rounds = 3;
  bool frames_given = false, size_given = false, rounds_given = false;
  bool smoke = false, quick = false, plot = true;
  // The plot's time. CPU time per frame by default: on the shared 2-core machine other jobs
  // stretch wall times (median or fastest frame) 2-3x more than CPU times (see README.md).
  std::string plot_x = "cpu";
  // --set name=value from the command line, after every configuration's own settings.
  std::vector<std::string> sets;
  // --replot: run nothing, mark and plot this CSV.
  std::filesystem::path replot;
  // --backend, --device: the headless context (common/gl/context.hpp); empty: the default.
  std::string backend;
  int device = 0;
};

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
  std::optional<double> undersampled_pct;        // lessons with a map (texel_density.hpp)
  std::map<std::string, double> report_numbers;  // Sweep::report_numbers, from the report
  int gl_errors = 0;
  std::string renderer;
};

// ---- configs.cpp, studies.cpp

// The studies across lessons (studies.cpp), by name.
std::map<std::string, Sweep> studies();
// Every sweep this program can run: the linked lessons' and the studies, by name.
const std::map<std::string, Sweep>& allSweeps();
// "" or why --set `sets` cannot go with this sweep: a name or value the rendering lesson's
// Params::assign refuses, or a parameter an axis (or the scene) already varies.
std::string checkSets(const std::string& name, const Sweep& sweep,
                      const std::vector<std::string>& sets);
// scenes x axes (thinned by --quick, three by --smoke), axes[0] fastest.
std::vector<Config> expand(const std::string& name, const Sweep& sweep, const Options& o);
// What row `row` of a sweep's table sets: its axes' settings, bundles expanded ("lesson=NAME"
// included for a study).
std::vector<std::string> rowSettings(const Sweep& sweep, const Table& t, size_t row);
// Adds `settings` (what each row sets, in its lesson's parameter names; a study's in its own
// axis=label words) and `is_default` (1 where every setting the axes make is the rendering
// lesson's default). Returns, for a lesson's sweep, the lesson's defaults of every parameter
// the axes set ("pcf.mode=dithered pcf.taps=16 ..."), for the plot's key.
std::string describeConfigs(Table& t, const std::string& name, const Sweep& sweep);

// ---- run.cpp

class Bench {
 public:
  Bench(Options options, std::vector<Config> configs);

  std::vector<Result>& results() { return results_; }
  // One round of one configuration: a warm-up frame, then `frames` timed frames. The truth is
  // measured once per configuration, outside the timing loop.
  void run(benchmark::State& state, size_t index);
  // The benchmark library's mean process CPU time per frame over the rounds.
  void setCpuMs(size_t index, double cpu_ms) { results_[index].cpu_ms = cpu_ms; }

  void progress(size_t index);
  // The console table scrolls above; the progress line stays at the bottom of a terminal.
  void clearProgress() const;
  void redrawProgress() const;
  void endProgress() const;

  void closeRunner() { runner_.reset(); }
  // How many configurations --benchmark_filter lets through, for the progress count.
  void setExpected(size_t n) { expected_ = n; }

 private:
  Runner& runnerFor(const std::string& lesson);
  void fail(benchmark::State& state, size_t index, const std::string& why);

  Options options_;
  std::vector<Config> configs_;
  std::vector<Result> results_;
  std::unique_ptr<Runner> runner_;
  std::string runner_lesson_, renderer_;
  size_t runs_done_ = 0, expected_ = configs_.size();
  bool tty_;
  std::string last_line_;
};

// The library's console table on stdout, one row per configuration (the median over its rounds),
// with our progress line kept below it; and the CPU time per frame for the CSV.
class Reporter : public benchmark::ConsoleReporter {
 public:
  Reporter(Bench& bench, std::map<std::string, size_t> index_of, OutputOptions options)
      : ConsoleReporter(options), bench_(bench), index_of_(std::move(index_of)) {}
  // The library calls this once per configuration, after its last round.
  void ReportRuns(const std::vector<Run>& runs) override;

 private:
  Bench& bench_;
  std::map<std::string, size_t> index_of_;
};

// ---- tables.cpp

std::string number(double v);  // "%.6g", "nan" for what is not finite
// Columns: lesson, scene, each axis, size and frames, timings, work, error, renderer, machine.
Table makeTable(const std::vector<const Config*>& configs,
                const std::vector<const Result*>& results, const Options& o);
std::string toJson(const Table& t, const std::string& lesson, const Options& o);
// Written next to the final name, then renamed: a reader never sees half a file.
bool writeFile(const std::filesystem::path& path, const std::string& text);
// Checks of every run; --smoke also re-reads what was written (checkFiles).
std::vector<std::string> checkResults(const std::vector<const Config*>& configs,
                                      const std::vector<const Result*>& results);
std::vector<std::string> checkFiles(const std::filesystem::path& csv,
                                    const std::filesystem::path& json, const Table& t);

// ---- plot.cpp

// From a table marked by describeConfigs and markFronts: <name>.png and <name>.svg (error
// against time with the front; plot.gp), and <name>_along.png for a plot_along sweep
// (plot_along.gp), each with its .plot.dat; gnuplot's messages in <name>.plot.log. `defaults`
// is describeConfigs' answer, `sets` bench_sweep's --set. 0 plotted (the files appended to
// `written`), 1 failed, -1 no gnuplot (a note, not a failure).
int plotSweep(const std::string& name, const Sweep& sweep, const Table& t,
              const std::string& defaults, const std::vector<std::string>& sets,
              const std::filesystem::path& out_dir, std::vector<std::filesystem::path>& written);

}  // namespace shadows::bench
