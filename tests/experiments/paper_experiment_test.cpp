#include "experiments/paper_experiment.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "experiments/experiment_config.hpp"
#include "experiments/table_one.hpp"
#include "learning/q_table_file.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/summary.hpp"
#include "reports/report_figures.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

ExperimentParameters small_settings(int threads) {
  ExperimentParameters settings;
  settings.wall_pairs = 2;
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
  const fs::path dir = testing::test_folder() / name;
  fs::remove_all(dir);
  return dir;
}

TEST(PaperExperiment, SameSeedGivesIdenticalFilesWithOneOrTwoThreads) {
  const BodyModel& model = testing::human_model();
  const fs::path one = fresh_directory("threads1"), two = fresh_directory("threads2");
  for (const auto& [directory, threads] : {std::pair{one, 1}, std::pair{two, 2}}) {
    ExperimentParameters settings = small_settings(threads);
    settings.seeds_per_wall = 2;
    const auto write = [&](const fs::path& folder, const ExperimentResult& result) {
      const ExperimentAnalysis analysis = analyse_experiment(result, settings);
      ExperimentConfig config;
      config.settings = settings;
      // The figures read the grid's shape back from config.toml.
      const std::string config_toml = config_to_toml(config, ParameterSet{{"grid"}, {}});
      write_experiment_folder(folder, result, settings, model, config_toml,
                              summary_json(result, &analysis, settings, {}), write_paper_figure_files);
    };
    write(directory, run_paper_experiment(model, settings));
    settings.learning.dyna.planner = Planner::Prioritized;
    write(directory / "prioritized", run_paper_experiment(model, settings));
  }
  int compared = 0;
  // summary.json too: it records no wall-clock time.
  for (const auto& entry : fs::recursive_directory_iterator(one)) {
    if (!entry.is_regular_file()) continue;
    const fs::path twin = two / fs::relative(entry.path(), one);
    ASSERT_TRUE(fs::exists(twin)) << twin;
    EXPECT_EQ(read_bytes(entry.path()), read_bytes(twin)) << fs::relative(entry.path(), one);
    ++compared;
  }
  EXPECT_GE(compared, 2 * (3 * 4 * 4 + 4 + 3 + 4))
      << "every run's four files, the walls and the figures (CSV and SVG), per planner";
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

TEST(PaperExperiment, SeedsPerWallShareTheWallAndFormItsCluster) {
  const BodyModel& model = testing::human_model();
  ExperimentParameters settings = small_settings(2);
  settings.wall_pairs = 2;
  settings.seeds_per_wall = 2;
  settings.learning.iterations = 150;
  const ExperimentResult result = run_paper_experiment(model, settings);
  EXPECT_EQ(result.walls.size(), 4u) << "two training and two transfer walls";
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    ASSERT_EQ(c.runs.size(), 4u);
    EXPECT_EQ(c.cluster_of_run, (std::vector<std::size_t>{0, 0, 1, 1}));
    EXPECT_EQ(c.wall_of_run[0], c.wall_of_run[1]);
    EXPECT_NE(c.wall_of_run[1], c.wall_of_run[2]);
    EXPECT_NE(c.learning_seeds[0], c.learning_seeds[1]);
  }
  // With one seed per wall, run r's learning seed does not depend on the number of walls.
  ExperimentParameters four = small_settings(2), two = small_settings(2);
  four.wall_pairs = 4;
  four.learning.iterations = two.learning.iterations = 10;
  EXPECT_EQ(run_paper_experiment(model, four).conditions[0].learning_seeds[1],
            run_paper_experiment(model, two).conditions[0].learning_seeds[1]);
}

std::string q_table_bytes(const QTable& table, const std::string& name) {
  const fs::path path = testing::test_folder() / name;
  save_q_table(path.string(), table, "test space");
  return read_bytes(path);
}

