#include "experiments/episode_replay.hpp"

#include <filesystem>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/run_folder.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

RunFolder read_folder(const fs::path& directory) {
  RunFolder folder = locate_run_folder(directory);
  read_run_climb(folder, testing::human_model());
  return folder;
}

std::string iterations_file(const RunFolder& folder) { return (folder.directory / "iterations.csv").string(); }

ClimbingParameters run_parameters(const RunFolder& folder) {
  return read_run_config(folder.config_file).settings.learning.climbing;
}

// Replaying the last completed episode from the run's actions gives back climb.csv's
// postures bit for bit (the CSV keeps the shortest text that reads back exactly) and its moves.
TEST(EpisodeReplay, TheLastEpisodeReplayedIsTheRecordedClimb) {
  const RunFolder folder = read_folder(testing::trained_run_folder());
  ASSERT_GE(folder.last.episode, 1);
  const RecordedClimb replayed = replay_episode(testing::human_model(), folder.wall, run_parameters(folder),
                                                folder.steps, folder.last.episode, iterations_file(folder), "--climb");
  EXPECT_EQ(replayed.kind, "episode");
  EXPECT_EQ(replayed.episode, folder.last.episode);
  ASSERT_EQ(replayed.steps.size(), folder.last.steps.size());
  for (std::size_t i = 0; i < replayed.steps.size(); ++i) {
    EXPECT_EQ(replayed.steps[i].iteration, folder.last.steps[i].iteration);
  }
  ASSERT_EQ(replayed.postures.size(), folder.last.postures.size());
  for (std::size_t i = 0; i < replayed.postures.size(); ++i)
    EXPECT_EQ(replayed.postures[i], folder.last.postures[i]) << i;
}

// Episode 1, iterations.csv's episode 0 (--climb counts from 1, as Fig. 4 does), ends
// with the finishing move; the run's last episode, cut off by its iterations, is
// replayed as unfinished.
TEST(EpisodeReplay, EpisodesEndWhereTheRunFinishedThem) {
  const RunFolder folder = read_folder(testing::trained_run_folder());
  const ClimbingParameters parameters = run_parameters(folder);
  const RecordedClimb first = climb_to_show(folder, testing::human_model(), parameters, "1", "--climb");
  EXPECT_EQ(first.episode, 0);
  std::size_t rows = 0;
  for (const RunStep& step : folder.steps) rows += step.episode == 0 ? 1 : 0;
  ASSERT_EQ(first.steps.size(), rows);
  EXPECT_TRUE(first.finished);
  EXPECT_GT(first.steps.back().reward, 0) << "the finishing reward";
  const int unfinished = folder.steps.back().episode;
  ASSERT_EQ(unfinished, folder.last.episode + 1);
  const RecordedClimb cut = replay_episode(testing::human_model(), folder.wall, parameters, folder.steps, unfinished,
                                           iterations_file(folder), "--climb");
  EXPECT_FALSE(cut.finished);
  EXPECT_EQ(cut.steps.back().iteration, 8000);
}

TEST(EpisodeReplay, NamedClimbsAndBadChoicesNameTheFlag) {
  const RunFolder folder = read_folder(testing::trained_run_folder());
  const ClimbingParameters parameters = run_parameters(folder);
  EXPECT_EQ(climb_to_show(folder, testing::human_model(), parameters, "greedy", "--climb").kind, "greedy");
  EXPECT_EQ(climb_to_show(folder, testing::human_model(), parameters, "last", "--climb").kind, "last");
  for (const std::string choice : {"-1", "0", "99999", "2x", "", "best"}) {
    try {
      climb_to_show(folder, testing::human_model(), parameters, choice, "--climb");
      ADD_FAILURE() << "accepted --climb '" << choice << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "--climb") << choice;
    }
  }
  // Episodes are named from 1 in what the user reads too.
  const int episodes = folder.steps.back().episode + 1;
  for (const auto& [choice, problem] : std::vector<std::pair<std::string, std::string>>{
           {"0", "episodes are numbered from 1, not 0"},
           {std::to_string(episodes + 1),
            fmt::format("the run has episodes 1 to {}, not {}", episodes, episodes + 1)}}) {
    try {
      climb_to_show(folder, testing::human_model(), parameters, choice, "--climb");
      ADD_FAILURE() << "accepted --climb " << choice;
    } catch (const InputError& e) {
      EXPECT_EQ(e.problem(), problem);
    }
  }
  EXPECT_EQ(climb_to_show(folder, testing::human_model(), parameters, std::to_string(episodes), "--climb").episode,
            episodes - 1)
      << "the last episode, numbered from 1";
}

