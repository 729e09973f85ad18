// The command-line contract of every lesson binary: bad input is exit 2, one line that
// names what is wrong, and no file left behind.
#include <gtest/gtest.h>

#include <unistd.h>
#include "cli_run.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/image.hpp"

namespace {

namespace fs = std::filesystem;

using shadows::testing::Result;
using shadows::testing::run;

// A report file read by a real JSON parser; a report that is not JSON fails the test.
nlohmann::json readReport(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json parsed = nlohmann::json::parse(text.str(), nullptr, false);
  EXPECT_FALSE(parsed.is_discarded()) << path << " is not JSON:\n" << text.str();
  return parsed;
}

// A shell word holding exactly `bytes` (control characters, 0xFF), for popen's /bin/sh.
std::string shellBytes(const std::string& bytes) {
  std::string octal;
  for (const unsigned char c : bytes) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\%03o", c);
    octal += buf;
  }
  return "\"$(printf '" + octal + "')\"";
}

class Cli : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("shadows_cli_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
           "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  bool dirIsEmpty() const { return fs::is_empty(dir); }
  fs::path dir;
};

const std::string kLesson = "03_shadow_map_basic";

TEST_F(Cli, HeadlessRunWritesPictureAndReportWithTimingsCountersAndError) {
  const auto out = (dir / "x.png").string(), report = (dir / "r.json").string();
  const Result r = run(kLesson,
                       "--headless --size 320x240 --frames 2 --set shadow.size=2048"
                       " --set view=compare --out " +
                           out + " --report " + report);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(fs::exists(out));
  const nlohmann::json json = readReport(report);
  EXPECT_TRUE(json["frame_ms"].is_number());
  EXPECT_TRUE(json["pass_ms"]["eye"].is_number());
  EXPECT_TRUE(json["counters"]["eye"]["fragment_invocations"].is_number());
  EXPECT_TRUE(json["counters"]["shadow_map_renders"].is_number());
  EXPECT_EQ(json["gl_errors"], 0);
  EXPECT_TRUE(json["error"]["false_shadow_pct"].is_number());
  EXPECT_EQ(json["error"]["truth"], "point");
  EXPECT_EQ(json["params"]["shadow.size"], 2048);
  EXPECT_EQ(json["params"]["view"], "compare");
  EXPECT_EQ(json["backend"], "osmesa");
  // No temporary is left beside them.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
}

// scripts/neutral_floor.sh's hook (issue 56): a run dumps every variant's source as the GL
// gets it; a floor file of one's name is compiled in its place, and the run says so.
TEST_F(Cli, AShaderFloorReplacesTheVariantOfItsNameAndSaysSo) {
  const fs::path dump = dir / "dump", floor = dir / "floor";
  const std::string args = "--headless --no-truth --size 64x48 --frames 1 --out ";
  Result r =
      run(kLesson, args + (dir / "a.png").string(), "SHADOWS_SHADER_DUMP=" + dump.string() + " ");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The eye pass's lit variant: 03's scene.frag without SHADOW_OFF.
  fs::path lit;
  for (const auto& entry : fs::directory_iterator(dump)) {
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string name = entry.path().filename().string();
    if (name.starts_with("scene-") && text.str().find("#define SHADOW_OFF 1") == std::string::npos)
      lit = entry.path();
  }
  ASSERT_FALSE(lit.empty()) << "no lit scene.frag among the dumped variants";
  // Its copy with one more line before main: a fragment that is always red.
  std::ifstream in(lit);
  std::stringstream text;
  text << in.rdbuf();
  std::string red = text.str();
  const size_t main_at = red.rfind("void main()");
  ASSERT_NE(main_at, std::string::npos);
  red.replace(main_at, 11, "void mainAsRun()");
  red += "\nvoid main() { mainAsRun(); outColor = vec4(1.0, 0.0, 0.0, 1.0); }\n";
  fs::create_directories(floor);
  std::ofstream(floor / lit.filename()) << red;
  r = run(kLesson, args + (dir / "b.png").string(), "SHADOWS_SHADER_FLOOR=" + floor.string() + " ");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("shader floor: " + lit.filename().string()), std::string::npos)
      << r.output;
  const shadows::Image a = shadows::readPng((dir / "a.png").string());
  const shadows::Image b = shadows::readPng((dir / "b.png").string());
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  EXPECT_NE(a.rgba, b.rgba) << "the floor's red was not drawn";
}

