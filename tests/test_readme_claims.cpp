// The numbers the READMEs quote, re-measured. A claim sits in the README next to the number
// it backs, as an HTML comment on a line of its own, which a reader does not see:
//   <!-- claim: 06_dual_texture_8bit --set light.near=0.5 => /error/false_lit_pct 0.59 +- 0.1 -->
// The test runs the lesson headless with those flags (--frames 1, the README's own --size if
// it gives one, else 640x480), reads the report field by its JSON pointer and checks it within
// the stated precision. Only what is deterministic can be claimed: error numbers and work
// counters, never timings (a field ending in _ms or named *_overhead is refused).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Claim {
  std::string readme, lesson, flags, pointer;
  double value = 0, tolerance = 0;
  int line = 0;
};

std::vector<Claim> claimsIn(const fs::path& readme) {
  std::vector<Claim> claims;
  std::ifstream in(readme);
  const std::regex pattern(
      R"(^\s*<!--\s*claim:\s*(\S+)\s+(.*?)\s*=>\s*(\S+)\s+([-0-9.eE+]+)\s*\+-\s*([0-9.eE+-]+)\s*-->)");
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    for (std::sregex_iterator it(line.begin(), line.end(), pattern), end; it != end; ++it) {
      const std::smatch& m = *it;
      claims.push_back({fs::relative(readme, SHADOWS_SOURCE_DIR).string(), m[1], m[2], m[3],
                        std::stod(m[4]), std::stod(m[5]), number});
    }
    // A claim that does not parse must not pass silently (one quoted in `code` is prose).
    const auto at = line.find("<!-- claim:");
    if (at != std::string::npos && at == line.find_first_not_of(" \t") &&
        !std::regex_search(line, pattern)) {
      ADD_FAILURE() << readme << ":" << number << ": a claim that does not parse: " << line;
    }
  }
  return claims;
}

std::vector<Claim> allClaims() {
  std::vector<Claim> claims;
  // The project's README and each directory's (lessons, tests, bench), one level down.
  std::vector<fs::path> readmes = {fs::path(SHADOWS_SOURCE_DIR) / "README.md"};
  for (const auto& entry : fs::directory_iterator(SHADOWS_SOURCE_DIR)) {
    if (entry.is_directory() && fs::exists(entry.path() / "README.md")) {
      readmes.push_back(entry.path() / "README.md");
    }
  }
  for (const fs::path& readme : readmes) {
    for (Claim& c : claimsIn(readme)) claims.push_back(std::move(c));
  }
  return claims;
}

TEST(ReadmeClaims, EveryQuotedErrorAndCounterStillMeasuresSo) {
  const std::vector<Claim> claims = allClaims();
  ASSERT_GE(claims.size(), 6u) << "the READMEs' claims were not found";
  const fs::path report = fs::temp_directory_path() / ("claim_" + std::to_string(getpid()));
  // Claims about the same run (lesson and flags) share one render.
  std::map<std::string, nlohmann::json> runs;
  for (const Claim& c : claims) {
    const std::string where = c.readme + ":" + std::to_string(c.line) + " (" + c.lesson + " " +
                              c.flags + " => " + c.pointer + ")";
    ASSERT_EQ(c.pointer.find("_ms"), std::string::npos) << where << ": timings are not claims";
    ASSERT_EQ(c.pointer.find("overhead"), std::string::npos) << where;
    const std::string size = c.flags.find("--size") == std::string::npos ? " --size 640x480" : "";
    const std::string command = std::string(SHADOWS_BINARY_DIR) + "/" + c.lesson +
                                " --headless --frames 1" + size + " " + c.flags +
                                " --out /dev/null --report " + report.string() + " >/dev/null 2>&1";
    auto run = runs.find(command);
    if (run == runs.end()) {
      ASSERT_EQ(std::system(command.c_str()), 0) << where;
      std::ifstream in(report);
      run = runs.emplace(command, nlohmann::json::parse(in, nullptr, false)).first;
    }
    const nlohmann::json& json = run->second;
    ASSERT_FALSE(json.is_discarded()) << where;
    const nlohmann::json::json_pointer at(c.pointer);
    ASSERT_TRUE(json.contains(at)) << where << ": no such field";
    const double measured = json.at(at).get<double>();
    EXPECT_NEAR(measured, c.value, c.tolerance)
        << where << ": the README says " << c.value << ", the lesson now measures " << measured;
  }
  fs::remove(report);
}

}  // namespace
