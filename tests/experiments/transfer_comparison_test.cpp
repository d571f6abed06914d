#include "experiments/transfer_comparison.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

// A run from its episodes, each given as a string of regimes ('w', 'g', 'r'), then
// `tail` unfinished iterations of random actions. Rewards: -1 per action, +100 for each
// episode's last action.
RunResult run_of(const std::vector<std::string>& episodes, int tail = 0) {
  RunResult run;
  for (std::size_t e = 0; e < episodes.size(); ++e) {
    for (std::size_t i = 0; i < episodes[e].size(); ++i) {
      const Regime regime = episodes[e][i] == 'w'   ? Regime::WGreedy
                            : episodes[e][i] == 'g' ? Regime::GGreedy
                                                    : Regime::Random;
      const bool last = i + 1 == episodes[e].size();
      run.iterations.push_back({static_cast<int>(e), regime, static_cast<int>(i + 1), true, 0.0, last ? 100.0 : -1.0});
    }
    run.episode_lengths.push_back(static_cast<int>(episodes[e].size()));
  }
  for (int i = 0; i < tail; ++i)
    run.iterations.push_back({static_cast<int>(episodes.size()), Regime::Random, 1, false, 0.0, -1.0});
  return run;
}

double metric(const std::string& name, const RunResult& run, const MetricWindows& windows) {
  for (const EpisodeMetric& m : episode_metrics(windows)) {
    if (m.name == name) return m.of_run(run, windows);
  }
  ADD_FAILURE() << "no metric " << name;
  return 0.0;
}

TEST(TransferComparison, MetricsByHand) {
  // Episodes of 6, 3 and 4 actions, then 7 unfinished: 20 iterations.
  const RunResult run = run_of({"rrrrrr", "wwr", "wrrr"}, 7);
  const MetricWindows windows{20, 10, 4};
  EXPECT_EQ(metric("early_episodes", run, windows), 2) << "episodes ending at 6 and 9 lie in the first 10";
  EXPECT_EQ(metric("late_episodes", run, windows), 1) << "the one ending at 13 lies in the last 10";
  EXPECT_EQ(metric("jumpstart", run, windows), 6);
  EXPECT_EQ(metric("time_to_threshold", run, windows), 9) << "the first episode of at most 4 ends at 9";
  EXPECT_EQ(metric("first_5_iterations", run, windows), 20) << "fewer than 5 episodes: the run's length";
  // 13 actions inside episodes, 3 of them finishing: 3 x 100 - 10; 7 more at -1.
  EXPECT_EQ(metric("total_reward", run, windows), 300 - 10 - 7);
  EXPECT_DOUBLE_EQ(metric("last_10_length", run, windows), 13.0 / 3.0);
  const RunResult none = run_of({}, 20);
  EXPECT_EQ(metric("jumpstart", none, windows), 20);
  EXPECT_EQ(metric("time_to_threshold", none, windows), 20);
  EXPECT_EQ(metric("last_10_length", none, windows), 20);
}

TEST(TransferComparison, TimeToThresholdAtHalfTwiceAndFourTimesTheLength) {
  // Episodes of 21, 11, 7, 3 and 2 actions, ending at 21, 32, 39, 42 and 44;
  // threshold_length 5 gives thresholds 2 (half, rounded down), 5, 10 and 20.
  const RunResult run = run_of({std::string(21, 'r'), std::string(11, 'r'), "rrrrrrr", "rrr", "rr"}, 6);
  const MetricWindows windows{50, 10, 5};
  EXPECT_EQ(metric("time_to_threshold_half", run, windows), 44) << "the episode of 2";
  EXPECT_EQ(metric("time_to_threshold", run, windows), 42) << "the episode of 3";
  EXPECT_EQ(metric("time_to_threshold_2x", run, windows), 39) << "the episode of 7";
  EXPECT_EQ(metric("time_to_threshold_4x", run, windows), 32) << "the episode of 11";
  // Never that short: the run's length, as for the single threshold.
  EXPECT_EQ(metric("time_to_threshold_half", run_of({"rrrr"}, 46), windows), 50);
}

TEST(TransferComparison, TheThresholdMultiplesFollowTheMetricsOfEarlierVersions) {
  std::vector<std::string> names;
  for (const EpisodeMetric& m : episode_metrics({8000, 2000, 61})) names.push_back(m.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"early_episodes", "jumpstart", "time_to_threshold", "first_5_iterations",
                                      "total_reward", "late_episodes", "last_10_length", "time_to_threshold_half",
                                      "time_to_threshold_2x", "time_to_threshold_4x"}));
  EXPECT_NE(episode_metrics({8000, 2000, 61})[7].description.find("at most 30 "), std::string::npos);
}

TEST(TransferComparison, TakeOffNeedsAShortEpisodeMostlyWGreedy) {
  // Episode 2 is short but one w-greedy action in three; episode 3 has two of four.
  const RunResult run = run_of({"rrrrrr", "wgr", "wwrg", "w"});
  EXPECT_EQ(take_off_iteration(run, 4), 13);
  EXPECT_EQ(take_off_iteration(run, 3), 14) << "episode 3 is too long; the single w-greedy action of episode 4";
  EXPECT_EQ(take_off_iteration(run_of({"rrrrrr", "gggg"}), 10), -1);
}

TEST(TransferComparison, FirstDivergenceIsTheFirstDifferentHoldOrVerdict) {
  RunResult a = run_of({"rrrrr"}), b = run_of({"rrrrr"});
  EXPECT_EQ(first_divergence(a, b), -1);
  b.iterations[3].success = false;
  EXPECT_EQ(first_divergence(a, b), 4);
  b.iterations[1].hold_id = 99;
  EXPECT_EQ(first_divergence(a, b), 2);
  b.iterations[0].regime = Regime::GGreedy;
  EXPECT_EQ(first_divergence(a, b), 2) << "the same hold by another regime is the same step";
}

}  // namespace
}  // namespace crux
