// The command line of every lesson binary, and its main().
#include "run/runner.hpp"

#include "core/arguments.hpp"
#include "core/json.hpp"
#include "core/output_files.hpp"
#include "core/text.hpp"
#include "gl/context.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

namespace shadows {

// ---------------------------------------------------------------- command line

namespace {

const char* kUsage =
    "usage: %s [options]\n"
    "  (no option)          a window with the ImGui panel if a display exists, else headless\n"
    "  --headless           render without a display (OSMesa) and write --out\n"
    "  --window             a window even when DISPLAY is unset (fails without a display)\n"
    "  --backend NAME       headless context: osmesa (the default on desktop GL), egl\n"
    "                       (surfaceless; the default on OpenGL ES), egl-device (a GPU\n"
    "                       without a display, EGL_EXT_platform_device) or glfw (a\n"
    "                       hidden window: macOS)\n"
    "  --device N           the EGL device of --backend egl-device (default 0; a wrong\n"
    "                       one lists those there are)\n"
    "  --size WxH           image size (default 800x600; a window without it: 1280x720,\n"
    "                       the picture beside the panel's column)\n"
    "  --frames N           timed frames after one warm-up frame (default 5; in a window:\n"
    "                       render N frames, the last once a truth being traced is\n"
    "                       done, write the outputs asked for, exit)\n"
    "  --out FILE.png       write the final frame (default out/LESSON.png; in a window:\n"
    "                       --frames frames, then exit). Outputs may be links (written\n"
    "                       through), devices or pipes (written in place), /dev/stdout\n"
    "  --panel              draw the ImGui panel into the headless picture too\n"
    "  --hide-panel         a window without the panel (the key H shows and hides it)\n"
    "  --orbit DEG          in a window, turn the camera DEG degrees (1..90) around its\n"
    "                       target every frame, as a mouse drag does (to time a moving window)\n"
    "  --set name=value     set a parameter (repeatable); see --list-params\n"
    "  --settings FILE      the settings in FILE, one name=value a line (what the panel's\n"
    "                       \"Save settings\" writes), as --sets in their place\n"
    "  --list-params        list every parameter: name, type, default, range, help\n"
    "  --report FILE.json   parameters, timings, work counters, error against the truth\n"
    "  --truth-out FILE.png the ray-traced truth (white lit, black shadowed)\n"
    "  --error-out FILE.png the mistakes: magenta false shadow, cyan false lit\n"
    "  --no-truth           skip the ray-traced truth (faster)\n"
    "  --truth-job FILE     the truth's job: triangles, surfaces, light, air (bytes; see\n"
    "                       web/truth/README.md), for another tracer to trace\n"
    "  --truth-result FILE  the trace the metrics came from (Embree's, or --truth-from's)\n"
    "  --truth-from FILE    take the truth from a trace of this run's job (web/truth's)\n"
    "                       instead of tracing it; a trace of another job is bad input\n"
    "  --exercise N         start the lesson's exercise N: its goal, measured live, in the\n"
    "                       panel (docs/EXERCISES.md)\n"
    "  --grade N            grade a run by exercise N: headless (640x480 unless --size),\n"
    "                       measured against the truth; the last line is the verdict, the\n"
    "                       report's \"exercise\" says it too. Exit 0 met, 1 not met, 2 bad\n"
    "                       input (no such exercise, a --set the exercise does not allow)\n"
    "  --help               this text\n"
    "exit codes: 0 ok (--grade: met), 1 runtime failure (no context, shader error, GL\n"
    "error; --grade: not met), 2 bad input\n";

// "" or why `path` cannot be the output `flag` names (exit 2 before anything is rendered);
// `target` says where the bytes will go.
std::string outputProblem(const std::string& flag, const std::string& path, OutputTarget& target) {
  std::string shown = printable(path);
  if (shown.size() > 80) shown = shown.substr(0, 60) + "...";
  if (std::string why = resolveOutput(path, target); !why.empty()) {
    return flag + ": cannot write '" + shown + "' (" + why + ")";
  }
  // A picture goes into a .png; a device or a pipe takes whatever it is given.
  const bool picture = flag == "--out" || flag == "--truth-out" || flag == "--error-out";
  if (picture && target.kind == OutputTarget::Kind::Replace) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png") return flag + ": expected a .png file name, got '" + shown + "'";
  }
  return {};
}

// The flags without a value; false for any other.
bool readSwitch(const std::string& arg, RunOptions& o) {
  if (arg == "--headless") return o.headless = true;
  if (arg == "--window") return o.force_window = true;
  if (arg == "--hide-panel") return o.hide_panel = true;
  if (arg == "--panel") return o.panel = true;
  if (arg == "--list-params") return o.list_params = true;
  if (arg == "--help" || arg == "-h") return o.help = true;
  if (arg == "--no-truth") {
    o.truth = false;
    return true;
  }
  return false;
}

// What the flags mean together: "" or why they cannot run so. A grade is headless at the
// grader's size.
std::string checkTogether(RunOptions& o, bool device_given) {
  // One rule for both: an exercise is judged by the truth, so --no-truth contradicts it.
  if (o.exercise > 0 && !o.truth) {
    return std::string(o.grade ? "--grade" : "--exercise") +
           " judges by the truth: it cannot run with --no-truth";
  }
  if (o.grade) {
    // A verdict is a headless run measured against the truth, at the READMEs' size.
    o.headless = true;
    if (!o.size_given) o.width = kExerciseWidth, o.height = kExerciseHeight;
  }
  if (device_given && o.backend != "egl-device") {
    return "--device chooses an EGL device: it needs --backend egl-device";
  }
  return {};
}

}  // namespace

