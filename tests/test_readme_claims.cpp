// The numbers the READMEs quote, re-measured. A claim sits in the README next to the number
// it backs, as an HTML comment on a line of its own, which a reader does not see:
//   <!-- claim: 06_dual_texture_8bit --size 640x480 --set light.near=0.5 => /error/false_lit_pct
//   0.59 +- 0.1 -->
// The test runs the lesson headless with exactly those flags (and --frames 1, which changes
// no error or counter): nothing unstated, so the command a reader copies gives the number. It
// reads the report field by its JSON pointer and checks it within the stated precision. Only what
// is deterministic can be claimed: error numbers and work counters, never timings (a field ending
// in _ms or named *_overhead is refused). A timing is claimed against the CSV it was read from
// instead, never re-timed:
//   <!-- csv-claim: docs/bench_precision_far.csv map=16bit_two_digits => median(frame_ms) 53.9 +-
//   0.05 -->
// takes the rows whose columns hold every key=value given, and compares the median of the
// column over them.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
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

// The project's README and each directory's (lessons, tests, bench), one level down.
std::vector<fs::path> readmes() {
  std::vector<fs::path> found = {fs::path(SHADOWS_SOURCE_DIR) / "README.md"};
  for (const auto& entry : fs::directory_iterator(SHADOWS_SOURCE_DIR)) {
    if (entry.is_directory() && fs::exists(entry.path() / "README.md")) {
      found.push_back(entry.path() / "README.md");
    }
  }
  return found;
}

// One test per README that holds claims, so that ctest spreads them over the cores.
class ReadmeClaims : public ::testing::TestWithParam<fs::path> {};

TEST_P(ReadmeClaims, EveryQuotedErrorAndCounterStillMeasuresSo) {
  const std::vector<Claim> claims = claimsIn(GetParam());
  ASSERT_FALSE(claims.empty()) << GetParam() << ": its claims were not found";
  const fs::path report = fs::temp_directory_path() / ("claim_" + std::to_string(getpid()));
  // Claims about the same run (lesson and flags) share one render.
  std::map<std::string, nlohmann::json> runs;
  for (const Claim& c : claims) {
    const std::string where = c.readme + ":" + std::to_string(c.line) + " (" + c.lesson + " " +
                              c.flags + " => " + c.pointer + ")";
    ASSERT_EQ(c.pointer.find("_ms"), std::string::npos) << where << ": timings are not claims";
    ASSERT_EQ(c.pointer.find("overhead"), std::string::npos) << where;
    const std::string command = std::string(SHADOWS_BINARY_DIR) + "/" + c.lesson +
                                " --headless --frames 1 " + c.flags + " --out /dev/null --report " +
                                report.string() + " >/dev/null 2>&1";
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

// The READMEs with claims (at least the six lessons' that had them first), found once when the
// tests are listed.
std::vector<fs::path> readmesWithClaims() {
  std::vector<fs::path> found;
  for (const fs::path& readme : readmes()) {
    if (!claimsIn(readme).empty()) found.push_back(readme);
  }
  std::sort(found.begin(), found.end());
  return found;
}

INSTANTIATE_TEST_SUITE_P(Readmes, ReadmeClaims, ::testing::ValuesIn(readmesWithClaims()),
                         [](const ::testing::TestParamInfo<fs::path>& param) {
                           std::string name = param.param.parent_path().filename().string();
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

TEST(ReadmeClaimsFound, EveryLessonThatQuotedNumbersStillHasItsClaims) {
  // A README whose claims stopped parsing would drop out of the list above unseen.
  const std::vector<fs::path> found = readmesWithClaims();
  ASSERT_GE(found.size(), 6u) << "the READMEs' claims were not found";
  for (const char* lesson :
       {"03_shadow_map_basic", "04_bias_offset", "05_pcf_dithered", "06_dual_texture_8bit",
        "07_multidigit_16bit", "08_atmospherics", "09_shadow_volumes", "10_plane_optimal",
        "11_omni_cube", "12_cascades", "13_filterable_maps", "14_soft_shadows", "15_light_maps"}) {
    EXPECT_NE(
        std::find(found.begin(), found.end(), fs::path(SHADOWS_SOURCE_DIR) / lesson / "README.md"),
        found.end())
        << lesson << "'s README has no claim any more";
  }
}

// ---------------------------------------------------------------- timings, from their CSV

struct CsvClaim {
  std::string readme, csv, column;
  std::vector<std::pair<std::string, std::string>> filters;
  double value = 0, tolerance = 0;
  int line = 0;
};

std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

TEST(ReadmeTimingClaims, EveryQuotedTimingIsTheMedianOfTheCsvItCites) {
  const std::regex pattern(
      R"(^\s*<!--\s*csv-claim:\s*(\S+)\s+(.*?)\s*=>\s*median\((\S+)\)\s+([-0-9.eE+]+)\s*\+-\s*([0-9.eE+-]+)\s*-->)");
  std::vector<CsvClaim> claims;
  for (const fs::path& readme : readmes()) {
    std::ifstream in(readme);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      std::smatch m;
      const auto at = line.find("<!-- csv-claim:");
      if (at == std::string::npos || at != line.find_first_not_of(" \t")) continue;
      ASSERT_TRUE(std::regex_search(line, m, pattern)) << readme << ":" << number << ": " << line;
      CsvClaim c{fs::relative(readme, SHADOWS_SOURCE_DIR).string(),
                 m[1],
                 m[3],
                 {},
                 std::stod(m[4]),
                 std::stod(m[5]),
                 number};
      std::stringstream words(m[2].str());
      for (std::string word; words >> word;) {
        const auto eq = word.find('=');
        ASSERT_NE(eq, std::string::npos) << c.readme << ":" << number << ": " << word;
        c.filters.emplace_back(word.substr(0, eq), word.substr(eq + 1));
      }
      claims.push_back(c);
    }
  }
  ASSERT_GE(claims.size(), 3u) << "the READMEs' timing claims were not found";
  for (const CsvClaim& c : claims) {
    const std::string where = c.readme + ":" + std::to_string(c.line);
    std::ifstream in(fs::path(SHADOWS_SOURCE_DIR) / c.csv);
    ASSERT_TRUE(in) << where << ": no " << c.csv;
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = csvFields(line);
    const auto column = [&](const std::string& name) {
      const auto it = std::find(header.begin(), header.end(), name);
      return it == header.end() ? -1 : static_cast<int>(it - header.begin());
    };
    ASSERT_GE(column(c.column), 0) << where << ": no column " << c.column;
    std::vector<double> values;
    while (std::getline(in, line)) {
      const std::vector<std::string> row = csvFields(line);
      bool match = true;
      for (const auto& [key, value] : c.filters) {
        const int k = column(key);
        ASSERT_GE(k, 0) << where << ": no column " << key;
        match =
            match && static_cast<size_t>(k) < row.size() && row[static_cast<size_t>(k)] == value;
      }
      const auto k = static_cast<size_t>(column(c.column));
      if (match && k < row.size() && !row[k].empty()) values.push_back(std::stod(row[k]));
    }
    ASSERT_FALSE(values.empty()) << where << ": no row matches";
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    EXPECT_NEAR(median, c.value, c.tolerance)
        << where << ": the README says " << c.value << ", " << c.csv << " gives " << median;
  }
}

}  // namespace