TEST(PaperExperiment, TrainingWallsLearnInSequenceEachFromThePreviousQGrid) {
  const BodyModel& model = testing::human_model();
  ExperimentParameters one = small_settings(2);
  one.wall_pairs = 1;
  one.learning.iterations = 150;
  ExperimentParameters three = one;
  three.training_walls = 3;
  EXPECT_EQ(one.learning_runs(), 3);
  EXPECT_EQ(three.learning_runs(), 5) << "total runs: K training runs, then transfer and control";
  const ExperimentResult k1 = run_paper_experiment(model, one), k3 = run_paper_experiment(model, three);
  ASSERT_EQ(k3.preceding_training_walls.size(), 2u);
  EXPECT_TRUE(k1.preceding_training_walls.empty());
  // By hand: the first run learns on preceding wall 0 from an empty Q_grid, the second on
  // preceding wall 1 from the first's Q_grid, the third on the pair's training wall from
  // the second's.
  const ExperimentWall first_wall = draw_preceding_training_wall(model, three, 0, 0),
                       second_wall = draw_preceding_training_wall(model, three, 0, 1);
  EXPECT_EQ(first_wall.seed, k3.preceding_training_walls[0].seed);
  EXPECT_EQ(second_wall.seed, k3.preceding_training_walls[1].seed);
  const RunResult first =
      run_learning(model, first_wall.wall, three.learning, preceding_learning_seed(three.seed, 0, 0), nullptr);
  const RunResult second =
      run_learning(model, second_wall.wall, three.learning, preceding_learning_seed(three.seed, 0, 1), &first.q_grid);
  const RunResult third = run_learning(model, k3.walls[0].wall, three.learning,
                                       learning_seed(three.seed, Condition::Training, 0), &second.q_grid);
  const auto& training = k3.conditions[static_cast<int>(Condition::Training)].runs[0];
  EXPECT_EQ(q_table_bytes(training.q_grid, "k3_training.bin"), q_table_bytes(third.q_grid, "by_hand.bin"));
  EXPECT_EQ(training.episode_lengths, third.episode_lengths);
  EXPECT_NE(q_table_bytes(training.q_grid, "k3_training.bin"),
            q_table_bytes(k1.conditions[0].runs[0].q_grid, "k1_training.bin"))
      << "the last run starts from knowledge";
  // The preceding walls' stream shifts no other draw.
  for (std::size_t w = 0; w < k1.walls.size(); ++w) EXPECT_EQ(k1.walls[w].seed, k3.walls[w].seed);
  EXPECT_NE(first_wall.seed, k3.walls[0].seed);
  EXPECT_NE(first_wall.seed, second_wall.seed);
  for (const Condition c : kConditions) {
    EXPECT_EQ(k1.conditions[static_cast<int>(c)].learning_seeds, k3.conditions[static_cast<int>(c)].learning_seeds);
  }
  EXPECT_EQ(k1.conditions[static_cast<int>(Condition::Control)].runs[0].episode_lengths,
            k3.conditions[static_cast<int>(Condition::Control)].runs[0].episode_lengths);
  // Taylor and Stone's total: K x iterations of training, then the transfer run's.
  const ExperimentAnalysis analysis = analyse_experiment(k3, three);
  const auto spent = summary_json(k3, &analysis, three, {})["iterations_spent"];
  EXPECT_EQ(spent["training_walls"], 3);
  EXPECT_EQ(spent["training"], 450);
  EXPECT_EQ(spent["transfer"], 150);
  EXPECT_EQ(spent["total"], 600);
  EXPECT_EQ(spent["control"], 150);
  EXPECT_EQ(spent["preceding_training_walls"][1]["seed"], second_wall.seed);
  const ExperimentAnalysis analysis1 = analyse_experiment(k1, one);
  EXPECT_FALSE(summary_json(k1, &analysis1, one, {}).contains("iterations_spent")) << "K = 1: the paper's summary";
}

