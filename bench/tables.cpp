// The table behind <lesson>.csv and .json, writing files, and the checks on what was measured
// and written.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <thread>

#include "bench.hpp"
#include "core/json.hpp"

namespace shadows::bench {

namespace {

// The CPU the times were taken on, for the plot's title: "2 cores, Intel(R) Xeon(R) ...".
std::string machineName() {
  std::ifstream in("/proc/cpuinfo");
  std::string model;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("model name")) {
      model = line.substr(line.find(':') + 1);
      model.erase(0, model.find_first_not_of(" \t"));
      break;
    }
  }
  const unsigned cores = std::thread::hardware_concurrency();
  return std::to_string(cores) + (cores == 1 ? " core" : " cores") +
         (model.empty() ? "" : " of " + model);
}

}  // namespace

std::string number(double v) {
  if (!std::isfinite(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Columns: lesson, scene, each axis, size and frames, timings, work, error, renderer, machine.
// Passes and counters are the union over all rows, so a lesson with more passes gets more
// columns.
Table makeTable(const std::vector<const Config*>& configs,
                const std::vector<const Result*>& results, const Options& o) {
  std::set<std::string> passes, counts, report_numbers;
  for (const Result* r : results) {
    for (const auto& [p, ms] : r->pass_ms) passes.insert(p);
    for (const auto& [p, w] : r->work) passes.insert(p);
    for (const auto& [name, n] : r->counts) counts.insert(name);
    for (const auto& [name, v] : r->report_numbers) report_numbers.insert(name);
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
        "counted_pixels", "air_mae", "air_rel_rmse", "air_truth_noise", "undersampled_pct"}) {
    column(name, true);
  }
  for (const auto& name : report_numbers) column(name, true);
  column("truth", false);
  column("gl_errors", true);
  column("renderer", false);
  column("machine", false);
  column("status", false);

  const std::string machine = machineName();
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
      row.push_back(it == r.work.end() || !it->second.fragment_invocations
                        ? ""
                        : std::to_string(*it->second.fragment_invocations));
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
    row.push_back(r.undersampled_pct ? number(*r.undersampled_pct) : "");
    for (const auto& name : report_numbers) {
      const auto it = r.report_numbers.find(name);
      row.push_back(it == r.report_numbers.end() ? "" : number(it->second));
    }
    row.push_back(e ? r.error.truth : "");
    row.push_back(std::to_string(r.gl_errors));
    row.push_back(r.renderer);
    row.push_back(machine);
    row.push_back(r.done ? "ok" : "failed: " + r.failure);
    t.rows.push_back(std::move(row));
  }
  return t;
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
  if (!o.sets.empty()) {  // bench_sweep's --set, after every row's own settings
    json.beginArray("sets");
    for (const std::string& set : o.sets) json.value("", set);
    json.endArray();
  }
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

}  // namespace shadows::bench
