// A run from its start to its exit code: the starting settings (an exercise's, then the
// command line's), the exercise chosen later and its verdicts, headless or a window, the grade.
#include <cstdio>
#include <cstdlib>

#include "core/json.hpp"
#include "core/text.hpp"
#include "run/runner.hpp"

namespace shadows {

std::string Runner::applyStartingSettings() {
  if (std::string problem = exercise_.problem(options_); !problem.empty()) return problem;
  // An exercise starts from its own settings; the student's come after them.
  std::vector<std::string> sets =
      exercise_.chosen() ? exercise_.chosen()->setup : std::vector<std::string>{};
  sets.insert(sets.end(), options_.sets.begin(), options_.sets.end());
  // A grade is measured on the lesson's own frame: a debug view (or the runner's truth and
  // error views, where the lesson draws nothing) would leave its counters out.
  if (options_.grade && exercise_.chosen()) sets.push_back("view=shaded");
  exercise_.lockWidgets();
  return applySets(sets);
}

std::string Runner::chooseExercise(int n) {
  const std::string view = params_.at("view").choice();
  if (std::string why = exercise_.select(n); !why.empty()) return why;
  params_.resetToDefaults();
  // The defaults' scene now, before the exercise's light and camera: a scene loaded later
  // (render, after the panel) would put the preset's light back over the exercise's.
  if (params_.consume(kDirtyScene)) loadScene();
  const Exercise* chosen = exercise_.chosen();
  const std::string problem = chosen ? applySets(chosen->setup) : "";
  params_.setChoice(params_.at("view"), view);  // the student's view stays
  exercise_.lockWidgets();
  // The sliders the exercise lets a student move are in view, folded sections opened once.
  if (chosen) {
    for (const Param& p : params_.all()) {
      if (!p.shared || !allowedIn(*chosen, p.name) || p.name == "view") continue;
      const bool light = p.name.rfind("light.", 0) == 0 || p.name.rfind("camera.", 0) == 0;
      window_.unfold.insert(light ? "Light and camera" : "Shadow map");
    }
  }
  // Where the truth already measured is this very start, its verdict now, not "measuring...".
  if (chosen && errors_.truth().key() == errors_.key()) judgeExercise();
    // Judged on the grader's picture size: a page fits its canvas so (page_main.cpp); a window
    // keeps its size and draws the picture at that size in a corner (RunnerWindow::frame).
#ifdef __EMSCRIPTEN__
  if (n > 0 && !options_.size_given) window_.fitExercise();
#endif
  return problem;
}

void Runner::judgeExercise() {
  const long long measured = errors_.truth().measured();
  if (!exercise_.needsVerdict(measured)) return;
  JsonWriter json;
  writeReport(json);  // the verdict reads the report's own numbers
  exercise_.judge(json, measured);
}

int Runner::grade() {
  if (const int code = headless_.run(); code != 0) return code;
  const std::string why_none = errors_.truth().error().valid ? ""
                               : haveTruth()                 ? "the truth was not measured"
                                                             : truthUnavailable();
  JsonWriter json;
  if (why_none.empty()) writeReport(json);
  return exercise_.grade(json, why_none);
}

int Runner::run() {
  if (!options_.truth_from.empty()) {
    try {
      errors_.truth().given = readTruthTrace(options_.truth_from);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "%s: --truth-from: %s\n", name_.c_str(), printable(e.what()).c_str());
      return 2;
    }
  }
  try {
    return options_.grade ? grade() : runHeadlessOrWindow();
  } catch (const TruthMismatch& e) {
    std::fprintf(stderr, "%s: %s\n", name_.c_str(), printable(e.what()).c_str());
    return 2;
  }
}

int Runner::runHeadlessOrWindow() {
  const char* display = std::getenv("DISPLAY");
  const bool has_display = display != nullptr && *display != '\0';
  if (options_.headless || (!has_display && !options_.force_window)) {
    // Said on stderr, as every diagnostic: `--report /dev/stdout` stays the report alone.
    if (!options_.headless)
      std::fprintf(stderr, "%s: no display, rendering headless\n", name_.c_str());
    return headless_.run();
  }
  const int result = window_.run();
  if (result != RunnerWindow::kNoWindow) return result;
  const std::string why = printable(window_.error.empty() ? "unknown reason" : window_.error);
  if (options_.force_window) {
    std::fprintf(stderr, "%s: cannot open a window (%s)\n", name_.c_str(), why.c_str());
    return 1;
  }
  // A DISPLAY that leads nowhere (a closed ssh tunnel, a stale variable): say so once, go on.
  std::fprintf(stderr, "%s: cannot open a window on DISPLAY=%s (%s), rendering headless\n",
               name_.c_str(), has_display ? printable(display).c_str() : "", why.c_str());
  return headless_.run();
}

}  // namespace shadows
