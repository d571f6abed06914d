#include "reports/text_report.hpp"

#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "common/counted.hpp"
#include "common/printable.hpp"
#include "reports/paper_reference.hpp"
#include "reports/table_one_text.hpp"

namespace crux {

namespace {

std::string episode_text(const ExperimentResult& result, const ExperimentParameters& parameters) {
  const int total = parameters.runs();
  std::string text = "\nEpisode lengths (mean over runs):\n";
  for (const Condition c : kConditions) {
    const auto& cr = result.conditions[static_cast<int>(c)];
    double episodes = 0, greedy = 0;
    int greedy_ok = 0;
    for (const RunResult& r : cr.runs) {
      episodes += static_cast<double>(r.episode_lengths.size()) / total;
      if (r.greedy_length > 0) greedy += r.greedy_length, ++greedy_ok;
    }
    text += fmt::format("  {:<9} {:6.1f} episodes per run; greedy climb finishes in {} of {}{}\n", enum_name(c),
                        episodes, greedy_ok, counted(total, "run"),
                        greedy_ok ? fmt::format(", in {:.1f} actions on average", greedy / greedy_ok) : "");
  }
  if (parameters.plan) {
    double plan = 0;
    int found = 0;
    int stopped = 0;
    for (const ExperimentWall& w : result.walls) {
      if (w.plan.found) plan += w.plan.length, ++found;
      if (w.plan.stopped_at_limit) ++stopped;
    }
    text += fmt::format("  exact shortest climb: {} ({} of {}; the paper: about {})\n",
                        found ? fmt::format("{:.1f} actions on average", plan / found) : std::string("none found"),
                        found, counted(result.walls.size(), "wall"), kPaperOptimalClimbLength);
    if (stopped > 0) {
      text += fmt::format("  the exact planner stopped at its limit of {} on {} (--plan-max-solves)\n",
                          counted(parameters.plan_search.max_ik_solves, "IK solve"), counted(stopped, "wall"));
    }
  }
  return text;
}

// The walls for 80 % power, or why there is no such number (clusters_for_power's -1).
std::string walls_for_power_text(const MetricComparison& m) {
  if (m.walls_for_power > 0) return std::to_string(m.walls_for_power);
  const ClusteredDifference& d = m.transfer_minus_control;
  if (d.clusters < 2) {
    return "not estimable (needs at least 2 walls: with one, the difference has no spread to plan from)";
  }
  if (d.mean == 0.0) return "not estimable (the mean difference is 0: no effect to detect)";
  if (!std::isfinite(d.mean) || !std::isfinite(d.standard_deviation)) {
    return "not estimable (the difference is not finite)";
  }
  return fmt::format("more than {} (the difference is tiny against its spread over walls)", kMaxClustersForPower);
}

std::string transfer_text(const ExperimentAnalysis& analysis, const ExperimentParameters& parameters) {
  std::string text = fmt::format(
      "\nTransfer against control, paired by wall and seed ({} x {}); means over walls with 95 % intervals:\n",
      counted(parameters.wall_pairs, "wall"), counted(parameters.seeds_per_wall, "seed"));
  if (parameters.training_walls > 1) {
    // Taylor and Stone's total time: transfer's runs were paid for by K training runs.
    const long iterations = parameters.learning.iterations;
    text += fmt::format("  Iterations spent per transfer run: training over {} {}, transfer {}, total {}; control {}\n",
                        counted(parameters.training_walls, "wall"), parameters.training_walls * iterations, iterations,
                        (parameters.training_walls + 1) * iterations, iterations);
  }
  for (const MetricComparison& m : analysis.metrics) {
    const auto& tr = m.per_condition[static_cast<int>(Condition::Transfer)];
    const auto& co = m.per_condition[static_cast<int>(Condition::Control)];
    const ClusteredDifference& d = m.transfer_minus_control;
    text += fmt::format("  {} ({} is better)\n", m.metric.description, m.metric.higher_is_better ? "higher" : "lower");
    text += fmt::format(
        "    transfer {:.4g} +- {:.3g}, control {:.4g} +- {:.3g}; difference {:+.4g} ({:+.0f} %), t-interval over "
        "walls "
        "[{:.4g}, {:.4g}], cluster bootstrap [{:.4g}, {:.4g}], p = {:.3g}; paired r = {}; walls for 80 % power: "
        "{}\n",
        tr.mean, tr.half_width, co.mean, co.half_width, d.mean, 100 * m.relative_difference, d.t_low, d.t_high,
        d.bootstrap_low, d.bootstrap_high, d.p_value,
        std::isfinite(m.paired_correlation) ? fmt::format("{:.2f}", m.paired_correlation)
                                            : "undefined (needs 2 pairs or more and spread in both conditions)",
        walls_for_power_text(m));
  }
  text += fmt::format(
      "\nrliable's view (Agarwal et al., NeurIPS 2021): interquartile means over runs and the probability that "
      "transfer beats control on a wall, with 95 % stratified bootstrap intervals ({} replicates; the walls are kept "
      "and their seeds resampled, so they leave out wall-to-wall variation, unlike the t-intervals above):\n",
      kStratifiedBootstrapReplicates);
  // An interval only where the bootstrap had seeds to resample.
  const auto estimate = [](const BootstrapEstimate& e, const char* format) {
    const std::string_view full(format);
    if (std::isnan(e.low)) return fmt::format(fmt::runtime(full.substr(0, full.find(' '))), e.value);
    return fmt::format(fmt::runtime(format), e.value, e.low, e.high);
  };
  const bool intervals = analysis.metrics.empty() || analysis.metrics.front().stratified.has_intervals;
  if (!intervals) text += fmt::format("  No intervals: {}.\n", kNoStratifiedIntervals);
  for (const MetricComparison& m : analysis.metrics) {
    const StratifiedComparison& r = m.stratified;
    text += fmt::format("  {:<22} IQM transfer {}, control {}, difference {}; P(improvement) {}\n", m.metric.name,
                        estimate(r.iqm_a, "{:.4g} [{:.4g}, {:.4g}]"), estimate(r.iqm_b, "{:.4g} [{:.4g}, {:.4g}]"),
                        estimate(r.iqm_difference, "{:+.4g} [{:+.4g}, {:+.4g}]"),
                        estimate(r.probability_of_improvement, "{:.2f} [{:.2f}, {:.2f}]"));
  }
  text += fmt::format("\nTake-off (first episode of at most {}, at least half w-greedy):\n",
                      counted(parameters.analysis.threshold_length, "iteration"));
  for (const Condition c : kConditions) {
    const ExperimentAnalysis::TakeOff& t = analysis.take_off[static_cast<int>(c)];
    text += fmt::format("  {:<9} {} of {} take off{}\n", enum_name(c), t.taken_off, counted(t.runs, "run"),
                        t.taken_off > 0 ? fmt::format("; median iteration {:.0f}", t.median_iteration) : "");
  }
  text += fmt::format("Transfer and control runs first differ at iteration {:.1f} (median over pairs)\n",
                      analysis.median_first_divergence);
  text += fmt::format(
      "\nTransfer's choices in its first {} (evidence: earlier tries of the same "
      "agent-space pair; far: more than {:.0f} cm from them in the tile):\n",
      counted(parameters.analysis.beginning, "iteration"), 100 * kFarFromEvidence);
  const auto share = [](int part, int whole) {
    return whole > 0 ? fmt::format("{:.0f} %", 100.0 * part / whole) : std::string("-");
  };
  for (int r = 0; r < kRegimeCount; ++r) {
    const ChoiceProfile& p = analysis.transfer_choices[r];
    text += fmt::format(
        "  {:<9} {:6d} {}, {} reachable; back to the hold just left {} (reachable {}); the hold that failed "
        "just before {} (reachable {}); of the others, with evidence {} "
        "(which succeeded {}); far {} (reachable {}), near {} (reachable {}); median distance {}\n",
        enum_name(static_cast<Regime>(r)), p.actions, counted_noun(p.actions, "action"), share(p.successes, p.actions),
        share(p.back_to_left_hold, p.actions), share(p.back_to_left_hold_successes, p.back_to_left_hold),
        share(p.repeats_of_failure, p.actions), share(p.repeats_of_failure_successes, p.repeats_of_failure),
        share(p.with_evidence, p.actions - p.repeats_of_failure),
        fmt::format("{:.0f} %", 100 * p.evidence_success_rate), share(p.far, p.with_evidence),
        share(p.far_successes, p.far), share(p.near, p.with_evidence), share(p.near_successes, p.near),
        p.median_distance_cm >= 0 ? fmt::format("{:.1f} cm", p.median_distance_cm) : std::string("-"));
  }
  return text;
}

}  // namespace

std::string experiment_text(const ExperimentResult& result, const ExperimentAnalysis& analysis,
                            const ExperimentParameters& parameters) {
  return table_one_text(result, parameters) + episode_text(result, parameters) + transfer_text(analysis, parameters);
}

std::string run_text(const ExperimentResult& result, int iterations, const std::string& output) {
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    if (c.runs.empty()) continue;
    const RunResult& run = c.runs.front();
    // Under the dynamic model, what the verdicts cost: the moves performed in MuJoCo.
    const std::string simulated = run.simulates ? fmt::format("; {} simulated in MuJoCo, {} performed",
                                                              counted(run.moves_simulated, "move"), run.moves_performed)
                                                : "";
    return fmt::format(
        "{} on '{}': {} in {}; greedy climb: {}{}; wrote {}\n",
        condition == Condition::Transfer ? "transfer" : "training", printable(result.walls.front().wall.name),
        counted(run.episode_lengths.size(), "episode"), counted(iterations, "iteration"),
        run.greedy_length > 0 ? counted(run.greedy_length, "action") : "does not finish", simulated, output);
  }
  return {};
}

}  // namespace crux
