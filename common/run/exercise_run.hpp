// The exercise a run works on (lesson/exercise.hpp), chosen by --exercise, --grade or the
// panel's selector: its starting settings, the sliders it locks, its verdict on each truth,
// the student's settings saved for the grader (--settings), and the grade itself.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lesson/exercise.hpp"

namespace shadows {

class Runner;

// The picture an exercise is judged on, everywhere: --grade, a window or a page with an
// exercise chosen (fragment counts and texels per pixel depend on the picture's size).
inline constexpr int kExerciseWidth = 640, kExerciseHeight = 480;

class ExerciseRun {
 public:
  explicit ExerciseRun(Runner& runner) : runner_(runner) {}

  // The exercise chosen (null: none) and its verdict on the last truth measured (no figures
  // before the first).
  const Exercise* chosen() const { return chosen_ ? &*chosen_ : nullptr; }
  const Verdict& verdict() const { return verdict_; }
  bool judged() const { return judged_at_ >= 0; }
  // "" or why the command line's exercise cannot run: no such exercise, or (grading) a --set
  // of a parameter it does not let a student move.
  std::string problem() const;
  // Chooses exercise n (0: none) in a running lesson, as the panel's selector does: every
  // parameter back to its default, the exercise's own settings, the sliders it does not let a
  // student move locked, the window at the grader's picture size. "" or why not.
  std::string choose(int n);
  // The settings a student changed, one name=value a line (--settings reads them back): with
  // an exercise, only those it lets a student move. "" or why it could not write.
  std::string save(const std::string& path) const;
  std::string query() const;  // the same as a page's query (?exercise=1&a=b), for a link

 private:
  friend class Runner;
  friend class ErrorMeasure;
  void pick(int n);    // the command line's exercise, before any setting is applied
  void judge();        // after a truth is installed: the verdict on it, once per truth
  void lockWidgets();  // the panel's sliders the exercise does not allow, locked
  int grade();         // --grade N after its headless run: the verdict line, the exit code
  std::vector<std::string> changedSettings() const;

  Runner& runner_;
  std::optional<Exercise> chosen_;
  Verdict verdict_;
  long long judged_at_ = -1;  // the truth (TruthMeasure::measured()) the verdict was made on
};

}  // namespace shadows