TEST_F(Cli, OutputsToDevNullLeaveItADevice) {
  const Result r = run(kLesson,
                       "--headless --size 64x48 --frames 1 --out /dev/null --report "
                       "/dev/null --error-out /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_character_file("/dev/null")) << "the run replaced /dev/null with a file";
}

// Lesson 08 in a window (issue 20): at rest the full air, the headless picture within the
// golden tolerance (16 pixels: a window and the headless target differ by a pixel or two in
// any lesson); while the camera turns (--orbit, a scripted drag) the preview, and the report
// says which it drew.
TEST_F(Cli, Lesson08sWindowAtRestIsTheHeadlessPictureAndTurningItPreviews) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "no xvfb-run";
  const std::string xvfb = "xvfb-run -a -s '-screen 0 1024x768x24' ";
  const std::string size = " --size 320x240 --no-truth";
  const fs::path rest = dir / "rest.png", headless = dir / "headless.png";
  Result r = run("08_atmospherics",
                 "--window --hide-panel --frames 2" + size + " --out " + rest.string() +
                     " --report " + (dir / "rest.json").string(),
                 xvfb);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(readReport(dir / "rest.json")["air_quality"], "full");
  r = run("08_atmospherics", "--headless --frames 1" + size + " --out " + headless.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const shadows::Image a = shadows::readPng(rest.string()), b = shadows::readPng(headless.string());
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  size_t differing = 0;
  for (size_t i = 0; i + 4 <= a.rgba.size(); i += 4) {
    differing += !std::equal(a.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                             a.rgba.begin() + static_cast<std::ptrdiff_t>(i + 4),
                             b.rgba.begin() + static_cast<std::ptrdiff_t>(i));
  }
  EXPECT_LE(differing, 16u);
  r = run("08_atmospherics",
          "--window --hide-panel --frames 3 --orbit 3" + size + " --out " +
              (dir / "orbit.png").string() + " --report " + (dir / "orbit.json").string(),
          xvfb);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(readReport(dir / "orbit.json")["air_quality"], "preview");
}

TEST_F(Cli, ADisplayThatLeadsNowhereFallsBackToHeadless) {
  const auto out = (dir / "x.png").string();
  const Result r = run(kLesson, "--size 64x48 --frames 1 --no-truth --out " + out, "DISPLAY=:97 ");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rendering headless"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out));
  // Said once, on one line with GLFW's reason, not once by GLFW and again by us.
  size_t lines_naming_it = 0;
  std::stringstream lines(r.output);
  for (std::string line; std::getline(lines, line);)
    lines_naming_it += line.find(":97") != line.npos;
  EXPECT_EQ(lines_naming_it, 1u) << r.output;
}

TEST_F(Cli, ALightMapPastItsMemoryLimitIsRefusedWithTheLimitNamed) {
  // Lesson 15's cubes at 128 texels a unit: their floor alone would be 6401 texels wide.
  const auto r =
      run("15_light_maps", "--size 64x48 --set scene=cubes --set lightmap.texels_per_unit=128");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("over the limit of 4096 texels a side and 4096 x 4096 in all"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("lower lightmap.texels_per_unit"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("MB"), std::string::npos) << r.output;
}

TEST_F(Cli, ListParamsListsEverySlider) {
  const Result r = run(kLesson, "--list-params");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* name :
       {"scene", "view", "shadow.size", "shadow.height", "shadow.format", "shadow.filter",
        "shadow.fit", "shadow.cache", "dimming", "inset", "light.type", "light.pos", "light.target",
        "light.fov", "light.near", "light.far", "camera.pos", "camera.target"}) {
    EXPECT_NE(("\n" + r.output).find(std::string("\n") + name + " "), std::string::npos) << name;
  }
}

TEST_F(Cli, HelpExitsZero) {
  const Result r = run(kLesson, "--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("--set name=value"), std::string::npos);
}

// The one number a pattern captures in `text` ("" when it does not match).
std::string captured(const std::string& text, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(pattern)) ? m[1].str() : std::string();
}

TEST_F(Cli, TheDocumentedDefaultsOfTheCommandLineAreWhatARunDoes) {
  // What --help and CONTRACTS.md say a flag defaults to, read from their text, against what a
  // run without the flag does (its report, the file it writes). A default changed in the code
  // but not in the text, or the other way round, fails here.
  const std::string help = run(kLesson, "--help").output;
  std::ifstream contracts_in(std::string(SHADOWS_SOURCE_DIR) + "/docs/CONTRACTS.md");
  const std::string contracts{std::istreambuf_iterator<char>(contracts_in), {}};
  const std::string help_size =
      captured(help, R"(--size WxH\s+image size \(default (\d+x\d+)[;)])");
  const std::string help_frames =
      captured(help, R"(--frames N\s+timed frames[^(]*\(default (\d+))");
  const std::string help_device = captured(help, R"(--device N[^(]*\(default (\d+))");
  const std::string help_backend =
      captured(help, R"(--backend NAME\s+headless context: (\w+) \(the default on desktop GL\))");
  ASSERT_EQ(help_size, captured(contracts, R"(image size \(default (\d+x\d+)[;)])"));
  ASSERT_EQ(help_frames, captured(contracts, R"(after one warm-up frame \(default (\d+)\))"));
  ASSERT_EQ(help_device, captured(contracts, R"(egl-device`, 0\.\.63 \(default (\d+)\))"));
  std::string contracts_backend =
      captured(contracts, R"(no window: (\w+) \(default on desktop GL)");
  std::transform(contracts_backend.begin(), contracts_backend.end(), contracts_backend.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  ASSERT_EQ(help_backend, contracts_backend);  // "OSMesa" there, "osmesa" as typed
  ASSERT_NE(help.find("(default out/LESSON.png"), std::string::npos) << help;
  ASSERT_NE(contracts.find("headless default: `out/<lesson>.png`"), std::string::npos);
  ASSERT_FALSE(help_size.empty() || help_frames.empty() || help_backend.empty()) << help;

  // A run that names none of them, from a fresh working directory.
  const Result r =
      run(kLesson, "--headless --no-truth --report r.json", "cd " + dir.string() + " && ");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / (kLesson + ".png"))) << "the default picture";
  const nlohmann::json report = readReport(dir / "r.json");
  EXPECT_EQ(std::to_string(report["size"][0].get<int>()) + "x" +
                std::to_string(report["size"][1].get<int>()),
            help_size);
  EXPECT_EQ(std::to_string(report["frames"].get<int>()), help_frames);
  EXPECT_EQ(report["backend"], help_backend);
  EXPECT_EQ(report["flavour"], "gl45");
}

