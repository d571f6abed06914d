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
#include "reports/run_folder.hpp"
#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// A real run folder: crux train on random wall 3 with learning seed 5, 8000 iterations,
// completes episodes and learns a greedy climb (both checked below).
const fs::path& trained_folder() {
  static const fs::path folder = [] {
    // Per process: ctest runs this file's tests in parallel processes, each training once.
    const fs::path path = testing::temporary_path("replay_train_" + std::to_string(::getpid()));
    const testing::Outcome outcome = testing::run_crux(
        "train --wall-seed 3 --seed 5 --overwrite -o " + path.string());
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return path;
  }();
  return folder;
}

RunFolder read_trained_folder() {
  RunFolder folder = locate_run_folder(trained_folder());
  read_run_climb(folder, testing::human_model());
  return folder;
}

Posture frame(const nlohmann::ordered_json& replay, int index) {
  Posture posture;
  for (int i = 0; i < kConfigurationDof; ++i) posture[i] = replay["frames"]["postures"][index * kConfigurationDof + i];
  return posture;
}

TEST(RunFolder, ReadsTheLastCompletedClimbWithItsEpisode) {
  const RunFolder folder = read_trained_folder();
  ASSERT_GE(folder.last.episode, 1);
  std::size_t reached = 0;
  for (const RunStep& step : folder.last.steps) {
    EXPECT_EQ(step.episode, folder.last.episode);
    reached += step.success ? 1 : 0;
  }
  EXPECT_EQ(folder.last.postures.size(), reached + 1);
  EXPECT_EQ(folder.wall.name, "random wall, seed 3");
  EXPECT_EQ(folder.urdf, testing::human_model().source);
}

// A greedy climb: a reached move per posture after the start, its rise from the
// postures, and as many moves as summary.json's greedy_length.
TEST(RunFolder, ReadsTheGreedyClimb) {
  const RunFolder folder = read_trained_folder();
  std::ifstream in(folder.summary_file);
  const auto summary = nlohmann::json::parse(in);
  const int length = summary["run_facts"]["training"][0]["greedy_length"];
  ASSERT_GT(length, 0) << "seed 5 on wall 3 learns a greedy climb in 8000 iterations";
  ASSERT_EQ(folder.greedy.steps.size(), static_cast<std::size_t>(length));
  ASSERT_EQ(folder.greedy.postures.size(), folder.greedy.steps.size() + 1);
  EXPECT_EQ(folder.greedy.postures.front(), folder.last.postures.front()) << "both start at the start posture";
  for (std::size_t i = 0; i < folder.greedy.steps.size(); ++i) {
    const RunStep& step = folder.greedy.steps[i];
    EXPECT_TRUE(step.success);
    EXPECT_EQ(step.regime, Regime::WGreedy);
    EXPECT_GE(folder.wall.index_of(step.hold_id), 0);
    EXPECT_DOUBLE_EQ(step.root_rise_cm, 100 * (folder.greedy.postures[i + 1][2] - folder.greedy.postures[i][2]));
  }
  EXPECT_GT(folder.greedy.steps.back().reward, 0) << "the last move is the finishing one";
}

TEST(RunFolder, AFolderThatIsNoRunIsNamed) {
  const fs::path empty = testing::temporary_path("not_a_run_" + std::to_string(::getpid()));
  fs::create_directories(empty);
  try {
    locate_run_folder(empty);
    FAIL() << "accepted a folder without a run";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), empty.string());
    EXPECT_NE(e.problem().find("not a run folder"), std::string::npos) << e.what();
  }
}

TEST(RunFolder, AClimbThatDoesNotMatchItsIterationsIsRefused) {
  const fs::path copy = testing::temporary_path("replay_train_cut_" + std::to_string(::getpid()));
  fs::copy(trained_folder(), copy, fs::copy_options::recursive);
  std::string climb;
  {
    std::ifstream in(copy / "climb.csv");
    climb.assign(std::istreambuf_iterator<char>(in), {});
  }
  climb.erase(climb.rfind('\n', climb.size() - 2) + 1);  // drop the finishing posture
  std::ofstream(copy / "climb.csv") << climb;
  RunFolder folder = locate_run_folder(copy);
  EXPECT_THROW(read_run_climb(folder, testing::human_model()), InputError);
}

// Every move takes its frames in order; a reached move ends exactly on the recorded
// posture (as rounded), an unreachable one keeps the body still.
TEST(ReplayData, MovesCoverTheFramesAndEndOnTheRecordedPostures) {
  const RunFolder folder = read_trained_folder();
  const ReplaySettings settings;
  const RecordedClimb& climb = folder.last;
  const auto replay = replay_data(testing::human_model(), folder.wall, climb, {}, "test", "test", settings);
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

// Each reached move's recorded posture grasps the four holds the replay says it holds, with
// the root inside its tolerance (Algorithm 1's termination test): the moves and the
// postures are those of one climb.
TEST(ReplayData, EachReachedPostureGraspsTheConfigurationShown) {
  const BodyModel& model = testing::human_model();
  const RunFolder folder = read_trained_folder();
  const ReachabilityParameters reach;
  BodyData data(model);
  for (const RecordedClimb* climb : {&folder.last, &folder.greedy}) {
    const auto replay = replay_data(model, folder.wall, *climb, reach, "test", "test");
    std::size_t posture = 0;
    for (const auto& move : replay["moves"]) {
      if (!move["success"]) continue;
      HoldConfiguration configuration;
      for (int limb = 0; limb < kLimbCount; ++limb) {
        configuration.holds[limb] = folder.wall.index_of(move["configuration"][limb_name(static_cast<Limb>(limb))]);
      }
      forward_kinematics(model, data, climb->postures[++posture]);
      EXPECT_TRUE(target_reached(data.points, reach_target(model, folder.wall, configuration, reach.root),
                                 reach.ik.tolerances))
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
  const RunFolder folder = read_trained_folder();
  for (const RecordedClimb* climb : {&folder.last, &folder.greedy}) {
    expect_continuous(*climb, replay_data(testing::human_model(), folder.wall, *climb, {}, "test", "test"));
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
  const RunFolder folder = read_trained_folder();
  const auto replay = replay_data(model, folder.wall, folder.greedy, {}, "test", "test");
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
