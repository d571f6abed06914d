#include "experiments/experiment_output.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "agent_space/agent_descriptor.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "experiments/table_one.hpp"
#include "experiments/statistics.hpp"
#include "learning/q_table_file.hpp"
#include "wall/wall_file.hpp"

namespace crux {

namespace fs = std::filesystem;

const PaperTableOne& paper_table_one() {
  // Section IV, Table I (w-greedy, g-greedy, random).
  static const PaperTableOne table{
      {{{7.3, 0.4, 2.0}, {9.4, 4.3, 2.0}}, {{12.0, 1.8, 2.0}, {10.6, 3.4, 2.0}}},
      {{{1.00, 0.46, 0.43}, {1.00, 0.60, 0.43}}, {{1.00, 0.45, 0.44}, {1.00, 0.57, 0.44}}}};
  return table;
}

namespace {

void make_directory(const fs::path& directory) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec || !fs::is_directory(directory)) throw InputError(directory.string(), "cannot create the output folder");
}

std::string number(double value) { return fmt::format("{:.17g}", value); }

// [low, high] of a 95 % interval, or null when fewer than two runs give no interval.
nlohmann::json interval_json(const MeanInterval& m) {
  if (m.n < 2) return nullptr;
  return {m.mean - m.half_width, m.mean + m.half_width};
}

// Σ over agent-space states with each free limb of Q_grid(s, tile): Fig. 2b's maps.
std::vector<std::array<double, kLimbCount>> q_grid_maps(const QTable& q, const GridParameters& grid) {
  std::vector<std::array<double, kLimbCount>> maps(grid.tile_count(), std::array<double, kLimbCount>{});
  q.for_each_row([&](StateCode s, std::span<const double> values, std::span<const std::uint32_t>) {
    const int limb = static_cast<int>(decode_agent_state(static_cast<std::uint32_t>(s), grid).free_limb);
    for (int tile = 0; tile < grid.tile_count(); ++tile) maps[tile][limb] += values[tile];
  });
  return maps;
}

std::string regime_curve_csv(const ExperimentResult& result, int iterations) {
  std::ostringstream csv;
  csv << "condition,iteration,w_greedy,g_greedy,random\n";
  for (const Condition condition : kConditions) {
    const auto& runs = result.conditions[static_cast<int>(condition)].runs;
    std::vector<std::array<double, kRegimeCount>> cumulative(iterations, std::array<double, kRegimeCount>{});
    for (const RunResult& run : runs) {
      std::array<double, kRegimeCount> count{};
      for (int i = 0; i < iterations && i < static_cast<int>(run.iterations.size()); ++i) {
        count[static_cast<int>(run.iterations[i].regime)] += 1.0;
        for (int r = 0; r < kRegimeCount; ++r) cumulative[i][r] += count[r] / static_cast<double>(runs.size());
      }
    }
    for (int i = 0; i < iterations; ++i) {
      csv << condition_name(condition) << ',' << i + 1 << ',' << number(cumulative[i][0]) << ','
          << number(cumulative[i][1]) << ',' << number(cumulative[i][2]) << '\n';
    }
  }
  return csv.str();
}

}  // namespace

void write_run_files(const fs::path& directory, const RunResult& run, const BodyModel& model) {
  make_directory(directory);
  std::ostringstream iterations;
  iterations << "iteration,episode,regime,hold,success,root_rise_cm,reward\n";
  for (std::size_t i = 0; i < run.iterations.size(); ++i) {
    const IterationRecord& r = run.iterations[i];
    iterations << i + 1 << ',' << r.episode << ',' << regime_name(r.regime) << ',' << r.hold_id << ','
               << (r.success ? 1 : 0) << ',' << number(100.0 * r.root_rise_m) << ',' << number(r.reward) << '\n';
  }
  write_file_atomically(directory / "iterations.csv", iterations.str());
  std::ostringstream episodes;
  episodes << "episode,length\n";
  for (std::size_t e = 0; e < run.episode_lengths.size(); ++e) episodes << e << ',' << run.episode_lengths[e] << '\n';
  write_file_atomically(directory / "episodes.csv", episodes.str());
  save_q_table((directory / "q_grid.bin").string(), run.q_grid);
  std::ostringstream climb;
  climb << "step";
  for (const BodyJoint& joint : model.joints) climb << ',' << joint.name;
  climb << '\n';
  for (std::size_t s = 0; s < run.last_climb.size(); ++s) {
    climb << s;
    for (int i = 0; i < kConfigurationDof; ++i) climb << ',' << number(run.last_climb[s][i]);
    climb << '\n';
  }
  write_file_atomically(directory / "climb.csv", climb.str());
}

namespace {

// A number that may be NaN (a correlation without variance) as JSON: null then.
nlohmann::json finite_or_null(double value) { return std::isfinite(value) ? nlohmann::json(value) : nullptr; }

}  // namespace

