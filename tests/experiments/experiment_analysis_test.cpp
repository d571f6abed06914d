#include "experiments/experiment_analysis.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace crux {
namespace {

constexpr int kIterations = 8;

// A run from its episodes, each a string of regimes ('w', 'g', 'r'), padded with
// unfinished random iterations to kIterations. Hold ids count 1.. within an episode;
// episode actions succeed, the padding fails.
RunResult rising_run_of(const std::vector<std::string>& episodes) {
  RunResult run;
  for (std::size_t e = 0; e < episodes.size(); ++e) {
    for (std::size_t i = 0; i < episodes[e].size(); ++i) {
      const char c = episodes[e][i];
      const Regime regime = c == 'w' ? Regime::WGreedy : c == 'g' ? Regime::GGreedy : Regime::Random;
      const bool last = i + 1 == episodes[e].size();
      run.iterations.push_back({static_cast<int>(e), regime, static_cast<int>(i + 1), true, 0.01, last ? 100.0 : -1.0});
    }
    run.episode_lengths.push_back(static_cast<int>(episodes[e].size()));
  }
  while (run.iterations.size() < kIterations) {
    run.iterations.push_back({static_cast<int>(episodes.size()), Regime::Random, 1, false, 0.0, -1000.0});
  }
  return run;
}

ConditionResult condition_of(std::vector<RunResult> runs) {
  ConditionResult c;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    c.wall_of_run.push_back(r);
    c.cluster_of_run.push_back(r);  // one seed per wall pair
    c.learning_seeds.push_back(r + 1);
  }
  c.runs = std::move(runs);
  return c;
}

// Three wall pairs, one run each, of 8 iterations. With a threshold of 3 iterations,
// take-off (the end of the first episode of at most 3 that is at least half w-greedy):
//   training: t0 rrrrr|w -> 6, t1 nothing -> -1, t2 w -> 1
//   transfer: x0 wrr|w -> 4 (wrr is one w in three), x1 ww|rrr -> 2, x2 rrrr|ggg|w -> 8
//   control:  c0 wrr|g -> -1, c1 = x1 -> 2, c2 rrrr|gww|w -> 7
// Control pairs with transfer: c0 tries another hold at iteration 3, c1 never differs,
// c2 fails where x2 succeeded at iteration 6 (regimes alone are no divergence).
ExperimentResult small_experiment() {
  ExperimentResult result;
  result.conditions[static_cast<int>(Condition::Training)] =
      condition_of({rising_run_of({"rrrrr", "w"}), rising_run_of({}), rising_run_of({"w"})});
  result.conditions[static_cast<int>(Condition::Transfer)] =
      condition_of({rising_run_of({"wrr", "w"}), rising_run_of({"ww", "rrr"}), rising_run_of({"rrrr", "ggg", "w"})});
  std::vector<RunResult> control{rising_run_of({"wrr", "g"}), rising_run_of({"ww", "rrr"}),
                                 rising_run_of({"rrrr", "gww", "w"})};
  control[0].iterations[2].hold_id = 99;
  control[2].iterations[5].success = false;
  result.conditions[static_cast<int>(Condition::Control)] = condition_of(std::move(control));
  return result;
}

ExperimentParameters small_settings() {
  ExperimentParameters settings;
  settings.learning.iterations = kIterations;
  settings.analysis.beginning = 4;
  settings.analysis.threshold_length = 3;
  settings.analysis.bootstrap_resamples = 200;
  settings.wall_pairs = 3;
  settings.seed = 11;
  return settings;
}

const MetricComparison& metric(const ExperimentAnalysis& analysis, const std::string& name) {
  for (const MetricComparison& m : analysis.metrics) {
    if (m.metric.name == name) return m;
  }
  ADD_FAILURE() << "no metric " << name;
  static const MetricComparison none{};
  return none;
}

TEST(ExperimentAnalysis, TakeOffPerConditionByHand) {
  const ExperimentAnalysis analysis = analyse_experiment(small_experiment(), small_settings());
  const auto& training = analysis.take_off[static_cast<int>(Condition::Training)];
  EXPECT_EQ(training.iterations, (std::vector<int>{6, -1, 1}));
  EXPECT_EQ(training.runs, 3);
  EXPECT_EQ(training.taken_off, 2);
  EXPECT_DOUBLE_EQ(training.median_iteration, 3.5) << "the median of 1 and 6; the run that never took off is out";
  const auto& transfer = analysis.take_off[static_cast<int>(Condition::Transfer)];
  EXPECT_EQ(transfer.iterations, (std::vector<int>{4, 2, 8}));
  EXPECT_EQ(transfer.taken_off, 3);
  EXPECT_DOUBLE_EQ(transfer.median_iteration, 4.0);
  const auto& control = analysis.take_off[static_cast<int>(Condition::Control)];
  EXPECT_EQ(control.iterations, (std::vector<int>{-1, 2, 7}));
  EXPECT_EQ(control.taken_off, 2);
  EXPECT_DOUBLE_EQ(control.median_iteration, 4.5);
}

TEST(ExperimentAnalysis, NoTakeOffHasMedianMinusOne) {
  ExperimentResult result = small_experiment();
  for (ConditionResult& c : result.conditions) {
    for (RunResult& run : c.runs) run = rising_run_of({});
  }
  const ExperimentAnalysis analysis = analyse_experiment(result, small_settings());
  for (const auto& t : analysis.take_off) {
    EXPECT_EQ(t.runs, 3);
    EXPECT_EQ(t.taken_off, 0);
    EXPECT_EQ(t.median_iteration, -1.0);
  }
}

