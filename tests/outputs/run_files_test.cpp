#include "outputs/run_files.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "learning/q_table_file.hpp"
#include "support/output_text.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Two episodes (3 actions, then 1), a Q_grid of 35 actions and a climb of 3 postures.
RunResult hand_made_run() {
  RunResult run;
  run.iterations = {{0, Regime::WGreedy, 5, true, 0.25, -1.0},
                    {0, Regime::Random, 9, false, 0.0, -1000.0},
                    {0, Regime::GGreedy, 12, true, 0.5, 200000.0},
                    {1, Regime::Random, 3, true, -0.125, -1.0}};
  run.episode_lengths = {3, 1};
  run.q_grid = QTable(35);
  run.q_grid.set_value(4, 34, -99.5);
  run.q_grid.set_value(9, 0, 180000.25);
  run.q_grid.add_visit(9, 0);
  run.q_grid.add_visit(9, 0);
  const Eigen::Vector3d root(0.3, 0.6, 1.0);
  run.last_climb = {standing_posture(root), standing_posture(root + Eigen::Vector3d(0, 0, 0.125)),
                    standing_posture(root + Eigen::Vector3d(0, 0.1, 0.3))};
  run.last_climb[1][5] = 0.75;  // one bent joint
  run.greedy_climb = {run.last_climb[0], run.last_climb[2]};
  run.greedy_moves = {{12, 200000.5}};
  return run;
}

TEST(RunFiles, IterationsCsvByHand) {
  const auto dir = testing::temporary_path("run_files_iterations");
  write_run_files(dir, hand_made_run(), testing::human_model(), GridParameters{});
  // Iterations count from 1; the rise is in cm; success is 0 or 1.
  EXPECT_EQ(testing::read_output_text(dir / "iterations.csv"),
            "iteration,episode,regime,hold,success,root_rise_cm,reward\n"
            "1,0,w_greedy,5,1,25,-1\n"
            "2,0,random,9,0,0,-1000\n"
            "3,0,g_greedy,12,1,50,200000\n"
            "4,1,random,3,1,-12.5,-1\n");
}

// Under the static model the file says where the climber fell (docs/MODEL.md, C27).
TEST(RunFiles, AStaticRunsIterationsSayWhereTheClimberFell) {
  const auto dir = testing::temporary_path("run_files_falls");
  RunResult run = hand_made_run();
  run.can_fall = true;
  run.iterations[1].fell = true;
  write_run_files(dir, run, testing::human_model(), GridParameters{});
  EXPECT_EQ(testing::read_output_text(dir / "iterations.csv"),
            "iteration,episode,regime,hold,success,root_rise_cm,reward,fell\n"
            "1,0,w_greedy,5,1,25,-1,0\n"
            "2,0,random,9,0,0,-1000,1\n"
            "3,0,g_greedy,12,1,50,200000,0\n"
            "4,1,random,3,1,-12.5,-1,0\n");
}

TEST(RunFiles, RisesAndRewardsReadBackExactly) {
  RunResult run;
  run.iterations = {{0, Regime::Random, 1, true, 0.07, -0.1}};
  const auto dir = testing::temporary_path("run_files_exact");
  write_run_files(dir, run, testing::human_model(), GridParameters{});
  const std::vector<std::string> lines = lines_of(testing::read_output_text(dir / "iterations.csv"));
  ASSERT_EQ(lines.size(), 2u);
  std::istringstream row(lines[1]);
  std::vector<std::string> cells;
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  ASSERT_EQ(cells.size(), 7u);
  EXPECT_EQ(std::stod(cells[5]), 100.0 * 0.07) << cells[5];
  EXPECT_EQ(std::stod(cells[6]), -0.1) << cells[6];
  // ... from the shortest text that does so, not 17 digits (7.0000000000000009, -0.10000000000000001).
  EXPECT_EQ(cells[5], "7.000000000000001");
  EXPECT_EQ(cells[6], "-0.1");
}

