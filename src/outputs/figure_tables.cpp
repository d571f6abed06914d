#include "outputs/figure_tables.hpp"

#include <fmt/format.h>

#include "agent_space/agent_descriptor.hpp"

namespace crux {

std::vector<std::array<double, kLimbCount>> q_grid_maps(const QTable& q_grid, const GridParameters& grid) {
  std::vector<std::array<double, kLimbCount>> maps(grid.tile_count(), std::array<double, kLimbCount>{});
  q_grid.for_each_row([&](StateCode s, std::span<const double> values, std::span<const std::uint32_t>) {
    const int limb = static_cast<int>(decode_agent_state(static_cast<std::uint32_t>(s), grid).free_limb);
    for (int tile = 0; tile < grid.tile_count(); ++tile) maps[tile][limb] += values[tile];
  });
  return maps;
}

std::vector<std::array<double, kLimbCount>> mean_q_grid_maps(const ConditionResult& condition,
                                                             const GridParameters& grid) {
  std::vector<std::array<double, kLimbCount>> mean(grid.tile_count(), std::array<double, kLimbCount>{});
  for (const RunResult& run : condition.runs) {
    const auto map = q_grid_maps(run.q_grid, grid);
    for (std::size_t t = 0; t < map.size(); ++t) {
      for (int l = 0; l < kLimbCount; ++l) mean[t][l] += map[t][l] / static_cast<double>(condition.runs.size());
    }
  }
  return mean;
}

std::string fig2b_csv(const ExperimentResult& result, const GridParameters& grid) {
  std::string csv = "condition,free_limb,tile,column,row,value\n";
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    if (c.runs.empty()) continue;
    const auto maps = mean_q_grid_maps(c, grid);
    for (int l = 0; l < kLimbCount; ++l) {
      for (int t = 0; t < grid.tile_count(); ++t) {
        csv += fmt::format("{},{},{},{},{},{}\n", enum_name(condition), enum_name(static_cast<Limb>(l)), t,
                           t % grid.columns, t / grid.columns, maps[t][l]);
      }
    }
  }
  return csv;
}

std::string fig3_csv(const ExperimentResult& result, int iterations) {
  std::string csv = "condition,iteration,w_greedy,g_greedy,random\n";
  for (const Condition condition : kConditions) {
    const auto& runs = result.conditions[static_cast<int>(condition)].runs;
    if (runs.empty()) continue;
    std::vector<std::array<double, kRegimeCount>> cumulative(iterations, std::array<double, kRegimeCount>{});
    for (const RunResult& run : runs) {
      std::array<double, kRegimeCount> count{};
      for (int i = 0; i < iterations && i < static_cast<int>(run.iterations.size()); ++i) {
        count[static_cast<int>(run.iterations[i].regime)] += 1.0;
        for (int r = 0; r < kRegimeCount; ++r) cumulative[i][r] += count[r] / static_cast<double>(runs.size());
      }
    }
    for (int i = 0; i < iterations; ++i) {
      csv += fmt::format("{},{},{},{},{}\n", enum_name(condition), i + 1, cumulative[i][0], cumulative[i][1],
                         cumulative[i][2]);
    }
  }
  return csv;
}

std::string fig4_csv(const ExperimentResult& result) {
  std::string csv = "condition,run,episode,length\n";
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    for (std::size_t i = 0; i < c.runs.size(); ++i) {
      for (std::size_t e = 0; e < c.runs[i].episode_lengths.size(); ++e) {
        csv += fmt::format("{},{},{},{}\n", enum_name(condition), i, e, c.runs[i].episode_lengths[e]);
      }
    }
  }
  return csv;
}

}  // namespace crux
