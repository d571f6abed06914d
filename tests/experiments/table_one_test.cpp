#include "experiments/table_one.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace crux {
namespace {

constexpr Regime W = Regime::WGreedy, G = Regime::GGreedy, R = Regime::Random;

// One action of a run. A failed action is given a rise it never made (0.5 m) so that a
// test fails if failures leak into the vertical displacement.
IterationRecord action(Regime regime, bool success, double rise_m = 0.0) {
  return IterationRecord{0, regime, 1, success, success ? rise_m : 0.5, success ? -1.0 : -1000.0};
}

RunResult run_with(std::vector<IterationRecord> iterations) {
  RunResult run;
  run.iterations = std::move(iterations);
  return run;
}

// Two runs of 6 and 4 actions:
//   run A: w ok 0.10, r fail, g ok 0.02 | r ok 0.04, w ok 0.06, r fail
//   run B: r ok 0.02, r fail, g fail    | w ok 0.12
// where "|" marks the end of a 3-iteration beginning window.
std::vector<RunResult> two_runs() {
  return {run_with({action(W, true, 0.10), action(R, false), action(G, true, 0.02), action(R, true, 0.04),
                    action(W, true, 0.06), action(R, false)}),
          run_with({action(R, true, 0.02), action(R, false), action(G, false), action(W, true, 0.12)})};
}

struct ExpectedStats {
  std::uint64_t actions, successes;
  double actions_per_run, success_rate, vertical_cm;
};

void expect_stats(const RegimeStats& got, const ExpectedStats& want, const char* regime) {
  EXPECT_EQ(got.actions, want.actions) << regime;
  EXPECT_EQ(got.successes, want.successes) << regime;
  EXPECT_DOUBLE_EQ(got.actions_per_run, want.actions_per_run) << regime;
  EXPECT_DOUBLE_EQ(got.success_rate, want.success_rate) << regime;
  EXPECT_NEAR(got.vertical_cm, want.vertical_cm, 1e-12) << regime;
}

TEST(TableOne, WholeRunsByHand) {
  const std::vector<RunResult> runs = two_runs();
  // w-greedy: A 2, B 1 actions, all successful, rises 10 + 6 + 12 cm.
  expect_stats(regime_stats(runs, W, -1), {3, 3, 1.5, 1.0, 28.0 / 3.0}, "w-greedy");
  // g-greedy: one each, A's successful (2 cm).
  expect_stats(regime_stats(runs, G, -1), {2, 1, 1.0, 0.5, 2.0}, "g-greedy");
  // random: A 1 of 3, B 1 of 2 successful. Pooled 2 / 5 = 0.4, not the mean of the
  // runs' rates (1/3 + 1/2) / 2 = 5/12; the rises 4 and 2 cm average to 3 cm.
  expect_stats(regime_stats(runs, R, -1), {5, 2, 2.5, 0.4, 3.0}, "random");
}

TEST(TableOne, TheBeginningWindowCountsTheFirstIterationsOfEachRun) {
  const std::vector<RunResult> runs = two_runs();
  // First 3 of each: A: w ok 10 cm, r fail, g ok 2 cm; B: r ok 2 cm, r fail, g fail.
  const RegimeStats w = regime_stats(runs, W, 3);
  EXPECT_EQ(w.actions, 1u);
  EXPECT_DOUBLE_EQ(w.actions_per_run, 0.5) << "B's w-greedy action comes at iteration 4";
  EXPECT_DOUBLE_EQ(w.success_rate, 1.0);
  EXPECT_NEAR(w.vertical_cm, 10.0, 1e-12);
  const RegimeStats g = regime_stats(runs, G, 3);
  EXPECT_EQ(g.actions, 2u);
  EXPECT_DOUBLE_EQ(g.success_rate, 0.5);
  EXPECT_NEAR(g.vertical_cm, 2.0, 1e-12);
  const RegimeStats r = regime_stats(runs, R, 3);
  EXPECT_EQ(r.actions, 3u);
  EXPECT_EQ(r.successes, 1u);
  EXPECT_DOUBLE_EQ(r.actions_per_run, 1.5);
  EXPECT_DOUBLE_EQ(r.success_rate, 1.0 / 3.0);
  EXPECT_NEAR(r.vertical_cm, 2.0, 1e-12);
}

TEST(TableOne, AWindowLongerThanARunTakesTheWholeRun) {
  const std::vector<RunResult> runs = two_runs();
  // 5 iterations: all of B's 4, A's first 5 (A's last, random, failed action is left out).
  const RegimeStats r5 = regime_stats(runs, R, 5);
  EXPECT_EQ(r5.actions, 4u);
  EXPECT_EQ(r5.successes, 2u);
  EXPECT_DOUBLE_EQ(r5.success_rate, 0.5);
  EXPECT_EQ(regime_stats(runs, W, 5).actions, 3u) << "B's w-greedy action at iteration 4 is in";
  for (const Regime regime : {W, G, R}) {
    const RegimeStats all = regime_stats(runs, regime, -1);
    const RegimeStats longer = regime_stats(runs, regime, 1000);
    EXPECT_EQ(longer.actions, all.actions);
    EXPECT_EQ(longer.successes, all.successes);
    EXPECT_EQ(longer.vertical_cm, all.vertical_cm);
  }
}

TEST(TableOne, NothingToCountGivesZeros) {
  const std::vector<RunResult> runs = two_runs();
  const RegimeStats none = regime_stats(runs, W, 0);
  EXPECT_EQ(none.actions, 0u);
  EXPECT_EQ(none.actions_per_run, 0.0);
  EXPECT_EQ(none.success_rate, 0.0) << "no division by zero actions";
  EXPECT_EQ(none.vertical_cm, 0.0);
  const RegimeStats no_runs = regime_stats(std::span<const RunResult>(), R, -1);
  EXPECT_EQ(no_runs.actions, 0u);
  EXPECT_EQ(no_runs.actions_per_run, 0.0);
  // Failures only: a rate of 0 and no displacement, whatever the failures' rise.
  const std::vector<RunResult> failures{run_with({action(G, false), action(G, false)})};
  const RegimeStats failed = regime_stats(failures, G, -1);
  EXPECT_EQ(failed.actions, 2u);
  EXPECT_EQ(failed.success_rate, 0.0);
  EXPECT_EQ(failed.vertical_cm, 0.0);
}

TEST(TableOne, ARunWithoutARegimeStillCountsInItsMeanPerRun) {
  // Three runs, only the first with g-greedy actions: 3 actions over 3 runs is 1 per run.
  const std::vector<RunResult> runs{run_with({action(G, true, 0.01), action(G, true, 0.03), action(G, false)}),
                                    run_with({action(R, false)}), run_with({})};
  const RegimeStats g = regime_stats(runs, G, -1);
  EXPECT_DOUBLE_EQ(g.actions_per_run, 1.0);
  EXPECT_DOUBLE_EQ(g.success_rate, 2.0 / 3.0);
  EXPECT_NEAR(g.vertical_cm, 2.0, 1e-12);
}

TEST(TableOne, TableHoldsBothWindowsForEveryRegime) {
  const std::vector<RunResult> runs = two_runs();
  const auto table = table_one(runs, 3);
  const auto& beginning = table[static_cast<int>(Window::Beginning)];
  const auto& overall = table[static_cast<int>(Window::Overall)];
  // Numbers of the two tests above, in [window][regime] order w, g, r.
  EXPECT_DOUBLE_EQ(beginning[static_cast<int>(W)].actions_per_run, 0.5);
  EXPECT_DOUBLE_EQ(beginning[static_cast<int>(G)].success_rate, 0.5);
  EXPECT_DOUBLE_EQ(beginning[static_cast<int>(R)].success_rate, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(overall[static_cast<int>(W)].actions_per_run, 1.5);
  EXPECT_NEAR(overall[static_cast<int>(W)].vertical_cm, 28.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(overall[static_cast<int>(R)].success_rate, 0.4);
  EXPECT_NEAR(overall[static_cast<int>(R)].vertical_cm, 3.0, 1e-12);
  EXPECT_STREQ(enum_name(Window::Beginning), "beginning");
  EXPECT_STREQ(enum_name(Window::Overall), "overall");
}

}  // namespace
}  // namespace crux
