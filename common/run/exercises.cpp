// ExerciseRun (run/exercise_run.hpp): the exercise a run was started with or chose, its checks
// on the command line, its starting settings and locks, its verdict on each truth, the
// student's settings for the grader, and the grade.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/json.hpp"
#include "core/output_files.hpp"
#include "gl/caps.hpp"
#include "run/runner.hpp"

namespace shadows {

void ExerciseRun::pick(int n) {
  std::vector<Exercise> all = runner_.lesson_->exercises();
  if (n > 0 && n <= static_cast<int>(all.size())) {
    chosen_ = std::move(all[static_cast<size_t>(n - 1)]);
  }
}

std::string ExerciseRun::problem() const {
  const RunOptions& options = runner_.options_;
  if (options.exercise == 0) return {};
  const std::string flag =
      std::string(options.grade ? "--grade " : "--exercise ") + std::to_string(options.exercise);
  if (!chosen_) {
    const size_t count = runner_.lesson_->exercises().size();
    return flag + ": " + runner_.name_ + " has " +
           (count == 0 ? std::string("no exercises")
                       : "exercises 1.." + std::to_string(count) + " (docs/EXERCISES.md)");
  }
  // A submission, or a page's link, moves only what the exercise lets a student move: a
  // setting the grader refuses cannot show a verdict in the window or the page either.
  for (const std::string& set : options.sets) {
    const std::string name = set.substr(0, set.find('='));
    if (allowedIn(*chosen_, name)) continue;
    std::string allowed;
    for (const std::string& a : chosen_->allowed) allowed += (allowed.empty() ? "" : ", ") + a;
    return flag + ": the exercise lets you set " + allowed +
           (chosen_->camera_free ? ", camera.* and view" : " and view (not the camera)") +
           "; not " + name;
  }
  return {};
}

std::string Runner::applyStartingSettings() {
  if (std::string problem = exercise_.problem(); !problem.empty()) return problem;
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

std::string ExerciseRun::choose(int n) {
  std::vector<Exercise> all = runner_.lesson_->exercises();
  if (n < 0 || n > static_cast<int>(all.size())) {
    return "exercise " + std::to_string(n) + ": " + runner_.name_ + " has " +
           std::to_string(all.size()) + " exercises";
  }
  Params& params = runner_.params_;
  const std::string view = params.at("view").choice();
  params.resetToDefaults();
  // The defaults' scene now, before the exercise's light and camera: a scene loaded later
  // (renderInto, after the panel) would put the preset's light back over the exercise's.
  if (params.consume(kDirtyScene)) runner_.loadScene();
  chosen_.reset();
  verdict_ = {};
  judged_at_ = -1;
  runner_.options_.exercise = n;
  std::string problem;
  if (n > 0) {
    chosen_ = std::move(all[static_cast<size_t>(n - 1)]);
    problem = runner_.applySets(chosen_->setup);
  }
  params.setChoice(params.at("view"), view);  // the student's view stays
  lockWidgets();
  // The sliders the exercise lets a student move are in view, folded sections opened once.
  if (chosen_) {
    for (const Param& p : params.all()) {
      if (!p.shared || !allowedIn(*chosen_, p.name) || p.name == "view") continue;
      const bool light = p.name.rfind("light.", 0) == 0 || p.name.rfind("camera.", 0) == 0;
      runner_.window_.unfold.insert(light ? "Light and camera" : "Shadow map");
    }
  }
  // Where the truth already measured is this very start, its verdict now, not "measuring...".
  if (chosen_ && runner_.errors_.truth().key() == runner_.errors_.key()) judge();
    // Judged on the grader's picture size: a page fits its canvas so (page_main.cpp); a window
    // keeps its size and draws the picture at that size in a corner (RunnerWindow::frame).
#ifdef __EMSCRIPTEN__
  if (n > 0 && !runner_.options_.size_given) runner_.window_.fitExercise();
#endif
  return problem;
}

void ExerciseRun::lockWidgets() {
  if (!chosen_) {
    runner_.params_.lockWidgets(nullptr);
    return;
  }
  const Exercise ex = *chosen_;
  const std::string why = "exercise " + std::to_string(runner_.options_.exercise) + " (" +
                          ex.title + ") does not let you move this";
  runner_.params_.lockWidgets(
      [ex, why](const Param& p) { return allowedIn(ex, p.name) ? "" : why; });
}

// What a student set, as name=value lines: with an exercise, every parameter it lets them
// move (a fix that puts one back to its default is an answer too: the grader starts from the
// exercise's settings, not the defaults); without one, what differs from the defaults.
std::vector<std::string> ExerciseRun::changedSettings() const {
  std::vector<std::string> lines;
  for (const Param& p : runner_.params_.all()) {
    if (p.name == "view") continue;
    if (chosen_) {
      if (allowedIn(*chosen_, p.name)) lines.push_back(p.name + "=" + p.text());
      continue;
    }
    if (!p.atDefault()) lines.push_back(p.name + "=" + p.text());
  }
  return lines;
}

std::string ExerciseRun::save(const std::string& path) const {
  const std::string& name = runner_.name_;
  const int n = runner_.options_.exercise;
  std::ostringstream out;
  out << "# " << name << " settings: " << name << " --settings " << path;
  if (chosen_) {
    out << "\n# exercise " << n << ": " << chosen_->title << "\n# grade it: " << name << " --grade "
        << n << " --settings " << path;
  }
  out << "\n";
  for (const std::string& line : changedSettings()) out << line << "\n";
  // As every output: a temporary renamed over the file, never half a submission.
  return writeOutputFile(path, out.str()) ? "" : "cannot write " + path;
}

std::string ExerciseRun::query() const {
  std::string query;
  if (chosen_) query = "exercise=" + std::to_string(runner_.options_.exercise);
  for (const std::string& line : changedSettings()) {
    query += (query.empty() ? "" : "&") + line;
  }
  return "?" + query;
}

void ExerciseRun::judge() {
  const TruthMeasure& truth = runner_.errors_.truth();
  if (!chosen_ || judged_at_ == truth.measured()) return;
  JsonWriter json;
  runner_.writeReport(json);  // the verdict reads the report's own numbers
  verdict_ = evaluate(*chosen_, json);
  judged_at_ = truth.measured();
}

// --grade N: the headless run (its picture, outputs and summary line), then the verdict of
// exercise N on its truth, one line, and the exit code: 0 met, 1 not.
int ExerciseRun::grade() {
  if (const int code = runner_.headless_.run(); code != 0) return code;
  const std::string& name = runner_.name_;
  const int n = runner_.options_.exercise;
  if (!runner_.errors_.truth().error().valid) {
    std::printf("%s exercise %d: no verdict: %s\n", name.c_str(), n,
                haveTruth() ? "the truth was not measured" : truthUnavailable().c_str());
    return 1;
  }
  // On the numbers of the last frame, as the report written just before has them.
  JsonWriter json;
  runner_.writeReport(json);
  const Verdict v = evaluate(*chosen_, json);
  // A figure this build cannot measure (05's taps on GL 4.1 and ES: no storage buffers) is no
  // answer either way; a figure over nothing (no fragment filtered) is one: not met, its reason
  // in the line.
  for (const FigureResult& f : v.figures) {
    if (!f.known() && !f.not_counted) {
      std::printf("%s exercise %d: no verdict: %s is not measured here (%s)\n", name.c_str(), n,
                  f.figure->label.c_str(), caps().flavour.c_str());
      return 1;
    }
  }
  std::printf("%s exercise %d (%s): %s\n", name.c_str(), n, chosen_->title.c_str(),
              v.line().c_str());
  return v.met ? 0 : 1;
}

}  // namespace shadows