// Why the climb shown is the one: the greedy climb when it finishes, else the last
// completed episode, saying that the greedy policy did not reach the top and within how
// many actions (experiment.greedy_cap); an episode asked for by number.
TEST(EpisodeReplay, TheReasonForTheClimbShownNamesItAndWhy) {
  RunFolder folder = read_folder(testing::trained_run_folder());
  const ClimbingParameters parameters = run_parameters(folder);
  ASSERT_FALSE(folder.greedy.postures.empty()) << "the trained run's greedy policy finishes";
  const RecordedClimb greedy = climb_to_show(folder, testing::human_model(), parameters, "greedy", "--climb");
  EXPECT_EQ(shown_climb_reason(folder, greedy, "greedy", 500, "--climb"),
            fmt::format("the greedy policy's climb after learning, which reaches the top in {} actions",
                        folder.greedy.steps.size()));
  const std::string last = fmt::format("the last completed episode (episode {})", folder.last.episode + 1);
  EXPECT_EQ(shown_climb_reason(folder, folder.last, "last", 500, "--climb"), last + ", as --climb last asks");
  const RecordedClimb second = climb_to_show(folder, testing::human_model(), parameters, "2", "--climb");
  EXPECT_EQ(shown_climb_reason(folder, second, "2", 500, "--climb"), "episode 2, as --climb 2 asks");
  const std::string unfinished = std::to_string(folder.steps.back().episode + 1);
  const RecordedClimb cut = climb_to_show(folder, testing::human_model(), parameters, unfinished, "--climb");
  EXPECT_EQ(shown_climb_reason(folder, cut, unfinished, 500, "--climb"),
            fmt::format("episode {0}, as --climb {0} asks; the run ended during it, so it does not reach the top",
                        unfinished));

  // The same folder as if its greedy policy had not finished (greedy_climb.csv then holds
  // the header only): the last completed episode, and why.
  folder.greedy = {};
  const RecordedClimb fallback = climb_to_show(folder, testing::human_model(), parameters, "greedy", "--climb");
  EXPECT_EQ(fallback.kind, "last");
  EXPECT_EQ(shown_climb_reason(folder, fallback, "greedy", 1, "--climb"),
            last + ", since the greedy policy did not reach the top within 1 action (experiment.greedy_cap)");
  EXPECT_EQ(shown_climb_reason(folder, RecordedClimb{"last", -1, true, {}, {}}, "greedy", 500, "--climb"),
            "the greedy policy did not reach the top within 500 actions (experiment.greedy_cap) and the run "
            "completed no episode");
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
    replay_episode(testing::human_model(), folder.wall, run_parameters(folder), folder.steps, 0,
                   iterations_file(folder), "--climb");
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
    replay_episode(testing::human_model(), folder.wall, run_parameters(folder), folder.steps, 1,
                   iterations_file(folder), "--climb");
    FAIL() << "replayed across a moved episode boundary";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("episode 0 where the MDP is in episode 1"), std::string::npos) << e.what();
  }
}

// A climb's postures grasp the start, then each reached move's 4-configuration: the free
// limb of the cycle (right hand, left hand, right foot, ...) on the move's hold; failed
// moves change nothing.
TEST(EpisodeReplay, EachPostureOfAClimbGraspsItsConfiguration) {
  const Wall wall = generate_random_wall(1);
  const HoldConfiguration start = start_configuration(wall);
  const int a = wall.holds[0].id, b = wall.holds[1].id, c = wall.holds[2].id;
  RecordedClimb climb;
  climb.steps = {{1, 0, Regime::Random, a, true},
                 {2, 0, Regime::Random, c, false},
                 {3, 0, Regime::Random, b, true},
                 {4, 0, Regime::Random, c, true}};
  climb.postures.assign(4, Posture::Zero());
  const std::vector<HoldConfiguration> configurations = climb_configurations(wall, climb);
  ASSERT_EQ(configurations.size(), 4u);
  EXPECT_EQ(configurations[0].holds, start.holds);
  EXPECT_EQ(configurations[1].holds, start.with(Limb::RightHand, 0).holds);
  EXPECT_EQ(configurations[2].holds, start.with(Limb::RightHand, 0).with(Limb::LeftHand, 1).holds);
  EXPECT_EQ(configurations[3].holds,
            start.with(Limb::RightHand, 0).with(Limb::LeftHand, 1).with(Limb::RightFoot, 2).holds);
}

}  // namespace
}  // namespace crux
