#include "reports/episode_replay.hpp"


#include <filesystem>

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "experiments/run_config_file.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

RunFolder read_folder(const fs::path& directory) {
  RunFolder folder = locate_run_folder(directory);
  read_run_climb(folder, testing::human_model());
  return folder;
}

ClimbingParameters run_parameters(const RunFolder& folder) {
  return read_run_config(folder.config_file).settings.learning.climbing;
}

// Replaying the last completed episode from the run's actions gives back climb.csv's
// postures bit for bit (the CSV keeps 17 significant digits) and its moves.
TEST(EpisodeReplay, TheLastEpisodeReplayedIsTheRecordedClimb) {
  const RunFolder folder = read_folder(testing::trained_run_folder());
  ASSERT_GE(folder.last.episode, 1);
  const RecordedClimb replayed =
      replay_episode(folder, testing::human_model(), run_parameters(folder), folder.last.episode, "--climb");
  EXPECT_EQ(replayed.kind, "episode");
  EXPECT_EQ(replayed.episode, folder.last.episode);
  ASSERT_EQ(replayed.steps.size(), folder.last.steps.size());
  for (std::size_t i = 0; i < replayed.steps.size(); ++i) {
    EXPECT_EQ(replayed.steps[i].iteration, folder.last.steps[i].iteration);
  }
  ASSERT_EQ(replayed.postures.size(), folder.last.postures.size());
  for (std::size_t i = 0; i < replayed.postures.size(); ++i) EXPECT_EQ(replayed.postures[i], folder.last.postures[i]) << i;
}

// Episode 0 ends with the finishing move; the run's last episode, cut off by its
// iterations, is replayed as unfinished.
TEST(EpisodeReplay, EpisodesEndWhereTheRunFinishedThem) {
  const RunFolder folder = read_folder(testing::trained_run_folder());
  const ClimbingParameters parameters = run_parameters(folder);
  const RecordedClimb first = climb_to_show(folder, testing::human_model(), parameters, "0", "--climb");
  std::size_t rows = 0;
  for (const RunStep& step : folder.steps) rows += step.episode == 0 ? 1 : 0;
  ASSERT_EQ(first.steps.size(), rows);
  EXPECT_TRUE(first.finished);
  EXPECT_GT(first.steps.back().reward, 0) << "the finishing reward";
  const int unfinished = folder.steps.back().episode;
  ASSERT_EQ(unfinished, folder.last.episode + 1);
  const RecordedClimb cut = replay_episode(folder, testing::human_model(), parameters, unfinished, "--climb");
  EXPECT_FALSE(cut.finished);
  EXPECT_EQ(cut.steps.back().iteration, 8000);
}

TEST(EpisodeReplay, NamedClimbsAndBadChoicesNameTheFlag) {
  const RunFolder folder = read_folder(testing::trained_run_folder());
  const ClimbingParameters parameters = run_parameters(folder);
  EXPECT_EQ(climb_to_show(folder, testing::human_model(), parameters, "greedy", "--climb").kind, "greedy");
  EXPECT_EQ(climb_to_show(folder, testing::human_model(), parameters, "last", "--climb").kind, "last");
  for (const std::string choice : {"-1", "99999", "2x", "", "best"}) {
    try {
      climb_to_show(folder, testing::human_model(), parameters, choice, "--climb");
      ADD_FAILURE() << "accepted --climb '" << choice << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "--climb") << choice;
    }
  }
}

// A folder whose actions the MDP does not reproduce (here a move's verdict flipped) is
// refused, naming its iterations.csv and the iteration.
TEST(EpisodeReplay, ActionsThatDoNotReplayAreRefused) {
  const fs::path copy = testing::edited_trained_run("replay_flipped", "iterations.csv", [](std::string& text) {
    // iteration,episode,regime,hold,success,...: flip the first row's success.
    std::size_t cell = text.find('\n');
    for (int comma = 0; comma < 4; ++comma) cell = text.find(',', cell + 1);
    text[cell + 1] = text[cell + 1] == '0' ? '1' : '0';
  });
  const RunFolder folder = read_folder(copy);
  try {
    replay_episode(folder, testing::human_model(), run_parameters(folder), 0, "--climb");
    FAIL() << "replayed a flipped verdict";
  } catch (const InputError& e) {
    EXPECT_NE(e.source().find("iterations.csv"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("iteration 1:"), std::string::npos) << e.what();
  }
}

// An episode boundary moved by one row no longer matches the MDP's finishes.
TEST(EpisodeReplay, AShiftedEpisodeBoundaryIsRefused) {
  const fs::path copy = testing::edited_trained_run("replay_shifted", "iterations.csv", [](std::string& text) {
    // iteration,episode,...: the first row whose episode cell is 1 now claims episode 0.
    std::size_t line = text.find('\n') + 1;
    while (line < text.size() && text.compare(text.find(',', line), 3, ",1,") != 0) line = text.find('\n', line) + 1;
    ASSERT_LT(line, text.size());
    text[text.find(',', line) + 1] = '0';
  });
  const RunFolder folder = read_folder(copy);
  try {
    replay_episode(folder, testing::human_model(), run_parameters(folder), 1, "--climb");
    FAIL() << "replayed across a moved episode boundary";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("episode 0 where the MDP is in episode 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace crux
