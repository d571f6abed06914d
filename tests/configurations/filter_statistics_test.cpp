#include "configurations/filter_statistics.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/test_walls.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

using testing::wall_with_holds;
using R = FeetAboveHandsReading;

// Four holds, two high and two low, each pair a right (y 0.3) and a left (y 0.9) one:
//   0 (0.3, 1.5)   1 (0.9, 1.6)
//   2 (0.3, 0.0)   3 (0.9, 0.2)
// No two holds are more than 1.71 m apart, so the 2.8 m span never rejects.
Wall four_holds() { return wall_with_holds({{0.3, 1.5}, {0.9, 1.6}, {0.3, 0.0}, {0.9, 0.2}}); }

std::size_t index_of(R reading) {
  for (std::size_t r = 0; r < kFeetAboveHandsReadings.size(); ++r) {
    if (kFeetAboveHandsReadings[r] == reading) return r;
  }
  ADD_FAILURE() << "unknown reading";
  return 0;
}

// The counts of one reading by brute force over passes_filter.
FilterCounts brute_force(const std::vector<Wall>& walls, FilterParameters parameters, R reading) {
  parameters.feet_above_hands = reading;
  FilterCounts counts;
  for (const Wall& wall : walls) {
    const int n = wall.hold_count();
    HoldConfiguration c;
    for (int h0 = 0; h0 < n; ++h0)
      for (int h1 = 0; h1 < n; ++h1)
        for (int h2 = 0; h2 < n; ++h2)
          for (int h3 = 0; h3 < n; ++h3) {
            const int holds[4] = {h0, h1, h2, h3};
            bool distinct = true;
            for (int a = 0; a < 4; ++a)
              for (int b = a + 1; b < 4; ++b) distinct = distinct && holds[a] != holds[b];
            if (!distinct) continue;
            c.holds = {h0, h1, h2, h3};
            ++counts.configurations4;
            counts.pass4 += passes_filter(wall, c, parameters);
          }
    // A free limb, the three others on distinct holds in limb order.
    for (int free = 0; free < kLimbCount; ++free)
      for (int h0 = 0; h0 < n; ++h0)
        for (int h1 = 0; h1 < n; ++h1)
          for (int h2 = 0; h2 < n; ++h2) {
            if (h0 == h1 || h0 == h2 || h1 == h2) continue;
            const int held[3] = {h0, h1, h2};
            int slot = 0;
            for (int limb = 0; limb < kLimbCount; ++limb) c.holds[limb] = limb == free ? kFree : held[slot++];
            ++counts.configurations3;
            counts.pass3 += passes_filter(wall, c, parameters);
          }
  }
  return counts;
}

void expect_brute_force(const std::vector<Wall>& walls, const FilterParameters& parameters) {
  const auto counts = filter_statistics(walls, parameters);
  for (const R reading : kFeetAboveHandsReadings) {
    const FilterCounts expected = brute_force(walls, parameters, reading);
    const FilterCounts& got = counts[index_of(reading)];
    EXPECT_EQ(got.configurations3, expected.configurations3) << enum_name(reading);
    EXPECT_EQ(got.configurations4, expected.configurations4) << enum_name(reading);
    EXPECT_EQ(got.pass3, expected.pass3) << enum_name(reading);
    EXPECT_EQ(got.pass4, expected.pass4) << enum_name(reading);
  }
}

