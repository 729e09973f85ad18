// bench_sweep: the time-vs-error benchmark. For one lesson (or all that have a sweep) it renders
// every configuration of a sweep (scenes x the Cartesian product of parameter axes) headless,
// times N frames after a warm-up, measures the error against the ray-traced truth, and writes
// DIR/<lesson>.csv, DIR/<lesson>.json and gnuplot plots of error against time with the Pareto
// front, DIR/<lesson>.png and .svg. --replot draws them again from a CSV.
//
// Google Benchmark drives the runs: one registered benchmark per configuration with a fixed
// iteration count (= frames) and manual time (= the runner's glFinish-bracketed frame time), the
// error metrics as counters. Warm-up and the truth happen outside the timing loop.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>

#include "bench.hpp"
#include "core/arguments.hpp"
#include "core/text.hpp"
#include "gl/context.hpp"

namespace shadows::bench {
namespace {

const char* kUsage =
    "usage: bench_sweep [--lesson NAME | --all] [--out-dir DIR] [--size WxH] [--frames N]\n"
    "                   [--rounds R] [--smoke] [--quick] [--plot-x cpu|min|median] [--no-plot]\n"
    "                   [--set name=value ...] [--benchmark_... flags]\n"
    "       bench_sweep [--lesson NAME] --replot FILE.csv [--out-dir DIR] [--plot-x ...]\n"
    "  --lesson NAME  the lesson to sweep (default 03_shadow_map_basic); --all: every lesson\n"
    "                 with a sweep\n"
    "  --out-dir DIR  where <lesson>.csv, .json, .png and .svg go (default bench/results)\n"
    "  --size WxH     render size (default 640x480; --smoke: 160x120)\n"
    "  --frames N     timed frames per round after one warm-up (default 5; --smoke 1; --quick 3)\n"
    "  --rounds R     visits per configuration, in shuffled order; the CSV has the median over\n"
    "                 all R x N frames (default 3; --smoke, --quick 1)\n"
    "  --smoke        three tiny configurations per lesson; exit 1 on any problem (a CTest)\n"
    "  --quick        every other value along each series, one round of 3 frames\n"
    "  --plot-x cpu|min|median  the plot's time: process CPU time per frame, all threads\n"
    "                 (default: the least disturbed by other jobs), or the fastest or the median\n"
    "                 frame's wall time\n"
    "  --set name=value  a lesson parameter for every configuration (repeatable), as the\n"
    "                 lessons' --set takes it; checked against every lesson the sweep renders\n"
    "  --backend NAME, --device N  the headless context, as the lessons take them (a GPU\n"
    "                 without a display: --backend egl-device --device N)\n"
    "  --no-plot      skip gnuplot\n"
    "  --replot FILE  run nothing: mark the fronts of a CSV bench_sweep wrote and plot it into\n"
    "                 DIR (the sweep: --lesson, else the CSV's lesson column)\n"
    "Google Benchmark's own flags (e.g. --benchmark_filter=cubes) are passed through.\n";

// Returns "" or what was wrong (exit 2). --size, --frames, --rounds and --set read and say
// what is wrong as the lessons' own command line does (common/core/arguments.hpp).
std::string parse(int argc, char** argv, Options& o, bool& all) {
  bool device_given = false;
  for (Arguments args(argc, argv); args.next();) {
    const std::string& arg = args.flag();
    std::string v, why;
    if (arg == "--lesson") {
      if (!args.value(v)) return "--lesson needs a name";
      o.lessons.push_back(v);
    } else if (arg == "--all") {
      all = true;
    } else if (arg == "--out-dir") {
      if (!args.value(v) || v.empty()) return "--out-dir needs a directory";
      o.out_dir = v;
    } else if (arg == "--size") {
      why = readSize(args, o.width, o.height, 16);
      o.size_given = true;
    } else if (arg == "--frames") {
      why = readCount(args, o.frames, 10000);
      o.frames_given = true;
    } else if (arg == "--rounds") {
      why = readCount(args, o.rounds, 100);
      o.rounds_given = true;
    } else if (arg == "--set") {
      why = readSet(args, o.sets);
    } else if (arg == "--smoke") {
      o.smoke = true;
    } else if (arg == "--quick") {
      o.quick = true;
    } else if (arg == "--plot-x") {
      if (!args.value(v) || (v != "median" && v != "min" && v != "cpu")) {
        return "--plot-x wants cpu, min or median (got '" + v + "')";
      }
      o.plot_x = v;
    } else if (arg == "--backend") {
      args.value(v);
      if (why = checkBackend(v); why.empty()) o.backend = v;
    } else if (arg == "--device") {
      why = readIndex(args, o.device, 63);
      device_given = true;
    } else if (arg == "--no-plot") {
      o.plot = false;
    } else if (arg == "--replot") {
      if (!args.value(v) || v.empty()) return "--replot needs a CSV file";
      o.replot = v;
    } else {
      return unknownOption(arg);
    }
    if (!why.empty()) return why;
  }
  if (all && !o.lessons.empty()) return "--all and --lesson exclude each other";
  if (device_given && o.backend != "egl-device") {
    return "--device chooses an EGL device: it needs --backend egl-device";
  }
  if (o.smoke && o.quick) return "--smoke and --quick exclude each other";
  if (!o.replot.empty() && (all || o.smoke || o.quick || !o.sets.empty() || o.lessons.size() > 1)) {
    return "--replot draws one CSV as it is: not with --all, --smoke, --quick, --set or a "
           "second --lesson";
  }
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

// The files of one sweep from its table: the front and the default marked into it (both
// readers, the plot and bench/tables.py, take them from there), the CSV and the JSON, the plots.
// Returns what went wrong; `table` keeps the columns added.
std::vector<std::string> finishSweep(const std::string& name, Table& table, const Options& o) {
  const Sweep& sweep = allSweeps().at(name);
  const std::string defaults = describeConfigs(table, name, sweep);
  std::vector<std::string> axes;
  for (const Axis& axis : sweep.axes) axes.push_back(axis.name);
  const std::string time_column = o.plot_x == "cpu"   ? "cpu_ms"
                                  : o.plot_x == "min" ? "frame_min_ms"
                                                      : "frame_ms";
  markFronts(table, time_column, sweep.plot_metrics, axes);
  const auto csv = o.out_dir / (name + ".csv");
  const auto json = o.out_dir / (name + ".json");
  if (!writeFile(csv, toCsv(table)) || !writeFile(json, toJson(table, name, o))) {
    return {"cannot write " + csv.string()};
  }
  std::vector<std::string> problems;
  if (o.smoke) problems = checkFiles(csv, json, table);
  std::string written = csv.string() + ", " + json.string();
  const bool any_ok = std::any_of(table.rows.begin(), table.rows.end(), [&](const auto& row) {
    return row[static_cast<size_t>(table.column("status"))] == "ok";
  });
  if (o.plot && any_ok) {
    std::vector<std::filesystem::path> plots;
    const int plot = plotSweep(name, sweep, table, defaults, o.sets, o.out_dir, plots);
    for (const auto& p : plots) written += ", " + p.string();
    if (plot < 0) {
      std::fprintf(stderr,
                   "bench_sweep: note: gnuplot not found, no plot (apt install "
                   "gnuplot-nox); the CSV and JSON are complete\n");
    } else if (plot > 0) {
      problems.push_back("no plot: gnuplot or a plot script failed, see " +
                         (o.out_dir / (name + ".plot.log")).string());
    }
  }
  std::fprintf(stderr, "%s: %zu configurations -> %s\n", name.c_str(), table.rows.size(),
               written.c_str());
  return problems;
}

// --replot: the sweep's files again from a CSV it wrote, nothing rendered.
int replot(Options o) {
  Table table;
  if (std::string e = readCsv(o.replot, table); !e.empty()) {
    std::fprintf(stderr, "bench_sweep: %s\n", printable(e).c_str());
    return 2;
  }
  if (table.rows.empty() || table.column("status") < 0 || table.column("scene") < 0) {
    std::fprintf(stderr, "bench_sweep: %s: not a CSV bench_sweep wrote\n",
                 printable(o.replot.string()).c_str());
    return 2;
  }
  const std::string name = o.lessons.empty() ? table.cell(0, "lesson") : o.lessons.front();
  if (!allSweeps().contains(name)) {
    std::fprintf(stderr, "bench_sweep: no sweep '%s' (a study's CSV needs --lesson NAME)\n",
                 printable(name).c_str());
    return 2;
  }
  // The run's size and samples, for the JSON, from the CSV.
  auto count = [&](const char* column, int fallback) {
    const double v = table.value(0, column);
    return std::isfinite(v) ? static_cast<int>(v) : fallback;
  };
  o.width = count("width", o.width);
  o.height = count("height", o.height);
  o.frames = count("frames", o.frames);
  o.rounds = count("rounds", o.rounds);
  const auto problems = finishSweep(name, table, o);
  for (const auto& p : problems) std::fprintf(stderr, "bench_sweep: FAIL %s\n", p.c_str());
  return problems.empty() ? 0 : 1;
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
    std::fprintf(stderr, "bench_sweep: %s\n", printable(e).c_str());
    return 2;
  }
  int exit_code = 0;
  if (std::string e = headlessProblem(o.backend, o.device, exit_code); !e.empty()) {
    std::fprintf(stderr, "bench_sweep: %s\n", printable(e).c_str());
    return exit_code;
  }
  std::vector<std::string> with_sweep;
  for (const auto& [name, sweep] : allSweeps()) with_sweep.push_back(name);
  if (all) o.lessons = with_sweep;
  if (o.lessons.empty() && o.replot.empty()) o.lessons = {"03_shadow_map_basic"};
  for (const auto& lesson : o.lessons) {
    if (std::find(with_sweep.begin(), with_sweep.end(), lesson) == with_sweep.end()) {
      std::fprintf(stderr, "bench_sweep: no sweep for lesson '%s'; lessons with one: %s\n",
                   printable(lesson).c_str(), joined(with_sweep).c_str());
      return 2;
    }
    // A bad --set stops here, before anything is rendered, with the runner's own message.
    if (std::string e = checkSets(lesson, allSweeps().at(lesson), o.sets); !e.empty()) {
      std::fprintf(stderr, "bench_sweep: %s\n", printable(e).c_str());
      return 2;
    }
  }
  // Fail on an unwritable directory now, not after minutes of rendering.
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  const auto probe = o.out_dir / ".bench_sweep_probe";
  if (ec || !std::ofstream(probe)) {
    std::fprintf(stderr, "bench_sweep: cannot write into %s\n",
                 printable(o.out_dir.string()).c_str());
    return 2;
  }
  std::filesystem::remove(probe, ec);
  if (!o.replot.empty()) return replot(o);

  std::vector<Config> configs;
  for (const auto& lesson : o.lessons) {
    auto c = expand(lesson, allSweeps().at(lesson), o);
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
    Table table = makeTable(cs, rs, o);
    std::vector<std::string> problems = checkResults(cs, rs);
    const auto more = finishSweep(lesson, table, o);
    problems.insert(problems.end(), more.begin(), more.end());
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
}  // namespace shadows::bench

int main(int argc, char** argv) {
  return shadows::bench::sweepMain(argc, argv);
}
