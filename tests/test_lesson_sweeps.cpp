// Every lesson's time-vs-error sweep (NN_name/sweep.cpp, SHADOWS_SWEEP) names the lesson's own
// scenes and parameters with values it takes: a typo in an axis would otherwise surface only
// when bench_sweep reaches that value (its smoke test touches the ends of each axis only).
#include <algorithm>

#include "harness.hpp"
#include "lesson/sweep_spec.hpp"

namespace shadows {
namespace {

TEST(LessonSweeps, EverySettingIsOneTheLessonTakes) {
  ASSERT_FALSE(registeredSweeps().empty());
  const std::vector<std::string> lessons = registeredLessons();
  for (const auto& [name, sweep] : registeredSweeps()) {
    SCOPED_TRACE(name);
    ASSERT_NE(std::find(lessons.begin(), lessons.end(), name), lessons.end()) << "no such lesson";
    EXPECT_FALSE(sweep.study) << "a study across lessons belongs in bench/studies.cpp";
    ASSERT_FALSE(sweep.axes.empty());
    Runner probe(name, makeLesson(name), RunOptions{});  // parameters only, no GL
    const std::vector<std::string> scenes = probe.lesson().scenes();
    for (const std::string& scene : sweep.scenes) {
      EXPECT_NE(std::find(scenes.begin(), scenes.end(), scene), scenes.end()) << scene;
    }
    for (const Axis& axis : sweep.axes) {
      for (const std::string& value : axis.values) {
        for (const std::string& set : settingsOf(axis, value).second) {
          EXPECT_EQ(probe.params().assign(set), "") << axis.name << " " << value;
        }
      }
    }
    for (const std::string& set : sweep.fixed) EXPECT_EQ(probe.params().assign(set), "") << set;
  }
}

}  // namespace
}  // namespace shadows