TEST(FilterStatistics, CountsEveryConfigurationOfATinyWallByHand) {
  const auto counts = filter_statistics({four_holds()}, FilterParameters{});
  for (const FilterCounts& c : counts) {
    EXPECT_EQ(c.configurations4, 24u) << "4! ways to put 4 limbs on 4 holds";
    EXPECT_EQ(c.configurations3, 96u) << "4 free limbs x 4 x 3 x 2";
  }
  // The 4-configurations without crossed arms or legs (right y <= left y), by hand set
  // {hands | feet}: {0,1|2,3} 1, {2,3|0,1} 1, {0,2|1,3} 4 (equal y never cross),
  // {1,3|0,2} 4, {0,3|1,2} 1, {1,2|0,3} 1. Which of them each reading keeps:
  //   {0,1|2,3} feet low: all;  {2,3|0,1} feet high: none;
  //   {0,2|1,3} hands 1.5/0, feet 1.6/0.2: lowest foot above the highest hand? no: kept
  //             by that reading only;
  //   {1,3|0,2} hands 1.6/0.2, feet 1.5/0: kept by all but highest-foot-above-lowest-hand;
  //   {0,3|1,2} hands 1.5/0.2, feet 1.6/0 (means 0.85 / 0.8): as {1,3|0,2};
  //   {1,2|0,3} hands 1.6/0, feet 1.5/0.2 (means 0.8 / 0.85): as {0,2|1,3}.
  EXPECT_EQ(counts[index_of(R::LowestFootAboveHighestHand)].pass4, 11u);  // 1 + 4 + 4 + 1 + 1
  EXPECT_EQ(counts[index_of(R::LowestFootAboveLowestHand)].pass4, 6u);    // 1 + 4 + 1
  EXPECT_EQ(counts[index_of(R::HighestFootAboveLowestHand)].pass4, 1u);   // the natural stance only
  EXPECT_EQ(counts[index_of(R::MeanFeetAboveMeanHands)].pass4, 6u);       // 1 + 4 + 1
  // 3-configurations under highest-foot-above-lowest-hand (every held foot at most as
  // high as every held hand), per free limb:
  //   a free hand, the other hand on h: h = 0 (1.5) feet 2, 3 uncrossed: 1; h = 1 (1.6)
  //     feet among 0, 2, 3 uncrossed: (0,2) (2,0) (0,3) (2,3): 4; h = 2 or 3: none;
  //   a free foot: 8 uncrossed hand pairs; the one foot below both hands: (0,1) 2,
  //     (0,3) 1, (1,3) 1, (3,1) 1, the others (a hand on 2 at z 0) none.
  // 5 per free limb, 20 in all.
  EXPECT_EQ(counts[index_of(R::HighestFootAboveLowestHand)].pass3, 20u);
  EXPECT_DOUBLE_EQ(counts[index_of(R::HighestFootAboveLowestHand)].share4(), 1.0 / 24.0);
  EXPECT_DOUBLE_EQ(counts[index_of(R::HighestFootAboveLowestHand)].share3(), 20.0 / 96.0);
}

// Moved from geometric_filter_test.cpp. Holds: 0 right hand (0.3, 1.5), 1 left hand
// (0.9, 1.5), 2 right foot (0.3, 0), 3 left foot (0.9, 0), 4 far up (0.6, 3.0), 5 low
// middle (0.6, 0.8).
TEST(FilterStatistics, CountsEveryOrderedConfigurationOnce) {
  const Wall wall = wall_with_holds({{0.3, 1.5}, {0.9, 1.5}, {0.3, 0.0}, {0.9, 0.0}, {0.6, 3.0}, {0.6, 0.8}});
  const auto counts = filter_statistics({wall}, FilterParameters{});
  for (const FilterCounts& c : counts) {
    EXPECT_EQ(c.configurations4, 6u * 5 * 4 * 3);
    EXPECT_EQ(c.configurations3, 4u * 6 * 5 * 4);
  }
  // Hand count of passing 4-configurations under the default reading, by brute force.
  std::uint64_t passing = 0;
  HoldConfiguration config;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b)
      for (int c = 0; c < 6; ++c)
        for (int d = 0; d < 6; ++d)
          if (a != b && a != c && a != d && b != c && b != d && c != d) {
            config.holds = {a, b, c, d};
            passing += passes_filter(wall, config, FilterParameters{});
          }
  const auto& selected = counts[2];
  ASSERT_EQ(kFeetAboveHandsReadings[2], FilterParameters{}.feet_above_hands);
  EXPECT_EQ(selected.pass4, passing);
  EXPECT_GT(passing, 0u);
}

