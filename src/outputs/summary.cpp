#include "outputs/summary.hpp"

#include <cmath>

#include "experiments/statistics.hpp"
#include "experiments/table_one.hpp"
#include "outputs/figure_tables.hpp"

namespace crux {

ExperimentResult single_run_result(RunResult run, const Wall& wall, std::optional<std::uint64_t> wall_seed,
                                   std::uint64_t learning_seed, Condition condition) {
  ExperimentResult result;
  ExperimentWall experiment_wall;
  experiment_wall.wall = wall;
  experiment_wall.seed = wall_seed.value_or(0);
  result.walls.push_back(std::move(experiment_wall));
  ConditionResult& c = result.conditions[static_cast<int>(condition)];
  c.runs.push_back(std::move(run));
  c.wall_of_run = {0};
  c.cluster_of_run = {0};
  c.learning_seeds = {learning_seed};
  return result;
}

namespace {

// [low, high] of a 95 % interval, or null when fewer than two walls give no interval.
nlohmann::json interval_json(const MeanInterval& m) {
  if (m.n < 2) return nullptr;
  return {m.mean - m.half_width, m.mean + m.half_width};
}

// A number that may be NaN (a correlation without variance) as JSON: null then.
nlohmann::json finite_or_null(double value) { return std::isfinite(value) ? nlohmann::json(value) : nullptr; }

nlohmann::ordered_json estimate_json(const BootstrapEstimate& e) {
  return {{"value", finite_or_null(e.value)}, {"low", finite_or_null(e.low)}, {"high", finite_or_null(e.high)}};
}

std::vector<Condition> present_conditions(const ExperimentResult& result) {
  std::vector<Condition> present;
  for (const Condition c : kConditions) {
    if (!result.conditions[static_cast<int>(c)].runs.empty()) present.push_back(c);
  }
  return present;
}

nlohmann::ordered_json table_one_json(const ExperimentResult& result, int beginning) {
  nlohmann::ordered_json table;
  for (const Condition condition : present_conditions(result)) {
    const auto cells = table_one(result.conditions[static_cast<int>(condition)].runs, beginning);
    for (const Window window : {Window::Beginning, Window::Overall}) {
      for (int r = 0; r < kRegimeCount; ++r) {
        const RegimeStats& s = cells[static_cast<int>(window)][r];
        table[enum_name(condition)][enum_name(window)][enum_name(static_cast<Regime>(r))] = {
            {"actions", s.actions_per_run}, {"success_rate", s.success_rate}, {"vertical_cm", s.vertical_cm}};
      }
    }
  }
  return table;
}

// Table I's cells computed run by run, then averaged per wall and over walls with 95 %
// intervals over walls (a run without actions of a regime has no rate and is left out).
nlohmann::ordered_json table_one_over_runs_json(const ExperimentResult& result, int beginning) {
  nlohmann::ordered_json intervals;
  for (const Condition condition : present_conditions(result)) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    for (const Window window : {Window::Beginning, Window::Overall}) {
      for (int r = 0; r < kRegimeCount; ++r) {
        struct Values {
          std::vector<double> values;
          std::vector<std::size_t> walls;
          void add(double value, std::size_t wall) { values.push_back(value), walls.push_back(wall); }
        } actions, rates, rises;
        for (std::size_t i = 0; i < c.runs.size(); ++i) {
          const RegimeStats s = regime_stats(std::span(&c.runs[i], 1), static_cast<Regime>(r),
                                             window == Window::Beginning ? beginning : -1);
          actions.add(s.actions_per_run, c.cluster_of_run[i]);
          if (s.actions > 0) rates.add(s.success_rate, c.cluster_of_run[i]);
          if (s.successes > 0) rises.add(s.vertical_cm, c.cluster_of_run[i]);
        }
        nlohmann::ordered_json cell;
        for (const auto& [name, v] : {std::pair<const char*, const Values&>{"actions", actions},
                                      {"success_rate", rates},
                                      {"vertical_cm", rises}}) {
          const MeanInterval m = mean_interval(cluster_means(v.values, v.walls));
          cell[name] = {
              {"mean", m.mean}, {"ci95_over_walls", interval_json(m)}, {"runs", v.values.size()}, {"walls", m.n}};
        }
        intervals[enum_name(condition)][enum_name(window)][enum_name(static_cast<Regime>(r))] = cell;
      }
    }
  }
  return intervals;
}

nlohmann::ordered_json transfer_choices_json(const ExperimentAnalysis& analysis) {
  nlohmann::ordered_json choices;
  for (int r = 0; r < kRegimeCount; ++r) {
    const ChoiceProfile& p = analysis.transfer_choices[r];
    choices[enum_name(static_cast<Regime>(r))] = {
        {"actions", p.actions},
        {"successes", p.successes},
        {"mean_root_rise_cm", p.mean_root_rise_cm},
        {"back_to_left_hold", p.back_to_left_hold},
        {"back_to_left_hold_successes", p.back_to_left_hold_successes},
        {"repeats_of_failure", p.repeats_of_failure},
        {"repeats_of_failure_successes", p.repeats_of_failure_successes},
        {"with_evidence", p.with_evidence},
        {"evidence_success_rate", p.evidence_success_rate},
        {"median_distance_from_evidence_cm",
         p.median_distance_cm >= 0 ? nlohmann::json(p.median_distance_cm) : nullptr},
        {"far_from_evidence", p.far},
        {"far_successes", p.far_successes},
        {"near_evidence", p.near},
        {"near_successes", p.near_successes}};
  }
  return choices;
}

}  // namespace

