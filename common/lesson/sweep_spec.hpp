// What bench_sweep measures for a lesson: its time-vs-error sweep (bench/README.md). A lesson
// declares its sweep next to itself, in NN_name/sweep.cpp:
//
//   SHADOWS_SWEEP({.scenes = {"torus_pyramid", "grazing"},
//                  .axes = {{"bias.units", {"0", "1", "4"}}, {"bias.factor", {"1.1", "2"}}},
//                  .fixed = {"shadow.cache=false", "inset=false"}});
//
// Pure data: the bench's engine (bench/) expands and runs it, and studies across lessons live
// there (bench/studies.cpp).
#pragma once

#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace shadows {

// A value is either plain (the setting is name=value) or a bundle "label:a=1 b=2" that sets
// several parameters at once, for knobs that only make sense together (a PCF mode and its
// tap count); the label names the point in the CSV and on the plot.
struct Axis {
  std::string name;
  std::vector<std::string> values;
};

// The label of a value and the --set assignments it stands for.
inline std::pair<std::string, std::vector<std::string>> settingsOf(const Axis& axis,
                                                                   const std::string& value) {
  const auto colon = value.find(':');
  if (colon == std::string::npos) return {value, {axis.name + "=" + value}};
  std::vector<std::string> sets;
  std::istringstream words(value.substr(colon + 1));
  for (std::string w; words >> w;) sets.push_back(w);
  return {value.substr(0, colon), sets};
}

// scenes x axes. axes[0] varies fastest, so neighbouring values of it are measured back to back;
// with plot_along it is also the x axis of <name>_along.png, the other axes picking its lines.
// The main plot (error against time, with the Pareto front) does not depend on the order.
struct Sweep {
  std::vector<std::string> scenes;
  std::vector<Axis> axes;
  std::vector<std::string> fixed;  // --set values every configuration shares
  // The error metrics plotted against time, one row of panels each: any of vis_mae,
  // false_shadow_pct, false_lit_pct, shade_mae, air_rel_rmse_pct, air_mae, undersampled_pct
  // (lessons with a map: texel_density.hpp).
  std::vector<std::string> plot_metrics = {"vis_mae"};
  // Also plot against axes[0]'s (numeric) value (<name>_along.png), for knobs that cost nothing
  // (a bias): there the question is how error moves with the knob.
  bool plot_along = false;
  // Numbers of the lesson's own report (top-level fields) written as columns of their own,
  // which plot_metrics may then name: lesson 12's shimmer_pct.
  std::vector<std::string> report_numbers{};
  // A study across lessons: its name is no lesson, and its bundles say `lesson=NAME`.
  bool study = false;
  // A parameter whose value makes each point one of several series (lesson 16's technique):
  // the plot colours each series' points and draws its own front through them, under the
  // overall one.
  std::string series{};
};

// Lessons 06 and 07 (DepthReadback's knobs): seed 000's copy claims, timed as the `readback`
// pass: "512x512 takes 4 times longer to copy than 256x256", "16-bit depth values copy twice as
// fast as 24-bit". The copy paths against map size and the light pass's depth bits.
inline Sweep copyCostSweep() {
  return {.scenes = {"torus_pyramid", "dueling"},
          .axes = {{"shadow.size", {"256", "512", "1024", "2048"}},
                   {"map.path", {"read_pixels", "copy_texture", "render_to_texture"}},
                   {"map.depth_bits", {"24", "16"}}},
          .fixed = {"shadow.cache=false", "inset=false"},
          .plot_metrics = {"false_shadow_pct", "false_lit_pct"}};
}

inline std::map<std::string, Sweep>& sweepRegistry() {
  static std::map<std::string, Sweep> sweeps;
  return sweeps;
}

// Every lesson's sweep, by lesson name (the lessons linked into this program).
inline const std::map<std::string, Sweep>& registeredSweeps() {
  return sweepRegistry();
}

struct SweepRegistrar {
  SweepRegistrar(const std::string& lesson, Sweep sweep) {
    sweepRegistry()[lesson] = std::move(sweep);
  }
};

// In NN_name/sweep.cpp: SHADOWS_SWEEP({.scenes = ..., .axes = ...}) or SHADOWS_SWEEP(aSweep()).
#define SHADOWS_SWEEP(...) \
  static const ::shadows::SweepRegistrar kSweepRegistrar(LESSON_NAME, __VA_ARGS__)

}  // namespace shadows
