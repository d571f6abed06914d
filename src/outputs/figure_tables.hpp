#pragma once
// The data of the paper's figures as CSV, for any plotting tool: Fig. 2b (Q_grid summed
// per tile and free limb), Fig. 3 (cumulative actions per regime) and Fig. 4 (episode
// lengths).

#include <array>
#include <string>
#include <vector>

#include "agent_space/moving_grid.hpp"
#include "experiments/paper_experiment.hpp"

namespace crux {

// Fig. 2b: sum over agent-space states with each free limb of Q_grid(s, tile),
// [tile][limb].
std::vector<std::array<double, kLimbCount>> q_grid_maps(const QTable& q_grid, const GridParameters& grid);

// The mean of q_grid_maps over a condition's runs.
std::vector<std::array<double, kLimbCount>> mean_q_grid_maps(const ConditionResult& condition,
                                                             const GridParameters& grid);

std::string fig2b_csv(const ExperimentResult& result, const GridParameters& grid);
std::string fig3_csv(const ExperimentResult& result, int iterations);
std::string fig4_csv(const ExperimentResult& result);

}  // namespace crux