TEST(RunFiles, EpisodesCsvByHand) {
  const auto dir = testing::temporary_path("run_files_episodes");
  write_run_files(dir, hand_made_run(), testing::human_model(), GridParameters{});
  EXPECT_EQ(testing::read_output_text(dir / "episodes.csv"), "episode,length\n0,3\n1,1\n") << "episodes count from 0";
}

TEST(RunFiles, QGridLoadsBackWithItsValuesAndVisits) {
  const auto dir = testing::temporary_path("run_files_q_grid");
  write_run_files(dir, hand_made_run(), testing::human_model(), GridParameters{});
  const QTable q = load_q_table((dir / "q_grid.bin").string(), 35, describe_grid(GridParameters{}));
  EXPECT_EQ(q.state_count(), 2u);
  EXPECT_EQ(q.value(4, 34), -99.5);
  EXPECT_EQ(q.value(9, 0), 180000.25);
  EXPECT_EQ(q.visits(9, 0), 2u);
  EXPECT_EQ(q.visits(4, 34), 0u);
}

TEST(RunFiles, ClimbCsvHasARowPerPosture) {
  const BodyModel& model = testing::human_model();
  const RunResult run = hand_made_run();
  const auto dir = testing::temporary_path("run_files_climb");
  write_run_files(dir, run, model, GridParameters{});
  const std::vector<std::string> lines = lines_of(testing::read_output_text(dir / "climb.csv"));
  ASSERT_EQ(lines.size(), 1 + run.last_climb.size());
  EXPECT_EQ(lines[0].rfind("step," + model.joints[0].name + ",", 0), 0u) << lines[0];
  for (std::size_t n = 0; n < run.last_climb.size(); ++n) {
    std::istringstream row(lines[n + 1]);
    std::vector<std::string> cells;
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 1u + kConfigurationDof) << "step " << n;
    EXPECT_EQ(cells[0], std::to_string(n));
    for (int i = 0; i < kConfigurationDof; ++i) EXPECT_EQ(std::stod(cells[1 + i]), run.last_climb[n][i]);
  }
}

TEST(RunFiles, GreedyClimbCsvHasTheHoldAndRewardOfEachMove) {
  const BodyModel& model = testing::human_model();
  const RunResult run = hand_made_run();
  const auto dir = testing::temporary_path("run_files_greedy");
  write_run_files(dir, run, model, GridParameters{});
  const std::vector<std::string> lines = lines_of(testing::read_output_text(dir / "greedy_climb.csv"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].rfind("step,hold,reward," + model.joints[0].name + ",", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("0,0,0,0.3,", 0), 0u) << "the start: no hold, no reward; " << lines[1];
  EXPECT_EQ(lines[2].rfind("1,12,200000.5,0.3,0.7,", 0), 0u) << lines[2];
}

TEST(RunFiles, CreatesTheFolderAndWritesOnlyItsFiveFiles) {
  const auto dir = testing::temporary_path("run_files_nested") / "runs" / "transfer_0";
  write_run_files(dir, hand_made_run(), testing::human_model(), GridParameters{});
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.insert(entry.path().filename().string());
  EXPECT_EQ(names,
            (std::set<std::string>{"climb.csv", "episodes.csv", "greedy_climb.csv", "iterations.csv", "q_grid.bin"}));
}

TEST(RunFiles, AnEmptyRunWritesHeadersAndAnEmptyTable) {
  const auto dir = testing::temporary_path("run_files_empty");
  const RunResult empty;
  write_run_files(dir, empty, testing::human_model(), GridParameters{});
  EXPECT_EQ(testing::read_output_text(dir / "iterations.csv"),
            "iteration,episode,regime,hold,success,root_rise_cm,reward\n");
  EXPECT_EQ(testing::read_output_text(dir / "episodes.csv"), "episode,length\n");
  EXPECT_EQ(lines_of(testing::read_output_text(dir / "climb.csv")).size(), 1u) << "the header only";
  EXPECT_EQ(load_q_table((dir / "q_grid.bin").string(), empty.q_grid.action_count(), describe_grid(GridParameters{}))
                .state_count(),
            0u);
}

}  // namespace
}  // namespace crux
