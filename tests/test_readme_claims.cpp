// The numbers the READMEs quote, re-measured. A claim sits in the README next to the number
// it backs, as an HTML comment on a line of its own, which a reader does not see:
//   <!-- claim: 06_dual_texture_8bit --size 640x480 --set light.near=0.5 => /error/false_lit_pct
//   0.59 -->
// The test runs the lesson headless with exactly those flags (and --frames 1, which changes
// no error or counter): nothing unstated, so the command a reader copies gives the number. It
// reads the report field by its JSON pointer. The figure is written as the README prints it, and
// is a promise to its last digit: the measurement rounds to it (within half a unit of that digit),
// and it stands in the visible text beside the claim (digits grouped by spaces, as in "1 174 752",
// or a k/M/G suffix, as in "61.04 M", read the same). A figure that moves (bake noise, a sampled
// truth) may carry "+- TOL moves: why" if the text beside it prints "± TOL". Only what is
// deterministic can be claimed: error numbers and work counters, never timings (a field ending
// in _ms or named *_overhead is refused). A timing is claimed against the CSV it was read from
// instead, never re-timed, under the same rule:
//   <!-- csv-claim: docs/bench_precision_far.csv map=16bit_two_digits => median(frame_ms) 23.6 -->
// takes the rows whose columns hold every key=value given, and compares the median of the
// column over them.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../16_choose_your_shadow/bench_front.hpp"

namespace {

namespace fs = std::filesystem;

// A figure as the README prints it: "0.011", "74.8", "1174752", "61.04M". Its precision is half a
// unit in its last digit, unless the claim says why it moves and by how much.
struct Figure {
  std::string text;  // as written in the claim, without a sign
  double value = 0, tolerance = 0;
  std::string moves;  // why a wider tolerance, as the claim says
};

std::optional<Figure> parseFigure(const std::string& written, const std::string& tolerance,
                                  const std::string& moves) {
  static const std::regex shape(R"((-?)(\d+)(?:\.(\d+))?([kMG]?))");
  std::smatch m;
  if (!std::regex_match(written, m, shape)) return std::nullopt;
  const double scale = m[4] == "k" ? 1e3 : m[4] == "M" ? 1e6 : m[4] == "G" ? 1e9 : 1.0;
  Figure f;
  f.text = written.substr(m[1].length());
  f.value = std::stod(written.substr(0, written.size() - m[4].length())) * scale;
  f.tolerance = 0.5 * std::pow(10.0, -static_cast<double>(m[3].length())) * scale;
  if (!tolerance.empty()) {
    const double wider = std::stod(tolerance);
    if (moves.empty() || wider <= f.tolerance) return std::nullopt;
    f.tolerance = wider;
    f.moves = moves;
  }
  return f;
}

bool within(double measured, const Figure& f) {
  // The slack is for the decimal figure's binary rounding, not for the measurement.
  return std::abs(measured - f.value) <= f.tolerance * (1 + 1e-9) + 1e-12;
}

// The figures a reader sees on a line: every number not part of a name or a longer number
// ("640x480", "1e-3", "light.pos=1,2" give none), digits grouped by spaces joined, a k/M/G
// suffix kept ("61.04 M" is "61.04M").
std::vector<std::string> printedFigures(std::string line) {
  static const std::regex grouped(R"((\d) (\d{3})(?!\d))");
  for (std::string before; before != line;) {
    before = line;
    line = std::regex_replace(line, grouped, "$1$2");
  }
  std::vector<std::string> found;
  const auto alnum = [&](size_t at) { return std::isalnum(static_cast<unsigned char>(line[at])); };
  // Part of a name, a longer number, a list of coordinates ("1,2") or an exponent ("1e-3").
  const auto glued = [&](size_t i) {
    if (i == 0) return false;
    const char c = line[i - 1];
    return alnum(i - 1) || c == '_' || c == '.' || c == '=' ||
           ((c == ',' || c == '-') && i >= 2 && alnum(i - 2));
  };
  for (size_t i = 0; i < line.size();) {
    if (!std::isdigit(static_cast<unsigned char>(line[i])) || glued(i)) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < line.size() && std::isdigit(static_cast<unsigned char>(line[j]))) ++j;
    if (j + 1 < line.size() && line[j] == '.' &&
        std::isdigit(static_cast<unsigned char>(line[j + 1]))) {
      ++j;
      while (j < line.size() && std::isdigit(static_cast<unsigned char>(line[j]))) ++j;
    }
    std::string figure = line.substr(i, j - i);
    size_t k = j < line.size() && line[j] == ' ' ? j + 1 : j;
    if (k < line.size() && std::string("kMG").find(line[k]) != std::string::npos &&
        (k + 1 == line.size() || !std::isalpha(static_cast<unsigned char>(line[k + 1])))) {
      found.push_back(figure + line[k]);
    }
    const bool runs_on =
        j < line.size() &&
        (alnum(j) || line[j] == '_' ||
         ((line[j] == '.' || line[j] == ',') && j + 1 < line.size() && alnum(j + 1)));
    if (!runs_on) found.push_back(figure);
    i = j;
  }
  return found;
}

