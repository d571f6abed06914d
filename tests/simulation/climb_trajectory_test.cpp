#include "simulation/climb_trajectory.hpp"

#include <gtest/gtest.h>

#include "simulation/mjcf_model.hpp"
#include "simulation/move_reference.hpp"
#include "support/jug_ladder.hpp"

namespace crux {
namespace {

// The jug ladder's start held still, sampled every 0.1 s.
struct HeldStart {
  testing::JugLadder ladder;
  TrajectoryRecorder recorder{0.1};
  MoveOutcome outcome;

  HeldStart() {
    const BodyModel& model = testing::human_model();
    const StrengthProfile limits =
        motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
    SimulatedClimber climber(model, ladder.wall, ladder.physics, limits, ladder.start, ServoParameters{});
    MoveReferences references(model, ladder.wall, ladder.physics, ladder.reach, 16);
    const HoldConfiguration four = start_configuration(ladder.wall);
    climber.place(ladder.start, four);
    outcome = hold_still(climber, ladder.start, four, references.holding(ladder.start, four).torques, 2.0,
                         MoveParameters{}, &recorder);
  }
};

TEST(ClimbTrajectory, OneSampleEveryIntervalFromTheFirstStep) {
  const HeldStart held;
  const std::vector<TrajectorySample>& samples = held.recorder.samples();
  // Steps of 2 ms, the first sample at the first.
  const double last_step = 0.002 * held.outcome.steps;
  ASSERT_EQ(samples.size(), static_cast<std::size_t>((last_step - 0.002) / 0.1 + 1e-9) + 1) << last_step << " s";
  EXPECT_NEAR(samples.front().time, 0.002, 1e-12);
  for (std::size_t k = 1; k < samples.size(); ++k) {
    EXPECT_NEAR(samples[k].time - samples[k - 1].time, 0.1, 1e-9) << "sample " << k;
    EXPECT_EQ(samples[k].move, -1) << "no move was started";
  }
}

// Held still, the holds carry the body's weight: their forces sum to m g up the wall (the
// wall's own push aside), and the root has not turned.
TEST(ClimbTrajectory, AtRestTheHoldsCarryTheWeightAndTheRootHasNotTurned) {
  const HeldStart held;
  ASSERT_TRUE(held.outcome.performed()) << enum_name(held.outcome.failure);
  const TrajectorySample& last = held.recorder.samples().back();
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& force : last.hold_forces) total += force;
  const double weight = testing::human_model().total_mass * kStandardGravity.norm();
  EXPECT_NEAR(total.z(), weight, 0.02 * weight) << total.transpose();
  EXPECT_LT(std::abs(total.y()), 0.02 * weight) << total.transpose();
  for (int limb = 0; limb < kLimbCount; ++limb) EXPECT_GT(last.hold_forces[limb].norm(), 1.0) << "limb " << limb;
  EXPECT_LT(last.root_orientation.angularDistance(Eigen::Quaterniond::Identity()), 0.05);
  EXPECT_LT((last.posture - held.ladder.start).tail<kConfigurationDof - kRootDof>().cwiseAbs().maxCoeff(), 0.2);
}

}  // namespace
}  // namespace crux