nlohmann::ordered_json transfer_vs_control_json(const ExperimentAnalysis& analysis) {
  nlohmann::ordered_json comparison;
  for (const MetricComparison& m : analysis.metrics) {
    nlohmann::ordered_json entry;
    entry["description"] = m.metric.description;
    entry["higher_is_better"] = m.metric.higher_is_better;
    for (const Condition c : kConditions) {
      const MeanInterval& v = m.per_condition[static_cast<int>(c)];
      entry[enum_name(c)] = {{"mean", v.mean}, {"ci95_over_walls", interval_json(v)}};
    }
    const ClusteredDifference& d = m.transfer_minus_control;
    entry["transfer_minus_control"] = {{"mean", d.mean},
                                       {"ci95_t_over_walls", {d.t_low, d.t_high}},
                                       {"ci95_cluster_bootstrap", {d.bootstrap_low, d.bootstrap_high}},
                                       {"t", finite_or_null(d.t)},
                                       {"p_value", d.p_value},
                                       {"walls", d.clusters},
                                       {"pairs", d.pairs}};
    entry["relative_difference"] = finite_or_null(m.relative_difference);
    entry["paired_correlation"] = finite_or_null(m.paired_correlation);
    entry["wall_correlation"] = finite_or_null(m.wall_correlation);
    entry["walls_for_80_percent_power"] = m.walls_for_power > 0 ? nlohmann::json(m.walls_for_power) : nullptr;
    const StratifiedComparison& r = m.stratified;
    entry["iqm"] = {{"transfer", estimate_json(r.iqm_a)},
                    {"control", estimate_json(r.iqm_b)},
                    {"difference", estimate_json(r.iqm_difference)}};
    entry["probability_of_improvement"] = estimate_json(r.probability_of_improvement);
    entry["stratified_intervals"] =
        r.has_intervals ? std::string(kStratifiedIntervals) : std::string("none: ") + kNoStratifiedIntervals;
    comparison[m.metric.name] = entry;
  }
  return comparison;
}

nlohmann::ordered_json take_off_json(const ExperimentAnalysis& analysis) {
  nlohmann::ordered_json take_off;
  for (const Condition c : kConditions) {
    const ExperimentAnalysis::TakeOff& t = analysis.take_off[static_cast<int>(c)];
    take_off[enum_name(c)] = {{"runs", t.runs},
                              {"taken_off", t.taken_off},
                              {"share", t.runs > 0 ? static_cast<double>(t.taken_off) / t.runs : 0.0},
                              {"median_iteration", t.taken_off > 0 ? nlohmann::json(t.median_iteration) : nullptr}};
  }
  return take_off;
}

nlohmann::ordered_json divergence_json(const ExperimentAnalysis& analysis) {
  return {{"median_first_divergence", analysis.median_first_divergence},
          {"first_divergence", analysis.first_divergence}};
}