std::string parseCommandLine(int argc, char** argv, RunOptions& o) {
  struct Output {
    const char* flag;
    std::string* path;
    OutputTarget target;
  };
  Output outputs[] = {{"--out", &o.out, {}},
                      {"--report", &o.report, {}},
                      {"--truth-out", &o.truth_out, {}},
                      {"--error-out", &o.error_out, {}},
                      {"--truth-job", &o.truth_job, {}},
                      {"--truth-result", &o.truth_result, {}}};
  auto outputNamed = [&](const std::string& flag) -> Output* {
    for (Output& output : outputs) {
      if (flag == output.flag) return &output;
    }
    return nullptr;
  };
  bool device_given = false;
  for (Arguments args(argc, argv); args.next();) {
    const std::string& arg = args.flag();
    std::string value, why;
    if (readSwitch(arg, o)) continue;
    if (arg == "--backend") {
      args.value(value);
      if (why = checkBackend(value); why.empty()) o.backend = value;
    } else if (arg == "--device") {
      why = readIndex(args, o.device, 63);
      device_given = true;
    } else if (arg == "--size") {
      why = readSize(args, o.width, o.height);
      o.size_given = true;
    } else if (arg == "--frames") {
      why = readCount(args, o.frames, 100000);
      o.frames_given = true;
    } else if (arg == "--exercise" || arg == "--grade") {
      const int before = o.exercise;
      why = readCount(args, o.exercise, 99);
      if (why.empty() && before != 0 && before != o.exercise) {
        return arg + ": a second, different exercise (" + std::to_string(before) + " and " +
               std::to_string(o.exercise) + ")";
      }
      if (arg == "--grade") o.grade = true;
    } else if (arg == "--orbit") {
      why = readCount(args, o.orbit, 90);
    } else if (arg == "--set") {
      why = readSet(args, o.sets);
    } else if (arg == "--settings") {
      if (why = readFileName(args, value); !why.empty()) return why;
      why = readSettingsFile(value, o.sets);
    } else if (arg == "--truth-from") {
      if (why = readFileName(args, value); !why.empty()) return why;
      o.truth_from = value;
    } else if (Output* output = outputNamed(arg)) {
      if (why = readFileName(args, value); !why.empty()) return why;
      if (why = outputProblem(arg, value, output->target); !why.empty()) return why;
      *output->path = value;
    } else {
      return unknownOption(arg);
    }
    if (!why.empty()) return why;
  }
  if (std::string why = checkTogether(o, device_given); !why.empty()) return why;
  // Two outputs into one file would leave only the last: refuse it up front, however the two
  // names spell it (./a.png, sub/../a.png, a link, a hard link). Only a character device such
  // as /dev/null may take several.
  for (size_t i = 0; i < std::size(outputs); ++i) {
    for (size_t j = i + 1; j < std::size(outputs); ++j) {
      if (!outputs[i].target.sameFileAs(outputs[j].target)) continue;
      return std::string(outputs[i].flag) + " and " + outputs[j].flag + " name the same file '" +
             printable(*outputs[j].path) + "'";
    }
  }
  return {};
}

int runLessonMain(int argc, char** argv, const std::string& lesson) {
  std::vector<std::string> lessons = registeredLessons();
  if (!lesson.empty()) {
    // A program with every lesson runs the one it is called as (a link named after it).
    if (std::find(lessons.begin(), lessons.end(), lesson) == lessons.end()) {
      std::string names;
      for (const std::string& name : lessons) names += (names.empty() ? "" : ", ") + name;
      std::fprintf(stderr, "%s: call this program by a lesson's name (a link): %s\n",
                   printable(lesson).c_str(), names.c_str());
      return 2;
    }
    lessons = {lesson};
  } else if (lessons.size() > 1 && registeredHosts().size() == 1) {
    lessons = registeredHosts();  // a host's binary (lesson 16) links the lessons it runs
  }
  if (lessons.size() != 1) {
    std::fprintf(stderr, "expected exactly one lesson in this binary\n");
    return 1;
  }
  // Every message leaves through here: one line, whatever bytes the user gave us.
  const auto complain = [&](const std::string& message, int exit_code) {
    std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), printable(message).c_str());
    return exit_code;
  };
  // A reader that goes away (`| head`) makes writes fail with EPIPE, which the outputs clean
  // up after, instead of a signal that kills the run with its temporaries on disk.
  std::signal(SIGPIPE, SIG_IGN);
  RunOptions options;
  if (std::string e = parseCommandLine(argc, argv, options); !e.empty()) return complain(e, 2);
  if (options.help) {
    std::printf(kUsage, argv[0]);
    return 0;
  }
  try {
    Runner runner(lessons[0], makeLesson(lessons[0]), options);
    if (std::string e = runner.applyStartingSettings(); !e.empty()) return complain(e, 2);
    if (std::string e = runner.checkConsistency(); !e.empty()) return complain(e, 2);
    if (options.list_params) {
      std::printf("%s", runner.params().listText().c_str());
      return 0;
    }
    // A device that is not there is bad input (2, with the list); an EGL that cannot list
    // devices is this machine's limit (1). Both before anything is rendered or written.
    int exit_code = 0;
    if (std::string e = headlessProblem(options.backend, options.device, exit_code); !e.empty()) {
      return complain(e, exit_code);
    }
    return runner.run();
  } catch (const std::exception& e) {
    return complain(e.what(), 1);
  }
}

}  // namespace shadows
