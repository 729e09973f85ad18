// The report writer: valid nesting, escaping, and no NaN in JSON.
#include "core/json.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/text.hpp"

namespace shadows {
namespace {

TEST(JsonWriter, NestsEscapesAndWritesNonFiniteAsNull) {
  JsonWriter json;
  json.beginObject();
  json.value("name", std::string("a \"quoted\"\\path\n"));
  json.value("nan", std::numeric_limits<double>::quiet_NaN());
  json.beginArray("xs");
  json.value("", 1);
  json.value("", 2.5);
  json.endArray();
  json.endObject();
  const std::string& s = json.str();
  EXPECT_NE(s.find(R"("name": "a \"quoted\"\\path\u000a")"), std::string::npos) << s;
  EXPECT_NE(s.find("\"nan\": null"), std::string::npos) << s;
  EXPECT_NE(s.find("1,"), std::string::npos) << s;
  EXPECT_EQ(std::count(s.begin(), s.end(), '{'), std::count(s.begin(), s.end(), '}'));
  EXPECT_EQ(std::count(s.begin(), s.end(), '['), std::count(s.begin(), s.end(), ']'));
}

}  // namespace
}  // namespace shadows

namespace shadows {
namespace {

// Every report goes through a real parser: what the writer makes of any bytes a user can put
// in a string (a file name in Latin-1, control characters) must parse, and say them back.
TEST(JsonWriter, AnyBytesInAStringStillMakeJson) {
  const std::string nasty = std::string("caf\xc3\xa9 \xff\xfe.png \x01\x7f tab\t \"q\" \\ ") +
                            "\xe2\x82" + /* a cut sequence */ " \xed\xa0\x80" /* a surrogate */;
  JsonWriter json;
  json.beginObject();
  json.value("path", nasty);
  json.endObject();
  const auto parsed = nlohmann::json::parse(json.str(), nullptr, false);
  ASSERT_FALSE(parsed.is_discarded()) << json.str();
  EXPECT_EQ(parsed["path"].get<std::string>(),
            "caf\xc3\xa9 \\xFF\\xFE.png \x01\x7f tab\t \"q\" \\ \\xE2\\x82 \\xED\\xA0\\x80");
}

TEST(Printable, OneLineOfValidUtf8AndIdempotent) {
  const std::string raw = "a\nb\rc\td\x01\x7f\xff caf\xc3\xa9";
  const std::string shown = printable(raw);
  EXPECT_EQ(shown, "a\\nb\\rc\\td\\x01\\x7F\\xFF caf\xc3\xa9");
  EXPECT_EQ(printable(shown), shown) << "printing a message twice must not change it";
  for (const char c : shown) EXPECT_GE(static_cast<unsigned char>(c), 0x20) << shown;
}

TEST(Printable, BidiControlsAreEscapedSoNoMessageReadsBackwards) {
  // A right-to-left override (U+202E) in a --set value would reverse the rest of the notice.
  const std::string raw =
      "dueling\xe2\x80\xae<junk> \xe2\x81\xa6x\xe2\x81\xa9 \xd8\x9c \xe2\x80\x8f \xe2\x82\xac";
  const std::string shown = printable(raw);
  EXPECT_EQ(shown, "dueling\\u202E<junk> \\u2066x\\u2069 \\u061C \\u200F \xe2\x82\xac");
  EXPECT_EQ(printable(shown), shown);
}

TEST(Utf8, WellFormedSequencesOnly) {
  EXPECT_EQ(utf8SequenceLength("a", 0), 1u);
  EXPECT_EQ(utf8SequenceLength("\xc3\xa9", 0), 2u);
  EXPECT_EQ(utf8SequenceLength("\xe2\x82\xac", 0), 3u);
  EXPECT_EQ(utf8SequenceLength("\xf0\x9f\x98\x80", 0), 4u);
  EXPECT_EQ(utf8SequenceLength("\xc0\xaf", 0), 0u) << "overlong";
  EXPECT_EQ(utf8SequenceLength("\xed\xa0\x80", 0), 0u) << "surrogate";
  EXPECT_EQ(utf8SequenceLength("\xf4\x90\x80\x80", 0), 0u) << "above U+10FFFF";
  EXPECT_EQ(utf8SequenceLength("\xe2\x82", 0), 0u) << "cut short";
  EXPECT_EQ(utf8SequenceLength("\x80", 0), 0u) << "a continuation alone";
}

}  // namespace
}  // namespace shadows

// The decimals the parameter ranges and 05's compiled tap offsets are written with: each reads
// back as the same float, and no shorter decimal would.
TEST(ShortestDecimal, ReadsBackAndIsShortest) {
  using shadows::shortestDecimal;
  EXPECT_EQ(shortestDecimal(0.1f), "0.1");
  EXPECT_EQ(shortestDecimal(1.0f), "1");
  EXPECT_EQ(shortestDecimal(-2.5f), "-2.5");
  EXPECT_EQ(shortestDecimal(1e-5f), "1e-05");
  uint32_t bits = 0x3f800000u;
  for (int i = 0; i < 20000; ++i) {
    bits = bits * 1664525u + 1013904223u;  // a spread of floats, every exponent
    float f;
    std::memcpy(&f, &bits, sizeof f);
    if (!std::isfinite(f)) continue;
    const std::string text = shortestDecimal(f);
    ASSERT_EQ(std::strtof(text.c_str(), nullptr), f) << text;
    // One significant digit fewer never reads back (else it would have been chosen).
    std::string mantissa;
    for (const char c : text.substr(0, text.find('e'))) {
      if (std::isdigit(static_cast<unsigned char>(c)) && !(mantissa.empty() && c == '0')) {
        mantissa += c;
      }
    }
    const int significant = static_cast<int>(mantissa.size());
    char shorter[400];  // %g of a float needs at most ~50
    if (significant > 1) {
      std::snprintf(shorter, sizeof shorter, "%.*g", significant - 1, static_cast<double>(f));
      EXPECT_NE(std::strtof(shorter, nullptr), f) << text << " vs " << shorter;
    }
  }
}