nlohmann::ordered_json experiment_summary(const ExperimentResult& result, const ExperimentAnalysis& analysis,
                                          const ExperimentSettings& settings) {
  const int beginning = settings.analysis.beginning;
  nlohmann::ordered_json out;
  out["format"] = "crux-summary";
  out["version"] = 2;
  out["seed"] = settings.seed;
  out["walls"] = settings.wall_pairs;
  out["seeds_per_wall"] = settings.seeds_per_wall;
  out["runs_per_condition"] = settings.runs();
  out["iterations"] = settings.learning.iterations;
  out["beginning_iterations"] = beginning;
  out["threshold_length"] = settings.analysis.threshold_length;
  out["solver"] = ik_solver_name(settings.learning.climbing.reachability.ik.solver);
  out["seconds"] = result.seconds;
  nlohmann::ordered_json table;
  for (const Condition condition : kConditions) {
    const auto cells = table_one(result.conditions[static_cast<int>(condition)].runs, beginning);
    for (const Window window : {Window::Beginning, Window::Overall}) {
      for (int r = 0; r < kRegimeCount; ++r) {
        const RegimeStats& s = cells[static_cast<int>(window)][r];
        table[condition_name(condition)][window_name(window)][regime_name(static_cast<Regime>(r))] = {
            {"actions", s.actions_per_run}, {"success_rate", s.success_rate}, {"vertical_cm", s.vertical_cm}};
      }
    }
  }
  out["table1"] = table;
  // The same cells computed run by run, then averaged per wall and over walls with 95 %
  // intervals over walls (a run without actions of a regime has no rate and is left out).
  nlohmann::ordered_json intervals;
  for (const Condition condition : kConditions) {
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
          cell[name] = {{"mean", m.mean}, {"ci95_over_walls", interval_json(m)}, {"runs", v.values.size()}, {"walls", m.n}};
        }
        intervals[condition_name(condition)][window_name(window)][regime_name(static_cast<Regime>(r))] = cell;
      }
    }
  }
  out["table1_over_runs"] = intervals;
  nlohmann::ordered_json comparison;
  for (const MetricComparison& m : analysis.metrics) {
    nlohmann::ordered_json entry;
    entry["description"] = m.metric.description;
    entry["higher_is_better"] = m.metric.higher_is_better;
    for (const Condition c : kConditions) {
      const MeanInterval& v = m.per_condition[static_cast<int>(c)];
      entry[condition_name(c)] = {{"mean", v.mean}, {"ci95_over_walls", interval_json(v)}};
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
    comparison[m.metric.name] = entry;
  }
  out["transfer_vs_control"] = comparison;
  nlohmann::ordered_json take_off;
  for (const Condition c : kConditions) {
    const ExperimentAnalysis::TakeOff& t = analysis.take_off[static_cast<int>(c)];
    take_off[condition_name(c)] = {{"runs", t.runs},
                                   {"taken_off", t.taken_off},
                                   {"share", t.runs > 0 ? static_cast<double>(t.taken_off) / t.runs : 0.0},
                                   {"median_iteration", t.taken_off > 0 ? nlohmann::json(t.median_iteration) : nullptr}};
  }
  out["take_off"] = take_off;
  nlohmann::ordered_json choices;
  for (int r = 0; r < kRegimeCount; ++r) {
    const ChoiceProfile& p = analysis.transfer_choices[r];
    choices[regime_name(static_cast<Regime>(r))] = {
        {"actions", p.actions},
        {"successes", p.successes},
        {"mean_root_rise_cm", p.mean_root_rise_cm},
        {"back_to_left_hold", p.back_to_left_hold},
        {"back_to_left_hold_successes", p.back_to_left_hold_successes},
        {"repeats_of_failure", p.repeats_of_failure},
        {"repeats_of_failure_successes", p.repeats_of_failure_successes},
        {"with_evidence", p.with_evidence},
        {"evidence_success_rate", p.evidence_success_rate},
        {"median_distance_from_evidence_cm", p.median_distance_cm >= 0 ? nlohmann::json(p.median_distance_cm) : nullptr},
        {"far_from_evidence", p.far},
        {"far_successes", p.far_successes},
        {"near_evidence", p.near},
        {"near_successes", p.near_successes}};
  }
  out["transfer_choices"] = choices;
  out["transfer_control_divergence"] = {{"median_first_divergence", analysis.median_first_divergence},
                                        {"first_divergence", analysis.first_divergence}};
  nlohmann::ordered_json lengths, runs, maps;
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    const char* name = condition_name(condition);
    lengths[name] = nlohmann::json::array();
    runs[name] = nlohmann::json::array();
    std::vector<std::array<double, kLimbCount>> mean_map(settings.learning.climbing.grid.tile_count(),
                                                         std::array<double, kLimbCount>{});
    for (std::size_t i = 0; i < c.runs.size(); ++i) {
      const RunResult& run = c.runs[i];
      const ExperimentWall& wall = result.walls[c.wall_of_run[i]];
      lengths[name].push_back(run.episode_lengths);
      runs[name].push_back({{"wall", wall.wall.name},
                            {"wall_pair", c.cluster_of_run[i]},
                            {"wall_seed", wall.seed},
                            {"learning_seed", c.learning_seeds[i]},
                            {"take_off_iteration", analysis.take_off[static_cast<int>(condition)].iterations[i]},
                            {"planning_updates_per_step",
                             static_cast<double>(run.planning_updates) / static_cast<double>(run.iterations.size())},
                            {"episodes", run.episode_lengths.size()},
                            {"greedy_length", run.greedy_length},
                            {"plan_length", wall.plan.found ? wall.plan.length : -1},
                            {"explored_pairs", run.explored_pairs},
                            {"explored_share", wall.filtered_pairs > 0 ? static_cast<double>(run.explored_pairs) /
                                                                             static_cast<double>(wall.filtered_pairs)
                                                                       : 0.0},
                            {"ik_solves", run.ik_solves},
                            {"reached_configurations", run.reached_configurations},
                            {"unreachable_configurations", run.unreachable_configurations}});
      const auto map = q_grid_maps(run.q_grid, settings.learning.climbing.grid);
      for (std::size_t t = 0; t < map.size(); ++t) {
        for (int l = 0; l < kLimbCount; ++l) mean_map[t][l] += map[t][l] / static_cast<double>(c.runs.size());
      }
    }
    for (int l = 0; l < kLimbCount; ++l) {
      std::vector<double> tiles;
      for (const auto& tile : mean_map) tiles.push_back(tile[l]);
      maps[name][limb_name(static_cast<Limb>(l))] = tiles;
    }
  }
  out["episode_lengths"] = lengths;
  out["run_facts"] = runs;
  out["qgrid_maps"] = maps;
  nlohmann::ordered_json walls = nlohmann::json::array();
  for (const ExperimentWall& w : result.walls) {
    walls.push_back({{"name", w.wall.name},
                     {"seed", w.seed},
                     {"rejected_seeds", w.rejected_seeds},
                     {"plan_length", w.plan.found ? w.plan.length : -1},
                     {"plan_holds", w.plan.hold_ids}});
  }
  out["walls"] = walls;
  return out;
}

