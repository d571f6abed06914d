#include "common/progress_display.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(ProgressDisplay, TheThreeDisplaysAreNamedAsOutputProgressTakesThem) {
  EXPECT_EQ(enum_choices<ProgressDisplay>(), "bar, lines or none");
  EXPECT_EQ(parse_enum<ProgressDisplay>("lines"), ProgressDisplay::Lines);
  EXPECT_FALSE(parse_enum<ProgressDisplay>("quiet"));
}

}  // namespace
}  // namespace crux
