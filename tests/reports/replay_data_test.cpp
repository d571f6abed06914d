#include "reports/replay_data.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>
#include <unistd.h>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "common/input_error.hpp"
#include "configurations/hold_configuration.hpp"
#include "configurations/reachability.hpp"
#include "outputs/run_folder.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// The page's data of `climb`, as crux report computes and writes it.
nlohmann::ordered_json replayed(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                const ReachabilityParameters& reach, const ReplayOptions& options = {}) {
  return replay_data(model, wall, replay_climb(model, wall, climb, reach, "test", options), nullptr, "test");
}

Posture frame(const nlohmann::ordered_json& replay, int index) {
  Posture posture;
  for (int i = 0; i < kConfigurationDof; ++i) posture[i] = replay["frames"]["postures"][index * kConfigurationDof + i];
  return posture;
}

// Every move takes its frames in order; a reached move ends exactly on the recorded
// posture (as rounded), an unreachable one keeps the body still.
TEST(ReplayData, MovesCoverTheFramesAndEndOnTheRecordedPostures) {
  const RunFolder folder = testing::read_trained_run();
  const ReplayOptions settings;
  const RecordedClimb& climb = folder.last;
  const auto replay = replayed(testing::human_model(), folder.wall, climb, {}, settings);
  const auto& moves = replay["moves"];
  ASSERT_EQ(moves.size(), climb.steps.size());
  int next = 1;
  std::size_t posture = 0;
  for (std::size_t m = 0; m < moves.size(); ++m) {
    const int first = moves[m]["first_frame"], last = moves[m]["last_frame"];
    EXPECT_EQ(first, next) << "move " << m;
    const bool success = moves[m]["success"];
    EXPECT_EQ(success, climb.steps[m].success);
    EXPECT_EQ(last - first + 1, success ? settings.frames_per_move : settings.frames_per_failure);
    if (success) ++posture;
    const Posture expected = (climb.postures[posture] * settings.decimals).array().round() / settings.decimals;
    EXPECT_EQ(frame(replay, last), expected) << "move " << m;
    next = last + 1;
  }
  EXPECT_EQ(replay["frames"]["count"], next);
  EXPECT_EQ(posture + 1, climb.postures.size());
  EXPECT_EQ(replay["climb"], "last");
}

// Issue 25: a report's page grew with its climb without a bound. The replay shows the
// climb's first max_moves moves, frame for frame as the whole replay shows them, and
// says how many the climb has.
TEST(ReplayData, AReplayShowsTheFirstMaxMovesOfALongerClimb) {
  const RunFolder folder = testing::read_trained_run();
  const RecordedClimb& climb = folder.last;
  ASSERT_GT(climb.steps.size(), 3u);
  const auto whole = replayed(testing::human_model(), folder.wall, climb, {});
  ReplayOptions cut;
  cut.max_moves = 3;
  const auto first = replayed(testing::human_model(), folder.wall, climb, {}, cut);
  ASSERT_EQ(first["moves"].size(), 3u);
  EXPECT_EQ(first["climb_moves"], climb.steps.size());
  EXPECT_EQ(whole["climb_moves"], climb.steps.size());
  EXPECT_EQ(whole["moves"].size(), climb.steps.size());
  const int frames = first["frames"]["count"];
  EXPECT_EQ(frames, whole["moves"][2]["last_frame"].get<int>() + 1);
  for (int f = 0; f < frames; ++f) EXPECT_EQ(frame(first, f), frame(whole, f)) << "frame " << f;
  for (std::size_t m = 0; m < 3; ++m) EXPECT_EQ(first["moves"][m], whole["moves"][m]) << "move " << m;
}

// Each reached move's recorded posture grasps the four holds the replay says it holds, with
// the root inside its tolerance (Algorithm 1's termination test): the moves and the
// postures are those of one climb.
TEST(ReplayData, EachReachedPostureGraspsTheConfigurationShown) {
  const BodyModel& model = testing::human_model();
  const RunFolder folder = testing::read_trained_run();
  const ReachabilityParameters reach;
  BodyData data(model);
  for (const RecordedClimb* climb : {&folder.last, &folder.greedy}) {
    const auto replay = replayed(model, folder.wall, *climb, reach);
    std::size_t posture = 0;
    for (const auto& move : replay["moves"]) {
      if (!move["success"]) continue;
      HoldConfiguration configuration;
      for (int limb = 0; limb < kLimbCount; ++limb) {
        configuration.holds[limb] = folder.wall.index_of(move["configuration"][enum_name(static_cast<Limb>(limb))]);
      }
      forward_kinematics(model, data, climb->postures[++posture]);
      EXPECT_TRUE(
          target_reached(data.points, reach_target(model, folder.wall, configuration, reach.root), reach.ik.tolerances))
          << climb->kind << " climb, move to hold " << move["hold"];
    }
    EXPECT_EQ(posture + 1, climb->postures.size()) << climb->kind;
  }
}

