#pragma once
// What the paper's figures are drawn from, read back from a `crux paper` output folder:
// its config.toml's grid (run_config_file), its summary.json (summary_file) and each
// run's iterations.csv (iterations_file). The views draw it; sweeps build it for Fig. 4.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "agent_space/moving_grid.hpp"
#include "experiments/paper_experiment.hpp"
#include "learning/action_selection.hpp"

namespace crux {

struct PaperRunData {
  int wall_pair = 0;     // the run's cluster (run_facts' wall_pair)
  int plan_length = -1;  // the shortest climb on the run's wall; -1 when unknown
  std::vector<int> episode_lengths;
  std::vector<Regime> regimes;  // per iteration, from iterations.csv
};

struct PaperConditionData {
  Condition condition = Condition::Training;
  std::vector<PaperRunData> runs;
  // Per free limb (limb order), per tile (row * columns + column): the summed Q_grid.
  std::array<std::vector<double>, kLimbCount> q_grid_maps;
};

struct TransferMetricData {
  std::string name, description;
  bool higher_is_better = true;
  double control_mean = 0;
  double difference = 0;                                 // transfer - control, mean over walls
  std::optional<std::array<double, 2>> difference_ci95;  // ci95_t_over_walls; none when null
  double p_value = 1;
  int walls = 0;
};

struct PaperFigureData {
  GridParameters grid;  // config.toml's [grid]
  int iterations = 0;
  int seeds_per_wall = 1;
  std::vector<PaperConditionData> conditions;        // those present, in kConditions order
  std::vector<TransferMetricData> transfer_metrics;  // in summary.json's order
};

// Reads folder/config.toml, folder/summary.json and folder/runs/<condition>_<i>/
// iterations.csv, each by its own reader and rules. Throws InputError(file, problem) for
// a missing or unreadable file, or one those readers refuse, and for an iterations.csv
// whose number of rows is not summary.json's iterations.
PaperFigureData read_paper_figure_data(const std::filesystem::path& folder);

// A paper experiment's folder/summary.json into `data`: iterations, seeds_per_wall, the
// conditions present with their runs' facts and episode lengths and their Q_grid maps
// (one value per tile of data.grid, which must be set), and transfer_vs_control in the
// file's order. Leaves the runs' regimes (iterations.csv's) empty. InputError(file,
// problem) naming the key for a missing key or a value of the wrong type or range.
void read_paper_summary(const std::filesystem::path& folder, PaperFigureData& data);

}  // namespace crux
