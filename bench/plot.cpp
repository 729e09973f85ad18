// The plots, drawn from the table (so a CSV can be replotted): error against time with the
// Pareto front (front.cpp) as a PNG and an SVG whose points show their settings on hover
// (plot.gp), and for a sweep plotted along a knob also error against that knob
// (plot_along.gp). Panels, ranges and every label's position are decided here, in pixels, so
// that labels can be kept apart; the scripts only draw.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "bench.hpp"

#ifndef BENCH_DIR
#error "BENCH_DIR (the directory of plot.gp) must be defined by the build"
#endif

extern char** environ;

namespace shadows::bench {
namespace {

// pngcairo's DejaVu Sans at 9 pt, measured: 6.4 px a letter to 7.1 px a digit, 12 px high.
constexpr double kCharPx = 7.0, kLinePx = 14.0;
constexpr size_t kLabelChars = 34;    // a label wraps between settings beyond this
constexpr double kMaxLeader = 160.0;  // px: a longer leader line is harder to follow than none

std::string gnuplotString(const std::string& s) {
  std::string q = "'";  // single-quoted: only ' itself needs escaping, by doubling
  for (char ch : s) q += ch == '\'' ? std::string("''") : std::string(1, ch);
  return q + "'";
}

// Double-quoted, so that a line break can be written as \n.
std::string gnuplotText(const std::string& s) {
  std::string q = "\"";
  for (char ch : s) {
    q += ch == '\n'                ? std::string("\\n")
         : ch == '"' || ch == '\\' ? std::string("\\") + ch
                                   : std::string(1, ch);
  }
  return q + "\"";
}

// A quoted string in the data file: line breaks as the two characters \n (plot.gp splits them;
// a data file's strings take no escapes), quotes as a typographic apostrophe, since the SVG
// puts hover texts into single-quoted JavaScript as they are.
std::string datString(const std::string& s) {
  std::string q = "\"";
  for (char ch : s) {
    q += ch == '"' || ch == '\'' ? std::string("\u2019")
         : ch == '\n'            ? std::string("\\n")
                                 : std::string(1, ch);
  }
  return q + "\"";
}

// Which multiples of each decade get a labelled tic, for a log axis `pixels` long from lo to
// hi: more where a decade is long, so that tics are neither crowded nor far apart.
std::string ticSteps(double lo, double hi, double pixels) {
  const double per_decade = pixels / std::max(std::log10(hi / lo), 1e-3);
  return per_decade > 700   ? "1 1.5 2 2.5 3 4 5 6 7 8"
         : per_decade > 260 ? "1 2 3 5"
         : per_decade > 130 ? "1 2 5"
                            : "1";
}

std::vector<std::string> wrap(const std::string& text, size_t width) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  for (std::string w; words >> w;) {
    if (!lines.empty() && lines.back().size() + 1 + w.size() <= width) {
      lines.back() += " " + w;
    } else {
      lines.push_back(w);
    }
  }
  return lines;
}

std::string joinLines(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += (s.empty() ? "" : "\n") + l;
  return s;
}

// ---- Label placement, in a panel's pixels (y down) ---------------------------------------

struct Box {
  double x0, y0, x1, y1;
  bool hits(const Box& o, double pad) const {
    return x0 - pad < o.x1 && o.x0 < x1 + pad && y0 - pad < o.y1 && o.y0 < y1 + pad;
  }
  bool holds(double x, double y, double pad) const {
    return x > x0 - pad && x < x1 + pad && y > y0 - pad && y < y1 + pad;
  }
};

struct Segment {
  double x0, y0, x1, y1;
};

bool crosses(const Box& b, const Segment& s) {
  const double n = std::max(2.0, std::hypot(s.x1 - s.x0, s.y1 - s.y0) / 2.0);
  for (double i = 0; i <= n; ++i) {
    if (b.holds(s.x0 + (s.x1 - s.x0) * i / n, s.y0 + (s.y1 - s.y0) * i / n, 0.0)) return true;
  }
  return false;
}

bool crosses(const Segment& a, const Segment& b) {
  auto side = [](const Segment& s, double x, double y) {
    return (s.x1 - s.x0) * (y - s.y0) - (s.y1 - s.y0) * (x - s.x0);
  };
  return side(a, b.x0, b.y0) * side(a, b.x1, b.y1) < 0 &&
         side(b, a.x0, a.y0) * side(b, a.x1, a.y1) < 0;
}

struct Mark {
  double px, py;
  bool front, is_default;
};

struct Label {
  size_t mark;
  std::vector<std::string> lines;
  bool placed = false;
  Box box{};
  bool leader = false;
  Segment line{};
};

// Greedy: each label in turn takes the cheapest spot that stays inside the panel, off every
// other label and front point, and clear of the other marked points. A spot costs its gap to the
// point (beyond 10 px a leader line joins them, at most kMaxLeader long), plus extra for each faint
// point it covers, each line it crosses and each line its leader crosses. Spots are tried around
// the point first, then on a grid over the whole panel. Where nothing fits the label is left out
// (the SVG and the README table still name the point).
void placeLabels(std::vector<Label>& labels, const std::vector<Mark>& marks,
                 std::vector<Segment> lines, const Box& area) {
  // Down-left first: below and left of a front nothing is better, so that space is empty.
  static const std::array<double, 16> kAngles = {135, 90,  180,  112.5, 157.5,  45,    -135, 0,
                                                 -90, -45, 67.5, 202.5, -112.5, -67.5, 22.5, -22.5};
  static const std::array<double, 5> kDistances = {5, 12, 24, 40, 64};
  std::vector<Box> taken;
  for (Label& label : labels) {
    const Mark& m = marks[label.mark];
    size_t width = 0;
    for (const auto& l : label.lines) width = std::max(width, l.size());
    const double w = static_cast<double>(width) * kCharPx + 4.0;
    const double h = static_cast<double>(label.lines.size()) * kLinePx;
    std::vector<Box> spots;
    for (double d : kDistances) {
      for (double angle : kAngles) {
        const double dx = std::cos(angle * M_PI / 180.0), dy = std::sin(angle * M_PI / 180.0);
        const double cx = m.px + dx * d, cy = m.py + dy * d;
        const double x0 = dx > 0.38 ? cx : dx < -0.38 ? cx - w : cx - w / 2;
        const double y0 = dy > 0.38 ? cy : dy < -0.38 ? cy - h : cy - h / 2;
        spots.push_back({x0, y0, x0 + w, y0 + h});
      }
    }
    for (double y = area.y0 + 3; y + h < area.y1 - 3; y += 6) {
      for (double x = area.x0 + 3; x + w < area.x1 - 3; x += 8)
        spots.push_back({x, y, x + w, y + h});
    }
    double best = 1e300;
    for (size_t k = 0; k < spots.size(); ++k) {
      const Box& box = spots[k];
      if (box.x0 < area.x0 + 2 || box.x1 > area.x1 - 2 || box.y0 < area.y0 + 2 ||
          box.y1 > area.y1 - 2) {
        continue;
      }
      const Segment leader{m.px, m.py, std::clamp(m.px, box.x0, box.x1),
                           std::clamp(m.py, box.y0, box.y1)};
      const double gap = std::hypot(leader.x1 - leader.x0, leader.y1 - leader.y0);
      const bool far = gap > 10.0;
      if (gap > kMaxLeader) continue;
      // The order tried breaks ties: around the point, down-left first.
      double cost = 1.3 * gap + 1e-3 * static_cast<double>(k);
      if (cost >= best) continue;
      bool blocked = false;
      for (const Box& other : taken) {
        blocked = blocked || box.hits(other, 3.0) || (far && crosses(other, leader));
      }
      for (size_t i = 0; i < marks.size() && !blocked; ++i) {
        const Mark& p = marks[i];
        const double r = p.is_default ? 11.0 : p.front ? 6.0 : 3.0;
        if (box.holds(p.px, p.py, r)) {
          if (p.front || p.is_default) blocked = true;
          cost += 25.0;
        }
        // A label right next to another marked point would seem to name it: without a leader
        // it must be nearer its own point than any other, with one keep 14 px off the others.
        if (i != label.mark && (p.front || p.is_default)) {
          const double dx = std::max({box.x0 - p.px, 0.0, p.px - box.x1});
          const double dy = std::max({box.y0 - p.py, 0.0, p.py - box.y1});
          if (std::hypot(dx, dy) < (far ? 14.0 : std::max(gap, 5.0) + 4.0)) blocked = true;
        }
        // So would a leader passing over it.
        if (far && i != label.mark && (p.front || p.is_default) &&
            crosses(Box{p.px - 4, p.py - 4, p.px + 4, p.py + 4}, leader)) {
          cost += 40.0;
        }
      }
      for (const Segment& s : lines) {
        cost += crosses(box, s) ? 30.0 : 0.0;
        cost += far && crosses(leader, s) ? 40.0 : 0.0;
      }
      if (!blocked && cost < best) {
        best = cost;
        label.placed = true;
        label.box = box;
        label.leader = far;
        label.line = leader;
      }
    }
    if (label.placed) {
      taken.push_back(label.box);
      if (label.leader) lines.push_back(label.line);
    }
  }
}

// ---- The table, read for plotting ---------------------------------------------------------

const std::map<std::string, std::string>& metricTitles() {
  static const std::map<std::string, std::string> titles = {
      {"vis_mae", "vis_mae: mean |visibility - truth|"},
      {"false_shadow_pct", "false shadow (acne): % of counted pixels"},
      {"false_lit_pct", "false lit (leaks, jagged edges): % of pixels"},
      {"shade_mae", "shade_mae: mean |vis - truth| x N.L"},
      {"air_rel_rmse_pct", "air light: relative RMSE, %"},
      {"air_mae", "air light: mean |rendered - truth|"},
      {"undersampled_pct", "under-sampled: % of pixels, < 1 texel along an axis"},
      {"shimmer_pct", "shimmer: % of sunlit pixels flipping a step (12)"}};
  return titles;
}

std::string timeTitle(const std::string& column) {
  return column == "cpu_ms"         ? "CPU time per frame, all threads, ms"
         : column == "frame_min_ms" ? "frame time, ms (fastest frame)"
                                    : "frame time, ms (median)";
}

// Error 0 cannot sit on a log axis: it is drawn at half a pixel, the least this image size can
// measure. Sets `floored` when it did.
double plotted(const Table& t, size_t r, const std::string& metric, bool& floored) {
  const double v = metricValue(t, r, metric);
  const double pixel = 1.0 / std::max(t.value(r, "counted_pixels"), 1.0);
  const double floor = (metric.ends_with("_pct") ? 50.0 : 0.5) * pixel;
  if (!std::isfinite(v)) return v;
  if (v < floor) floored = true;
  return std::max(v, floor);
}

std::string firstOk(const Table& t, const std::string& column) {
  for (size_t r = 0; r < t.rows.size(); ++r) {
    if (t.cell(r, "status") == "ok" && !t.cell(r, column).empty()) return t.cell(r, column);
  }
  return {};
}

// What the title says about the run: the machine, the size and the samples.
std::string runLine(const Table& t) {
  std::string machine = firstOk(t, "renderer");
  if (const std::string cpu = firstOk(t, "machine"); !cpu.empty()) machine += " on " + cpu;
  const std::string rounds = firstOk(t, "rounds"), frames = firstOk(t, "frames");
  return machine + "; " + firstOk(t, "width") + "x" + firstOk(t, "height") + ", " + rounds +
         (rounds == "1" ? " round" : " rounds") + " x " + frames +
         (frames == "1" ? " frame" : " frames") + " per setting";
}

std::string fixedLine(const Sweep& sweep, const std::vector<std::string>& sets) {
  std::string fixed;
  for (const auto& f : sweep.fixed) fixed += (fixed.empty() ? "" : " ") + f;
  for (const auto& f : sets) fixed += (fixed.empty() ? "" : " ") + f;
  return "held fixed: " + (fixed.empty() ? std::string("nothing") : fixed) +
         (sweep.study ? "; the rest at each lesson's default"
                      : "; the rest at the lesson's default");
}

// ---- gnuplot ---------------------------------------------------------------------------

// 0 plotted, 1 gnuplot failed, -1 no gnuplot (a note, not a failure). gnuplot's chatter goes
// to `log`, shown only when it fails.
int runGnuplot(const std::string& script, const std::string& variables,
               const std::filesystem::path& out, const std::filesystem::path& log) {
  // Drawn next to the final name and renamed, so a failed plot leaves no stale or half picture.
  const std::filesystem::path temporary = out.string() + ".partial";
  std::error_code ec;
  std::filesystem::remove(out, ec);
  const std::string e = variables + "; out=" + gnuplotString(temporary.string());
  const std::string path = std::string(BENCH_DIR) + "/" + script;
  std::vector<std::string> args = {"gnuplot", "-e", e, path};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_APPEND, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    std::filesystem::rename(temporary, out, ec);
    return ec ? 1 : 0;
  }
  std::filesystem::remove(temporary, ec);
  std::ifstream in(log);
  std::cerr << in.rdbuf();
  return 1;
}

