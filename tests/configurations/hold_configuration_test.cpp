#include "configurations/hold_configuration.hpp"

#include <gtest/gtest.h>

#include "common/random.hpp"

namespace crux {
namespace {

TEST(HoldConfiguration, FreeLimbAndWith) {
  HoldConfiguration c;
  c.holds = {kFree, 4, 0, 9};
  EXPECT_EQ(c.free_limb(), Limb::RightHand);
  EXPECT_EQ(c.free_count(), 1);
  const HoldConfiguration full = c.with(Limb::RightHand, 12);
  EXPECT_EQ(full.holds, (std::array<int, 4>{12, 4, 0, 9}));
  EXPECT_EQ(full.free_count(), 0);
}

TEST(HoldConfiguration, RoundRobinOfTheFreeLimb) {
  EXPECT_EQ(next_free_limb(Limb::RightHand), Limb::LeftHand);
  EXPECT_EQ(next_free_limb(Limb::LeftHand), Limb::RightFoot);
  EXPECT_EQ(next_free_limb(Limb::RightFoot), Limb::LeftFoot);
  EXPECT_EQ(next_free_limb(Limb::LeftFoot), Limb::RightHand);
}

TEST(HoldConfiguration, EncodingIsCompactAndRoundTrips) {
  HoldConfiguration c;
  c.holds = {kFree, 0, 1, 44};
  // Digits (hold + 1) in base 46, right hand least significant: 0 + 1*46 + 2*46^2 + 45*46^3.
  EXPECT_EQ(encode(c, 45), 1u * 46 + 2u * 46 * 46 + 45u * 46 * 46 * 46);
  constexpr std::uint64_t seed = 99;
  Random random(seed);
  for (const int n : {4, 12, 45, 140, 400}) {
    for (int sample = 0; sample < 1000; ++sample) {
      HoldConfiguration x;
      for (int& h : x.holds) h = static_cast<int>(random.below(n + 1)) - 1;
      ASSERT_EQ(decode_configuration(encode(x, n), n), x) << "seed " << seed << " n " << n;
      ASSERT_LT(encode(x, n), static_cast<std::uint64_t>(n + 1) * (n + 1) * (n + 1) * (n + 1));
    }
  }
}

}  // namespace
}  // namespace crux
