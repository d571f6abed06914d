#pragma once
// The paper's central claim in numbers: does transfer shorten the early episodes against
// control (same walls, same seeds), and is long-run performance unchanged? Each metric
// is computed per run. Runs on one wall pair are not independent, so conditions are
// summarised over walls (the mean of each wall's runs), and transfer minus control is
// the clustered paired difference: per-wall mean differences, a t-interval over walls,
// and a cluster bootstrap that resamples walls. The metrics follow Taylor and Stone
// (JMLR 2009, section 2.1): jumpstart, time to threshold, total reward, asymptotic
// performance, beside the episode counts of earlier versions.

#include <string>
#include <vector>

#include "experiments/paper_experiment.hpp"
#include "experiments/statistics.hpp"
#include "experiments/stratified_bootstrap.hpp"

namespace crux {

// What the metrics measure against: the run's length, the early (and late) window, and
// the episode length that counts as climbing well (time to threshold, take-off).
struct MetricWindows {
  int iterations = 8000;
  int window = 2000;
  int threshold_length = 60;
};

struct EpisodeMetric {
  std::string name;
  std::string description;
  bool higher_is_better = false;
  double (*of_run)(const RunResult& run, const MetricWindows& windows);
};

// The metrics that fit a run of this length (the late window is left out when it would
// overlap the early one).
std::vector<EpisodeMetric> episode_metrics(const MetricWindows& windows);

struct MetricComparison {
  EpisodeMetric metric;
  std::array<MeanInterval, 3> per_condition;  // over walls: training, transfer, control
  ClusteredDifference transfer_minus_control;
  // The difference relative to control's mean; for total reward, Taylor and Stone's
  // total-reward ratio. NaN when control's mean is 0.
  double relative_difference = 0.0;
  double paired_correlation = 0.0;  // Pearson r of transfer and control runs, pair by pair
  double wall_correlation = 0.0;    // ... of their means per wall, the unit of inference
  int walls_for_power = -1;         // walls for 80 % power at the effect seen (-1: none)
  // rliable's view beside the t-interval: the IQMs of transfer's runs, of control's and
  // of the pair differences, and P(transfer beats control), with stratified bootstrap
  // intervals (strata: walls).
  StratifiedComparison stratified;
};

// `bootstrap_seed` keys the cluster bootstrap's resampling, `stratified_stream` the
// stratified bootstrap's.
std::vector<MetricComparison> compare_transfer(const ExperimentResult& result, const MetricWindows& windows,
                                               std::uint64_t bootstrap_seed, int bootstrap_resamples,
                                               const RandomStream& stratified_stream);

// Iterations until the end of the first `episodes` episodes, or the run's length when
// it completes fewer (a lower bound): comparable across runs that finish few episodes.
double iterations_to_complete(const RunResult& run, std::size_t episodes, int iterations);

// The iteration (1-based) at which a run "takes off": the end of its first episode of at
// most `threshold_length` iterations of which at least half were w-greedy, i.e. a short
// climb the agent made mostly from its own problem-space knowledge. -1 if none.
int take_off_iteration(const RunResult& run, int threshold_length);

// The first iteration (1-based) at which two runs try a different hold or get a
// different verdict; -1 if they agree throughout their common length.
int first_divergence(const RunResult& a, const RunResult& b);

}  // namespace crux
