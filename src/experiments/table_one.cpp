#include "experiments/table_one.hpp"

#include <algorithm>

namespace crux {

RegimeStats regime_stats(std::span<const RunResult> runs, Regime regime, int iterations) {
  RegimeStats stats;
  double rise_m = 0.0;
  for (const RunResult& run : runs) {
    const std::size_t end =
        iterations < 0 ? run.iterations.size() : std::min(run.iterations.size(), static_cast<std::size_t>(iterations));
    for (std::size_t i = 0; i < end; ++i) {
      const IterationRecord& record = run.iterations[i];
      if (record.regime != regime) continue;
      ++stats.actions;
      if (record.success) {
        ++stats.successes;
        rise_m += record.root_rise_m;
      }
    }
  }
  if (!runs.empty()) stats.actions_per_run = static_cast<double>(stats.actions) / static_cast<double>(runs.size());
  if (stats.actions > 0) stats.success_rate = static_cast<double>(stats.successes) / static_cast<double>(stats.actions);
  if (stats.successes > 0) stats.vertical_cm = 100.0 * rise_m / static_cast<double>(stats.successes);
  return stats;
}

std::array<std::array<RegimeStats, kRegimeCount>, 2> table_one(std::span<const RunResult> runs, int beginning) {
  std::array<std::array<RegimeStats, kRegimeCount>, 2> table;
  for (int r = 0; r < kRegimeCount; ++r) {
    table[static_cast<int>(Window::Beginning)][r] = regime_stats(runs, static_cast<Regime>(r), beginning);
    table[static_cast<int>(Window::Overall)][r] = regime_stats(runs, static_cast<Regime>(r), -1);
  }
  return table;
}

}  // namespace crux
