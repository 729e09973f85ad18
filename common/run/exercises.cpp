// ExerciseRun (run/exercise_run.hpp): the exercise a run was started with or chose, its checks
// on the command line, its locks, its verdict on each truth, the student's settings for the
// grader, and the grade's line.
#include "run/exercise_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/json.hpp"
#include "core/output_files.hpp"
#include "core/params.hpp"
#include "gl/caps.hpp"
#include "run/run_options.hpp"

namespace shadows {

void ExerciseRun::pick(int n) {
  number_ = n;
  if (n > 0 && n <= static_cast<int>(all_.size())) chosen_ = all_[static_cast<size_t>(n - 1)];
}

std::string ExerciseRun::problem(const RunOptions& options) const {
  if (options.exercise == 0) return {};
  const std::string flag =
      std::string(options.grade ? "--grade " : "--exercise ") + std::to_string(options.exercise);
  if (!chosen_) {
    const size_t count = all_.size();
    return flag + ": " + lesson_ + " has " +
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

std::string ExerciseRun::select(int n) {
  if (n < 0 || n > static_cast<int>(all_.size())) {
    return "exercise " + std::to_string(n) + ": " + lesson_ + " has " +
           std::to_string(all_.size()) + " exercises";
  }
  chosen_.reset();
  verdict_ = {};
  judged_at_ = -1;
  number_ = n;
  if (n > 0) chosen_ = all_[static_cast<size_t>(n - 1)];
  return {};
}

void ExerciseRun::lockWidgets() {
  if (!chosen_) {
    params_.lockWidgets(nullptr);
    return;
  }
  const Exercise ex = *chosen_;
  const std::string why =
      "exercise " + std::to_string(number_) + " (" + ex.title + ") does not let you move this";
  params_.lockWidgets([ex, why](const Param& p) { return allowedIn(ex, p.name) ? "" : why; });
}

// What a student set, as name=value lines: with an exercise, every parameter it lets them
// move (a fix that puts one back to its default is an answer too: the grader starts from the
// exercise's settings, not the defaults); without one, what differs from the defaults.
std::vector<std::string> ExerciseRun::changedSettings() const {
  std::vector<std::string> lines;
  for (const Param& p : params_.all()) {
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
  const std::string& name = lesson_;
  const int n = number_;
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
  if (chosen_) query = "exercise=" + std::to_string(number_);
  for (const std::string& line : changedSettings()) {
    query += (query.empty() ? "" : "&") + line;
  }
  return "?" + query;
}

void ExerciseRun::judge(const JsonWriter& report, long long measured) {
  if (!chosen_) return;
  verdict_ = evaluate(*chosen_, report);  // the verdict reads the report's own numbers
  judged_at_ = measured;
}

// --grade N: after the headless run (its picture, outputs and summary line), the verdict of
// exercise N on its truth, one line, and the exit code: 0 met, 1 not.
int ExerciseRun::grade(const JsonWriter& report, const std::string& why_none) const {
  const std::string& name = lesson_;
  const int n = number_;
  if (!why_none.empty()) {
    std::printf("%s exercise %d: no verdict: %s\n", name.c_str(), n, why_none.c_str());
    return 1;
  }
  // On the numbers of the last frame, as the report written just before has them.
  const Verdict v = evaluate(*chosen_, report);
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