// A similarity cell: only the training walls' geometry moves; the transfer walls, every
// learning seed and control's runs stay those of the default, so cells stay paired.
TEST(PaperExperiment, TrainingWallParametersShapeTheTrainingWallsAlone) {
  const BodyModel& model = testing::human_model();
  ExperimentParameters same = small_settings(2);
  same.learning.iterations = 150;
  same.training_walls = 2;
  ExperimentParameters sparse = same;
  sparse.training_wall = sparse.walls;
  sparse.training_wall->sigma = 0.2;
  sparse.training_wall->tile_width = 0.4;
  EXPECT_EQ(&same.training_wall_parameters(), &same.walls) << "none set: shaped like the transfer walls";
  const ExperimentResult base = run_paper_experiment(model, same), other = run_paper_experiment(model, sparse);
  const int pairs = same.wall_pairs;
  for (int w = 0; w < pairs; ++w) {
    const Wall& trained = other.walls[w].wall;
    EXPECT_NE(trained.holds[5].position, base.walls[w].wall.holds[5].position) << "training wall " << w;
    // The same seed stream draws the wall with the other parameters.
    Wall expected = generate_random_wall(other.walls[w].seed, *sparse.training_wall);
    EXPECT_EQ(trained.holds[5].position, expected.holds[5].position);
    EXPECT_EQ(other.walls[pairs + w].seed, base.walls[pairs + w].seed) << "transfer wall " << w;
    EXPECT_EQ(other.walls[pairs + w].wall.holds[5].position, base.walls[pairs + w].wall.holds[5].position);
  }
  for (std::size_t j = 0; j < base.preceding_training_walls.size(); ++j) {
    const ExperimentWall& drawn = other.preceding_training_walls[j];
    EXPECT_EQ(drawn.wall.holds[5].position, generate_random_wall(drawn.seed, *sparse.training_wall).holds[5].position);
  }
  for (const Condition c : kConditions) {
    EXPECT_EQ(base.conditions[static_cast<int>(c)].learning_seeds,
              other.conditions[static_cast<int>(c)].learning_seeds);
  }
  const auto& control = base.conditions[static_cast<int>(Condition::Control)].runs;
  const auto& control_other = other.conditions[static_cast<int>(Condition::Control)].runs;
  for (std::size_t r = 0; r < control.size(); ++r) {
    EXPECT_EQ(control[r].episode_lengths, control_other[r].episode_lengths);
    EXPECT_EQ(q_table_bytes(control[r].q_grid, "control.bin"), q_table_bytes(control_other[r].q_grid, "other.bin"));
  }
}

TEST(PaperExperiment, TrainingWallsGiveTheSameBytesWithOneOrTwoThreads) {
  const BodyModel& model = testing::human_model();
  std::vector<std::string> summaries;
  for (const int threads : {1, 2}) {
    ExperimentParameters settings = small_settings(threads);
    settings.learning.iterations = 120;
    settings.training_walls = 3;
    const ExperimentResult result = run_paper_experiment(model, settings);
    const ExperimentAnalysis analysis = analyse_experiment(result, settings);
    summaries.push_back(summary_json(result, &analysis, settings, {}).dump(1) +
                        q_table_bytes(result.conditions[0].runs[1].q_grid, "threads.bin"));
  }
  EXPECT_EQ(summaries[0], summaries[1]);
}

TEST(PaperExperiment, TheReachAgentSpaceGivesTheSameBytesWithOneOrTwoThreads) {
  const BodyModel& model = testing::human_model();
  std::vector<std::string> outputs;
  for (const int threads : {1, 2}) {
    ExperimentParameters settings = small_settings(threads);
    settings.learning.iterations = 200;
    GridParameters& grid = settings.learning.climbing.grid;
    grid.space = AgentSpaceKind::Reach;
    grid.columns = 8;
    grid.rows = 4;
    grid.tile_height = 0.3;
    const ExperimentResult result = run_paper_experiment(model, settings);
    const ExperimentAnalysis analysis = analyse_experiment(result, settings);
    outputs.push_back(summary_json(result, &analysis, settings, {}).dump(1) +
                      q_table_bytes(result.conditions[0].runs[1].q_grid, "reach_threads.bin"));
    EXPECT_EQ(result.conditions[0].runs[1].q_grid.action_count(), 32);
    EXPECT_GT(result.conditions[0].runs[1].q_grid.state_count(), 0u);
  }
  EXPECT_EQ(outputs[0], outputs[1]);
}

}  // namespace
}  // namespace crux
