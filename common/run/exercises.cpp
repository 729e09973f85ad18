// The exercise a run was started with (--exercise N, --grade N; lesson/exercise.hpp): its
// checks on the command line, its starting settings, its verdict on each truth, the grade.
#include <algorithm>
#include <cstdio>
#include <fstream>

#include "core/json.hpp"
#include "run/runner.hpp"

namespace shadows {

std::string Runner::exerciseProblem() const {
  if (options_.exercise == 0) return {};
  const std::string flag =
      std::string(options_.grade ? "--grade " : "--exercise ") + std::to_string(options_.exercise);
  if (!exercise_.chosen) {
    const size_t count = lesson_->exercises().size();
    return flag + ": " + name_ + " has " +
           (count == 0 ? std::string("no exercises")
                       : "exercises 1.." + std::to_string(count) + " (docs/EXERCISES.md)");
  }
  if (!options_.grade) return {};
  // A submission moves only what the exercise lets a student move.
  for (const std::string& set : options_.sets) {
    const std::string name = set.substr(0, set.find('='));
    if (allowedIn(*exercise_.chosen, name)) continue;
    std::string allowed;
    for (const std::string& a : exercise_.chosen->allowed)
      allowed += (allowed.empty() ? "" : ", ") + a;
    return flag + ": the exercise lets you set " + allowed +
           (exercise_.chosen->camera_free ? ", camera.* and view" : " and view (not the camera)") +
           "; not " + name;
  }
  return {};
}

std::string Runner::applyStartingSettings() {
  if (std::string problem = exerciseProblem(); !problem.empty()) return problem;
  // An exercise starts from its own settings; the student's come after them.
  std::vector<std::string> sets =
      exercise_.chosen ? exercise_.chosen->setup : std::vector<std::string>{};
  sets.insert(sets.end(), options_.sets.begin(), options_.sets.end());
  // A grade is measured on the lesson's own frame: a debug view (or the runner's truth and
  // error views, where the lesson draws nothing) would leave its counters out.
  if (options_.grade && exercise_.chosen) sets.push_back("view=shaded");
  lockExerciseWidgets();
  return applySets(sets);
}

std::string Runner::chooseExercise(int n) {
  std::vector<Exercise> all = lesson_->exercises();
  if (n < 0 || n > static_cast<int>(all.size())) {
    return "exercise " + std::to_string(n) + ": " + name_ + " has " + std::to_string(all.size()) +
           " exercises";
  }
  const std::string view = params_.at("view").choice();
  params_.resetToDefaults();
  exercise_ = {};
  options_.exercise = n;
  std::string problem;
  if (n > 0) {
    exercise_.chosen = std::move(all[static_cast<size_t>(n - 1)]);
    problem = applySets(exercise_.chosen->setup);
  }
  params_.setChoice(params_.at("view"), view);  // the student's view stays
  lockExerciseWidgets();
  // Judged on the grader's picture size (a page fits its canvas so too: page_main.cpp).
  if (n > 0 && !options_.size_given) {
    fitWindow(kExerciseWidth + (options_.hide_panel ? 0 : static_cast<int>(kPanelColumn)),
              kExerciseHeight);
  }
  return problem;
}

void Runner::lockExerciseWidgets() {
  if (!exercise_.chosen) {
    params_.lockWidgets(nullptr);
    return;
  }
  const Exercise ex = *exercise_.chosen;
  const std::string why = "exercise " + std::to_string(options_.exercise) + " (" + ex.title +
                          ") does not let you move this";
  params_.lockWidgets([ex, why](const Param& p) { return allowedIn(ex, p.name) ? "" : why; });
}

// What a student changed, as name=value lines: with an exercise, what it lets them move.
std::vector<std::string> Runner::changedSettings() const {
  std::vector<std::string> lines;
  for (const Param& p : params_.all()) {
    if (p.name == "view") continue;
    if (exercise_.chosen && !allowedIn(*exercise_.chosen, p.name)) continue;
    const bool same =
        p.kind == ParamKind::String
            ? p.string_value == p.string_fallback
            : std::equal(std::begin(p.value), std::end(p.value), std::begin(p.fallback));
    if (!same) lines.push_back(p.name + "=" + p.text());
  }
  return lines;
}

std::string Runner::saveSettings(const std::string& path) const {
  std::ofstream out(path);
  out << "# " << name_ << " settings: " << name_ << " --settings " << path;
  if (exercise_.chosen) {
    out << "\n# exercise " << options_.exercise << ": " << exercise_.chosen->title
        << "\n# grade it: " << name_ << " --grade " << options_.exercise << " --settings " << path;
  }
  out << "\n";
  for (const std::string& line : changedSettings()) out << line << "\n";
  out.flush();
  return out ? "" : "cannot write " + path;
}

std::string Runner::settingsQuery() const {
  std::string query;
  if (exercise_.chosen) query = "exercise=" + std::to_string(options_.exercise);
  for (const std::string& line : changedSettings()) {
    query += (query.empty() ? "" : "&") + line;
  }
  return "?" + query;
}

void Runner::judgeExercise() {
  if (!exercise_.chosen || exercise_.judged_at == truth_.measured()) return;
  JsonWriter json;
  writeReport(json);  // the verdict reads the report's own numbers
  exercise_.verdict = evaluate(*exercise_.chosen, json);
  exercise_.judged_at = truth_.measured();
}

// --grade N: the headless run (its picture, outputs and summary line), then the verdict of
// exercise N on its truth, one line, and the exit code: 0 met, 1 not.
int Runner::runGrade() {
  if (const int code = runHeadless(); code != 0) return code;
  if (!truth_.error().valid) {
    std::printf("%s exercise %d: no verdict: %s\n", name_.c_str(), options_.exercise,
                haveTruth() ? "the truth was not measured" : truthUnavailable().c_str());
    return 1;
  }
  // On the numbers of the last frame, as the report written just before has them.
  JsonWriter json;
  writeReport(json);
  const Verdict v = evaluate(*exercise_.chosen, json);
  std::string figures;
  for (const FigureResult& f : v.figures) figures += (figures.empty() ? "" : "; ") + f.line();
  std::printf("%s exercise %d (%s): %s: %s\n", name_.c_str(), options_.exercise,
              exercise_.chosen->title.c_str(), v.met ? "MET" : "NOT MET", figures.c_str());
  return v.met ? 0 : 1;
}

}  // namespace shadows
