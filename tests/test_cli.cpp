// The command-line contract of every lesson binary: bad input is exit 2, one line that
// names what is wrong, and no file left behind.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Result {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

Result run(const std::string& lesson, const std::string& args, const std::string& env = {}) {
  const std::string command =
      env + std::string(SHADOWS_BINARY_DIR) + "/" + lesson + " " + args + " 2>&1";
  Result result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
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
  std::ifstream in(report);
  std::stringstream json;
  json << in.rdbuf();
  for (const char* key : {"\"frame_ms\"", "\"pass_ms\"", "\"eye\"", "\"counters\"",
                          "\"fragment_invocations\"", "\"shadow_map_renders\"", "\"gl_errors\": 0",
                          "\"false_shadow_pct\"", "\"truth\": \"point\"", "\"shadow.size\": 2048",
                          "\"view\": \"compare\"", "\"backend\": \"osmesa\""}) {
    EXPECT_NE(json.str().find(key), std::string::npos) << key << "\n" << json.str();
  }
  EXPECT_FALSE(fs::exists(out + ".partial"));
}

TEST_F(Cli, OutputsToDevNullLeaveItADevice) {
  const Result r = run(kLesson,
                       "--headless --size 64x48 --frames 1 --out /dev/null --report "
                       "/dev/null --error-out /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_character_file("/dev/null")) << "the run replaced /dev/null with a file";
}

TEST_F(Cli, ADisplayThatLeadsNowhereFallsBackToHeadless) {
  const auto out = (dir / "x.png").string();
  const Result r = run(kLesson, "--size 64x48 --frames 1 --no-truth --out " + out, "DISPLAY=:97 ");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rendering headless"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out));
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
                      "--out /nonexistent/dir/x.png", "--report /nonexistent/r.json",
                      "--error-out /proc/none/e.png", "--truth-out", "--out /tmp/x.jpg",
                      "--error-out /tmp/e.bmp", "--set shadow.height=1", kLongName.c_str()));

TEST_F(Cli, AnOutputThatFailsLeavesNoneOfTheOthersAndSaysWhich) {
  // /dev/full accepts the open and fails the write: the report, truth or error picture
  // cannot be written, so the picture written before it must not stay either.
  for (const char* flag : {"--report", "--truth-out", "--error-out"}) {
    const std::string out = (dir / "x.png").string();
    const Result r =
        run(kLesson, "--headless --size 64x48 --frames 1 --out " + out + " " + flag + " /dev/full");
    EXPECT_EQ(r.exit_code, 1) << flag << "\n" << r.output;
    EXPECT_NE(r.output.find("cannot write /dev/full"), std::string::npos) << r.output;
    EXPECT_TRUE(dirIsEmpty()) << flag << ": a partial set of outputs was left";
  }
}

TEST_F(Cli, TwoOutputsIntoOneFileAreRefused) {
  const std::string same = (dir / "p.png").string();
  const Result r = run(kLesson, "--headless --size 64x48 --out " + same + " --error-out " + same);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("name the same file"), std::string::npos) << r.output;
  EXPECT_TRUE(dirIsEmpty());
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
  EXPECT_TRUE(fs::exists(dir / "r.json"));
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Lessons, EveryLessonCli, ::testing::ValuesIn(allLessons()),
                         [](const ::testing::TestParamInfo<std::string>& lesson) {
                           return lesson.param;
                         });

}  // namespace
