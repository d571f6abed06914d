#pragma once
// The analysis of a paper experiment that summary.json and the printed report share:
// the transfer metrics with their clustered statistics (transfer_comparison.hpp), the
// take-off of each condition, and where paired transfer and control runs part ways.

#include <array>
#include <vector>

#include "experiments/transfer_comparison.hpp"
#include "experiments/transfer_diagnosis.hpp"

namespace crux {

// The seed of the cluster bootstrap: its own named stream of the experiment seed.
std::uint64_t bootstrap_seed(const ExperimentParameters& parameters);
// The stratified bootstrap's stream (rliable's intervals): another named stream of it.
RandomStream stratified_bootstrap_stream(const ExperimentParameters& parameters);

// The windows of the transfer metrics under `parameters`.
MetricWindows metric_windows(const ExperimentParameters& parameters);

// What summary.json reports of the transfer metrics, take-off and paired divergence,
// computed once for the file and the printed report.
struct ExperimentAnalysis {
  std::vector<MetricComparison> metrics;
  struct TakeOff {
    std::vector<int> iterations;  // per run; -1: did not take off
    int runs = 0, taken_off = 0;
    double median_iteration = -1.0;  // over the runs that took off; -1 if none
  };
  std::array<TakeOff, 3> take_off;                           // per condition
  std::vector<int> first_divergence;                         // per transfer/control pair; -1: never
  double median_first_divergence = 0.0;                      // "never" counted as the run's length + 1
  std::array<ChoiceProfile, kRegimeCount> transfer_choices;  // transfer's beginning, per regime
};
ExperimentAnalysis analyse_experiment(const ExperimentResult& result, const ExperimentParameters& parameters);

}  // namespace crux
