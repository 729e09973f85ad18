// An exercise: a goal a student reaches with a few of a lesson's sliders, stated in the
// lesson's own measured figures (the report's numbers: the error against the ray-traced
// truth, deterministic counters, derived fields; never a wall-clock time). The panel shows
// it live (--exercise N), and `--grade N` gives an instructor the verdict (docs/EXERCISES.md).
#pragma once

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "core/json.hpp"

namespace shadows {

// One figure of the goal: the report's number at `pointer` against a bound.
struct Figure {
  std::string pointer;  // a JSON pointer into the report: "/error/false_lit_pct"
  std::string label;    // how the panel and the verdict name it: "false lit %"
  enum class Bound { AtMost, AtLeast } bound = Bound::AtMost;
  double value = 0.0;
};

struct Exercise {
  std::string title;  // one line: what the exercise is about
  std::string goal;   // the goal in words, with its numbers
  // Settings the exercise starts from (a scene, a broken method): applied first, not the
  // student's to change unless also allowed.
  std::vector<std::string> setup;
  // The parameters a student may move; `view` always may (a grade is measured on the shaded
  // frame, whatever it says; the panel's figures on the frame shown), the camera
  // (camera.*) only where the exercise says so: the figures are measured in the picture the
  // camera sees, and looking away from a problem is no answer.
  std::vector<std::string> allowed;
  bool camera_free = false;
  std::vector<Figure> figures;  // all must hold
  std::string hint;             // shown after a while in the panel
};

// One figure measured against its bound.
struct FigureResult {
  const Figure* figure = nullptr;
  std::optional<double> measured;  // empty or NaN: not measured (no pixel counted, ...)
  // Why a figure is null over nothing (JsonWriter::notCounted): "no fragment was filtered".
  // Such a figure is not met. Empty where it is null for another reason (a counter the
  // context cannot count: no verdict at all, ExerciseRun::grade).
  std::optional<std::string> not_counted;
  bool met = false;
  bool known() const { return measured && std::isfinite(*measured); }
  // "false lit % 0.06044 <= 0.07: met", "filter taps none (no fragment was filtered) <= 16:
  // not met"
  std::string line() const {
    std::string value = "not measured";
    if (known()) {
      char text[32];
      std::snprintf(text, sizeof text, "%.4g", *measured);
      value = text;
    } else if (not_counted) {
      value = "none (" + *not_counted + ")";
    }
    char bound[48];
    std::snprintf(bound, sizeof bound, " %s %g: %s",
                  figure->bound == Figure::Bound::AtMost ? "<=" : ">=", figure->value,
                  met ? "met" : "not met");
    return figure->label + " " + value + bound;
  }
};

struct Verdict {
  std::vector<FigureResult> figures;
  bool met = false;
  // "MET: false lit % 0.06 <= 0.07: met; ..." or "NOT MET: ...": the grader's line, and a
  // page's under its canvas.
  std::string line() const {
    std::string text = met ? "MET: " : "NOT MET: ";
    for (size_t i = 0; i < figures.size(); ++i) text += (i ? "; " : "") + figures[i].line();
    return text;
  }
};

// The exercise's figures read from a report written with JsonWriter.
inline Verdict evaluate(const Exercise& exercise, const JsonWriter& report) {
  Verdict v;
  v.met = !exercise.figures.empty();
  for (const Figure& f : exercise.figures) {
    FigureResult r;
    r.figure = &f;
    r.measured = report.number(f.pointer);
    r.not_counted = report.whyNotCounted(f.pointer);
    const bool known = r.known();
    r.met = known &&
            (f.bound == Figure::Bound::AtMost ? *r.measured <= f.value : *r.measured >= f.value);
    v.met = v.met && r.met;
    v.figures.push_back(r);
  }
  return v;
}

// Whether `name` may be set by a student in this exercise.
inline bool allowedIn(const Exercise& exercise, const std::string& name) {
  if (name == "view" || (exercise.camera_free && name.rfind("camera.", 0) == 0)) return true;
  for (const std::string& a : exercise.allowed) {
    if (a == name) return true;
  }
  return false;
}

}  // namespace shadows