// ---- Error against time, with the front -----------------------------------------------------

struct Panel {
  std::string group;
  size_t metric = 0, col = 0, row = 0;
  std::vector<size_t> rows;  // the table's, with a time and an error
};

// Writes the data file and returns plot.gp's -e variables ("" when nothing can be drawn).
std::string frontPlotData(const std::filesystem::path& dat, const std::string& name,
                          const Sweep& sweep, const Table& t, const std::string& defaults,
                          const std::vector<std::string>& sets) {
  const std::string time_column = firstOk(t, "front_time");
  const std::vector<std::string>& metrics = sweep.plot_metrics;
  if (time_column.empty() || metrics.empty()) return {};
  // Columns are scenes; rows are each scene's groups (front.cpp: the rows that share a truth)
  // times the metrics, both in order of first appearance.
  std::vector<std::string> scenes;
  std::map<std::string, std::vector<std::string>> groups;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string& scene = t.cell(r, "scene");
    const std::string& group = t.cell(r, "front_group");
    if (group.empty()) continue;
    if (!groups.contains(scene)) scenes.push_back(scene);
    auto& g = groups[scene];
    if (std::find(g.begin(), g.end(), group) == g.end()) g.push_back(group);
  }
  size_t most_groups = 0;
  for (const auto& [scene, g] : groups) most_groups = std::max(most_groups, g.size());
  bool floored = false;
  std::vector<Panel> panels;
  std::vector<double> x(t.rows.size(), std::nan(""));
  std::vector<std::vector<double>> y(metrics.size(), x);
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const double ms = t.value(r, time_column);
    x[r] = ms > 0 ? ms : std::nan("");  // a time not measured is missing, not 0
    for (size_t m = 0; m < metrics.size(); ++m) y[m][r] = plotted(t, r, metrics[m], floored);
  }
  double xmin = 1e300, xmax = 0;
  std::vector<double> ymin(most_groups * metrics.size(), 1e300), ymax(ymin.size(), 0.0);
  for (size_t s = 0; s < scenes.size(); ++s) {
    const auto& g = groups[scenes[s]];
    for (size_t k = 0; k < g.size(); ++k) {
      for (size_t m = 0; m < metrics.size(); ++m) {
        Panel p{g[k], m, s, k * metrics.size() + m, {}};
        for (size_t r = 0; r < t.rows.size(); ++r) {
          if (t.cell(r, "front_group") != g[k] || !std::isfinite(x[r]) || !std::isfinite(y[m][r]) ||
              y[m][r] <= 0) {
            continue;
          }
          p.rows.push_back(r);
          xmin = std::min(xmin, x[r]);
          xmax = std::max(xmax, x[r]);
          ymin[p.row] = std::min(ymin[p.row], y[m][r]);
          ymax[p.row] = std::max(ymax[p.row], y[m][r]);
        }
        if (!p.rows.empty()) panels.push_back(std::move(p));
      }
    }
  }
  if (panels.empty()) return {};
  // Ranges padded, not rounded out to a decade: the points spread over the panel, and room is
  // left below and left of the front, where its labels go first.
  auto pad = [](double& lo, double& hi, double below, double above) {
    const double span = std::max(std::log10(hi / lo), 0.3);
    lo /= std::pow(10.0, below * span);
    hi *= std::pow(10.0, above * span);
  };
  pad(xmin, xmax, 0.45, 0.2);
  for (size_t row = 0; row < ymin.size(); ++row) {
    if (ymax[row] > 0) pad(ymin[row], ymax[row], 0.4, 0.12);
  }

  // Series (Sweep::series): each row's, by the value its settings give the parameter, and a
  // colour each, in the order the sweep's values name them (a lesson that lists them in its
  // choice's order gets its panel's colours), whichever rows ran.
  std::vector<std::string> series_names;
  std::vector<size_t> series_of(t.rows.size(), 0);
  if (!sweep.series.empty()) {
    // The series parameter's value among `assignments` ("" where they leave it alone).
    const auto seriesOf = [&](const std::vector<std::string>& assignments) {
      std::string value;
      for (const std::string& set : assignments) {
        if (set.rfind(sweep.series + "=", 0) == 0) value = set.substr(sweep.series.size() + 1);
      }
      return value;
    };
    const auto indexOf = [&](const std::string& value) {
      const auto k = static_cast<size_t>(
          std::find(series_names.begin(), series_names.end(), value) - series_names.begin());
      if (k == series_names.size()) series_names.push_back(value);
      return k;
    };
    for (const Axis& axis : sweep.axes) {
      for (const std::string& v : axis.values) {
        const std::string value = seriesOf(settingsOf(axis, v).second);
        if (!value.empty()) indexOf(value);
      }
    }
    for (size_t r = 0; r < t.rows.size(); ++r)
      series_of[r] = indexOf(seriesOf(rowSettings(sweep, t, r)));
  }
  static constexpr unsigned kSeriesColours[] = {0xe08a00, 0x2a9d3c, 0x8e44ad, 0x16a3b8, 0xd6336c,
                                                0x7a5c2e, 0x5a6b8c, 0xb5b000, 0xe377c2};
  const auto colourOf = [&](size_t r) {
    return series_names.empty() ? 0xb9b9b9u
                                : kSeriesColours[series_of[r] % std::size(kSeriesColours)];
  };
  // The page, in pixels: a title band, the key, then one cell per panel.
  const double cell_w = std::clamp(1760.0 / static_cast<double>(scenes.size()), 640.0, 1200.0);
  // One column of panels (one scene) is wide anyway: taller panels give its labels room.
  const double plot_h = scenes.size() == 1 ? 480.0 : 350.0;
  // The key grows by a line a series.
  const double head = 170.0 + 20.0 * static_cast<double>(series_names.size());
  const double cell_h = plot_h + 130.0, left = 96.0, right = 26.0, above = 56.0;
  const double width = 16.0 + cell_w * static_cast<double>(scenes.size());
  const double height = head + cell_h * static_cast<double>(most_groups * metrics.size()) + 8.0;

  std::ostringstream data;
  data << "# " << name << ": six blocks per panel: the other points (x y hover colour), the "
       << "front in cost order (x y hover), the default, label lines (x y text colour), leader "
       << "lines, each series' own front (x y colour)\n";
  std::string p_left, p_right, p_bottom, p_top, p_ymin, p_ymax, p_ysteps, p_titles, p_ylabels;
  size_t unlabelled = 0;
  bool any_default = false;
  auto hoverOf = [&](size_t r, const std::string& metric, bool on) {
    std::vector<std::string> lines = wrap(t.cell(r, "scene") + ": " + t.cell(r, "settings"), 60);
    if (sweep.study) {
      std::string literal;
      for (const auto& s : rowSettings(sweep, t, r)) literal += (literal.empty() ? "" : " ") + s;
      for (const auto& l : wrap(literal, 60)) lines.push_back(l);
    }
    // The rest of the settings, so the hover text is the whole configuration.
    for (const auto& l : wrap(fixedLine(sweep, sets), 60)) lines.push_back(l);
    char line[160];
    std::snprintf(line, sizeof line, "CPU %.3g ms per frame; frame %.3g ms median, %.3g fastest",
                  t.value(r, "cpu_ms"), t.value(r, "frame_ms"), t.value(r, "frame_min_ms"));
    lines.push_back(line);
    std::string errors;
    for (const auto& m : metrics) {
      std::snprintf(line, sizeof line, "%s %.3g", m.c_str(), metricValue(t, r, m));
      errors += (errors.empty() ? "" : ", ") + std::string(line);
    }
    lines.push_back(errors);
    lines.push_back(on ? "on the " + metric + " front"
                       : "off the " + metric +
                             " front: another setting is at least as fast "
                             "and as accurate, and better in one");
    if (t.cell(r, "is_default") == "1") {
      lines.push_back(sweep.study ? "a lesson's default settings" : "the lesson's default");
    }
    return joinLines(lines);
  };
  for (const Panel& p : panels) {
    const std::string& metric = metrics[p.metric];
    const double x0 = 8.0 + cell_w * static_cast<double>(p.col) + left;
    const double x1 = 8.0 + cell_w * static_cast<double>(p.col + 1) - right;
    const double y0 = head + cell_h * static_cast<double>(p.row) + above, y1 = y0 + plot_h;
    const double lo = ymin[p.row], hi = ymax[p.row];
    auto px = [&](double v) {
      return x0 + (std::log(v) - std::log(xmin)) / (std::log(xmax) - std::log(xmin)) * (x1 - x0);
    };
    auto py = [&](double v) {
      return y0 + (std::log(hi) - std::log(v)) / (std::log(hi) - std::log(lo)) * (y1 - y0);
    };
    auto dataX = [&](double pixel) {
      return xmin * std::pow(xmax / xmin, (pixel - x0) / (x1 - x0));
    };
    auto dataY = [&](double pixel) { return hi * std::pow(lo / hi, (pixel - y0) / (y1 - y0)); };
    std::vector<size_t> front, others;
    std::vector<Mark> marks;
    for (size_t r : p.rows) {
      const bool on = t.cell(r, "on_front." + metric) == "1";
      (on ? front : others).push_back(r);
    }
    std::sort(front.begin(), front.end(), [&](size_t a, size_t b) {
      return std::make_pair(x[a], y[p.metric][a]) < std::make_pair(x[b], y[p.metric][b]);
    });
    // Marks: the front first (in cost order), then the others.
    std::vector<size_t> order = front;
    order.insert(order.end(), others.begin(), others.end());
    for (size_t i = 0; i < order.size(); ++i) {
      const size_t r = order[i];
      marks.push_back(
          {px(x[r]), py(y[p.metric][r]), i < front.size(), t.cell(r, "is_default") == "1"});
    }
    // The front is drawn as steps (plot.gp `with steps`): the least error for a time budget.
    std::vector<Segment> lines;
    for (size_t i = 1; i < front.size(); ++i) {
      const Mark &a = marks[i - 1], &b = marks[i];
      lines.push_back({a.px, a.py, b.px, a.py});
      lines.push_back({b.px, a.py, b.px, b.py});
    }
    // The default off the front first: its short label belongs right at its ring.
    std::vector<Label> labels;
    for (size_t i = front.size(); i < order.size(); ++i) {
      if (!marks[i].is_default) continue;
      // A study holds several lessons' defaults: say which.
      labels.push_back({i, sweep.study
                               ? wrap("default: " + t.cell(order[i], "settings"), kLabelChars)
                               : std::vector<std::string>{"the lesson's default"}});
    }
    for (size_t i = 0; i < front.size(); ++i) {
      std::string text = t.cell(order[i], "settings");
      if (marks[i].is_default) text += " (default)";
      labels.push_back({i, wrap(text, kLabelChars)});
    }
    placeLabels(labels, marks, lines, Box{x0, y0, x1, y1});

    for (size_t i = 0; i < 2; ++i) {
      const auto& rows = i == 0 ? others : front;
      for (size_t r : rows) {
        data << number(x[r]) << " " << number(y[p.metric][r]) << " "
             << datString(hoverOf(r, metric, i == 1));
        if (i == 0) data << " " << colourOf(r);
        data << "\n";
      }
      if (rows.empty()) data << (i == 0 ? "nan nan \"\" 0\n" : "nan nan \"\"\n");
      data << "\n\n";
    }
    bool drew_default = false;
    for (size_t r : p.rows) {
      if (t.cell(r, "is_default") != "1") continue;
      data << number(x[r]) << " " << number(y[p.metric][r]) << "\n";
      drew_default = any_default = true;
    }
    if (!drew_default) data << "nan nan\n";
    data << "\n\n";
    bool any_label = false;
    for (const Label& l : labels) {
      if (!l.placed) {
        ++unlabelled;
        continue;
      }
      const bool default_only = l.mark >= front.size();
      for (size_t k = 0; k < l.lines.size(); ++k) {
        const double ly = l.box.y0 + (static_cast<double>(k) + 0.5) * kLinePx;
        data << number(dataX(l.box.x0 + 2.0)) << " " << number(dataY(ly)) << " "
             << datString(l.lines[k]) << " " << (default_only ? 0xb03020 : 0x1a1a1a) << "\n";
        any_label = true;
      }
    }
    if (!any_label) data << "nan nan \"\" 0\n";
    data << "\n\n";
    bool any_leader = false;
    for (const Label& l : labels) {
      if (!l.placed || !l.leader) continue;
      // From just outside the point's marker to the label's nearest edge.
      const Segment& s = l.line;
      const double len = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
      const double k = std::min(0.9, 7.0 / std::max(len, 1.0));
      data << number(dataX(s.x0 + (s.x1 - s.x0) * k)) << " "
           << number(dataY(s.y0 + (s.y1 - s.y0) * k)) << "\n"
           << number(dataX(s.x1)) << " " << number(dataY(s.y1)) << "\n\n";
      any_leader = true;
    }
    if (!any_leader) data << "nan nan\n";
    data << "\n\n";
    // Each series' own front, in cost order: the least error that series reaches for a time.
    bool any_series_front = false;
    for (size_t k = 0; k < series_names.size(); ++k) {
      std::vector<size_t> rows;
      for (size_t r : p.rows) {
        if (series_of[r] == k) rows.push_back(r);
      }
      std::sort(rows.begin(), rows.end(), [&](size_t a, size_t b) {
        return std::make_pair(x[a], y[p.metric][a]) < std::make_pair(x[b], y[p.metric][b]);
      });
      // Drawn as steps, written out: gnuplot's steps take no colour per point.
      double best = 1e300;
      bool any = false;
      for (size_t r : rows) {
        if (y[p.metric][r] >= best) continue;
        if (any) data << number(x[r]) << " " << number(best) << " " << colourOf(r) << "\n";
        best = y[p.metric][r];
        data << number(x[r]) << " " << number(best) << " " << colourOf(r) << "\n";
        any = any_series_front = true;
      }
      if (any) data << "\n";
    }
    if (!any_series_front) data << "nan nan 0\n";
    data << "\n\n";

    char frac[64];
    auto add = [&](std::string& list, double v) {
      std::snprintf(frac, sizeof frac, "%.5f ", v);
      list += frac;
    };
    add(p_left, x0 / width);
    add(p_right, x1 / width);
    add(p_bottom, 1.0 - y1 / height);
    add(p_top, 1.0 - y0 / height);
    p_ymin += number(lo) + " ";
    p_ymax += number(hi) + " ";
    p_ysteps += datString(ticSteps(lo, hi, y1 - y0)) + " ";
    const auto title = wrap(p.group, static_cast<size_t>((x1 - x0) / 8.0));
    p_titles += datString(joinLines(title)) + " ";
    p_ylabels += datString(metricTitles().at(metric) + "\n(lower is better, log scale)") + " ";
  }
  if (!writeFile(dat, data.str())) return {};

  const std::string key_front =
      "Pareto front: no other setting is both faster and more accurate; its steps give the "
      "least error for a time budget";
  const std::string key_other = series_names.empty()
                                    ? "every other setting (faint; the SVG names each on hover)"
                                    : "every other setting, in its " + sweep.series +
                                          "'s colour (the SVG names each on hover)";
  std::string series_list, series_colours;
  for (size_t k = 0; k < series_names.size(); ++k) {
    char colour[16];
    std::snprintf(colour, sizeof colour, "#%06x", kSeriesColours[k % std::size(kSeriesColours)]);
    series_list += (series_list.empty() ? "" : " ") + series_names[k];
    series_colours += (series_colours.empty() ? "" : " ") + std::string(colour);
  }
  std::string key_default;
  if (sweep.study) {
    key_default =
        any_default ? "a lesson's default settings" : "no setting here is a lesson's default";
  } else {
    // A line of the key, cut at a word (lesson 16's defaults name every technique's knobs):
    // the CSV's is_default row has them all.
    std::string shown = defaults;
    if (shown.size() > 150) shown = shown.substr(0, shown.rfind(' ', 150)) + " ...";
    key_default = "the lesson's default" + (shown.empty() ? "" : " (" + shown + ")") +
                  (any_default ? "" : ": not in this sweep");
  }
  std::string note;
  if (floored) note += "an error of 0 is drawn at half a pixel. ";
  if (unlabelled > 0) {
    note += std::to_string(unlabelled) + " front label" + (unlabelled == 1 ? "" : "s") +
            " did not fit: the SVG and the README table name every front point.";
  }
  const std::string title = name + ": error against time. Which setting is cheapest at the " +
                            "error you need?\n" + runLine(t) + "\n" + fixedLine(sweep, sets);
  char geometry[256];
  std::snprintf(geometry, sizeof geometry,
                "width=%d; height=%d; xmin=%s; xmax=%s; key_x=%.5f; key_y=%.5f; npanels=%zu",
                static_cast<int>(width), static_cast<int>(height), number(xmin).c_str(),
                number(xmax).c_str(), (8.0 + left) / width, 1.0 - 84.0 / height, panels.size());
  return std::string(geometry) + "; data=" + gnuplotString(dat.string()) +
         "; title=" + gnuplotText(title) +
         "; xlabel=" + gnuplotString(timeTitle(time_column) + " (lower is better, log scale)") +
         "; p_left=" + gnuplotString(p_left) + "; p_right=" + gnuplotString(p_right) +
         "; p_bottom=" + gnuplotString(p_bottom) + "; p_top=" + gnuplotString(p_top) +
         "; p_ymin=" + gnuplotString(p_ymin) + "; p_ymax=" + gnuplotString(p_ymax) +
         "; p_ysteps=" + gnuplotString(p_ysteps) +
         "; xsteps=" + gnuplotString(ticSteps(xmin, xmax, cell_w - left - right)) +
         "; p_titles=" + gnuplotString(p_titles) + "; p_ylabels=" + gnuplotString(p_ylabels) +
         "; key_front=" + gnuplotString(key_front) + "; key_other=" + gnuplotString(key_other) +
         "; key_default=" + gnuplotString(key_default) + "; note=" + gnuplotString(note) +
         "; series=" + gnuplotString(series_list) +
         "; series_colours=" + gnuplotString(series_colours);
}