TEST(ExperimentAnalysis, FirstDivergenceCountsNeverAsTheRunsLengthPlusOne) {
  const ExperimentAnalysis analysis = analyse_experiment(small_experiment(), small_settings());
  EXPECT_EQ(analysis.first_divergence, (std::vector<int>{3, -1, 6}));
  // Median of 3, 6 and 8 + 1 = 9.
  EXPECT_DOUBLE_EQ(analysis.median_first_divergence, 6.0);

  // Identical pairs throughout: every pair counts as 9.
  ExperimentResult same = small_experiment();
  same.conditions[static_cast<int>(Condition::Control)].runs =
      same.conditions[static_cast<int>(Condition::Transfer)].runs;
  const ExperimentAnalysis never = analyse_experiment(same, small_settings());
  EXPECT_EQ(never.first_divergence, (std::vector<int>{-1, -1, -1}));
  EXPECT_DOUBLE_EQ(never.median_first_divergence, kIterations + 1.0);
}

TEST(ExperimentAnalysis, MetricsUseTheSettingsWindowsByHand) {
  const ExperimentAnalysis analysis = analyse_experiment(small_experiment(), small_settings());
  constexpr int training = static_cast<int>(Condition::Training), transfer = static_cast<int>(Condition::Transfer);
  // Jumpstart: a run without an episode counts the run's length (settings.learning).
  EXPECT_NEAR(metric(analysis, "jumpstart").per_condition[training].mean, (5.0 + 8.0 + 1.0) / 3.0, 1e-12);
  EXPECT_NEAR(metric(analysis, "jumpstart").per_condition[transfer].mean, (3.0 + 2.0 + 4.0) / 3.0, 1e-12);
  // Time to threshold (3 iterations): transfer's episodes of at most 3 end at 3, 2, 7.
  EXPECT_NEAR(metric(analysis, "time_to_threshold").per_condition[transfer].mean, 4.0, 1e-12);
  EXPECT_NEAR(metric(analysis, "time_to_threshold").per_condition[training].mean, (6.0 + 8.0 + 1.0) / 3.0, 1e-12);
  // Early episodes (the beginning window, 4): transfer's end at {3, 4}, {2}, {4}.
  EXPECT_NEAR(metric(analysis, "early_episodes").per_condition[transfer].mean, 4.0 / 3.0, 1e-12);
  // A window of 4 in 8 iterations leaves room for the late window.
  EXPECT_EQ(metric(analysis, "late_episodes").metric.name, "late_episodes");
}

TEST(ExperimentAnalysis, MetricsAreCompareTransferWithTheExperimentsBootstrapSeed) {
  ExperimentResult result = small_experiment();
  // Runs 0 and 1 on one wall, so that the stratified bootstrap has seeds to resample.
  for (ConditionResult& c : result.conditions) c.cluster_of_run = c.wall_of_run = {0, 0, 1};
  const ExperimentParameters settings = small_settings();
  const ExperimentAnalysis analysis = analyse_experiment(result, settings);
  const std::vector<MetricComparison> direct =
      compare_transfer(result, {kIterations, 4, 3}, bootstrap_seed(settings), settings.analysis.bootstrap_resamples,
                       stratified_bootstrap_stream(settings));
  ASSERT_EQ(analysis.metrics.size(), direct.size());
  for (std::size_t m = 0; m < direct.size(); ++m) {
    EXPECT_EQ(analysis.metrics[m].metric.name, direct[m].metric.name);
    const ClusteredDifference &a = analysis.metrics[m].transfer_minus_control, &d = direct[m].transfer_minus_control;
    EXPECT_EQ(a.mean, d.mean) << direct[m].metric.name;
    EXPECT_EQ(a.bootstrap_low, d.bootstrap_low) << direct[m].metric.name;
    EXPECT_EQ(a.bootstrap_high, d.bootstrap_high) << direct[m].metric.name;
    const StratifiedComparison &ra = analysis.metrics[m].stratified, &rd = direct[m].stratified;
    ASSERT_TRUE(ra.has_intervals) << direct[m].metric.name;
    EXPECT_EQ(ra.iqm_difference.low, rd.iqm_difference.low) << direct[m].metric.name;
    EXPECT_EQ(ra.probability_of_improvement.high, rd.probability_of_improvement.high) << direct[m].metric.name;
  }
}

TEST(ExperimentAnalysis, TransferChoicesProfileTransfersBeginningWindow) {
  const ExperimentAnalysis analysis = analyse_experiment(small_experiment(), small_settings());
  // First 4 iterations of the transfer runs: w r r w | w w r r | r r r r.
  EXPECT_EQ(analysis.transfer_choices[static_cast<int>(Regime::WGreedy)].actions, 4);
  EXPECT_EQ(analysis.transfer_choices[static_cast<int>(Regime::GGreedy)].actions, 0);
  EXPECT_EQ(analysis.transfer_choices[static_cast<int>(Regime::Random)].actions, 8);
  EXPECT_EQ(analysis.transfer_choices[static_cast<int>(Regime::Random)].successes, 8) << "all inside episodes";
  EXPECT_NEAR(analysis.transfer_choices[static_cast<int>(Regime::WGreedy)].mean_root_rise_cm, 1.0, 1e-12);
}

TEST(ExperimentAnalysis, BootstrapSeedIsAFunctionOfTheExperimentSeedOnly) {
  ExperimentParameters one, also_one, two;
  one.seed = also_one.seed = 1;
  two.seed = 2;
  also_one.wall_pairs = 20;
  also_one.analysis.bootstrap_resamples = 5;
  EXPECT_EQ(bootstrap_seed(one), bootstrap_seed(also_one));
  EXPECT_NE(bootstrap_seed(one), bootstrap_seed(two));
  EXPECT_NE(bootstrap_seed(one), one.seed) << "its own stream, not the experiment seed itself";
}

}  // namespace
}  // namespace crux
