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

// A per-run measure of episode lengths; `window` is the early (and late) window in
// iterations, `iterations` the run's length.
struct EpisodeMetric {
  std::string name;
  std::string description;
  double (*of_run)(const RunResult& run, int iterations, int window);
};

// The metrics that fit a run of `iterations` with this window (the late window is left
// out when it would overlap the early one).
std::vector<EpisodeMetric> episode_metrics(int iterations, int window);

struct MetricComparison {
  EpisodeMetric metric;
  std::array<MeanInterval, 3> per_condition;  // training, transfer, control
  PairedTest transfer_minus_control;
};

std::vector<MetricComparison> compare_transfer(const ExperimentResult& result, int iterations, int window);

// Iterations until the end of the first `episodes` episodes, or the run's length when
// it completes fewer (a lower bound): comparable across runs that finish few episodes.
double iterations_to_complete(const RunResult& run, std::size_t episodes, int iterations);

}  // namespace crux
