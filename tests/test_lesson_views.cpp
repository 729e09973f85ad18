// Views are typed handles (common/lesson/view.hpp): a lesson declares each once and its render()
// asks frame.shows(kCubeCross), so a misspelled view is a compile error. These asserts fail the
// build if a string ever converts to a View again.
#include <concepts>
#include <set>
#include <type_traits>

#include "harness.hpp"

namespace shadows {
namespace {

static_assert(!std::is_convertible_v<const char*, View>);
static_assert(!std::is_convertible_v<std::string, View>);
static_assert(!std::equality_comparable_with<View, const char*>);
static_assert(!std::equality_comparable_with<View, std::string>);
static_assert(views::kShaded == View("shaded") && !(views::kShaded == views::kVisibility));

TEST(Views, EachChoiceIsOneDeclaredViewAndTheOneTheFrameShows) {
  for (const std::string& lesson : registeredLessons()) {
    auto runner = testing::startLesson(lesson, {}, 8, 8);
    const std::vector<std::string> choices = runner->params().at("view").choices;
    // A lesson's view named like a shared one (truth, error) or twice would be one choice.
    EXPECT_EQ(std::set<std::string>(choices.begin(), choices.end()).size(), choices.size())
        << lesson;
    // The runner's own texel pass is never offered.
    EXPECT_EQ(std::count(choices.begin(), choices.end(), views::kTexels.str()), 0) << lesson;
    for (const std::string& view : choices) {
      ASSERT_EQ(runner->params().set("view", view), "");
      EXPECT_EQ(runner->currentView().name(), view) << lesson;
    }
  }
}

}  // namespace
}  // namespace shadows
