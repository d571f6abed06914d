#pragma once
// The paper's central claim in numbers: does transfer shorten the early episodes
// against control (same walls, same seeds), and is long-run performance unchanged?
// Each metric is computed per run, then summarised per condition with a 95 %
// confidence interval and compared by a paired t-test.

#include <string>
#include <vector>

#include "experiments/paper_experiment.hpp"
#include "experiments/statistics.hpp"

namespace crux {

struct EpisodeMetric {
  std::string name;
  std::string description;
  double (*of_run)(const RunResult& run, int iterations);
  bool higher_is_better;
};

const std::vector<EpisodeMetric>& episode_metrics();

struct MetricComparison {
  const EpisodeMetric* metric = nullptr;
  std::array<MeanInterval, 3> per_condition;  // training, transfer, control
  PairedTest transfer_minus_control;
};

std::vector<MetricComparison> compare_transfer(const ExperimentResult& result, int iterations);

}  // namespace crux
