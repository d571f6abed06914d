#include "agent_space/agent_descriptor.hpp"

#include <gtest/gtest.h>

#include "common/random.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

const GridParameters kPaperGrid;

TEST(AgentDescriptor, EncodingIsCompactAndRoundTrips) {
  EXPECT_EQ(agent_state_count(kPaperGrid), 4u * 36 * 36 * 36);
  AgentState s;
  s.free_limb = Limb::LeftFoot;
  s.held_tiles = {kOutsideGrid, 0, 34};
  EXPECT_EQ(encode(s, kPaperGrid), ((3u * 36 + 0) * 36 + 1) * 36 + 35);
  constexpr std::uint64_t seed = 5;
  Random random(seed);
  for (int n = 0; n < 2000; ++n) {
    AgentState x;
    x.free_limb = static_cast<Limb>(random.below(4));
    for (int& t : x.held_tiles) t = static_cast<int>(random.below(36)) - 1;
    const std::uint32_t code = encode(x, kPaperGrid);
    ASSERT_LT(code, agent_state_count(kPaperGrid));
    ASSERT_EQ(decode_agent_state(code, kPaperGrid), x) << "seed " << seed;
  }
}

TEST(AgentDescriptor, HeldLimbsAreDescribedInLimbOrder) {
  const Wall wall = generate_random_wall(2);
  HoldConfiguration state;
  state.holds = wall.start;
  state.holds[static_cast<int>(Limb::LeftHand)] = kFree;
  const GridPlacement placement = place_grid(kPaperGrid, Limb::LeftHand, wall.holds[wall.start[1]].position);
  const AgentState d = describe_state(wall, state, placement);
  EXPECT_EQ(d.free_limb, Limb::LeftHand);
  EXPECT_EQ(d.held_tiles[0], placement.tile_of(wall.holds[wall.start[0]].position));
  EXPECT_EQ(d.held_tiles[1], placement.tile_of(wall.holds[wall.start[2]].position));
  EXPECT_EQ(d.held_tiles[2], placement.tile_of(wall.holds[wall.start[3]].position));
}

// The point of an agent space: moving the whole wall and the body together changes no
// descriptor of a state or of an action.
TEST(AgentDescriptor, UnchangedWhenWallAndBodyAreTranslatedTogether) {
  constexpr std::uint64_t seed = 17;
  Random random(seed);
  const Wall wall = generate_random_wall(6);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d shift(0.0, random.uniform(-5, 5), random.uniform(-5, 5));
    Wall moved = wall;
    for (Hold& h : moved.holds) h.position += shift;
    HoldConfiguration state;
    state.holds = wall.start;
    const Limb free = static_cast<Limb>(random.below(4));
    const Eigen::Vector3d limb = wall.holds[state.hold(free)].position + Eigen::Vector3d(0.3, 0.02, -0.03);
    state.holds[static_cast<int>(free)] = kFree;
    const GridPlacement here = place_grid(kPaperGrid, free, limb);
    const GridPlacement there = place_grid(kPaperGrid, free, limb + shift);
    ASSERT_EQ(describe_state(wall, state, here), describe_state(moved, state, there))
        << "seed " << seed << " trial " << trial;
    for (int hold = 0; hold < wall.hold_count(); ++hold) {
      ASSERT_EQ(here.tile_of(wall.holds[hold].position), there.tile_of(moved.holds[hold].position))
          << "seed " << seed << " trial " << trial << " hold " << hold;
    }
  }
}

}  // namespace
}  // namespace crux
