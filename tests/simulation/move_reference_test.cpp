#include "simulation/move_reference.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "body/wall_penetration.hpp"
#include "climbing/stance_check.hpp"
#include "support/jug_ladder.hpp"

namespace crux {
namespace {

using testing::JugLadder;

// The path ends on the planned stance; on the way the kept limbs stay on their holds, the
// free hand comes off the wall by the lift at mid-path, and no segment passes through the
// wall; the feed-forward holds each sample on the kept holds as the static model does.
TEST(MoveReferences, ThePathLiftsTheFreeLimbOffTheWallAndKeepsTheOthersOnTheirHolds) {
  const BodyModel& model = testing::human_model();
  const JugLadder ladder;
  MoveReferences references(model, ladder.wall, ladder.physics, ladder.reach, 16, 0.5, 0.1);
  const MoveReference move = references.move(ladder.start, ladder.reached, ladder.before, 0, 4);
  EXPECT_EQ(move.limb, Limb::RightHand);
  EXPECT_EQ(move.hold, 4);
  EXPECT_EQ(move.left_hold, 0);
  ASSERT_EQ(move.samples.size(), 16u);
  ASSERT_EQ(move.feed_forward.size(), 16u);
  EXPECT_EQ(move.samples.back(), ladder.reached);
  BodyData data(model), start(model);
  forward_kinematics(model, start, ladder.start);
  double farthest = 0.0;
  for (const Posture& sample : move.samples) {
    forward_kinematics(model, data, sample);
    EXPECT_FALSE(wall_penetration(model, data).passes_through());
    for (const Limb kept : {Limb::LeftHand, Limb::RightFoot, Limb::LeftFoot}) {
      EXPECT_LT((data.points[operational_point(kept)] - start.points[operational_point(kept)]).norm(), 0.011);
    }
    farthest = std::max(farthest, -data.points[operational_point(Limb::RightHand)].x());
  }
  EXPECT_GT(farthest, 0.09) << "the hand comes about 10 cm off the wall";
  // Each sample's holding torques are the static model's on the kept holds, within the margin's choice.
  StanceCheck check(model, ladder.wall, ladder.physics);
  const HoldingTorques holding = references.holding(move.samples[7], ladder.before);
  EXPECT_TRUE(holding.balanced);
  // The program warm starts from its last basis: the same optimum, to the last bits or so.
  EXPECT_LT((holding.torques - move.feed_forward[7]).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_TRUE(check.solve(move.samples[7], ladder.before).balanced);
  EXPECT_LT(
      (move.unloaded_feed_forward - references.holding(ladder.start, ladder.before).torques).cwiseAbs().maxCoeff(),
      1e-9);
  EXPECT_LT((move.loaded_feed_forward - references.holding(ladder.start, start_configuration(ladder.wall)).torques)
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
}

}  // namespace
}  // namespace crux