// The visible text beside a claim: the lines a reader sees (not comments) from 30 above to 5
// below, within its section.
std::vector<std::string> besideClaim(const std::vector<std::string>& lines, size_t at) {
  const auto comment = [](const std::string& l) {
    const auto first = l.find_first_not_of(" \t");
    return first != std::string::npos && l.compare(first, 4, "<!--") == 0;
  };
  const auto heading = [](const std::string& l) { return !l.empty() && l[0] == '#'; };
  std::vector<std::string> beside;
  for (size_t i = at, seen = 0; i-- > 0 && seen < 30 && !heading(lines[i]);) {
    if (!comment(lines[i])) {
      beside.push_back(lines[i]);
      ++seen;
    }
  }
  for (size_t i = at + 1, seen = 0; i < lines.size() && seen < 5 && !heading(lines[i]); ++i) {
    if (!comment(lines[i])) {
      beside.push_back(lines[i]);
      ++seen;
    }
  }
  return beside;
}

// What is wrong with how a figure is printed beside its claim, or "" when nothing is.
std::string printedBeside(const Figure& f, const std::vector<std::string>& beside) {
  bool printed = false, said = f.moves.empty();
  for (const std::string& line : beside) {
    for (const std::string& figure : printedFigures(line)) printed = printed || figure == f.text;
    said = said || line.find("±") != std::string::npos;
  }
  if (!printed) return "the figure " + f.text + " is not printed beside its claim";
  if (!said) return "the figure moves (" + f.moves + ") but the text beside it gives no ± range";
  return "";
}

struct Claim {
  std::string readme, lesson, flags, pointer;
  Figure figure;
  std::string misprinted;  // why the figure is not as the text beside it prints it
  int line = 0;
};