TEST(FilterStatistics, TheSpanRuleHoldsForEveryReading) {
  // At most 1.6 m: holds 1 and 2 (1.71 m apart) never go together, and every
  // 4-configuration of a 4-hold wall uses both.
  FilterParameters parameters;
  parameters.max_span_m = 1.6;
  const auto counts = filter_statistics({four_holds()}, parameters);
  for (const FilterCounts& c : counts) {
    EXPECT_EQ(c.pass4, 0u);
    EXPECT_EQ(c.configurations4, 24u);
  }
  expect_brute_force({four_holds()}, parameters);
}

TEST(FilterStatistics, IgnoresTheChosenReadingAndCountsThemAll) {
  FilterParameters a, b;
  a.feet_above_hands = R::LowestFootAboveHighestHand;
  b.feet_above_hands = R::MeanFeetAboveMeanHands;
  const auto with_a = filter_statistics({four_holds()}, a), with_b = filter_statistics({four_holds()}, b);
  for (std::size_t r = 0; r < kFeetAboveHandsReadings.size(); ++r) {
    EXPECT_EQ(with_a[r].pass3, with_b[r].pass3);
    EXPECT_EQ(with_a[r].pass4, with_b[r].pass4);
  }
}

TEST(FilterStatistics, MatchesPassesFilterByBruteForce) {
  RandomWallParameters small;
  small.columns = 2;
  small.rows = 2;  // 3 x 3 = 9 holds
  const std::vector<Wall> walls{generate_random_wall(1, small), generate_random_wall(2, small), four_holds()};
  expect_brute_force(walls, FilterParameters{});
  FilterParameters crossing_allowed;
  crossing_allowed.reject_crossed_arms = false;
  crossing_allowed.reject_crossed_legs = false;
  crossing_allowed.max_span_m = 1.0;
  expect_brute_force(walls, crossing_allowed);
}

TEST(FilterStatistics, SumsOverWallsAndReportsProgress) {
  const Wall wall = four_holds();
  std::vector<int> progress;
  const auto twice = filter_statistics({wall, wall}, FilterParameters{}, [&](int done) { progress.push_back(done); });
  const auto once = filter_statistics({wall}, FilterParameters{});
  EXPECT_EQ(progress, (std::vector<int>{1, 2}));
  for (std::size_t r = 0; r < kFeetAboveHandsReadings.size(); ++r) {
    EXPECT_EQ(twice[r].configurations4, 2 * once[r].configurations4);
    EXPECT_EQ(twice[r].pass3, 2 * once[r].pass3);
    EXPECT_EQ(twice[r].pass4, 2 * once[r].pass4);
    EXPECT_DOUBLE_EQ(twice[r].share3(), once[r].share3()) << "a share does not change with repetition";
  }
}

TEST(FilterStatistics, NoWallsNoConfigurationsZeroShares) {
  const auto counts = filter_statistics({}, FilterParameters{});
  for (const FilterCounts& c : counts) {
    EXPECT_EQ(c.configurations3, 0u);
    EXPECT_EQ(c.configurations4, 0u);
    EXPECT_EQ(c.share3(), 0.0);
    EXPECT_EQ(c.share4(), 0.0);
  }
  // Fewer than 4 holds: 3-configurations but no 4-configuration.
  const auto three = filter_statistics({wall_with_holds({{0.3, 1.5}, {0.9, 1.5}, {0.6, 0.0}})}, FilterParameters{});
  EXPECT_EQ(three[0].configurations4, 0u);
  EXPECT_EQ(three[0].configurations3, 4u * 3 * 2 * 1);
  EXPECT_EQ(three[0].share4(), 0.0);
}

}  // namespace
}  // namespace crux
