#include "experiments/paper_experiment.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "experiments/experiment_output.hpp"
#include "experiments/table_one.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

ExperimentSettings small_settings(int threads) {
  ExperimentSettings settings;
  settings.runs = 2;
  settings.learning.iterations = 400;
  settings.seed = 77;
  settings.threads = threads;
  settings.plan = false;
  return settings;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "crux-tests" / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(PaperExperiment, SameSeedGivesIdenticalFilesWithOneOrTwoThreads) {
  const BodyModel& model = testing::human_model();
  const fs::path one = fresh_directory("threads1"), two = fresh_directory("threads2");
  write_experiment(one, run_paper_experiment(model, small_settings(1)), small_settings(1), model, "", 100);
  write_experiment(two, run_paper_experiment(model, small_settings(2)), small_settings(2), model, "", 100);
  int compared = 0;
  // summary.json differs only in the wall-clock time it records.
  auto first_summary = nlohmann::json::parse(read_bytes(one / "summary.json"));
  auto second_summary = nlohmann::json::parse(read_bytes(two / "summary.json"));
  first_summary.erase("seconds");
  second_summary.erase("seconds");
  EXPECT_EQ(first_summary.dump(), second_summary.dump());
  for (const auto& entry : fs::recursive_directory_iterator(one)) {
    if (!entry.is_regular_file() || entry.path().filename() == "summary.json") continue;
    const fs::path twin = two / fs::relative(entry.path(), one);
    ASSERT_TRUE(fs::exists(twin)) << twin;
    EXPECT_EQ(read_bytes(entry.path()), read_bytes(twin)) << fs::relative(entry.path(), one);
    ++compared;
  }
  EXPECT_GE(compared, 3 * 2 * 4 + 4 + 3) << "every run's four files, the walls and the figures";
}

TEST(PaperExperiment, ControlRunsOnTransferWallsAndTransferStartsFromTraining) {
  const BodyModel& model = testing::human_model();
  const ExperimentResult result = run_paper_experiment(model, small_settings(2));
  const auto& training = result.conditions[static_cast<int>(Condition::Training)];
  const auto& transfer = result.conditions[static_cast<int>(Condition::Transfer)];
  const auto& control = result.conditions[static_cast<int>(Condition::Control)];
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(control.wall_of_run[i], transfer.wall_of_run[i]) << "paired: the same wall";
    EXPECT_NE(training.wall_of_run[i], transfer.wall_of_run[i]);
    EXPECT_EQ(control.learning_seeds[i], transfer.learning_seeds[i]);
    EXPECT_EQ(transfer.runs[i].iterations.size(), 400u);
  }
  // Transfer starts with knowledge, so it uses g-greedy early; control cannot (its Q_grid is empty).
  const auto transfer_table = table_one(transfer.runs, 400);
  EXPECT_GT(transfer_table[0][static_cast<int>(Regime::GGreedy)].actions, 0u);
  EXPECT_NE(result.walls[0].wall.holds[0].position, result.walls[2].wall.holds[0].position);
}

TEST(PaperExperiment, SummaryHasTheDocumentedKeys) {
  const BodyModel& model = testing::human_model();
  const ExperimentSettings settings = small_settings(2);
  const auto summary = experiment_summary(run_paper_experiment(model, settings), settings, 100);
  for (const char* condition : {"training", "transfer", "control"}) {
    for (const char* window : {"beginning", "overall"}) {
      for (const char* regime : {"w_greedy", "g_greedy", "random"}) {
        const auto& cell = summary["table1"][condition][window][regime];
        EXPECT_TRUE(cell.contains("actions") && cell.contains("success_rate") && cell.contains("vertical_cm"));
      }
    }
    EXPECT_EQ(summary["episode_lengths"][condition].size(), 2u);
  }
}

}  // namespace
}  // namespace crux
