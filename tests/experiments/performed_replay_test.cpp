#include "experiments/performed_replay.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include "common/input_error.hpp"
#include "common/random.hpp"
#include "simulation/mjcf_model.hpp"
#include "simulation/mujoco_layout.hpp"
#include "simulation/mujoco_model.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

Wall replay_wall() {
  return testing::wall_with_holds({{-0.25, 1.75}, {0.25, 1.75}, {-0.15, 0.45}, {0.15, 0.45}, {-0.25, 1.95}});
}

TrajectorySample sample_of(double time, int move) {
  TrajectorySample sample;
  sample.time = time;
  sample.move = move;
  sample.posture = standing_posture({-0.3, 0.0, 1.0});
  return sample;
}

// Frames are the samples; each move spans the samples that name it, and its configuration
// is the one after it when performed, the one it started from when it failed.
TEST(PerformedReplay, EachMoveSpansItsSamplesAndKeepsItsOutcome) {
  const BodyModel& model = testing::human_model();
  const Wall wall = replay_wall();
  const std::vector<AttemptedMove> moves{{Limb::RightHand, 4, true, MoveFailure::None, 0.5},
                                         {Limb::LeftHand, 1, false, MoveFailure::HitWall, 0.9}};
  std::vector<TrajectorySample> samples{sample_of(0.0, -1), sample_of(0.02, -1), sample_of(0.04, 0), sample_of(0.06, 0),
                                        sample_of(0.08, 1)};
  samples[3].hold_forces[2] = Eigen::Vector3d(1.0, -2.0, 300.123456789);
  samples[3].root_orientation = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5);
  const PerformedReplay replay = replay_performed_climb(model, wall, moves, samples, "trajectory.csv");
  ASSERT_EQ(replay.frame_count, 5);
  EXPECT_EQ(replay.postures.size(), 5u * kConfigurationDof);
  ASSERT_EQ(replay.moves.size(), 2u);
  EXPECT_EQ(replay.moves[0].first_frame, 2);
  EXPECT_EQ(replay.moves[0].last_frame, 3);
  EXPECT_EQ(replay.moves[1].first_frame, 4);
  EXPECT_EQ(replay.moves[1].last_frame, 4);
  const HoldConfiguration after = start_configuration(wall).with(Limb::RightHand, 4);
  EXPECT_EQ(replay.moves[0].configuration.holds, after.holds);
  EXPECT_EQ(replay.moves[1].configuration.holds, after.holds) << "a failed move leaves the holds as they were";
  EXPECT_EQ(replay.moves[1].move.cause, MoveFailure::HitWall);
  // Rotations as x, y, z, w; forces 12 a frame, rounded to 1e-5.
  EXPECT_EQ(std::vector<double>(replay.root_rotations.begin() + 12, replay.root_rotations.begin() + 16),
            (std::vector<double>{0.5, -0.5, 0.5, 0.5}));
  EXPECT_EQ(std::vector<double>(replay.hold_forces.begin() + 36 + 6, replay.hold_forces.begin() + 36 + 9),
            (std::vector<double>{1.0, -2.0, 300.12346}));
  EXPECT_EQ(replay.times, (std::vector<double>{0.0, 0.02, 0.04, 0.06, 0.08}));
  EXPECT_EQ(replay.check_frame, 2);
}

// The replay's grasp points, crux's forward kinematics turned by the root's rotation, are
// where MuJoCo puts them for a body whose free root has turned.
TEST(PerformedReplay, ItsGraspPointsAreMujocosOnATurnedRoot) {
  const BodyModel& model = testing::human_model();
  Wall wall = generate_random_wall(2);
  wall.incline_deg = 15.0;
  const Posture standing = standing_posture({-0.5, 0.1, 1.0});
  const MujocoModel mujoco(mjcf_text(model, wall, PhysicsParameters{}, StrengthProfile{}, standing), "test");
  const MujocoLayout layout = mujoco_layout(model, mujoco.get(), wall.incline_deg);
  mjData* data = mj_makeData(mujoco.get());
  const unsigned seed = 20261129;
  Random random(seed);
  for (int trial = 0; trial < 5; ++trial) {
    place_at_rest(layout, mujoco.get(), data, testing::random_posture(model, random));
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.3 + 0.2 * trial, Eigen::Vector3d(trial, 1.0, 2.0).normalized()));
    const Eigen::Quaterniond world = Eigen::Quaterniond(layout.to_world) * turn;
    data->qpos[layout.root_qpos + 3] = world.w();
    data->qpos[layout.root_qpos + 4] = world.x();
    data->qpos[layout.root_qpos + 5] = world.y();
    data->qpos[layout.root_qpos + 6] = world.z();
    mj_forward(mujoco.get(), data);
    TrajectorySample sample;
    sample.posture = simulated_posture(layout, data);
    sample.root_orientation = root_orientation(layout, data);
    const PerformedReplay replay = replay_performed_climb(model, wall, {}, std::vector{sample}, "test");
    ASSERT_EQ(replay.check_frame, 0);
    for (int limb = 0; limb < kLimbCount; ++limb) {
      // Within the rounding of the replay's values to 1e-5 (m, rad) over the body's levers.
      EXPECT_LT((replay.check_grasp_points[limb] - simulated_grasp_point(layout, data, static_cast<Limb>(limb))).norm(),
                2e-4)
          << "seed " << seed << ", trial " << trial << ", limb " << limb;
    }
  }
  mj_deleteData(data);
}

TEST(PerformedReplay, SamplesOutOfOrderOrOfNoMoveAreRefusedNamingTheSource) {
  const BodyModel& model = testing::human_model();
  const Wall wall = replay_wall();
  const std::vector<AttemptedMove> one{{Limb::RightHand, 4, true, MoveFailure::None, 0.5}};
  const auto refused = [&](const std::vector<AttemptedMove>& moves, const std::vector<TrajectorySample>& samples) {
    try {
      replay_performed_climb(model, wall, moves, samples, "trajectory.csv");
    } catch (const InputError& e) {
      return e.source() == "trajectory.csv";
    }
    return false;
  };
  EXPECT_TRUE(refused(one, {sample_of(0.0, 0), sample_of(0.02, -1)})) << "a move index that decreases";
  EXPECT_TRUE(refused(one, {sample_of(0.0, 1)})) << "a sample of a move not attempted";
  EXPECT_TRUE(refused({{Limb::RightHand, 9, true, MoveFailure::None, 0.5}}, {sample_of(0.0, 0)}))
      << "a hold the wall does not have";
  EXPECT_FALSE(refused(one, {sample_of(0.0, -1), sample_of(0.02, 0)}));
}

}  // namespace
}  // namespace crux
