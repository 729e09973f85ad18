// Lesson 16's panel front (16_choose_your_shadow/tried.hpp): the points a student measured on
// one preset and light, and the front through them.
#include <gtest/gtest.h>

#include "../16_choose_your_shadow/tried.hpp"

namespace shadows {
namespace {

TEST(Tried, TheFrontIsWhatNothingElseBeatsInBothCheapestFirst) {
  Tried tried;
  tried.record({"contact", "a", 0, 5.0, 0.004});
  tried.record({"contact", "b", 1, 8.0, 0.001});
  tried.record({"contact", "c", 2, 9.0, 0.002});  // slower and worse than b: off
  tried.record({"contact", "d", 3, 20.0, 0.0005});
  tried.record({"street", "e", 0, 1.0, 0.0001});  // another plot's
  const auto here = tried.at("contact");
  ASSERT_EQ(here.size(), 4u);
  const auto front = Tried::front(here);
  ASSERT_EQ(front.size(), 3u);
  EXPECT_EQ(front[0]->label, "a");
  EXPECT_EQ(front[1]->label, "b");
  EXPECT_EQ(front[2]->label, "d");
}

TEST(Tried, TheSameSettingsMeasuredAgainReplaceTheirPoint) {
  Tried tried;
  tried.record({"bulb", "cube", 5, 10.0, 0.002});
  tried.record({"bulb", "cube", 5, 11.0, 0.0015});
  const auto here = tried.at("bulb");
  ASSERT_EQ(here.size(), 1u);
  EXPECT_EQ(here[0]->ms, 11.0);
  EXPECT_EQ(here[0]->error, 0.0015);
  // The same settings on another preset are another point.
  tried.record({"contact", "cube", 5, 4.0, 0.003});
  EXPECT_EQ(tried.at("bulb").size(), 1u);
  EXPECT_EQ(tried.at("contact").size(), 1u);
  tried.clear();
  EXPECT_TRUE(tried.at("bulb").empty());
}

TEST(Tried, AnEqualCostKeepsTheLesserErrorAndATieInBothOnce) {
  Tried tried;
  tried.record({"x", "worse", 0, 5.0, 0.003});
  tried.record({"x", "better", 0, 5.0, 0.001});
  tried.record({"x", "twin", 0, 5.0, 0.001});
  const auto front = Tried::front(tried.at("x"));
  ASSERT_EQ(front.size(), 1u);
  EXPECT_EQ(front[0]->label, "better");
}

}  // namespace
}  // namespace shadows
