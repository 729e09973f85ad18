// The report writer: valid nesting, escaping, and no NaN in JSON.
#include "json.hpp"

#include <gtest/gtest.h>

#include <limits>

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