// ---- Error along a knob (plot_along sweeps: a bias costs no time) ---------------------------

// The data for plot_along.gp: one block per (scene, series), series = combinations of
// axes[1..], rows along axes[0]. Returns its -e variables.
std::string alongPlotData(const std::filesystem::path& path, const std::string& name,
                          const Sweep& sweep, const Table& t,
                          const std::vector<std::string>& sets) {
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
  // Each row's value index on every axis, by its label.
  auto indexOf = [&](size_t r, size_t a) {
    const Axis& axis = sweep.axes[a];
    for (size_t v = 0; v < axis.values.size(); ++v) {
      if (settingsOf(axis, axis.values[v]).first == t.cell(r, axis.name)) return v;
    }
    return axis.values.size();
  };
  // axes[0] as a number; 0 is drawn at half the smallest positive value so a log axis holds it.
  double smallest_positive = 1e300;
  for (const auto& v : sweep.axes[0].values) {
    const double x = std::strtod(settingsOf(sweep.axes[0], v).first.c_str(), nullptr);
    if (x > 0) smallest_positive = std::min(smallest_positive, x);
  }
  bool floored = false;
  std::ostringstream data;
  data << "# " << name << ": " << sweep.axes[0].name << ", then one error column per metric\n";
  std::string present;
  for (const auto& scene : sweep.scenes) {
    std::string here;
    for (size_t k = 0; k < series.size(); ++k) {
      bool any = false;
      for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.cell(r, "scene") != scene || t.cell(r, "status") != "ok") continue;
        bool in = true;
        for (size_t a = 1; a < sweep.axes.size(); ++a) in = in && indexOf(r, a) == series[k][a - 1];
        if (!in) continue;
        const std::string& label = t.cell(r, sweep.axes[0].name);
        char* end = nullptr;
        const double v = std::strtod(label.c_str(), &end);
        data << (end == label.c_str() || *end ? "nan" : number(v > 0 ? v : 0.5 * smallest_positive))
             << " " << datString(label);
        for (const auto& m : sweep.plot_metrics) data << " " << number(plotted(t, r, m, floored));
        data << "\n";
        any = true;
      }
      // gnuplot does not count a block without records: keep every index in its place.
      if (!any) {
        data << "nan \"\"";
        for (size_t m = 0; m < sweep.plot_metrics.size(); ++m) data << " nan";
        data << "\n";
      }
      data << "\n\n";
      if (any) here += std::to_string(k + 1) + " ";
    }
    present += "\"" + here + "\" ";
  }
  if (!writeFile(path, data.str())) return {};
  std::string titles, colors, dashes, scenes, ylabels;
  for (const auto& s : series) {
    std::string title;
    for (size_t a = 1; a < sweep.axes.size(); ++a) {
      const std::string& axis = sweep.axes[a].name;  // "factor=2", not "bias.factor=2": short
      if (a > 1) title += ' ';
      title.append(axis, axis.rfind('.') + 1).append("=");
      title += settingsOf(sweep.axes[a], sweep.axes[a].values[s[a - 1]]).first;
    }
    titles += datString(title.empty() ? name : title) + " ";
    colors += std::to_string(s.empty() ? 1 : s[0] + 1) + " ";
    dashes += std::to_string(s.size() < 2 ? 1 : s[1] + 1) + " ";
  }
  for (const auto& scene : sweep.scenes) scenes += scene + " ";
  for (const auto& m : sweep.plot_metrics) {
    ylabels += datString(metricTitles().at(m) + ", lower is better, log scale") + " ";
  }
  std::string key = "one line per combination:";
  if (floored) key += "\nan error of 0 is drawn at half a pixel";
  const std::string title = name + ": error along " + sweep.axes[0].name + "\n" + runLine(t) +
                            "\n" + fixedLine(sweep, sets);
  return "data=" + gnuplotString(path.string()) + "; scenes=" + gnuplotString(scenes) +
         "; nseries=" + std::to_string(series.size()) + "; titles=" + gnuplotString(titles) +
         "; present=" + gnuplotString(present) + "; colors=" + gnuplotString(colors) +
         "; dashes=" + gnuplotString(dashes) + "; along=" + gnuplotString(sweep.axes[0].name) +
         "; nmetrics=" + std::to_string(sweep.plot_metrics.size()) +
         "; ylabels=" + gnuplotString(ylabels) + "; key_title=" + gnuplotText(key) +
         "; title=" + gnuplotText(title);
}

}  // namespace

int plotSweep(const std::string& name, const Sweep& sweep, const Table& t,
              const std::string& defaults, const std::vector<std::string>& sets,
              const std::filesystem::path& out_dir, std::vector<std::filesystem::path>& written) {
  const auto log = out_dir / (name + ".plot.log");
  std::error_code ec;
  std::filesystem::remove(log, ec);
  const auto dat = out_dir / (name + ".plot.dat");
  const std::string vars = frontPlotData(dat, name, sweep, t, defaults, sets);
  if (vars.empty()) return 1;
  for (const char* term : {"png", "svg"}) {
    const auto out = out_dir / (name + "." + term);
    const int status = runGnuplot("plot.gp", vars + "; term='" + term + "'", out, log);
    if (status != 0) return status;
    written.push_back(out);
  }
  if (sweep.plot_along) {
    const auto along_dat = out_dir / (name + "_along.plot.dat");
    const std::string along = alongPlotData(along_dat, name, sweep, t, sets);
    if (along.empty()) return 1;
    const auto out = out_dir / (name + "_along.png");
    const int status = runGnuplot("plot_along.gp", along, out, log);
    if (status != 0) return status;
    written.push_back(out);
  }
  return 0;
}

}  // namespace shadows::bench