namespace {

// Taylor and Stone's total time: the iterations behind each transfer run, training over
// K walls included, beside control's; and the preceding training walls that cost them.
nlohmann::ordered_json iterations_spent_json(const ExperimentResult& result, const ExperimentParameters& parameters) {
  const long iterations = parameters.learning.iterations;
  nlohmann::ordered_json preceding = nlohmann::json::array();
  for (const ExperimentWall& w : result.preceding_training_walls) {
    preceding.push_back({{"name", w.wall.name}, {"seed", w.seed}, {"rejected_seeds", w.rejected_seeds}});
  }
  return {{"training_walls", parameters.training_walls},
          {"training", parameters.training_walls * iterations},
          {"transfer", iterations},
          {"total", (parameters.training_walls + 1) * iterations},
          {"control", iterations},
          {"preceding_training_walls", preceding}};
}

// A wall's seed, or null when `seeded` is false: a wall read from a file has none.
nlohmann::json summary_wall_seed(const ExperimentWall& wall, bool seeded) {
  return seeded ? nlohmann::json(wall.seed) : nlohmann::json(nullptr);
}

// What every run's entry of run_facts holds: its wall, its seeds and what it learnt at what cost.
nlohmann::ordered_json run_facts_common(const RunResult& run, const ExperimentWall& wall, std::size_t wall_pair,
                                        std::uint64_t learning_seed, const ExperimentParameters& parameters,
                                        bool seeded) {
  return {{"wall", wall.wall.name},
          {"wall_pair", wall_pair},
          {"wall_seed", summary_wall_seed(wall, seeded)},
          {"learning_seed", learning_seed},
          {"take_off_iteration", take_off_iteration(run, parameters.analysis.threshold_length)},
          {"planning_updates_per_step",
           static_cast<double>(run.planning_updates) / static_cast<double>(run.iterations.size())},
          {"episodes", run.episode_lengths.size()},
          {"greedy_length", run.greedy_length},
          {"plan_length", wall.plan.found ? wall.plan.length : -1},
          {"explored_pairs", run.explored_pairs},
          {"explored_share", wall.filtered_pairs > 0 ? nlohmann::json(static_cast<double>(run.explored_pairs) /
                                                                      static_cast<double>(wall.filtered_pairs))
                                                     : nlohmann::json(nullptr)},
          {"ik_solves", run.ik_solves},
          {"reached_configurations", run.reached_configurations},
          {"unreachable_configurations", run.unreachable_configurations}};
}

// One run's entry of run_facts.
nlohmann::ordered_json run_facts_json(const RunResult& run, const ExperimentWall& wall, std::size_t wall_pair,
                                      std::uint64_t learning_seed, const ExperimentParameters& parameters,
                                      bool seeded) {
  nlohmann::ordered_json facts = run_facts_common(run, wall, wall_pair, learning_seed, parameters, seeded);
  // Only a run of the dynamic model simulates, so that the others' summaries keep their bytes.
  if (run.simulates) {
    facts["moves_simulated"] = run.moves_simulated;
    facts["moves_performed"] = run.moves_performed;
  }
  return facts;
}

nlohmann::ordered_json summary_walls_json(const ExperimentResult& result, bool seeded) {
  nlohmann::ordered_json walls = nlohmann::json::array();
  for (const ExperimentWall& w : result.walls) {
    walls.push_back({{"name", w.wall.name},
                     {"seed", summary_wall_seed(w, seeded)},
                     {"rejected_seeds", w.rejected_seeds},
                     {"plan_length", w.plan.found ? w.plan.length : -1},
                     {"plan_holds", w.plan.hold_ids},
                     {"plan_stopped_at_limit", w.plan.stopped_at_limit}});
  }
  return walls;
}

}  // namespace

nlohmann::ordered_json summary_json(const ExperimentResult& result, const ExperimentAnalysis* analysis,
                                    const ExperimentParameters& parameters, const Provenance& provenance) {
  const int beginning = parameters.analysis.beginning;
  // A wall read from a file has no seed.
  const bool seeded = analysis != nullptr || provenance.wall_seed;
  nlohmann::ordered_json out;
  out["format"] = "crux-summary";
  out["version"] = 4;  // 4: no wall-clock seconds; the provenance names its caller
  out["kind"] = analysis != nullptr ? "experiment" : "run";
  out["provenance"] = provenance_json(provenance);
  out["seed"] = parameters.seed;
  out["wall_pairs"] = analysis != nullptr ? parameters.wall_pairs : 1;
  out["seeds_per_wall"] = analysis != nullptr ? parameters.seeds_per_wall : 1;
  out["runs_per_condition"] = analysis != nullptr ? parameters.runs() : 1;
  out["iterations"] = parameters.learning.iterations;
  out["beginning_iterations"] = beginning;
  out["threshold_length"] = parameters.analysis.threshold_length;
  out["solver"] = enum_name(parameters.learning.climbing.reachability.ik.solver);
  out["table1"] = table_one_json(result, beginning);
  if (analysis != nullptr) {
    out["table1_over_runs"] = table_one_over_runs_json(result, beginning);
    out["transfer_vs_control"] = transfer_vs_control_json(*analysis);
    if (parameters.training_walls > 1) out["iterations_spent"] = iterations_spent_json(result, parameters);
    out["take_off"] = take_off_json(*analysis);
    out["transfer_choices"] = transfer_choices_json(*analysis);
    out["transfer_control_divergence"] = divergence_json(*analysis);
  }
  nlohmann::ordered_json lengths, runs, maps;
  const GridParameters& grid = parameters.learning.climbing.grid;
  for (const Condition condition : present_conditions(result)) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    const char* name = enum_name(condition);
    lengths[name] = nlohmann::json::array();
    runs[name] = nlohmann::json::array();
    for (std::size_t i = 0; i < c.runs.size(); ++i) {
      const RunResult& run = c.runs[i];
      const ExperimentWall& wall = result.walls[c.wall_of_run[i]];
      lengths[name].push_back(run.episode_lengths);
      runs[name].push_back(run_facts_json(run, wall, c.cluster_of_run[i], c.learning_seeds[i], parameters, seeded));
    }
    const auto mean_map = mean_q_grid_maps(c, grid);
    for (int l = 0; l < kLimbCount; ++l) {
      std::vector<double> tiles;
      for (const auto& tile : mean_map) tiles.push_back(tile[l]);
      maps[name][enum_name(static_cast<Limb>(l))] = tiles;
    }
  }
  out["episode_lengths"] = lengths;
  out["run_facts"] = runs;
  out["qgrid_maps"] = maps;
  out["walls"] = summary_walls_json(result, seeded);
  return out;
}

}  // namespace crux
