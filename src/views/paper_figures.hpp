#pragma once
// The paper's figures drawn as standalone SVG files from a `crux paper` output folder:
// Fig. 2b (Q_grid maps per free limb), Fig. 3 (cumulative actions per selection regime),
// Fig. 4 (episode lengths), and a forest plot of transfer minus control per metric.
// Runs on one wall are not independent, so every mean is over walls (of each wall's
// mean over its runs) and every band a Student-t 95 % interval over walls.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
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

// Reads folder/summary.json, folder/config.toml and folder/runs/<condition>_<i>/
// iterations.csv. Throws InputError(file, problem) for a missing or unreadable file, a
// file that is not JSON or TOML, a missing key or a value of the wrong type or size, and
// an iterations.csv with a wrong header, a bad row or a number of rows other than
// summary.json's iterations.
PaperFigureData read_paper_figure_data(const std::filesystem::path& folder);

// A mean over walls per x, with its Student-t 95 % interval over walls; low and high are
// NaN where fewer than two walls give a value (no interval).
struct WallBandSeries {
  std::vector<double> x, mean, low, high;
  std::vector<int> walls;  // walls giving a value at each x
};

// Fig. 3: per regime (Regime order), the cumulative number of its actions at iteration
// 1, every `step`-th iteration and the last.
std::array<WallBandSeries, kRegimeCount> regime_series(const PaperConditionData& condition, int iterations, int step);

// Fig. 4: the length of episode x (from 1), over the runs that completed it.
WallBandSeries episode_length_series(const PaperConditionData& condition);

// Throws std::invalid_argument when a map does not hold one value per tile of the grid.
std::string fig2b_svg(const PaperFigureData& data);
std::string fig3_svg(const PaperFigureData& data);
// `title` replaces Fig. 4's (a sweep draws one per cell).
std::string fig4_svg(const PaperFigureData& data, std::string_view title = "Fig. 4: episode lengths");
std::string transfer_metrics_svg(const PaperFigureData& data);

// (file name, SVG) of fig2b_qgrid_maps.svg, fig3_regimes.svg, fig4_episode_lengths.svg
// and transfer_minus_control.svg, in that order.
std::vector<std::pair<std::string, std::string>> paper_figures(const PaperFigureData& data);

}  // namespace crux
