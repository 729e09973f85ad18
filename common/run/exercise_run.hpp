// The exercise a run works on (lesson/exercise.hpp), chosen by --exercise, --grade or the
// panel's selector: its checks on the command line, the sliders it locks, its verdict on each
// truth, the student's settings saved for the grader (--settings), and the grade's line. The
// Runner chooses (Runner::chooseExercise: parameters reset, the exercise's settings applied)
// and hands it the report each verdict reads.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lesson/exercise.hpp"

namespace shadows {

struct RunOptions;
class JsonWriter;
class Params;

// The picture an exercise is judged on, everywhere: --grade, a window or a page with an
// exercise chosen (fragment counts and texels per pixel depend on the picture's size).
inline constexpr int kExerciseWidth = 640, kExerciseHeight = 480;

class ExerciseRun {
 public:
  // `all`: the lesson's exercises; `lesson`: its name, in the lines it writes.
  ExerciseRun(std::vector<Exercise> all, Params& params, const std::string& lesson)
      : all_(std::move(all)), params_(params), lesson_(lesson) {}

  // The exercise chosen (null: none) and its verdict on the last truth measured (no figures
  // before the first).
  const Exercise* chosen() const { return chosen_ ? &*chosen_ : nullptr; }
  int number() const { return number_; }  // its number (1-based; 0: none)
  const Verdict& verdict() const { return verdict_; }
  bool judged() const { return judged_at_ >= 0; }
  // The command line's exercise, before any setting is applied.
  void pick(int n);
  // "" or why the command line's exercise cannot run: no such exercise, or (grading) a --set
  // of a parameter it does not let a student move.
  std::string problem(const RunOptions& options) const;
  // Exercise n (0: none) chosen, no verdict yet; "" or why not (the choice is then none).
  std::string select(int n);
  // The panel's sliders the exercise does not allow, locked (none without one).
  void lockWidgets();
  // Whether the truth measured `measured` (TruthMeasure::measured()) still needs a verdict,
  // and the verdict on it from the report's own numbers.
  bool needsVerdict(long long measured) const { return chosen_ && judged_at_ != measured; }
  void judge(const JsonWriter& report, long long measured);
  // --grade N after its headless run: the verdict line on the report, the exit code (0 met).
  // `why_none`: "" or why the truth was not measured.
  int grade(const JsonWriter& report, const std::string& why_none) const;
  // The settings a student changed, one name=value a line (--settings reads them back): with
  // an exercise, only those it lets a student move. "" or why it could not write.
  std::string save(const std::string& path) const;
  std::string query() const;  // the same as a page's query (?exercise=1&a=b), for a link

 private:
  std::vector<std::string> changedSettings() const;

  std::vector<Exercise> all_;
  Params& params_;
  const std::string& lesson_;
  std::optional<Exercise> chosen_;
  int number_ = 0;
  Verdict verdict_;
  long long judged_at_ = -1;  // the truth (TruthMeasure::measured()) the verdict was made on
};

}  // namespace shadows