std::vector<std::string> readLines(const fs::path& file) {
  std::vector<std::string> lines;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<Claim> claimsIn(const fs::path& readme) {
  std::vector<Claim> claims;
  const std::vector<std::string> lines = readLines(readme);
  const std::regex pattern(
      R"(^\s*<!--\s*claim:\s*(\S+)\s+(.*?)\s*=>\s*(\S+)\s+(\S+?)(?:\s*\+-\s*(\S+)\s+moves:\s*(.*?))?\s*-->)");
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const int number = static_cast<int>(i) + 1;
    std::smatch m;
    std::optional<Figure> figure;
    if (std::regex_search(line, m, pattern)) figure = parseFigure(m[4], m[5], m[6]);
    if (figure) {
      claims.push_back({fs::relative(readme, SHADOWS_SOURCE_DIR).string(), m[1], m[2], m[3],
                        *figure, printedBeside(*figure, besideClaim(lines, i)), number});
    }
    // A claim that does not parse must not pass silently (one quoted in `code` is prose).
    const auto at = line.find("<!-- claim:");
    if (at != std::string::npos && at == line.find_first_not_of(" \t") && !figure) {
      ADD_FAILURE() << readme << ":" << number
                    << ": a claim that does not parse (a figure as printed, and a tolerance "
                       "wider than its last digit only with 'moves: why'): "
                    << line;
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
    EXPECT_EQ(c.misprinted, "") << where;
    ASSERT_TRUE(json.at(at).is_number()) << where << ": " << json.at(at).dump();
    const double measured = json.at(at).get<double>();
    EXPECT_TRUE(within(measured, c.figure))
        << where << ": the README prints " << c.figure.text << " (+- " << c.figure.tolerance
        << "), the lesson now measures " << measured;
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

// The rule itself: what a figure holds, what the text beside it prints.
TEST(ReadmeClaimRule, AFigureHoldsHalfItsLastDigitAndMustBePrintedBesideIt) {
  const std::optional<Figure> f = parseFigure("0.011", "", "");
  ASSERT_TRUE(f);
  EXPECT_TRUE(within(0.0114, *f));
  EXPECT_TRUE(within(0.0106, *f));
  EXPECT_FALSE(within(0.0092, *f));  // 09's default, printed 0.009 while it measured 0.011
  EXPECT_FALSE(within(0.0116, *f));
  EXPECT_TRUE(within(1174752, *parseFigure("1174752", "", "")));
  EXPECT_FALSE(within(1174753, *parseFigure("1174752", "", "")));
  EXPECT_TRUE(within(61.04e6, *parseFigure("61.0M", "", "")));
  // A tolerance wider than the last digit only with a reason; never one narrower.
  EXPECT_FALSE(parseFigure("0.0092", "0.01", ""));
  EXPECT_FALSE(parseFigure("0.0034", "0.00001", "bake noise"));
  EXPECT_TRUE(parseFigure("0.0034", "0.0003", "bake noise"));
  EXPECT_FALSE(parseFigure("1e-3", "", ""));
  EXPECT_EQ(printedFigures("| silhouettes | 610 | 1 174 752 |"),
            (std::vector<std::string>{"610", "1174752"}));
  EXPECT_EQ(printedFigures("`--size 640x480 --set light.pos=1.373,5.1` gives 0.27 %, 1e-3."),
            (std::vector<std::string>{"0.27"}));
  EXPECT_EQ(printedFigures("61.0 M fragments, 4 MB"),
            (std::vector<std::string>{"61.0M", "61.0", "4"}));
  const std::vector<std::string> beside = {"The default's 0.009 % are single pixels."};
  EXPECT_EQ(printedBeside(*parseFigure("0.009", "", ""), beside), "");
  EXPECT_NE(printedBeside(*parseFigure("0.011", "", ""), beside), "");
  EXPECT_NE(
      printedBeside(*parseFigure("0.0034", "0.0003", "bake noise"), {"0.0034 of the picture"}),
      "");  // moves, but the text gives no ± range
}

// ---------------------------------------------------------------- timings, from their CSV

struct CsvClaim {
  std::string readme, csv, column;
  std::vector<std::pair<std::string, std::string>> filters;
  Figure figure;
  std::string misprinted;
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
      R"(^\s*<!--\s*csv-claim:\s*(\S+)\s+(.*?)\s*=>\s*median\((\S+)\)\s+(\S+?)(?:\s*\+-\s*(\S+)\s+moves:\s*(.*?))?\s*-->)");
  std::vector<CsvClaim> claims;
  for (const fs::path& readme : readmes()) {
    const std::vector<std::string> lines = readLines(readme);
    for (size_t i = 0; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      const int number = static_cast<int>(i) + 1;
      std::smatch m;
      const auto at = line.find("<!-- csv-claim:");
      if (at == std::string::npos || at != line.find_first_not_of(" \t")) continue;
      ASSERT_TRUE(std::regex_search(line, m, pattern)) << readme << ":" << number << ": " << line;
      const std::optional<Figure> figure = parseFigure(m[4], m[5], m[6]);
      ASSERT_TRUE(figure) << readme << ":" << number << ": a figure as printed: " << line;
      CsvClaim c{fs::relative(readme, SHADOWS_SOURCE_DIR).string(), m[1],  m[3], {}, *figure,
                 printedBeside(*figure, besideClaim(lines, i)),     number};
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
    EXPECT_EQ(c.misprinted, "") << where;
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
    EXPECT_TRUE(within(median, c.figure))
        << where << ": the README prints " << c.figure.text << ", " << c.csv << " gives " << median;
  }
}

// Lesson 16's panel draws the bench's front from bench_points.inc: its rows must be the CSV the
// README reads, or the panel and the plot disagree.
TEST(ReadmeTimingClaims, Lesson16sPanelPointsAreItsSweepsCsv) {
  using shadows::BenchPoint, shadows::kBenchPoints, shadows::kBenchTime;
  const std::string csv = "docs/bench_16_choose_your_shadow.csv";
  const std::string again = "; after a sweep, run: bench/tables.py points " + csv +
                            " > 16_choose_your_shadow/bench_points.inc";
  std::ifstream in(fs::path(SHADOWS_SOURCE_DIR) / csv);
  ASSERT_TRUE(in) << csv;
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = csvFields(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << csv << ": no column " << name;
    return static_cast<size_t>(it - header.begin());
  };
  size_t n = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> row = csvFields(line);
    if (row.size() != header.size() || row[column("status")] != "ok") continue;
    ASSERT_LT(n, std::size(kBenchPoints)) << "more rows than the panel's" << again;
    const BenchPoint& p = kBenchPoints[n++];
    const std::string where = csv + " row " + std::to_string(n) + again;
    EXPECT_EQ(p.scene, row[column("scene")]) << where;
    EXPECT_EQ(p.light, row[column("light")]) << where;
    EXPECT_EQ(p.setting, row[column("setting")]) << where;
    EXPECT_EQ(p.settings, row[column("settings")]) << where;
    EXPECT_EQ(kBenchTime, row[column("front_time")]) << where;
    EXPECT_NEAR(p.ms, std::stod(row[column(kBenchTime)]), 1e-5 * p.ms) << where;
    EXPECT_NEAR(p.error, std::stod(row[column("vis_mae")]), 1e-5 * p.error) << where;
  }
  EXPECT_EQ(n, std::size(kBenchPoints)) << "fewer rows than the panel's" << again;
}

}  // namespace
