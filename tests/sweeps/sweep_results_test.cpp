#include "sweeps/sweep_results.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "agent_space/moving_grid.hpp"
#include "common/input_error.hpp"
#include "experiments/experiment_analysis.hpp"
#include "experiments/statistics.hpp"
#include "learning/q_table_file.hpp"
#include "outputs/iterations_file.hpp"
#include "outputs/summary.hpp"
#include "outputs/sweep_files.hpp"
#include "support/sweep_cells.hpp"
#include "support/test_models.hpp"
#include "sweeps/sweep_run.hpp"
#include "sweeps/sweep_task.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;
using testing::small_sweep_config;
using testing::sweep_cell;

nlohmann::json as_json(const nlohmann::ordered_json& value) { return nlohmann::json::parse(value.dump()); }

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A sweep of `config` alone, on two threads, in a scratch folder named `name`.
SweepJob run_one_cell_sweep(const ExperimentConfig& config, const std::string& name) {
  SweepJob job;
  job.plan = plan_sweep({}, {sweep_cell(config)});
  job.folder = fs::absolute(testing::sweep_scratch(name));
  job.threads = 2;
  run_sweep(job, testing::human_model(), nullptr);
  return job;
}

// A cell read back from its run folders is analysed as crux paper analyses the same
// runs held in memory: the sweep adds no statistics of its own.
TEST(SweepResults, ACellsAnalysisIsCruxPapersOnTheSameRuns) {
  const ExperimentConfig config = small_sweep_config(3, 1500);
  const SweepJob job = run_one_cell_sweep(config, "paper");

  const ExperimentResult paper = run_paper_experiment(testing::human_model(), config.settings);
  const ExperimentAnalysis analysis = analyse_experiment(paper, config.settings);
  nlohmann::json cell = read_json(job.folder / "summary.json").at("cells").at(0);
  for (auto& [name, metric] : cell.at("transfer_vs_control").items()) {
    EXPECT_EQ(metric.at("transfer_minus_control").at("p_value_holm_over_cells"),
              metric.at("transfer_minus_control").at("p_value"))
        << "one cell: nothing to adjust";
    metric.at("transfer_minus_control").erase("p_value_holm_over_cells");
  }
  EXPECT_EQ(cell.at("transfer_vs_control"), as_json(transfer_vs_control_json(analysis)));
  EXPECT_EQ(cell.at("take_off"), as_json(take_off_json(analysis)));
  EXPECT_EQ(cell.at("transfer_control_divergence"), as_json(divergence_json(analysis)));

  const std::vector<std::string> rows = lines_of(job.folder / "results.csv");
  ASSERT_EQ(rows.size(), 1u + 9);
  EXPECT_EQ(rows[0].rfind("cell,condition,run,wall_pair,seed_index,wall_seed,learning_seed,", 0), 0u) << rows[0];
  // Row 4 is transfer run 0: its seeds are crux paper's.
  const ConditionResult& transfer = paper.conditions[static_cast<int>(Condition::Transfer)];
  EXPECT_EQ(rows[4].rfind(fmt::format("0,transfer,0,0,0,{},{},", paper.walls[3].seed, transfer.learning_seeds[0]), 0),
            0u)
      << rows[4];
  // Every fraction is the shortest text that reads back to it (std::to_chars' form):
  // 196.6, not the 17 digits 196.59999999999999.
  int fractions = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::istringstream row(rows[r]);
    for (std::string cell; std::getline(row, cell, ',');) {
      if (cell.find('.') == std::string::npos) continue;
      ++fractions;
      char shortest[32];
      const auto written = std::to_chars(shortest, shortest + sizeof shortest, std::stod(cell));
      EXPECT_EQ(cell, std::string(shortest, written.ptr)) << rows[r];
    }
  }
  EXPECT_GT(fractions, 0);
}

