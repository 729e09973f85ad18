// The EGL device platform (--backend egl-device, what a GPU without a display offers) on
// Mesa's software device renders every lesson byte for byte as OSMesa does, and the report
// names the device it chose.
#include "gl/context.hpp"
#include "harness.hpp"

namespace shadows {
namespace {

class EglDevice : public ::testing::TestWithParam<std::string> {};

TEST_P(EglDevice, RendersTheDefaultsAsOsMesaDoes) {
  const std::string lesson = GetParam();
  auto osmesa = testing::startLesson(lesson, {}, 160, 120, false, "osmesa");
  osmesa->renderFrame();
  ASSERT_EQ(testing::reportString(*osmesa, "backend"), "osmesa");
  const Image a = osmesa->readImage();
  osmesa.reset();
  auto device = testing::startLesson(lesson, {}, 160, 120, false, "egl-device");
  device->renderFrame();
  // Asked of the context itself: a silent fallback to another backend would show here.
  EXPECT_EQ(testing::reportString(*device, "backend"), "egl-device");
  const nlohmann::ordered_json chosen = testing::reportValue(*device, "/device");
  EXPECT_EQ(chosen["index"], 0);
  EXPECT_GE(chosen["count"].get<int>(), 1);
  EXPECT_FALSE(chosen["name"].get<std::string>().empty());
  EXPECT_FALSE(testing::reportString(*device, "vendor").empty());
  const Image b = device->readImage();
  EXPECT_EQ(testing::fractionDiffering(a, b, 0), 0.0) << lesson;
  EXPECT_EQ(device->glErrors(), 0);
}

INSTANTIATE_TEST_SUITE_P(EveryLesson, EglDevice, ::testing::ValuesIn(registeredLessons()),
                         [](const ::testing::TestParamInfo<std::string>& lesson) {
                           return lesson.param;
                         });

TEST(EglDeviceChoice, AMissingDeviceIsRefusedWithTheList) {
  int exit_code = 0;
  const std::string why = headlessProblem("egl-device", 63, exit_code);
  EXPECT_EQ(exit_code, 2);
  EXPECT_NE(why.find("--device 63: no such EGL device (there are 0: "), std::string::npos) << why;
  EXPECT_EQ(headlessProblem("egl-device", 0, exit_code), "");
  EXPECT_EQ(headlessProblem("osmesa", 63, exit_code), "");
  EXPECT_THROW(createHeadlessContext("egl-device", 63), GlFailure);
}

}  // namespace
}  // namespace shadows
