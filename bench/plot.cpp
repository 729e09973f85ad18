// The plot: its data file (one block per scene and series) and gnuplot with plot.gp.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bench.hpp"

#ifndef BENCH_DIR
#error "BENCH_DIR (the directory of plot.gp) must be defined by the build"
#endif

extern char** environ;

namespace shadows::bench {
namespace {

std::string gnuplotString(const std::string& s) {
  std::string q = "'";  // single-quoted: only ' itself needs escaping, by doubling
  for (char ch : s) q += ch == '\'' ? std::string("''") : std::string(1, ch);
  return q + "'";
}

}  // namespace

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

}  // namespace shadows::bench
