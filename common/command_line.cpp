// The command line of every lesson binary, and its main().
#include "app.hpp"

#include "arguments.hpp"
#include "context.hpp"
#include "json.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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
    "  --backend NAME       headless context: osmesa (default) or egl (surfaceless)\n"
    "  --size WxH           image size (default 800x600)\n"
    "  --frames N           timed frames after one warm-up frame (default 5)\n"
    "  --out FILE.png       write the final frame (default out/LESSON.png; in a window:\n"
    "                       --frames frames, then exit)\n"
    "  --panel              draw the ImGui panel into the headless picture too\n"
    "  --hide-panel         a window without the panel (the key H shows and hides it)\n"
    "  --set name=value     set a parameter (repeatable); see --list-params\n"
    "  --list-params        list every parameter: name, type, default, range, help\n"
    "  --report FILE.json   parameters, timings, work counters, error against the truth\n"
    "  --truth-out FILE.png the ray-traced truth (white lit, black shadowed)\n"
    "  --error-out FILE.png the mistakes: magenta false shadow, cyan false lit\n"
    "  --no-truth           skip the ray-traced truth (faster)\n"
    "  --help               this text\n"
    "exit codes: 0 ok, 1 runtime failure (no context, shader error, GL error), 2 bad input\n";

bool isDevice(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  return std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
}

// "" or why `path` cannot be the output `flag` names (exit 2 before anything is rendered).
std::string outputProblem(const std::string& flag, const std::string& path) {
  std::string shown = "'";
  shown += printable(path);
  shown += "'";
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return flag + ": cannot write " + shown + " (it is a directory)";
  }
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.size() > 255 || path.size() > 4095) {
    return flag + ": cannot write " + shown.substr(0, 60) + "... (file name too long)";
  }
  if (!canWrite(path)) {
    return flag + ": cannot write " + shown + " (no such directory, or read-only)";
  }
  if (flag != "--report" && !isDevice(path)) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png") return flag + ": expected a .png file name, got " + shown;
  }
  return {};
}

}  // namespace

std::string parseCommandLine(int argc, char** argv, RunOptions& o) {
  for (Arguments args(argc, argv); args.next();) {
    const std::string& arg = args.flag();
    std::string value, why;
    if (arg == "--headless") {
      o.headless = true;
    } else if (arg == "--window") {
      o.force_window = true;
    } else if (arg == "--hide-panel") {
      o.hide_panel = true;
    } else if (arg == "--panel") {
      o.panel = true;
    } else if (arg == "--no-truth") {
      o.truth = false;
    } else if (arg == "--list-params") {
      o.list_params = true;
    } else if (arg == "--help" || arg == "-h") {
      o.help = true;
    } else if (arg == "--backend") {
      if (!args.value(value) || (value != "osmesa" && value != "egl")) {
        return "--backend: expected osmesa or egl";
      }
      o.backend = value;
    } else if (arg == "--size") {
      why = readSize(args, o.width, o.height);
    } else if (arg == "--frames") {
      why = readCount(args, o.frames, 100000);
    } else if (arg == "--set") {
      why = readSet(args, o.sets);
    } else if (arg == "--out" || arg == "--report" || arg == "--truth-out" ||
               arg == "--error-out") {
      if (!args.value(value)) return arg + ": expected a file name";
      if (why = outputProblem(arg, value); !why.empty()) return why;
      (arg == "--out"         ? o.out
       : arg == "--report"    ? o.report
       : arg == "--truth-out" ? o.truth_out
                              : o.error_out) = value;
    } else {
      return unknownOption(arg);
    }
    if (!why.empty()) return why;
  }
  // Two outputs into one regular file would leave only the last: refuse it up front.
  const std::pair<const char*, const std::string*> outputs[] = {{"--out", &o.out},
                                                                {"--report", &o.report},
                                                                {"--truth-out", &o.truth_out},
                                                                {"--error-out", &o.error_out}};
  for (size_t i = 0; i < std::size(outputs); ++i) {
    for (size_t j = i + 1; j < std::size(outputs); ++j) {
      const std::string &a = *outputs[i].second, &b = *outputs[j].second;
      if (a.empty() || b.empty() || isDevice(a)) continue;
      std::error_code ec;
      if (std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec)) {
        return std::string(outputs[i].first) + " and " + outputs[j].first +
               " name the same file '" + printable(a) + "'";
      }
    }
  }
  return {};
}

int runLessonMain(int argc, char** argv) {
  const auto lessons = registeredLessons();
  if (lessons.size() != 1) {
    std::fprintf(stderr, "expected exactly one lesson in this binary\n");
    return 1;
  }
  RunOptions options;
  if (std::string e = parseCommandLine(argc, argv, options); !e.empty()) {
    std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.c_str());
    return 2;
  }
  if (options.help) {
    std::printf(kUsage, argv[0]);
    return 0;
  }
  try {
    Runner runner(lessons[0], makeLesson(lessons[0]), options);
    if (std::string e = runner.applySets(options.sets); !e.empty()) {
      std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.c_str());
      return 2;
    }
    if (std::string e = runner.checkConsistency(); !e.empty()) {
      std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.c_str());
      return 2;
    }
    if (options.list_params) {
      std::printf("%s", runner.params().listText().c_str());
      return 0;
    }
    return runner.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", lessons[0].c_str(), e.what());
    return 1;
  }
}

}  // namespace shadows