void expect_continuous(const RecordedClimb& climb, const nlohmann::ordered_json& replay);

// Between two recorded postures the body follows the IK path: where a replay without
// in-between frames would make the whole move in one frame, no frame here moves any
// joint by more than a quarter of the move's largest joint change.
TEST(ReplayData, InBetweenFramesAreContinuous) {
  const RunFolder folder = testing::read_trained_run();
  for (const RecordedClimb* climb : {&folder.last, &folder.greedy}) {
    expect_continuous(*climb, replayed(testing::human_model(), folder.wall, *climb, {}));
  }
}

void expect_continuous(const RecordedClimb& climb, const nlohmann::ordered_json& replay) {
  std::size_t posture = 0;
  int checked = 0;
  double largest_share = 0;
  for (const auto& move : replay["moves"]) {
    if (!move["success"]) continue;
    const double whole = (climb.postures[posture + 1] - climb.postures[posture]).cwiseAbs().maxCoeff();
    ++posture;
    for (int f = move["first_frame"]; f <= move["last_frame"]; ++f) {
      const double step = (frame(replay, f) - frame(replay, f - 1)).cwiseAbs().maxCoeff();
      EXPECT_LE(step, 0.25 * whole + 1e-4) << climb.kind << ", frame " << f;
      largest_share = std::max(largest_share, step / whole);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0) << climb.kind;
  ::testing::Test::RecordProperty("largest_frame_share_of_move_" + climb.kind, std::to_string(largest_share));
}

TEST(ReplayData, TheCheckPointsAreTheForwardKinematicsOfTheirFrame) {
  const BodyModel& model = testing::human_model();
  const RunFolder folder = testing::read_trained_run();
  const auto replay = replayed(model, folder.wall, folder.greedy, {});
  const int check = replay["check"]["frame"];
  BodyData data(model);
  forward_kinematics(model, data, frame(replay, check));
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const Eigen::Vector3d& p = data.points[operational_point(static_cast<Limb>(limb))];
    for (int k = 0; k < 3; ++k) EXPECT_EQ(replay["check"]["grasp_points"][limb][k].get<double>(), p[k]);
  }
  EXPECT_EQ(replay["model"]["joints"].size(), static_cast<std::size_t>(kConfigurationDof));
  EXPECT_EQ(replay["model"]["visuals"].size(), model.visuals.size());
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

// A performed climb's data: the replay's format with "performed", each frame's rotation,
// hold forces and time, and each move's outcome and cause, in words too.
TEST(ReplayData, APerformedClimbCarriesItsRotationsForcesAndOutcomes) {
  const BodyModel& model = testing::human_model();
  const Wall wall = testing::wall_with_holds({{-0.25, 1.75}, {0.25, 1.75}, {-0.15, 0.45}, {0.15, 0.45}, {-0.25, 1.95}});
  const std::vector<AttemptedMove> moves{{Limb::RightHand, 4, true, MoveFailure::None, 0.51234},
                                         {Limb::LeftHand, 1, false, MoveFailure::HitWall, 0.9}};
  std::vector<TrajectorySample> samples(4);
  for (int i = 0; i < 4; ++i) {
    samples[i].time = 0.02 * i;
    samples[i].move = i < 2 ? i - 1 : i - 2;
    samples[i].posture = standing_posture({-0.3, 0.0, 1.0});
  }
  const PerformedReplay replay = replay_performed_climb(model, wall, moves, samples, "test");
  const nlohmann::ordered_json data = performed_replay_data(model, wall, replay, 7, 0.04, "performed");
  EXPECT_EQ(data["format"], "crux-replay");
  EXPECT_EQ(data["performed"], true);
  EXPECT_EQ(data["climb_moves"], 7);
  EXPECT_EQ(data["grasp_radius"], 0.04);
  EXPECT_EQ(data["frames"]["count"], 4);
  EXPECT_EQ(data["frames"]["root_rotations"].size(), 16u);
  EXPECT_EQ(data["frames"]["hold_forces"].size(), 48u);
  EXPECT_EQ(data["frames"]["times"].size(), 4u);
  ASSERT_EQ(data["moves"].size(), 2u);
  EXPECT_EQ(data["moves"][0]["hold"], 5) << "holds by id";
  EXPECT_EQ(data["moves"][0]["success"], true);
  EXPECT_TRUE(data["moves"][0]["cause"].is_null());
  EXPECT_EQ(data["moves"][0]["max_torque_ratio"], 0.512);
  EXPECT_EQ(data["moves"][1]["cause"], "hit_wall");
  EXPECT_EQ(data["moves"][1]["cause_text"], "the body hit the wall");
  EXPECT_EQ(data["moves"][1]["first_frame"], 3);
  EXPECT_EQ(data["moves"][1]["last_frame"], 3);
  EXPECT_EQ(data["check"]["frame"], 2);
}

}  // namespace
}  // namespace crux
