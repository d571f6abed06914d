#include "outputs/summary.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"

namespace crux {
namespace {

ExperimentParameters small_settings() {
  ExperimentParameters settings;
  settings.wall_pairs = 2;
  settings.learning.iterations = 400;
  settings.seed = 77;
  settings.threads = 2;
  settings.plan = false;
  return settings;
}

// A hand-made run: 6 iterations in two episodes (3 and 3), one w-greedy success.
RunResult hand_made_summary_run() {
  RunResult run;
  for (int i = 0; i < 6; ++i) {
    IterationRecord r;
    r.episode = i / 3;
    r.regime = i == 2 ? Regime::WGreedy : Regime::Random;
    r.success = i == 2;
    r.root_rise_m = i == 2 ? 0.1 : 0.0;
    run.iterations.push_back(r);
  }
  run.episode_lengths = {3, 3};
  run.q_grid = QTable(GridParameters{}.tile_count());
  return run;
}

TEST(Summary, ExperimentHasTheDocumentedKeys) {
  const BodyModel& model = testing::human_model();
  const ExperimentParameters settings = small_settings();
  const ExperimentResult result = run_paper_experiment(model, settings);
  const ExperimentAnalysis analysis = analyse_experiment(result, settings);
  const auto summary = summary_json(result, &analysis, settings, {});
  EXPECT_EQ(summary["kind"], "experiment");
  EXPECT_EQ(summary["wall_pairs"], 2);
  EXPECT_EQ(summary["walls"].size(), 4u) << "training and transfer walls";
  for (const char* condition : {"training", "transfer", "control"}) {
    for (const char* window : {"beginning", "overall"}) {
      for (const char* regime : {"w_greedy", "g_greedy", "random"}) {
        const auto& cell = summary["table1"][condition][window][regime];
        EXPECT_TRUE(cell.contains("actions") && cell.contains("success_rate") && cell.contains("vertical_cm"));
      }
    }
    EXPECT_EQ(summary["episode_lengths"][condition].size(), 2u);
    EXPECT_TRUE(summary["take_off"][condition].contains("share"));
  }
  for (const char* metric : {"early_episodes", "jumpstart", "time_to_threshold", "total_reward", "last_10_length"}) {
    const auto& entry = summary["transfer_vs_control"][metric];
    EXPECT_EQ(entry["transfer_minus_control"]["walls"], 2) << metric;
    EXPECT_TRUE(entry.contains("paired_correlation")) << metric;
    EXPECT_EQ(entry["transfer_minus_control"]["ci95_cluster_bootstrap"].size(), 2u) << metric;
    for (const char* side : {"transfer", "control", "difference"}) {
      for (const char* field : {"value", "low", "high"}) EXPECT_TRUE(entry["iqm"][side].contains(field)) << metric;
    }
    // One seed per wall: the stratified bootstrap has nothing to resample, and says so.
    EXPECT_TRUE(entry["probability_of_improvement"]["low"].is_null()) << metric;
    EXPECT_TRUE(entry["iqm"]["difference"]["high"].is_null()) << metric;
    EXPECT_EQ(entry["stratified_intervals"],
              "none: one seed per wall leaves the stratified bootstrap nothing to resample")
        << metric;
  }
  // The metrics of earlier versions keep their places; the extra thresholds follow.
  std::vector<std::string> metrics;
  for (const auto& item : summary["transfer_vs_control"].items()) metrics.push_back(item.key());
  ASSERT_GE(metrics.size(), 3u);
  EXPECT_EQ(std::vector<std::string>(metrics.end() - 3, metrics.end()),
            (std::vector<std::string>{"time_to_threshold_half", "time_to_threshold_2x", "time_to_threshold_4x"}));
  EXPECT_EQ(metrics[0], "early_episodes");
  EXPECT_EQ(summary["transfer_control_divergence"]["first_divergence"].size(), 2u);
}

TEST(Summary, ARunHasTheExperimentsShapeForItsOneCondition) {
  ExperimentParameters settings;
  settings.analysis.beginning = 3;
  Provenance provenance;
  provenance.wall_seed = 5;
  const ExperimentResult run =
      single_run_result(hand_made_summary_run(), generate_random_wall(5), 5, 11, Condition::Transfer);
  const auto summary = summary_json(run, nullptr, settings, provenance);
  EXPECT_EQ(summary["kind"], "run");
  EXPECT_EQ(summary["runs_per_condition"], 1);
  EXPECT_FALSE(summary.contains("seconds")) << "the same run gives the same bytes";
  EXPECT_FALSE(summary.contains("transfer_vs_control"));
  EXPECT_EQ(summary["table1"].size(), 1u);
  // Hand-computed: the beginning (3 iterations) holds the one w-greedy success of 10 cm.
  const auto& w = summary["table1"]["transfer"]["beginning"]["w_greedy"];
  EXPECT_EQ(w["actions"], 1.0);
  EXPECT_EQ(w["success_rate"], 1.0);
  EXPECT_NEAR(w["vertical_cm"].get<double>(), 10.0, 1e-12);
  EXPECT_EQ(summary["table1"]["transfer"]["overall"]["random"]["actions"], 5.0);
  EXPECT_EQ(summary["episode_lengths"]["transfer"][0], nlohmann::ordered_json({3, 3}));
  EXPECT_EQ(summary["run_facts"]["transfer"][0]["learning_seed"], 11);
  EXPECT_EQ(summary["run_facts"]["transfer"][0]["wall_seed"], 5);
  EXPECT_EQ(summary["walls"][0]["seed"], 5);
  // Every key of a run's summary is a key of an experiment's, in the same order.
  const auto keys = [](const nlohmann::ordered_json& j) {
    std::vector<std::string> names;
    for (const auto& item : j.items()) names.push_back(item.key());
    return names;
  };
  EXPECT_EQ(keys(summary),
            (std::vector<std::string>{"format", "version", "kind", "provenance", "seed", "wall_pairs", "seeds_per_wall",
                                      "runs_per_condition", "iterations", "beginning_iterations", "threshold_length",
                                      "solver", "table1", "episode_lengths", "run_facts", "qgrid_maps", "walls"}));
}

TEST(Summary, AWallFromAFileHasNoSeed) {
  Provenance provenance;
  provenance.wall_file = "/walls/w.json";
  const ExperimentResult run =
      single_run_result(hand_made_summary_run(), generate_random_wall(5), std::nullopt, 11, Condition::Training);
  const auto summary = summary_json(run, nullptr, ExperimentParameters{}, provenance);
  EXPECT_TRUE(summary["walls"][0]["seed"].is_null());
  EXPECT_TRUE(summary["run_facts"]["training"][0]["wall_seed"].is_null());
}

}  // namespace
}  // namespace crux
