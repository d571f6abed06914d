#include "experiments/climb_replay.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "outputs/run_folder.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

// The start is frame 0; each move then takes its frames in order, a reached move ending
// on the posture it reached (rounded as options.decimals says), an unreachable one
// keeping the body where it is.
TEST(ClimbReplay, EachMoveTakesItsFramesAndEndsOnItsPosture) {
  const RunFolder folder = testing::read_trained_run();
  const RecordedClimb& climb = folder.last;
  ReplayOptions options;
  options.frames_per_move = 5;
  options.frames_per_failure = 2;
  const ClimbReplay replay = replay_climb(testing::human_model(), folder.wall, climb, {}, "test", options);
  ASSERT_EQ(replay.moves.size(), climb.steps.size());
  EXPECT_EQ(replay.climb_moves, climb.steps.size());
  EXPECT_EQ(replay.climb_kind, "last");
  int frames = 1, reached = 0;
  for (const ReplayMove& move : replay.moves) {
    EXPECT_EQ(move.first_frame, frames);
    frames += move.step.success ? 5 : 2;
    EXPECT_EQ(move.last_frame, frames - 1);
    if (!move.step.success) {
      EXPECT_EQ(move.posture, -1);
      continue;
    }
    EXPECT_EQ(move.posture, ++reached);
    const Posture expected = (climb.postures[reached] * 1e5).array().round() / 1e5;
    EXPECT_EQ(replay.frame(move.last_frame), expected);
  }
  EXPECT_EQ(replay.frame_count, frames);
  EXPECT_EQ(replay.frames.size(), static_cast<std::size_t>(frames) * kConfigurationDof);
  EXPECT_EQ(replay.check_frame, frames / 2);
}

// A replay capped at two moves shows the first two as the whole replay does, and keeps
// the climb's move count.
TEST(ClimbReplay, ACappedReplayIsTheWholeReplaysBeginning) {
  const RunFolder folder = testing::read_trained_run();
  const ClimbReplay whole = replay_climb(testing::human_model(), folder.wall, folder.last, {}, "test");
  ReplayOptions options;
  options.max_moves = 2;
  const ClimbReplay first = replay_climb(testing::human_model(), folder.wall, folder.last, {}, "test", options);
  ASSERT_EQ(first.moves.size(), 2u);
  EXPECT_EQ(first.climb_moves, whole.climb_moves);
  const std::size_t values = static_cast<std::size_t>(first.frame_count) * kConfigurationDof;
  EXPECT_TRUE(
      std::equal(first.frames.begin(), first.frames.end(), whole.frames.begin(), whole.frames.begin() + values));
}

// A move to a hold the wall does not have is refused naming the source.
TEST(ClimbReplay, AHoldTheWallDoesNotHaveIsRefused) {
  const RunFolder folder = testing::read_trained_run();
  RecordedClimb climb = folder.last;
  ASSERT_FALSE(climb.steps.empty());
  climb.steps.front().hold_id = 100000;
  try {
    replay_climb(testing::human_model(), folder.wall, climb, {}, "the/run");
    FAIL() << "a hold the wall does not have was replayed";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "the/run");
    EXPECT_NE(error.problem().find("hold 100000"), std::string::npos) << error.problem();
  }
}

}  // namespace
}  // namespace crux
