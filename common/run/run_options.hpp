// What the command line asks of a run (command_line.cpp parses it): headless or a window, the
// picture's size, the frames, the truth and the outputs, the --set list, an exercise.
#pragma once

#include <string>
#include <vector>

namespace shadows {

struct RunOptions {
  bool headless = false;
  bool force_window = false;
  std::string backend;  // a headless context (headlessBackends()); empty: the build's default
  int device = 0;       // --device: the EGL device of --backend egl-device
  int width = 800, height = 600;  // the picture's (a window sets them to what it shows)
  int frames = 5;
  bool frames_given = false;  // --frames on the command line: a window run stops after them
  bool panel = false;         // draw the ImGui panel into headless snapshots too
  bool hide_panel = false;    // a window starts without the panel (RunnerWindow's H key)
  int orbit = 0;              // a window turns the camera this many degrees a frame, as a drag
  bool truth = true;          // measure error against the ray-traced truth
  std::string out, report, truth_out, error_out;
  // The truth's job and its trace as bytes (truth_job.hpp), and a trace to use instead of
  // tracing (another tracer's answer to this very job, e.g. web/truth's).
  std::string truth_job, truth_result, truth_from;
  // Whether the run measures the truth: asked for, or an output that needs it.
  bool truthAsked() const {
    return truth || !truth_out.empty() || !error_out.empty() || !truth_job.empty() ||
           !truth_result.empty() || !truth_from.empty();
  }
  std::vector<std::string> sets;
  bool list_params = false, help = false;
  bool size_given = false;  // --size on the command line
  int exercise = 0;         // --exercise N or --grade N: the lesson's exercise N (1-based)
  bool grade = false;       // --grade N: headless, the verdict its exit code
};

// Parses argv. Returns "" or one line naming what is wrong (the caller exits 2).
std::string parseCommandLine(int argc, char** argv, RunOptions& options);

}  // namespace shadows
