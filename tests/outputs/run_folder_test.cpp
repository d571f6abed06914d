#include "outputs/run_folder.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "outputs/run_config_file.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

TEST(RunFolder, ReadsTheLastCompletedClimbWithItsEpisode) {
  const RunFolder folder = testing::read_trained_run();
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
  const RunFolder folder = testing::read_trained_run();
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
  const fs::path copy = testing::edited_trained_run("run_cut", "climb.csv", [](std::string& climb) {
    climb.erase(climb.rfind('\n', climb.size() - 2) + 1);  // drop the finishing posture
  });
  RunFolder folder = locate_run_folder(copy);
  EXPECT_THROW(read_run_climb(folder, testing::human_model()), InputError);
}

// Every row of iterations.csv is kept, and the config it was written with reads back.
TEST(RunFolder, KeepsEveryIterationAndReadsItsOwnConfig) {
  const RunFolder folder = testing::read_trained_run();
  ASSERT_EQ(folder.steps.size(), 8000u);
  for (std::size_t i = 0; i < folder.steps.size(); ++i) EXPECT_EQ(folder.steps[i].iteration, static_cast<int>(i) + 1);
  EXPECT_EQ(folder.steps.back().episode, folder.last.episode + 1) << "the last episode is unfinished";
  const ExperimentConfig config = read_run_config(folder.config_file);
  EXPECT_EQ(config.settings.seed, 5u);
  EXPECT_EQ(config.wall_seed, 3u);
  EXPECT_EQ(config.settings.learning.iterations, 8000);
}

TEST(RunFolder, ABadConfigIsNamedWithItsLineAndKey) {
  const fs::path copy = testing::edited_trained_run("run_bad_config", "config.toml", [](std::string& text) {
    const std::size_t gamma = text.find("gamma = 0.9");
    ASSERT_NE(gamma, std::string::npos);
    text.replace(gamma, 11, "gamma = 2.0");
  });
  const RunFolder folder = locate_run_folder(copy);
  try {
    read_run_config(folder.config_file);
    FAIL() << "accepted gamma = 2";
  } catch (const InputError& e) {
    EXPECT_NE(e.source().find("config.toml: line"), std::string::npos) << e.what();
    EXPECT_NE(e.source().find("learning.gamma"), std::string::npos) << e.what();
  }
}

TEST(RunFolder, AReportedRunIsTheFolderOrARunOfAPaperFolder) {
  const ReportedRun run = locate_reported_run(testing::trained_run_folder(), "ignored", "--run");
  EXPECT_FALSE(run.experiment);
  EXPECT_EQ(run.run_directory, testing::trained_run_folder());

  const fs::path paper = testing::temporary_path("reported_paper_" + std::to_string(::getpid()));
  fs::create_directories(paper / "runs" / "control_2");
  std::ofstream(paper / "summary.json") << "{}";
  const ReportedRun control = locate_reported_run(paper, "control_2", "--run");
  EXPECT_TRUE(control.experiment);
  EXPECT_EQ(control.run_directory, paper / "runs" / "control_2");
  for (const std::string name : {"control_3", "training", "../x", "train_1"}) {
    try {
      locate_reported_run(paper, name, "--run");
      ADD_FAILURE() << "accepted run " << name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "--run") << name;
    }
  }
  EXPECT_THROW(locate_reported_run(paper / "nowhere", "control_2", "--run"), InputError);
}

// A run the paper folder does not hold is refused with the runs it holds, each
// condition's consecutive runs as one range.
TEST(RunFolder, AMissingRunOfAPaperFolderListsTheRunsItHas) {
  const fs::path paper = testing::temporary_path("reported_runs_" + std::to_string(::getpid()));
  for (const char* run :
       {"training_0", "training_1", "transfer_0", "transfer_1", "control_0", "control_1", "control_3", "training_x"}) {
    fs::create_directories(paper / "runs" / run);
  }
  std::ofstream(paper / "runs" / "transfer_2") << "a file, not a run";
  std::ofstream(paper / "summary.json") << "{}";
  try {
    locate_reported_run(paper, "transfer_4", "--run");
    FAIL() << "accepted transfer_4";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "--run");
    EXPECT_EQ(e.problem(), fmt::format("'transfer_4' is not a run of {}; it has training_0..training_1, "
                                       "transfer_0..transfer_1, control_0..control_1, control_3",
                                       paper.string()));
  }
  fs::remove_all(paper / "runs");
  fs::create_directories(paper / "runs");
  try {
    locate_reported_run(paper, "training_0", "--run");
    FAIL() << "accepted a run of a folder without runs";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), fmt::format("'training_0' is not a run of {}; it has no runs", paper.string()));
  }
}

TEST(RunFolder, AClimbIsDescribedByItsKind) {
  EXPECT_EQ(climb_description({"greedy", -1, true, {}, {}}), "the greedy policy's climb after learning");
  // Episode indices from 0 (iterations.csv's) are shown from 1, as the paper's Fig. 4 counts them.
  EXPECT_EQ(climb_description({"last", 7, true, {}, {}}), "the climb of episode 8");
  EXPECT_EQ(climb_description({"episode", 0, true, {}, {}}), "the climb of episode 1");
  EXPECT_EQ(climb_description({"episode", 9, false, {}, {}}), "the climb of episode 10 (unfinished)");
  EXPECT_EQ(climb_description({"episode", 0, true, {}, {}, 3}),
            "the climb of episode 1, attempt 3 (after 2 falls back to the start)");
  EXPECT_EQ(climb_description({"last", 4, true, {}, {}, 2}),
            "the climb of episode 5, attempt 2 (after 1 fall back to the start)");
}

}  // namespace
}  // namespace crux
