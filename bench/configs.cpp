// From a sweep to its configurations, and which sweeps there are.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <set>

#include "bench.hpp"

namespace shadows::bench {

const std::map<std::string, Sweep>& allSweeps() {
  static const std::map<std::string, Sweep> all = [] {
    std::map<std::string, Sweep> sweeps = studies();
    sweeps.insert(registeredSweeps().begin(), registeredSweeps().end());
    return sweeps;
  }();
  return all;
}

std::string checkSets(const std::string& name, const Sweep& sweep,
                      const std::vector<std::string>& sets) {
  if (sets.empty()) return {};
  // What the sweep varies itself (a --set would override it, and the CSV would then name values
  // that did not run), and the lessons that render it.
  std::set<std::string> varied = {"scene"}, lessons;
  if (!sweep.study) lessons.insert(name);
  for (const Axis& axis : sweep.axes) {
    for (const std::string& value : axis.values) {
      for (const std::string& set : settingsOf(axis, value).second) {
        const std::string param = set.substr(0, set.find('='));
        if (param == "lesson") {
          lessons.insert(set.substr(7));
        } else {
          varied.insert(param);
        }
      }
    }
  }
  for (const std::string& set : sets) {
    const std::string param = set.substr(0, set.find('='));
    if (varied.contains(param)) {
      return "--set " + set + ": the sweep " + name + " varies " + param + " itself";
    }
  }
  // The runner's own check, on each lesson's parameters at their defaults, in order.
  for (const std::string& lesson : lessons) {
    Runner probe(lesson, makeLesson(lesson), RunOptions{});  // parameters only, no GL
    for (const std::string& set : sets) {
      if (std::string e = probe.params().assign(set); !e.empty()) return lesson + ": " + e;
    }
  }
  return {};
}

std::vector<Config> expand(const std::string& name, const Sweep& sweep, const Options& o) {
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
    Config c{name, name, scene, {}, {}, index, {"scene=" + scene}};
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
    c.sets.insert(c.sets.end(), o.sets.begin(), o.sets.end());  // --set: last, so it wins
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
  // What the lesson itself refuses (the command line's exit 2: lesson 16's cascades under a
  // lamp) is no configuration: its picture would be measured as a technique's.
  std::map<std::string, std::unique_ptr<Runner>> probes;
  auto refused = [&](const Config& c) {
    auto& probe = probes[c.lesson];
    if (!probe) probe = std::make_unique<Runner>(c.lesson, makeLesson(c.lesson), RunOptions{});
    probe->params().resetToDefaults();
    if (!probe->applySets(c.sets).empty()) return std::string();  // a bad value: run reports it
    return probe->checkConsistency();
  };
  size_t skipped = 0;
  const auto add = [&](Config c) {
    if (const std::string why = refused(c); !why.empty()) {
      if (skipped++ == 0)
        std::fprintf(stderr, "bench_sweep: %s, %s: left out (%s)\n", name.c_str(), c.scene.c_str(),
                     why.c_str());
      return;
    }
    configs.push_back(std::move(c));
  };
  const auto done = [&] {
    if (skipped > 1) {
      std::fprintf(stderr, "bench_sweep: %s: %zu configurations the lesson refuses left out\n",
                   name.c_str(), skipped);
    }
    return configs;
  };
  if (o.smoke) {
    // Three tiny runs that still touch both ends of every axis and two scenes.
    std::vector<size_t> first(axes.size(), 0), last(axes.size());
    for (size_t a = 0; a < axes.size(); ++a) last[a] = axes[a].values.size() - 1;
    std::vector<size_t> first_but_along = first;
    if (!axes.empty()) first_but_along[0] = last[0];
    add(make(scenes.front(), first));
    add(make(scenes.front(), first_but_along));
    add(make(scenes.size() > 1 ? scenes[1] : scenes.front(), last));
    return done();
  }
  for (const auto& scene : scenes) {
    std::vector<size_t> index(axes.size(), 0);
    for (;;) {
      add(make(scene, index));
      size_t a = 0;
      while (a < axes.size() && ++index[a] == axes[a].values.size()) index[a++] = 0;
      if (a == axes.size()) break;
    }
  }
  return done();
}

std::vector<std::string> rowSettings(const Sweep& sweep, const Table& t, size_t row) {
  std::vector<std::string> sets;
  for (const Axis& axis : sweep.axes) {
    for (const std::string& value : axis.values) {
      const auto [label, value_sets] = settingsOf(axis, value);
      if (label != t.cell(row, axis.name)) continue;
      sets.insert(sets.end(), value_sets.begin(), value_sets.end());
      break;
    }
  }
  return sets;
}

std::string describeConfigs(Table& t, const std::string& name, const Sweep& sweep) {
  const size_t settings_col = t.addColumn("settings", false);
  const size_t default_col = t.addColumn("is_default", true);
  // One parameter set at its defaults per lesson that renders this sweep (no GL).
  std::map<std::string, std::unique_ptr<Runner>> probes;
  auto paramsOf = [&](const std::string& lesson) -> Params& {
    auto& probe = probes[lesson];
    if (!probe) probe = std::make_unique<Runner>(lesson, makeLesson(lesson), RunOptions{});
    return probe->params();
  };
  // A setting is at its default when assigning it leaves the parameter's text unchanged.
  auto atDefault = [&](const std::string& lesson, const std::string& set) {
    Params& defaults = paramsOf(lesson);
    const std::string param = set.substr(0, set.find('='));
    const Param* p = defaults.find(param);
    if (p == nullptr) return false;
    Params changed = defaults;
    return changed.assign(set).empty() && changed.at(param).text() == p->text();
  };
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string> sets = rowSettings(sweep, t, r);
    std::string lesson = sweep.study ? t.cell(r, "lesson") : name;
    std::string text;
    bool is_default = !lesson.empty() && !sets.empty();
    if (sweep.study) {  // a study's axes are its own words: map=D24, not five settings
      for (const Axis& axis : sweep.axes) {
        text += (text.empty() ? "" : " ") + axis.name + "=" + t.cell(r, axis.name);
      }
    }
    for (const std::string& set : sets) {
      if (set.starts_with("lesson=")) continue;
      if (!sweep.study) text += (text.empty() ? "" : " ") + set;
      is_default = is_default && atDefault(lesson, set);
    }
    t.rows[r][settings_col] = text;
    t.rows[r][default_col] = is_default ? "1" : "0";
  }
  if (sweep.study) return {};
  // The lesson's defaults of every parameter the sweep's axes set, for the plot's key.
  std::vector<std::string> names;
  for (const Axis& axis : sweep.axes) {
    for (const std::string& value : axis.values) {
      for (const std::string& set : settingsOf(axis, value).second) {
        const std::string param = set.substr(0, set.find('='));
        if (std::find(names.begin(), names.end(), param) == names.end()) names.push_back(param);
      }
    }
  }
  std::string defaults;
  for (const std::string& param : names) {
    if (const Param* p = paramsOf(name).find(param)) {
      defaults += (defaults.empty() ? "" : " ") + param + "=" + p->text();
    }
  }
  return defaults;
}

}  // namespace shadows::bench
