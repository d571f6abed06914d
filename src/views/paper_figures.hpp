#pragma once
// The paper's figures drawn as standalone SVG files from a `crux paper` output folder:
// Fig. 2b (Q_grid maps per free limb), Fig. 3 (cumulative actions per selection regime),
// Fig. 4 (episode lengths), and a forest plot of transfer minus control per metric,
// drawn from what read_paper_figure_data (experiments/paper_figure_data) reads.
// Runs on one wall are not independent, so every mean is over walls (of each wall's
// mean over its runs) and every band a Student-t 95 % interval over walls.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "outputs/paper_figure_data.hpp"

namespace crux {

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