TEST_P(Cli, BadInputExitsTwoWithOneLineAndWritesNothing) {
  const std::string out = (dir / "x.png").string(), report = (dir / "r.json").string();
  const std::string args = std::string("--headless --size 64x48 ") + GetParam() + " --out " + out +
                           " --report " + report;
  const Result r = run(kLesson, args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  EXPECT_TRUE(dirIsEmpty()) << args;
  // One line, naming the lesson and what was wrong.
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_EQ(r.output.rfind(kLesson + ": ", 0), 0u) << r.output;
}

// A flag whose value was left out, followed by another option: the message names the missing
// value and the option it took for one, not the next word as unknown (issue 53, 13).
TEST_F(Cli, AMissingValueIsNamedNotTheWordAfterIt) {
  for (const std::string flag : {"--set", "--out", "--settings", "--truth-from", "--report"}) {
    const Result r = run(kLesson, "--headless " + flag + " --size 160x120");
    EXPECT_EQ(r.exit_code, 2) << flag << "\n" << r.output;
    EXPECT_NE(r.output.find(flag + ": expected"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("got the option '--size'"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("160x120"), std::string::npos) << r.output;
    EXPECT_TRUE(dirIsEmpty()) << flag;
  }
}

// A name longer than the file system takes (255 bytes): refused before rendering.
const std::string kLongName = "--out /tmp/" + std::string(300, 'a') + ".png";

INSTANTIATE_TEST_SUITE_P(
    EveryKind, Cli,
    ::testing::Values("--bogus", "--set shadow.sise=512", "--set shadow.size=abc",
                      "--set shadow.size=99999", "--set shadow.size=", "--set light.pos=1,2",
                      "--set light.pos=1,2,x", "--set shadow.format=8", "--set view=nope",
                      "--set scene=moon", "--set dimming=nan", "--set inset=maybe",
                      "--set noequals", "--set", "--size 0x10", "--size 640", "--size axb",
                      "--frames 0", "--frames -3", "--backend vulkan",
                      "--backend egl-device --device 63", "--device 0", "--device x",
                      "--backend egl-device --device -1", "--backend egl-device --device",
                      "--out /nonexistent/dir/x.png", "--report /nonexistent/r.json",
                      "--error-out /proc/none/e.png", "--truth-out", "--out /tmp/x.jpg",
                      "--error-out /tmp/e.bmp", "--set shadow.height=1", kLongName.c_str(),
                      "--truth-job", "--truth-result /nonexistent/t", "--truth-from",
                      "--truth-from /nonexistent/t.trace", "--truth-from /tmp", "--exercise 9",
                      "--grade 9", "--grade 0", "--grade x", "--exercise", "--settings",
                      "--settings /nonexistent/s.txt", "--settings /etc/passwd"));

// The EGL device platform (a GPU without a display): the report names the device, a device
// that is not there is refused with the list of those there are, and an EGL that cannot
// enumerate devices is this machine's limit (exit 1), said in one line.
TEST_F(Cli, EglDeviceBackendNamesItsDeviceInTheReport) {
  const auto out = (dir / "x.png").string(), report = (dir / "r.json").string();
  const Result r = run(kLesson,
                       "--headless --backend egl-device --device 0 --size 64x48 "
                       "--frames 1 --no-truth --out " +
                           out + " --report " + report);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json json = readReport(report);
  EXPECT_EQ(json["backend"], "egl-device");
  EXPECT_EQ(json["device"]["index"], 0);
  EXPECT_GE(json["device"]["count"].get<int>(), 1);
  EXPECT_FALSE(json["device"]["name"].get<std::string>().empty());
  EXPECT_TRUE(json["vendor"].is_string());
}

TEST_F(Cli, AMissingEglDeviceListsThoseThereAre) {
  const Result r = run(kLesson, "--headless --backend egl-device --device 63 --size 64x48");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--device 63: no such EGL device (there are 0: "), std::string::npos)
      << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST_F(Cli, AnEglWithoutDevicesExitsOneInOneLine) {
  // glvnd with no vendor library: its EGL offers no device enumeration.
  const auto out = (dir / "x.png").string();
  const Result r = run(kLesson, "--headless --backend egl-device --size 64x48 --out " + out,
                       "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json ");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("EGL_EXT_device_enumeration"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_TRUE(dirIsEmpty());
}

TEST_F(Cli, AnOutputThatFailsLeavesNoneOfTheOthersAndSaysWhich) {
  // /dev/full accepts the open and fails the write: the report, truth or error picture
  // cannot be written, so the picture written before it must not stay either.
  for (const char* flag :
       {"--report", "--truth-out", "--error-out", "--truth-job", "--truth-result"}) {
    const std::string out = (dir / "x.png").string();
    const Result r =
        run(kLesson, "--headless --size 64x48 --frames 1 --out " + out + " " + flag + " /dev/full");
    EXPECT_EQ(r.exit_code, 1) << flag << "\n" << r.output;
    EXPECT_NE(r.output.find("cannot write /dev/full"), std::string::npos) << r.output;
    EXPECT_TRUE(dirIsEmpty()) << flag << ": a partial set of outputs was left";
  }
}

std::vector<std::uint8_t> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// --truth-job and --truth-result write what another tracer needs and what Embree answered;
// --truth-from measures against a trace of the same job instead of tracing, through the same
// metrics, and refuses a trace of another job.
TEST_F(Cli, TheTruthJobAndItsTraceGoOutAndComeBack) {
  const std::string base = "--headless --size 96x72 --frames 1 --out " + (dir / "x.png").string();
  const fs::path job = dir / "job", trace = dir / "embree.trace", report = dir / "a.json";
  Result r = run(kLesson, base + " --truth-job " + job.string() + " --truth-result " +
                              trace.string() + " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::uint8_t> trace_bytes = readBytes(trace), job_bytes = readBytes(job);
  ASSERT_GT(job_bytes.size(), 16u);
  EXPECT_EQ(std::string(job_bytes.begin(), job_bytes.begin() + 4), "SHTJ");
  // Magic, version, job id, 96x72, no air, padding, noise, one float per pixel.
  ASSERT_EQ(trace_bytes.size(), 40u + 4u * 96 * 72);
  EXPECT_EQ(std::string(trace_bytes.begin(), trace_bytes.begin() + 4), "SHTR");
  // The trace names its job: the id the job carries after its magic and version.
  EXPECT_TRUE(
      std::equal(trace_bytes.begin() + 8, trace_bytes.begin() + 16, readBytes(job).begin() + 8));

  // The same trace back: the same numbers, and it is what was used.
  const fs::path again = dir / "again.trace", report2 = dir / "b.json";
  r = run(kLesson, base + " --truth-from " + trace.string() + " --truth-result " + again.string() +
                       " --report " + report2.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(readBytes(again), trace_bytes);
  EXPECT_EQ(readReport(report2)["error"], readReport(report)["error"]);

  // A different trace of the same job: the metrics follow it (lit and shadowed swapped).
  std::vector<std::uint8_t> swapped = trace_bytes;
  int counted = 0;
  for (size_t at = 40; at < swapped.size(); at += 4) {
    float v;
    std::memcpy(&v, &swapped[at], 4);
    if (v < 0.0f) continue;
    ++counted;
    v = 1.0f - v;
    std::memcpy(&swapped[at], &v, 4);
  }
  ASSERT_GT(counted, 100);
  std::ofstream(dir / "swapped.trace", std::ios::binary)
      .write(reinterpret_cast<const char*>(swapped.data()), static_cast<long>(swapped.size()));
  const fs::path report3 = dir / "c.json";
  r = run(kLesson, base + " --truth-from " + (dir / "swapped.trace").string() + " --report " +
                       report3.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json a = readReport(report)["error"], c = readReport(report3)["error"];
  EXPECT_EQ(c["counted_pixels"], a["counted_pixels"]);
  EXPECT_GT(c["false_shadow_pct"].get<double>() + c["false_lit_pct"].get<double>(), 50.0) << c;

  // Another job (the eye moved): bad input, one line, nothing written.
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "embree.trace", std::ios::binary)
      .write(reinterpret_cast<const char*>(trace_bytes.data()),
             static_cast<long>(trace_bytes.size()));
  r = run(kLesson, base + " --set camera.fov=40 --truth-from " + trace.string() + " --report " +
                       report.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("another job"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  EXPECT_FALSE(fs::exists(report));
  // A job is not a trace.
  r = run(kLesson, base + " --truth-from " + trace.string() + "x");
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

// A trace no tracer could have answered is bad input (exit 2, one line), never a figure:
// visibility outside [0, 1] (other than -1, not counted) or not finite, a file whose size is
// not what its header says (refused before its bytes are read: a 64 GiB sparse file would take
// minutes and all memory), and a header of 0x0 pixels (issue 53: 3, 4, 10).
// The suite's memo of traces (SHADOWS_TRUTH_MEMO): a job traced once is read back byte for
// byte, in air and under an area light too; a memo cut short is traced anew; without the
// variable nothing is kept.
TEST_F(Cli, TheSuitesMemoOfTracesAnswersAsTheTracerDoes) {
  for (const std::string lesson : {"08_atmospherics", "14_soft_shadows"}) {
    SCOPED_TRACE(lesson);
    const fs::path memo = dir / ("memo_" + lesson);
    const std::string base = "--headless --size 96x72 --frames 1 --out /dev/null --report ";
    const std::string with = "SHADOWS_TRUTH_MEMO=" + memo.string() + " ";
    const fs::path traced = dir / "traced.json", first = dir / "first.json",
                   again = dir / "again.json", cut = dir / "cut.json";
    ASSERT_EQ(run(lesson, base + traced.string(), "SHADOWS_TRUTH_MEMO= ").exit_code, 0);
    EXPECT_FALSE(fs::exists(memo));
    ASSERT_EQ(run(lesson, base + first.string(), with).exit_code, 0);
    std::vector<fs::path> kept;
    for (const auto& e : fs::directory_iterator(memo)) kept.push_back(e.path());
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0].extension(), ".trace");
    const auto written = fs::last_write_time(kept[0]);
    ASSERT_EQ(run(lesson, base + again.string(), with).exit_code, 0);
    EXPECT_EQ(fs::last_write_time(kept[0]), written);  // read, not traced and written again
    EXPECT_EQ(readReport(first)["error"], readReport(traced)["error"]);
    EXPECT_EQ(readReport(again)["error"], readReport(traced)["error"]);
    // Half a memo (a run killed while writing one is never renamed into place, but a disk can
    // fill): traced anew, the same numbers.
    fs::resize_file(kept[0], fs::file_size(kept[0]) / 2);
    ASSERT_EQ(run(lesson, base + cut.string(), with).exit_code, 0);
    EXPECT_EQ(readReport(cut)["error"], readReport(traced)["error"]);
    EXPECT_GT(fs::file_size(kept[0]), 100u);
  }
}

TEST_F(Cli, TruthFromRefusesWhatNoTracerAnswers) {
  const std::string base = "--headless --size 96x72 --frames 1 --out " + (dir / "x.png").string();
  const fs::path trace = dir / "embree.trace";
  Result r = run(kLesson, base + " --truth-result " + trace.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::uint8_t> good = readBytes(trace);
  ASSERT_EQ(good.size(), 40u + 4u * 96 * 72);
  size_t counted_at = 0;  // a counted pixel's float
  for (size_t at = 40; at < good.size() && counted_at == 0; at += 4) {
    float v;
    std::memcpy(&v, &good[at], 4);
    if (v >= 0.0f) counted_at = at;
  }
  ASSERT_NE(counted_at, 0u);
  const auto write = [](const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<long>(bytes.size()));
  };
  const auto refused = [&](const fs::path& path, const std::string& says, const std::string& what) {
    const fs::path report = dir / "r.json";
    const Result got =
        run(kLesson, base + " --truth-from " + path.string() + " --report " + report.string());
    EXPECT_EQ(got.exit_code, 2) << what << "\n" << got.output;
    EXPECT_NE(got.output.find(says), std::string::npos) << what << "\n" << got.output;
    EXPECT_EQ(std::count(got.output.begin(), got.output.end(), '\n'), 1) << what << got.output;
    EXPECT_FALSE(fs::exists(report)) << what;
  };
  for (const float bad : {1e30f, std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN(), -7.0f, 1.0001f, -0.5f}) {
    std::vector<std::uint8_t> bytes = good;
    std::memcpy(&bytes[counted_at], &bad, 4);
    const fs::path path = dir / "bad.trace";
    write(path, bytes);
    refused(path, "not in [0, 1]", "visibility " + std::to_string(bad));
  }
  // The header's size against the file's: one byte more, and a sparse 64 GiB file.
  std::vector<std::uint8_t> longer = good;
  longer.push_back(0);
  write(dir / "longer.trace", longer);
  refused(dir / "longer.trace", "the file " + std::to_string(longer.size()), "a byte too many");
  write(dir / "huge.trace", good);
  ASSERT_EQ(::truncate((dir / "huge.trace").c_str(), 64LL << 30), 0);
  refused(dir / "huge.trace", "the file " + std::to_string(64LL << 30), "64 GiB");
  std::vector<std::uint8_t> no_trace(64, 'x');
  write(dir / "huge_junk.trace", no_trace);
  ASSERT_EQ(::truncate((dir / "huge_junk.trace").c_str(), 64LL << 30), 0);
  refused(dir / "huge_junk.trace", "not a truth trace", "64 GiB of no trace");
  fs::remove(dir / "huge.trace");
  fs::remove(dir / "huge_junk.trace");
  // A header of 0x0 pixels and nothing after it: a trace of no job this run has.
  std::vector<std::uint8_t> empty(good.begin(), good.begin() + 40);
  std::memset(&empty[16], 0, 8);
  write(dir / "empty.trace", empty);
  refused(dir / "empty.trace", "does not fit its job", "a 0x0 trace");
}

TEST_F(Cli, TwoOutputsIntoOneFileAreRefused) {
  const std::string same = (dir / "p.png").string();
  const Result r = run(kLesson, "--headless --size 64x48 --out " + same + " --error-out " + same);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("name the same file"), std::string::npos) << r.output;
  EXPECT_TRUE(dirIsEmpty());
}

TEST_F(Cli, TheSameFileMessageNamesTheTwoFlagsInvolvedAndTheFile) {
  // Every pair of outputs, each given in either order on the command line: the one line names
  // exactly those two flags (in --help's order) and the later one's spelling of the file.
  const std::vector<std::string> flags = {"--out", "--report", "--truth-out", "--error-out",
                                          "--truth-job"};
  for (size_t i = 0; i < flags.size(); ++i) {
    for (size_t j = i + 1; j < flags.size(); ++j) {
      const std::string first = (dir / "a.png").string();
      const std::string second = dir.string() + "/./a.png";
      const std::string expected = "03_shadow_map_basic: " + flags[i] + " and " + flags[j] +
                                   " name the same file '" + second + "'\n";
      for (const bool reversed : {false, true}) {
        const std::string a = flags[i] + " " + first, b = flags[j] + " " + second;
        const Result r =
            run(kLesson, "--headless --size 64x48 " + (reversed ? b + " " + a : a + " " + b));
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(r.output, expected) << flags[i] << " " << flags[j];
        EXPECT_TRUE(dirIsEmpty());
      }
    }
  }
}

// ---------------------------------------------------------------- outputs never clobber

TEST_F(Cli, ALinkToStandardOutputIsWrittenThroughNotReplaced) {
  const fs::path link = dir / "mystdout", captured = dir / "captured.txt";
  fs::create_symlink("/proc/self/fd/1", link);
  const Result r = run(kLesson, "--headless --size 64x48 --frames 1 --no-truth --out " +
                                    (dir / "o.png").string() + " --report " + link.string() +
                                    " > " + captured.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << "the link was replaced by a file";
  std::ifstream in(captured);
  std::stringstream text;
  text << in.rdbuf();
  // The report, then the summary line: both reached what stdout was redirected to.
  const auto end = text.str().find("\n}\n");
  ASSERT_NE(end, std::string::npos) << text.str();
  EXPECT_FALSE(nlohmann::json::parse(text.str().substr(0, end + 3), nullptr, false).is_discarded());
  EXPECT_NE(text.str().find("gl_errors 0", end), std::string::npos) << text.str();
}

TEST_F(Cli, DevStdoutAndDevFdStayWhatTheyAre) {
  for (const char* name : {"/dev/stdout", "/dev/fd/1"}) {
    const fs::path captured = dir / "captured.txt";
    const Result r = run(
        kLesson, std::string("--headless --size 64x48 --frames 1 --no-truth --out ") +
                     (dir / "o.png").string() + " --report " + name + " > " + captured.string());
    EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.output;
    EXPECT_GT(fs::file_size(captured), 100u) << name;
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(name))) << name << " was replaced";
  }
  // Into a pipe: the report arrives through it, whole.
  const Result piped = run(kLesson, "--headless --size 64x48 --frames 1 --no-truth --out " +
                                        (dir / "o.png").string() + " --report /dev/stdout");
  EXPECT_EQ(piped.exit_code, 0) << piped.output;
  EXPECT_NE(piped.output.find("\"lesson\": \"" + kLesson + "\""), std::string::npos);
}

TEST_F(Cli, TheSameFileNamedTwoWaysIsRefusedUpFront) {
  fs::create_directories(dir / "sub");
  fs::create_symlink("a.png", dir / "link.png");
  std::ofstream(dir / "b.png") << "someone's";
  fs::create_hard_link(dir / "b.png", dir / "hard.png");
  const std::string a = (dir / "a.png").string();
  for (const std::string& other :
       {(dir / "." / "a.png").string(), (dir / "sub" / ".." / "a.png").string(),
        (dir / "link.png").string()}) {
    const Result r =
        run(kLesson, "--headless --size 64x48 --frames 1 --out " + a + " --truth-out " + other +
                         " --report " + (dir / "r.json").string());
    EXPECT_EQ(r.exit_code, 2) << other << "\n" << r.output;
    EXPECT_NE(r.output.find("name the same file"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "a.png")) << other;
    EXPECT_FALSE(fs::exists(dir / "r.json")) << other;
  }
  const Result hard = run(kLesson, "--headless --size 64x48 --out " + (dir / "b.png").string() +
                                       " --error-out " + (dir / "hard.png").string());
  EXPECT_EQ(hard.exit_code, 2) << hard.output;
}

TEST_F(Cli, EveryNameTheFileSystemTakesWorksAndLeftoversAreNotOurs) {
  // 255 bytes, the limit: a temporary named "<name>.partial" would not fit.
  const std::string longest = std::string(251, 'a') + ".png";
  // Someone's file and a directory where such a temporary would go.
  std::ofstream(dir / "o.png.partial") << "someone's";
  fs::create_directories(dir / "r.json.partial");
  const Result r =
      run(kLesson, "--headless --size 64x48 --frames 1 --no-truth --out " +
                       (dir / longest).string() + " --error-out " + (dir / "o.png").string() +
                       " --report " + (dir / "r.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / longest));
  EXPECT_TRUE(fs::exists(dir / "o.png"));
  EXPECT_FALSE(readReport(dir / "r.json").is_discarded());
  std::ifstream leftover(dir / "o.png.partial");
  std::string kept;
  std::getline(leftover, kept);
  EXPECT_EQ(kept, "someone's");
  EXPECT_TRUE(fs::is_directory(dir / "r.json.partial"));
}

TEST_F(Cli, PlacesThatTakeNoFilesAreBadInputEvenForRoot) {
  for (const char* place : {"/proc/x.png", "/sys/x.png"}) {
    const Result r = run(kLesson, std::string("--headless --size 64x48 --out ") + place);
    EXPECT_EQ(r.exit_code, 2) << place << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

TEST_F(Cli, AReportStaysJsonWhateverBytesItsStringsHold) {
  // A spotlight image whose name is not UTF-8 (byte 0xFF), and so a report that holds it.
  const std::string lesson = "08_atmospherics";
  const fs::path picture = dir / "spot.png";
  ASSERT_EQ(run(lesson, "--headless --size 16x16 --frames 1 --no-truth --out " + picture.string())
                .exit_code,
            0);
  const std::string odd_name = (dir / "\xff.png").string();
  fs::rename(picture, odd_name);
  const Result r = run(lesson, "--headless --size 64x48 --frames 1 --no-truth --set spot.image=" +
                                   shellBytes(odd_name) + " --out " + (dir / "o.png").string() +
                                   " --report " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json json = readReport(dir / "r.json");
  EXPECT_EQ(json["params"]["spot.image"], (dir / "\\xFF.png").string());
}

TEST_F(Cli, AReaderThatGoesAwayLeavesNoTemporaryBehind) {
  // `| true` closes the pipe at once: the write fails (EPIPE, not a fatal signal), the run
  // says so and removes the picture's temporary.
  const Result r = run(kLesson, "--headless --size 64x48 --frames 1 --no-truth --out " +
                                    (dir / "x.png").string() + " --report /dev/stdout | true; " +
                                    "ls -a " + dir.string());
  EXPECT_EQ(r.output.find(".shadows-"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "x.png")) << "the picture without its report";
}

TEST_F(Cli, AFifoNobodyReadsIsAFailureNotAHang) {
  const fs::path fifo = dir / "r.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const Result r = run(kLesson,
                       "--headless --size 64x48 --frames 1 --no-truth --out " +
                           (dir / "x.png").string() + " --report " + fifo.string(),
                       "timeout 60 ");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("no reader"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST_F(Cli, AFileWithOtherNamesIsWrittenInPlaceSoAllNamesSeeIt) {
  // Replacing the inode would leave the other hard link with the old bytes.
  std::ofstream(dir / "r.json") << "old";
  fs::create_hard_link(dir / "r.json", dir / "other.json");
  const Result r =
      run(kLesson, "--headless --size 64x48 --frames 1 --no-truth --out " +
                       (dir / "x.png").string() + " --report " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(fs::hard_link_count(dir / "r.json"), 2u);
  EXPECT_EQ(readReport(dir / "other.json")["lesson"], kLesson);
}

TEST_F(Cli, AnOutputOverALongerFileLeavesNoStaleTailHoweverItIsReached) {
  // Each output written over a file of 1 MiB of 'x': the file afterwards is exactly the new
  // content (the picture byte for byte what a fresh file gets, the report JSON to its last
  // byte), whether the name is the file itself, a second hard link to it, or a symbolic link.
  const std::string args = "--headless --size 64x48 --frames 1 --no-truth";
  ASSERT_EQ(run(kLesson, args + " --out " + (dir / "fresh.png").string()).exit_code, 0);
  std::ifstream fresh_in(dir / "fresh.png", std::ios::binary);
  const std::string fresh{std::istreambuf_iterator<char>(fresh_in), {}};
  ASSERT_GT(fresh.size(), 100u);
  const std::string stale(1 << 20, 'x');
  for (const std::string how : {"regular", "hard_link", "symlink"}) {
    const fs::path sub = dir / how;
    fs::create_directories(sub);
    for (const char* name : {"x.png", "r.json"}) {
      std::ofstream(sub / (std::string("target_") + name), std::ios::binary) << stale;
      if (how == "regular") fs::rename(sub / (std::string("target_") + name), sub / name);
      if (how == "hard_link")
        fs::create_hard_link(sub / (std::string("target_") + name), sub / name);
      if (how == "symlink") fs::create_symlink(sub / (std::string("target_") + name), sub / name);
    }
    const Result r = run(kLesson, args + " --out " + (sub / "x.png").string() + " --report " +
                                      (sub / "r.json").string());
    ASSERT_EQ(r.exit_code, 0) << how << ": " << r.output;
    std::ifstream png_in(sub / "x.png", std::ios::binary);
    const std::string png{std::istreambuf_iterator<char>(png_in), {}};
    EXPECT_EQ(png.size(), fresh.size()) << how;
    EXPECT_TRUE(png == fresh) << how << ": the picture is not what a fresh file gets";
    std::ifstream report_in(sub / "r.json", std::ios::binary);
    const std::string report{std::istreambuf_iterator<char>(report_in), {}};
    EXPECT_LT(report.size(), stale.size()) << how;
    EXPECT_EQ(report.find('x' + std::string(16, 'x')), std::string::npos) << how << ": stale tail";
    EXPECT_FALSE(nlohmann::json::parse(report, nullptr, false).is_discarded()) << how;
    if (how != "regular") {  // written through the other name: the target holds the same
      std::ifstream target_in(sub / "target_r.json", std::ios::binary);
      EXPECT_EQ(std::string(std::istreambuf_iterator<char>(target_in), {}), report) << how;
    }
  }
}

TEST_F(Cli, AnOutputOnTheDefaultPictureIsRefusedUpFront) {
  // Without --out the picture is out/<lesson>.png: another output there would replace it.
  fs::create_directories(dir / "out");
  const std::string command = "cd " + dir.string() + " && " + std::string(SHADOWS_BINARY_DIR) +
                              "/" + kLesson + " --headless --size 64x48 --truth-out out/" +
                              kLesson + ".png 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::array<char, 4096> buffer{};
  std::string output;
  while (fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
  const int status = pclose(pipe);
  EXPECT_EQ(WEXITSTATUS(status), 2) << output;
  EXPECT_NE(output.find("default picture"), std::string::npos) << output;
  EXPECT_TRUE(fs::is_empty(dir / "out"));
}

// ---------------------------------------------------------------- inputs never hang

TEST_F(Cli, AFifoAsAnImageIsRefusedWithoutReadingIt) {
  const fs::path fifo = dir / "f.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // `timeout` turns a hang into a failure instead of a stuck test.
  for (const auto& [lesson, param] :
       {std::pair<std::string, std::string>{"08_atmospherics", "spot.image"},
        {"02_projective_texture", "projector.image"}}) {
    for (const char* then : {"--headless --size 64x48 --out /dev/null", "--list-params"}) {
      const Result r =
          run(lesson, "--set " + param + "=" + fifo.string() + " " + then, "timeout 20 ");
      EXPECT_EQ(r.exit_code, 2) << lesson << " " << then << "\n" << r.output;
      EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
    }
  }
}

// A PNG whose header declares `side` x `side` pixels, followed by data that is not even a
// valid zlib stream: only the header can be read.
void writeHugeHeaderPng(const fs::path& path, std::uint32_t side) {
  auto be32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16),
                       static_cast<char>(v >> 8), static_cast<char>(v)};
  };
  // CRCs are not checked by the decoder; zeros keep the file short to write here.
  std::string png = "\x89PNG\r\n\x1a\n";
  png += be32(13) + "IHDR" + be32(side) + be32(side) + std::string("\x08\x06\0\0\0", 5) + be32(0);
  png += be32(8) + "IDAT" + std::string(8, '\xAB') + be32(0);
  png += be32(0) + "IEND" + be32(0);
  std::ofstream(path, std::ios::binary) << png;
}

TEST_F(Cli, AHugeImageIsRefusedFromItsHeaderBeforeDecoding) {
  const fs::path huge = dir / "huge.png";
  writeHugeHeaderPng(huge, 16384);
  const Result r =
      run("08_atmospherics",
          "--headless --size 64x48 --set spot.image=" + huge.string() + " --out /dev/null");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // Decoding first would have failed on the broken data instead.
  EXPECT_NE(r.output.find("16384x16384 is larger than 8192"), std::string::npos) << r.output;
}

TEST_F(Cli, APngCutBeforeItsEndSaysWhatIsWrong) {
  // A real picture without its IEND chunk: stb fails on it without a reason of its own.
  const fs::path whole = dir / "whole.png", cut = dir / "cut.png";
  ASSERT_EQ(run("08_atmospherics",
                "--headless --size 16x16 --frames 1 --no-truth --out " + whole.string())
                .exit_code,
            0);
  std::ifstream in(whole, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 12);
  const Result r =
      run("08_atmospherics",
          "--headless --size 64x48 --set spot.image=" + cut.string() + " --out /dev/null");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.find("()"), std::string::npos) << "an empty reason: " << r.output;
  EXPECT_NE(r.output.find("corrupt or truncated"), std::string::npos) << r.output;
}

TEST_F(Cli, EveryMessageIsOneLineOfPrintableText) {
  for (const std::string& bad :
       {"--set " + shellBytes("cam\nera.fov=45"), "--set " + shellBytes("\x01bogus=1"),
        "--frames " + shellBytes("1\n2"), "--size " + shellBytes("80x\n60"),
        "--set " + shellBytes("light.fov=\x1b[31m"), shellBytes("--\xff\x02"),
        "--out " + shellBytes("/nonexistent/\x7f\n.png")}) {
    const Result r = run(kLesson, "--headless --size 64x48 " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.output;
    ASSERT_FALSE(r.output.empty());
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << bad << ": " << r.output;
    for (size_t i = 0; i + 1 < r.output.size(); ++i) {
      const auto c = static_cast<unsigned char>(r.output[i]);
      EXPECT_TRUE(c >= 0x20 && c != 0x7f && c < 0x80)
          << bad << ": byte " << int{c} << " in " << r.output;
    }
  }
}

TEST_F(Cli, NumbersAreCheckedAsWrittenNotAfterRounding) {
  const std::string ok = "--headless --size 64x48 --frames 1 --no-truth --out /dev/null ";
  // Just outside the range, though they round to its ends in single precision.
  for (const char* outside : {"--set light.fov=4.9999999", "--set light.far=1000.00001"}) {
    EXPECT_EQ(run(kLesson, ok + outside).exit_code, 2) << outside;
  }
  // Inside it: an underflowing number is its nearest value (0 here), and leading zeros are
  // the same number for every flag.
  for (const char* inside : {"--set dimming=1e-320", "--size 0000064x48", "--frames 00001",
                             "--set light.fov=5", "--set light.far=1000"}) {
    const Result r = run(kLesson, ok + inside);
    EXPECT_EQ(r.exit_code, 0) << inside << "\n" << r.output;
  }
}

std::vector<std::string> allLessons() {
  std::vector<std::string> names;
  std::stringstream list(SHADOWS_LESSON_NAMES);
  for (std::string name; std::getline(list, name, ',');) names.push_back(name);
  return names;
}

// The contract holds for every lesson binary, not just 03.
class EveryLessonCli : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryLessonCli, BadInputExitsTwoWithOneLineAndWritesNothing) {
  const std::string lesson = GetParam();
  const auto dir = fs::temp_directory_path() / ("shadows_cli_all_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "x.png").string();
  for (const std::string bad :
       {"--bogus", "--set no.such.param=1", "--set view=nope", "--set scene=moon", "--size 0x10",
        "--frames 0", "--set camera.pos=1,2", "--out /nonexistent/x.png",
        "--set light.pos=1,2,3,4"}) {
    const Result r = run(lesson, "--headless --size 64x48 " + bad + " --out " + out);
    EXPECT_EQ(r.exit_code, 2) << lesson << " " << bad << "\n" << r.output;
    EXPECT_TRUE(fs::is_empty(dir)) << lesson << " " << bad;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  // Each parameter parses alone; together near >= far is no frustum.
  const Result listed = run(lesson, "--list-params");
  if (listed.output.find("light.near") != std::string::npos) {
    const Result r = run(lesson, "--headless --set light.near=5 --set light.far=1 --out " + out);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("must be less than light.far"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_empty(dir));
  }
  fs::remove_all(dir);
}

TEST_P(EveryLessonCli, DefaultHeadlessRunSucceedsWithAReport) {
  const std::string lesson = GetParam();
  const auto dir = fs::temp_directory_path() / ("shadows_cli_ok_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const Result r =
      run(lesson, "--headless --size 96x72 --frames 1 --out " + (dir / "x.png").string() +
                      " --report " + (dir / "r.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "x.png"));
  const nlohmann::json json = readReport(dir / "r.json");
  EXPECT_EQ(json["lesson"], lesson);
  EXPECT_EQ(json["gl_errors"], 0);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- documented limits

// One parameter's line of --list-params: its kind and, for numbers, the range it states.
struct Listed {
  std::string name, kind;
  double min = 0, max = 0;
  bool ranged = false;
};

std::vector<Listed> listedParams(const std::string& lesson) {
  std::vector<Listed> params;
  std::stringstream lines(run(lesson, "--list-params").output);
  for (std::string line; std::getline(lines, line);) {
    Listed p;
    std::stringstream words(line);
    words >> p.name >> p.kind;
    const auto open = line.rfind(" in [");
    if (open != std::string::npos) {
      const auto comma = line.find(", ", open), close = line.find(']', open);
      p.min = std::stod(line.substr(open + 5, comma - open - 5));
      p.max = std::stod(line.substr(comma + 2, close - comma - 2));
      p.ranged = true;
    }
    params.push_back(p);
  }
  return params;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string assignment(const Listed& p, double v) {
  const std::string x = number(v);
  return p.kind == "vec3" ? p.name + "=" + x + "," + x + "," + x : p.name + "=" + x;
}

// Both ends of every range --list-params states are accepted, together; one step beyond
// either end is exit 2. Read from the binaries, so a new parameter is covered by itself.
// --list-params after the --set list applies and checks them without rendering.
TEST(DocumentedLimits, EveryRangeEndIsAcceptedAndOneStepBeyondRefused) {
  std::set<std::string> tried;  // a shared parameter once, not once per lesson
  for (const std::string& lesson : allLessons()) {
    std::string at_min, at_max;
    std::vector<std::string> beyond;
    for (const Listed& p : listedParams(lesson)) {
      if (!p.ranged || (p.kind != "int" && p.kind != "float" && p.kind != "vec3")) continue;
      at_min += " --set " + assignment(p, p.min);
      at_max += " --set " + assignment(p, p.max);
      const std::string key = p.name + number(p.min) + number(p.max);
      if (!tried.insert(key).second) continue;
      const double step =
          p.kind == "int" ? 1.0 : 1e-6 * std::max({1.0, std::abs(p.min), std::abs(p.max)});
      beyond.push_back(assignment(p, p.min - step));
      beyond.push_back(assignment(p, p.max + step));
    }
    for (const std::string& ends : {at_min, at_max}) {
      const Result r = run(lesson, ends + " --list-params");
      EXPECT_EQ(r.exit_code, 0) << lesson << ends << "\n" << r.output;
    }
    for (const std::string& set : beyond) {
      const Result r = run(lesson, "--set " + set + " --list-params");
      EXPECT_EQ(r.exit_code, 2) << lesson << " " << set << "\n" << r.output;
    }
  }
}

// The flags state their ranges in their own message; both ends work, one beyond does not.
TEST(DocumentedLimits, FlagRangesFromTheirOwnMessages) {
  const Result size = run(kLesson, "--size 0x0");
  const auto in = size.output.find(" in "), dots = size.output.find("..", in);
  ASSERT_NE(dots, std::string::npos) << size.output;
  const int lo = std::stoi(size.output.substr(in + 4)),
            hi = std::stoi(size.output.substr(dots + 2));
  EXPECT_EQ(
      run(kLesson, "--size " + std::to_string(lo) + "x" + std::to_string(hi) + " --list-params")
          .exit_code,
      0);
  EXPECT_EQ(
      run(kLesson, "--size " + std::to_string(hi) + "x" + std::to_string(lo) + " --list-params")
          .exit_code,
      0);
  EXPECT_EQ(run(kLesson, "--size " + std::to_string(hi + 1) + "x64 --list-params").exit_code, 2);
  EXPECT_EQ(run(kLesson, "--size 64x" + std::to_string(lo - 1) + " --list-params").exit_code, 2);
  const Result frames = run(kLesson, "--frames 0");
  const auto fin = frames.output.find(" in "), fdots = frames.output.find("..", fin);
  ASSERT_NE(fdots, std::string::npos) << frames.output;
  const int flo = std::stoi(frames.output.substr(fin + 4));
  const int fhi = std::stoi(frames.output.substr(fdots + 2));
  EXPECT_EQ(run(kLesson, "--frames " + std::to_string(flo) + " --list-params").exit_code, 0);
  EXPECT_EQ(run(kLesson, "--frames " + std::to_string(fhi) + " --list-params").exit_code, 0);
  EXPECT_EQ(run(kLesson, "--frames " + std::to_string(fhi + 1) + " --list-params").exit_code, 2);
}

INSTANTIATE_TEST_SUITE_P(Lessons, EveryLessonCli, ::testing::ValuesIn(allLessons()),
                         [](const ::testing::TestParamInfo<std::string>& lesson) {
                           return lesson.param;
                         });

}  // namespace
