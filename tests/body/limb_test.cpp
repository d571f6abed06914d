#include "body/limb.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(Limb, NamesAndShortNamesParseBack) {
  const char* const short_names[kLimbCount] = {"rh", "lh", "rf", "lf"};
  for (int l = 0; l < kLimbCount; ++l) {
    const Limb limb = static_cast<Limb>(l);
    EXPECT_EQ(parse_enum<Limb>(enum_name(limb)), limb);
    EXPECT_EQ(parse_enum<Limb>(short_names[l]), limb);
  }
  EXPECT_STREQ(enum_name(Limb::LeftFoot), "left_foot");
  EXPECT_FALSE(parse_enum<Limb>("right_elbow"));
  EXPECT_FALSE(parse_enum<Limb>(""));
}

TEST(Limb, OperationalPointsFollowTheRoot) {
  EXPECT_EQ(operational_point(Limb::RightHand), 1);
  EXPECT_EQ(operational_point(Limb::LeftFoot), kOperationalPointCount - 1);
}

}  // namespace
}  // namespace crux
