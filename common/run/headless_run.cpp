// Running headless, and every output of a run, all or nothing (the report itself is
// Runner::writeReport, report.cpp).
#include "run/headless_run.hpp"

#include <cstdio>
#include <filesystem>

#include "core/json.hpp"
#include "core/output_files.hpp"
#include "run/runner.hpp"

namespace shadows {

void HeadlessRun::saveScreenshot(int width, int height, bool window) {
  Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  glBindFramebuffer(GL_FRAMEBUFFER, window ? 0 : target_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // Beside the headless pictures (out/, ignored by git), never over an earlier one.
  std::error_code ec;
  std::filesystem::create_directories(kScreenshotFolder, ec);
  std::string path;
  do {
    path = std::string(kScreenshotFolder) + "/" + r_.lessonName() + "_" +
           std::to_string(++screenshots_taken_) + ".png";
  } while (std::filesystem::exists(path, ec));
  // Said under the panel's button, and on the terminal with the folder it is in.
  screenshot_said_ =
      writePng(path, image) ? "screenshot: " + path : "screenshot: cannot write " + path;
  std::fprintf(stderr, "%s (in %s)\n", screenshot_said_.c_str(),
               std::filesystem::current_path(ec).string().c_str());
}

int HeadlessRun::run() {
  const RunOptions& options = r_.options();
  const std::string& name = r_.lessonName();
  // Without --out the picture goes where ./run.sh puts them, out/<lesson>.png (git-ignored):
  // checked against the other outputs like a given --out, before anything is rendered.
  std::string out = options.out;
  // A grade writes only what it was asked for: no default picture.
  if (out.empty() && !options.grade) {
    std::error_code ec;
    std::filesystem::create_directories("out", ec);
    out = "out/" + name + ".png";
    OutputTarget picture, other;
    if (const std::string why = resolveOutput(out, picture); !why.empty()) {
      std::fprintf(stderr, "%s: cannot write '%s' (%s)\n", name.c_str(), out.c_str(), why.c_str());
      return 2;
    }
    for (const auto& [flag, path] :
         {std::pair<const char*, const std::string*>{"--report", &options.report},
          {"--truth-out", &options.truth_out},
          {"--error-out", &options.error_out},
          {"--truth-job", &options.truth_job},
          {"--truth-result", &options.truth_result}}) {
      if (path->empty() || !resolveOutput(*path, other).empty()) continue;
      if (picture.sameFileAs(other)) {
        std::fprintf(stderr, "%s: %s names the default picture %s; give --out\n", name.c_str(),
                     flag, out.c_str());
        return 2;
      }
    }
  }
  r_.initHeadless();
  r_.renderFrame();  // warm-up: shader JIT and the first shadow map land here
  r_.baseline().render();
  // A snapshot with the panel should show the error numbers, so measure them first.
  if (options.panel && options.truth) r_.measureError();
  r_.measure().clearHistory();
  r_.baseline().measure().clearHistory();
  for (int i = 0; i < options.frames; ++i) {
    r_.baseline().render();  // interleaved with the frames it is compared with; first, as the
    r_.renderFrame();        // picture is read from the same target
  }
  // The panel shows the run's medians, the numbers the report gives: it is drawn once more,
  // untimed, after the last timed frame.
  if (options.panel) r_.renderFrame(/*timed=*/false);
  const Image image = r_.readImage();
  // Asking for the truth or error picture (or its job) asks for the truth, --no-truth or not.
  if (options.truthAsked()) r_.measureError();
  if (!writeOutputs(out, image)) return 1;
  const int errors = r_.glErrors();
  std::printf("%-30s %dx%d  frame %7.2f ms", out.empty() ? name.c_str() : out.c_str(),
              options.width, options.height, r_.measure().medianFrameMs());
  const auto& counts = r_.measure().lastFrameCounts();
  if (const auto it = counts.find("shadow_map_renders"); it != counts.end() && it->second == 0) {
    std::printf(" (map cached)");
  }
  if (const std::optional<double> overhead = r_.baseline().measuredOverhead()) {
    std::printf(", %.2fx without shadow", *overhead);
  }
  const ErrorState& error = r_.errors().truth().error();
  if (error.valid && error.metrics.counted_pixels == 0) {
    std::printf("  error: none counted (%s)", notCountedReason(error.metrics).c_str());
  } else if (error.valid) {
    std::printf("  false shadow %6.2f%%  false lit %5.2f%%", error.metrics.false_shadow_pct,
                error.metrics.false_lit_pct);
  }
  std::printf("  gl_errors %d\n", errors);
  if (errors > 0) {
    std::fprintf(stderr, "%s: %d GL error(s), last: %s\n", name.c_str(), errors,
                 GlErrorLog::last().c_str());
    return 1;
  }
  return 0;
}

bool HeadlessRun::writeOutputs(const std::string& out, const Image& image) {
  const RunOptions& options = r_.options();
  // Every output of the run, or none: a picture without its report is a half answer.
  OutputBatch batch;
  const TruthMeasure& truth = r_.errors().truth();
  // A picture sent to /dev/null is neither encoded nor written (the tests' runs: a tenth of a
  // short one).
  const auto picture = [&batch](const std::string& path, const Image& shown) {
    if (!path.empty() && !discardsWhatIsWritten(path)) batch.add(path, encodePng(shown));
  };
  picture(out, image);
  picture(options.truth_out, truth.truthImage());
  picture(options.error_out, truth.errorImage());
  if (!options.truth_job.empty())
    batch.add(options.truth_job, {truth.jobBytes().begin(), truth.jobBytes().end()});
  if (!options.truth_result.empty()) {
    batch.add(options.truth_result, {truth.traceBytes().begin(), truth.traceBytes().end()});
  }
  if (!options.report.empty()) {
    JsonWriter json;
    r_.writeReport(json);
    batch.add(options.report, json.str() + "\n");
  }
  if (batch.commit()) return true;
  std::fprintf(stderr, "%s: %s\n", r_.lessonName().c_str(), batch.failure().c_str());
  return false;
}

}  // namespace shadows