// A cell with K = 3 training walls of their own: each training task learns on its three
// walls in sequence as crux paper does, so every wall, run, Q_grid and the analysis are
// crux paper's, and the cell carries Taylor and Stone's total.
TEST(SweepResults, ACellOverThreeTrainingWallsIsCruxPapersExperiment) {
  const ExperimentConfig config =
      small_sweep_config(2, 1000, "[experiment]\ntraining_walls = 3\n[training_wall]\nsigma = 0.12\n");
  const SweepJob job = run_one_cell_sweep(config, "training-walls");

  const ExperimentResult paper = run_paper_experiment(testing::human_model(), config.settings);
  const ExperimentAnalysis analysis = analyse_experiment(paper, config.settings);
  nlohmann::json cell = read_json(job.folder / "summary.json").at("cells").at(0);
  for (auto& [name, metric] : cell.at("transfer_vs_control").items()) {
    metric.at("transfer_minus_control").erase("p_value_holm_over_cells");
  }
  EXPECT_EQ(cell.at("transfer_vs_control"), as_json(transfer_vs_control_json(analysis)));
  EXPECT_EQ(cell.at("take_off"), as_json(take_off_json(analysis)));
  EXPECT_EQ(cell.at("iterations_spent"),
            nlohmann::json::parse(
                R"({"training_walls": 3, "training": 3000, "transfer": 1000, "total": 4000, "control": 1000})"));
  const std::string grid = describe_grid(config.settings.learning.climbing.grid);
  for (const Condition condition : kConditions) {
    const ConditionResult& expected = paper.conditions[static_cast<int>(condition)];
    for (int r = 0; r < config.settings.runs(); ++r) {
      const fs::path run = job.folder / job.plan.tasks[run_task_index(job.plan, 0, condition, r)].folder;
      const std::vector<RunStep> steps = read_iterations_file(
          run / "iterations.csv", config.settings.learning.iterations, config.settings.learning.climbing.physics.model);
      ASSERT_EQ(steps.size(), expected.runs[r].iterations.size());
      for (std::size_t i = 0; i < steps.size(); ++i) {
        ASSERT_EQ(steps[i].hold_id, expected.runs[r].iterations[i].hold_id) << enum_name(condition) << r;
        ASSERT_EQ(steps[i].success, expected.runs[r].iterations[i].success) << enum_name(condition) << r;
      }
      const fs::path paper_q_grid = job.folder / fmt::format("paper_{}_{}.bin", enum_name(condition), r);
      save_q_table(paper_q_grid.string(), expected.runs[r].q_grid, grid);
      EXPECT_EQ(read_bytes(run / "q_grid.bin"), read_bytes(paper_q_grid)) << enum_name(condition) << r;
    }
  }
  // The walls are crux paper's, pair w's preceding wall j at w (K - 1) + j.
  const nlohmann::json facts = read_sweep_wall_facts(job.folder / "walls/g0/preceding_1_1");
  EXPECT_EQ(facts.at("seed"), paper.preceding_training_walls[3].seed);
  const fs::path paper_walls = job.folder / "paper_walls";
  fs::create_directories(paper_walls);
  save_wall((paper_walls / "training.json").string(), paper.walls[1].wall);
  save_wall((paper_walls / "preceding.json").string(), paper.preceding_training_walls[3].wall);
  EXPECT_EQ(read_bytes(job.folder / "walls/g0/training_1/wall.json"), read_bytes(paper_walls / "training.json"));
  EXPECT_EQ(read_bytes(job.folder / "walls/g0/preceding_1_1/wall.json"), read_bytes(paper_walls / "preceding.json"));
  const Wall trained_on = load_wall((job.folder / "runs/c0/training_1/wall.json").string());
  ASSERT_EQ(trained_on.holds.size(), paper.walls[1].wall.holds.size());
  for (std::size_t h = 0; h < trained_on.holds.size(); ++h) {
    EXPECT_EQ(trained_on.holds[h].position, paper.walls[1].wall.holds[h].position) << "hold " << h;
  }

  // Issue 39: a resume kept a damaged or missing preceding Q_grid and exited 0. The
  // results check it against the digest the run's config.toml recorded, as a replay would.
  const fs::path preceding =
      job.folder / preceding_q_grid_file(job.plan.tasks[run_task_index(job.plan, 0, Condition::Training, 1)]);
  const std::string kept = read_bytes(preceding);
  std::ofstream(preceding, std::ios::binary | std::ios::app) << 'x';
  try {
    write_sweep_results(job.plan, job.folder, job.provenance);
    ADD_FAILURE() << "a damaged preceding Q_grid was kept";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), preceding.string());
    EXPECT_NE(e.problem().find("is not the Q_grid that runs/c0/training_1 read"), std::string::npos) << e.problem();
  }
  fs::remove(preceding);
  EXPECT_THROW(write_sweep_results(job.plan, job.folder, job.provenance), InputError);
  std::ofstream(preceding, std::ios::binary) << kept;
  EXPECT_NO_THROW(write_sweep_results(job.plan, job.folder, job.provenance));
}

TEST(SweepResults, PValuesAreHolmAdjustedOverTheCells) {
  std::vector<SweepCell> cells;
  for (const char* epsilon : {"0.05", "0.3", "0.6"}) {
    cells.push_back(
        sweep_cell(small_sweep_config(2, 800, fmt::format("[learning]\nepsilon = {}\n", epsilon)), {epsilon}));
  }
  SweepJob job;
  job.plan = plan_sweep({"learning.epsilon"}, std::move(cells));
  job.folder = fs::absolute(testing::sweep_scratch("holm"));
  job.threads = 2;
  run_sweep(job, testing::human_model(), nullptr);
  const nlohmann::json summary = read_json(job.folder / "summary.json");
  EXPECT_EQ(summary.at("listed_keys"), nlohmann::json::array({"learning.epsilon"}));
  ASSERT_EQ(summary.at("cells").size(), 3u);
  EXPECT_EQ(summary.at("cells").at(1).at("parameters").at("learning.epsilon"), "0.3");
  for (const auto& [name, unused] : summary.at("cells").at(0).at("transfer_vs_control").items()) {
    std::vector<double> p, holm;
    for (const auto& cell : summary.at("cells")) {
      const auto& d = cell.at("transfer_vs_control").at(name).at("transfer_minus_control");
      p.push_back(d.at("p_value").get<double>());
      holm.push_back(d.at("p_value_holm_over_cells").get<double>());
    }
    EXPECT_EQ(holm, holm_adjusted(p)) << name;
  }
  // The extra thresholds are families of their own, and every metric has rliable's view.
  const auto& first = summary.at("cells").at(0).at("transfer_vs_control");
  EXPECT_TRUE(first.at("time_to_threshold_4x").at("transfer_minus_control").contains("p_value_holm_over_cells"));
  EXPECT_TRUE(first.at("first_5_iterations").at("probability_of_improvement").contains("low"));
  const std::vector<std::string> rows = lines_of(job.folder / "results.csv");
  ASSERT_EQ(rows.size(), 1u + 3 * 6);
  EXPECT_EQ(rows[0].rfind("cell,learning.epsilon,condition,", 0), 0u);
  EXPECT_EQ(rows[7].rfind("1,0.3,training,0,", 0), 0u) << rows[7];
}

}  // namespace
}  // namespace crux