void write_experiment(const fs::path& directory, const ExperimentResult& result, const ExperimentAnalysis& analysis,
                      const ExperimentSettings& settings, const BodyModel& model, const std::string& config_toml) {
  make_directory(directory);
  write_file_atomically(directory / "config.toml", config_toml);
  make_directory(directory / "walls");
  for (std::size_t w = 0; w < result.walls.size(); ++w) {
    const bool training = static_cast<int>(w) < settings.wall_pairs;
    save_wall((directory / "walls" / fmt::format("{}_{}.json", training ? "training" : "transfer",
                                                  w % settings.wall_pairs)).string(),
              result.walls[w].wall);
  }
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    for (std::size_t i = 0; i < c.runs.size(); ++i) {
      write_run_files(directory / "runs" / fmt::format("{}_{}", condition_name(condition), i), c.runs[i], model);
    }
  }
  make_directory(directory / "figures");
  write_file_atomically(directory / "figures" / "fig3_regimes.csv", regime_curve_csv(result, settings.learning.iterations));
  std::ostringstream fig4;
  fig4 << "condition,run,episode,length\n";
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    for (std::size_t i = 0; i < c.runs.size(); ++i) {
      for (std::size_t e = 0; e < c.runs[i].episode_lengths.size(); ++e) {
        fig4 << condition_name(condition) << ',' << i << ',' << e << ',' << c.runs[i].episode_lengths[e] << '\n';
      }
    }
  }
  write_file_atomically(directory / "figures" / "fig4_episode_lengths.csv", fig4.str());
  const nlohmann::ordered_json summary = experiment_summary(result, analysis, settings);
  std::ostringstream fig2b;
  fig2b << "condition,free_limb,tile,column,row,value\n";
  const GridParameters& grid = settings.learning.climbing.grid;
  for (const Condition condition : kConditions) {
    for (int l = 0; l < kLimbCount; ++l) {
      const auto& tiles = summary["qgrid_maps"][condition_name(condition)][limb_name(static_cast<Limb>(l))];
      for (int t = 0; t < grid.tile_count(); ++t) {
        fig2b << condition_name(condition) << ',' << limb_name(static_cast<Limb>(l)) << ',' << t << ','
              << t % grid.columns << ',' << t / grid.columns << ',' << number(tiles[t].get<double>()) << '\n';
      }
    }
  }
  write_file_atomically(directory / "figures" / "fig2b_qgrid_maps.csv", fig2b.str());
  write_file_atomically(directory / "summary.json", summary.dump(2) + "\n");
}

}  // namespace crux
