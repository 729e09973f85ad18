// The exercise a run was started with (--exercise N, --grade N; lesson/exercise.hpp): its
// checks on the command line, its starting settings, its verdict on each truth, the grade.
#include <cstdio>

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
  return applySets(sets);
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
