#include <gtest/gtest.h>

#include "shadow_math.hpp"

namespace shadows {
namespace {
TEST(ShadowMath, Placeholder) {
  EXPECT_EQ(biasMatrix()[3][0], 0.5f);
}
}  // namespace
}  // namespace shadows
