// The bench's front in the panel: bench_sweep's points for this lesson (its table,
// docs/bench_16_choose_your_shadow.csv, carried as bench_points.inc), those of the current
// preset and light, and which of them the current settings are. The student's own machine
// times differently; the bench's figures are the bench machine's, and say so.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/params.hpp"
#include "tried.hpp"

namespace shadows {

struct BenchPoint {
  const char* scene;
  const char* light;     // the sweep's light: point, disk, disk_moved
  const char* setting;   // the sweep's name for the settings: pcf_dithered_1024
  const char* settings;  // as --set takes them, the light's among them
  double ms;             // the bench's time (kBenchTime) on its machine (kBenchMachine)
                         // at its frame size (kBenchSize)
  double error;          // vis_mae
};

#include "bench_points.inc"

class BenchFront {
 public:
  // Lesson 16's parameters as declared: `technique`, and each technique's knobs named after it
  // ("pcf/pcf.taps"). Throws std::logic_error where a point's settings no longer read.
  explicit BenchFront(const Params& host, std::span<const BenchPoint> points = kBenchPoints) {
    for (const std::string& key : host.at("technique").choices) {
      knobs_.emplace_back();
      for (const Param& q : host.all()) {
        if (q.name.starts_with(key + "/")) knobs_.back().push_back(q.name);
      }
    }
    Params scratch = host;  // each point's settings read as --set reads them
    for (const BenchPoint& p : points) {
      Row row{&p, 0, {}};
      std::istringstream words(p.settings);
      for (std::string word; words >> word;) {
        const size_t eq = word.find('=');
        const std::string name = word.substr(0, eq);
        // A word that no longer reads (a knob renamed since the sweep) would match anything.
        const std::string why =
            eq == std::string::npos ? "no '='" : scratch.set(name, word.substr(eq + 1));
        if (!why.empty()) {
          throw std::logic_error(std::string("bench_points.inc: ") + p.setting + ": " + word +
                                 ": " + why + "; run bench_sweep again");
        }
        const Param& q = scratch.at(name);
        row.values.push_back({name, {q.value[0], q.value[1], q.value[2]}});
        if (name == "technique") row.technique = static_cast<size_t>(q.i());
      }
      rows_.push_back(std::move(row));
    }
  }

  struct Here {
    std::string light;                 // the sweep's name for the current light, "" for none
    std::vector<Tried::Point> points;  // where = light, label = setting, series = technique
    int current = -1;                  // the point the current settings are, -1 for none
  };
  // The bench's points on the current preset under the current light (none where the bench
  // did not measure this light, or the light or the camera moved), and which of them the
  // current settings are.
  Here at(const Params& host) const {
    Here here;
    const std::string scene = host.at("scene").choice();
    for (const Row& r : rows_) {
      if (scene != r.point->scene || !same(host, r, kFrame)) continue;
      here.light = r.point->light;
      if (same(host, r, {"technique"}) && same(host, r, knobs_.at(r.technique))) {
        here.current = static_cast<int>(here.points.size());
      }
      here.points.push_back(
          {here.light, r.point->setting, r.technique, r.point->ms, r.point->error});
    }
    return here;
  }

 private:
  struct Row {
    const BenchPoint* point;
    size_t technique;
    std::vector<std::pair<std::string, std::array<double, 3>>> values;  // as the sweep set them
  };
  // What makes the frame the sweep measured: the light as it varied it (a caster moved is
  // another truth), the preset's light and camera, which it left as they are.
  static inline const std::vector<std::string> kFrame = {
      "light.radius", "move.object", "move.x",       "move.z",     "light.type",    "light.pos",
      "light.target", "light.fov",   "light.extent", "camera.pos", "camera.target", "camera.fov"};
  // Does the host have, for each of `names`, the row's value, or the default the row left?
  static bool same(const Params& host, const Row& r, const std::vector<std::string>& names) {
    for (const std::string& name : names) {
      const Param& now = host.at(name);
      const double* want = now.fallback;
      for (const auto& [set, value] : r.values) {
        if (set == name) want = value.data();
      }
      for (int c = 0; c < 3; ++c) {  // as floats: a slider stores a float's value
        if (static_cast<float>(now.value[c]) != static_cast<float>(want[c])) return false;
      }
    }
    return true;
  }

  std::vector<std::vector<std::string>> knobs_;
  std::vector<Row> rows_;
};

}  // namespace shadows
