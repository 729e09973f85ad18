// main() of a lesson's web page. shell.html turns the page's query (?scene=dueling&size=640x480)
// into the command line (--set scene=dueling --size 640x480), which the lesson binaries' own
// parser reads; bad input is shown on the page as the same one line, and the lesson then runs
// with its defaults. The window loop (window.cpp) runs one frame per browser frame.
#include <emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "core/text.hpp"
#include "gl/gl.hpp"
#include "run/runner.hpp"

namespace {

using shadows::Runner;

std::unique_ptr<Runner> g_runner;
long long g_frames = 0;

// A line for the reader, on the page (not only in the console).
void notice(const std::string& line, const std::string& note) {
  std::fprintf(stderr, "%s\n", line.c_str());
  EM_ASM({ shadowsPage.notice(UTF8ToString($0), UTF8ToString($1)); }, line.c_str(), note.c_str());
}

void failed(const std::string& line) {
  std::fprintf(stderr, "%s\n", line.c_str());
  EM_ASM({ shadowsPage.failed(UTF8ToString($0)); }, line.c_str());
}

// The error line under the canvas: the last truth's numbers, or the worker's progress.
std::string errorSummary() {
  if (!shadows::haveTruth()) return shadows::truthUnavailable();
  char line[160];
  if (g_runner->errors().truth().running()) {
    std::snprintf(line, sizeof line, "tracing the truth (three-mesh-bvh, in Web Workers): %.0f %%",
                  100.0 * g_runner->errors().progress());
    return line;
  }
  const shadows::ErrorState& error = g_runner->host().lastError();
  if (g_runner->errors().truth().failed())
    return "the ray tracer failed: the browser's console says why";
  if (!error.valid) return "";
  // Lesson 08's air is measured on its own pixels, counted surfaces or not.
  char air[64] = "";
  if (error.metrics.air.valid) {
    std::snprintf(air, sizeof air, "; air mae %.4f", error.metrics.air.mae);
  }
  if (error.metrics.counted_pixels == 0) {
    return "error against the ray-traced truth: none counted (" +
           shadows::notCountedReason(error.metrics) + ")" + air;
  }
  std::snprintf(line, sizeof line,
                "error against the ray-traced truth: false shadow %.3f %%, false lit %.3f %%%s",
                error.metrics.false_shadow_pct, error.metrics.false_lit_pct, air);
  return line;
}

// The exercise's verdict on the last truth, one line, as --grade prints it: the page's
// grade of the settings in its address (?exercise=N&...).
std::string exerciseSummary() {
  const shadows::Exercise* ex = g_runner->exercises().chosen();
  if (ex == nullptr) return "";
  const shadows::Verdict& v = g_runner->exercises().verdict();
  std::string line =
      "\nexercise " + std::to_string(g_runner->exercises().number()) + " (" + ex->title + "): ";
  return line + (v.figures.empty() ? "measuring..." : v.line());
}

// Frame count, GL errors and truths measured every frame (the tests wait on them), the panel's
// cost lines four times a second or so.
void publish() {
  const bool text = g_frames % 15 == 1;
  const std::string cost = text ? g_runner->window().costSummary() : std::string();
  const std::string counters = text ? g_runner->window().counterSummary() : std::string();
  const std::string error = text ? errorSummary() + exerciseSummary() : std::string();
  EM_ASM(
      {
        shadowsPage.frame($0, $1, $2, $3 ? UTF8ToString($4) : null, UTF8ToString($5),
                          UTF8ToString($6));
      },
      static_cast<double>(g_frames), shadows::GlErrorLog::count(),
      static_cast<double>(g_runner->errors().truth().measured()), text ? 1 : 0, cost.c_str(),
      counters.c_str(), error.c_str());
}

// Without ?size= the canvas fills the page's stage (the browser's window less the header and
// the lines under it), picture and panel column, and follows it when the window is resized.
void fitCanvas() {
  if (g_runner->options().size_given) return;
  if (g_runner->exercises().chosen() != nullptr) {  // judged on the grader's picture, as natively
    g_runner->window().fitExercise();
    return;
  }
  double width = 0, height = 0;
  if (emscripten_get_element_css_size("#stage", &width, &height) != EMSCRIPTEN_RESULT_SUCCESS) {
    return;
  }
  // The shell's largestSide() (`!=`: clang-format splits a triple equals sign in C++ text).
  const int largest =
      EM_ASM_INT({ return typeof largest != 'undefined' && largest > 0 ? largest : 4096; });
  const auto fit = [&](double css, int least) {
    return std::clamp(static_cast<int>(css), least, std::max(least, largest));
  };
  g_runner->window().fit(fit(width, 480), fit(height, 240));
}

void frame() {
  try {
    fitCanvas();
    const bool more = g_runner->window().frame();
    ++g_frames;
    publish();
    if (!more) {
      g_runner->window().end();
      emscripten_cancel_main_loop();
    }
  } catch (const std::exception& e) {
    failed(g_runner->lessonName() + ": " + shadows::printable(e.what()));
    emscripten_cancel_main_loop();
  }
}

}  // namespace

extern "C" EMSCRIPTEN_KEEPALIVE void shadows_screenshot() {
  if (g_runner) g_runner->window().requestScreenshot();
}

// A parameter set from the page's JavaScript ("view=maps"), for the page tests: every view of a
// lesson in one page, the truth traced once for the truth and error views. It goes through
// the parser as --set does, not the panel's locks (an exercise's), which a test does not need.
// Returns "" or the command line's one line for a bad assignment.
extern "C" EMSCRIPTEN_KEEPALIVE const char* shadows_set(const char* assignment) {
  static std::string said;
  said = g_runner ? g_runner->params().assign(assignment) : "the lesson has not started";
  return said.c_str();
}

// A parameter's value as --set takes it ("" for an unknown name): the page tests read back
// what they set.
extern "C" EMSCRIPTEN_KEEPALIVE const char* shadows_get(const char* name) {
  static std::string value;
  const shadows::Param* p = g_runner ? g_runner->params().find(name) : nullptr;
  value = p != nullptr ? p->text() : "";
  return value.c_str();
}

int main(int argc, char** argv) {
  // A page holds one lesson, or one that hosts others (lesson 16) with theirs.
  const std::string name = shadows::registeredHosts().empty() ? shadows::registeredLessons().at(0)
                                                              : shadows::registeredHosts().at(0);
  const auto make = [&](shadows::RunOptions options) {
    options.force_window = true;
    return std::make_unique<Runner>(name, shadows::makeLesson(name), options);
  };
  try {
    shadows::RunOptions options;
    std::string problem = shadows::parseCommandLine(argc, argv, options);
    if (problem.empty()) {
      g_runner = make(options);
      problem = g_runner->applyStartingSettings();
      if (problem.empty()) problem = g_runner->checkConsistency();
    }
    if (!problem.empty()) {
      // The command line's message, word for word; then the lesson's defaults (at the size
      // asked for, when that was not what was wrong), as a student expects.
      notice(name + ": " + shadows::printable(problem), "running with the defaults instead");
      shadows::RunOptions defaults;
      if (g_runner) {
        defaults = options;
        defaults.sets.clear();
        defaults.exercise = 0;
      }
      g_runner = make(defaults);
    }
    if (!g_runner->window().begin()) {
      failed(name + ": cannot open a WebGL 2 canvas");
      return 1;
    }
  } catch (const std::exception& e) {
    failed(name + ": " + shadows::printable(e.what()));
    return 1;
  }
  emscripten_set_main_loop(frame, 0, true);
  return 0;
}
