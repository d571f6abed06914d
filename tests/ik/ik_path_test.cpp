#include "ik/ik_path.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "configurations/reachability.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

struct Move {
  Posture from, to;
  ReachTarget target;
};

// The start of random wall 1 and the first reachable move of its right hand.
Move first_move(const Wall& wall) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  ReachabilityParameters reach;
  const IkResult start = solve_start(model, data, wall, reach);
  EXPECT_TRUE(start.reached);
  for (int hold = 0; hold < wall.hold_count(); ++hold) {
    const HoldConfiguration complete = start_configuration(wall).with(Limb::RightHand, hold);
    if (complete.holds == start_configuration(wall).holds) continue;
    const ReachTarget target = reach_target(model, wall, complete, reach.root);
    const IkResult moved = solve_ik(model, data, start.posture, target, reach.ik);
    if (moved.reached) return {start.posture, moved.posture, target};
  }
  ADD_FAILURE() << "no reachable move";
  return {};
}

// count samples, the last exactly the move's end; the first close to its start (one
// sixteenth of the way along the IK path, blended one sixteenth towards the end); the
// path leaves the start at once: its first sample differs from it.
TEST(IkPath, SamplesEndOnTheRecordedPostureAndStartNearTheFirst) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(1);
  const Move move = first_move(wall);
  BodyData data(model);
  std::vector<Posture> path, samples;
  ik_path_samples(model, data, move.from, move.to, move.target, IkParameters{}, 16, path, samples);
  ASSERT_EQ(samples.size(), 16u);
  EXPECT_EQ(samples.back(), move.to);
  EXPECT_GT(path.size(), 2u) << "the paper's solver iterated";
  EXPECT_EQ(path.front(), move.from);
  const double whole = (move.to - move.from).norm();
  EXPECT_GT((samples.front() - move.from).norm(), 0.0);
  EXPECT_LT((samples.front() - move.from).norm(), 0.5 * whole);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    EXPECT_LT((samples[i] - samples[i - 1]).norm(), 0.5 * whole) << "sample " << i << ": no jump";
  }
}

// A move its start already grasps needs no path: the samples go straight to the end.
TEST(IkPath, AMoveAlreadyGraspedIsAStraightBlend) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(1);
  const Move move = first_move(wall);
  BodyData data(model);
  std::vector<Posture> path, samples;
  Posture nudged = move.to;
  nudged[0] += 1e-3;  // the end, a millimetre off: it still grasps the target
  ik_path_samples(model, data, move.to, nudged, move.target, IkParameters{}, 4, path, samples);
  ASSERT_EQ(samples.size(), 4u);
  EXPECT_EQ(path.size(), 1u);
  for (int k = 1; k <= 4; ++k) {
    const Posture expected = (1 - k / 4.0) * move.to + (k / 4.0) * nudged;
    EXPECT_LT((samples[k - 1] - expected).norm(), 1e-15) << "sample " << k;
  }
}

}  // namespace
}  // namespace crux
