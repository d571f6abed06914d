#include "sweeps/sweep_results.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/json_field.hpp"
#include "common/sha256.hpp"
#include "experiments/experiment_analysis.hpp"
#include "experiments/statistics.hpp"
#include "outputs/iterations_file.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/run_folder.hpp"
#include "outputs/summary.hpp"
#include "outputs/summary_file.hpp"
#include "outputs/sweep_files.hpp"
#include "reports/sweep_report.hpp"
#include "sweeps/sweep_task.hpp"

namespace crux {

namespace fs = std::filesystem;

namespace {

// A run as the analysis needs it: its iterations (problem-space columns of
// iterations.csv, which must hold the `recorded_iterations` of its summary.json) and
// episode lengths; the agent-space columns are not in the folder.
RunResult read_run(const fs::path& directory, int recorded_iterations, PhysicsModel model) {
  RunResult run;
  for (const RunStep& step : read_iterations_file(directory / "iterations.csv", recorded_iterations, model)) {
    IterationRecord record;
    record.episode = step.episode;
    record.regime = step.regime;
    record.hold_id = step.hold_id;
    record.success = step.success;
    record.fell = step.fell;
    record.root_rise_m = step.root_rise_cm / 100.0;
    record.reward = step.reward;
    run.iterations.push_back(record);
  }
  run.episode_lengths = read_episode_lengths(directory);
  return run;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

// Of a summary.json (ordered) or a wall's facts file.
template <typename Json>
std::string number_cell(const Json& value) {
  if (value.is_null()) return "";
  if (value.is_number_float()) return fmt::format("{}", value.template get<double>());
  return value.dump();
}

// The facts results.csv copies from a run's summary.json, in column order.
constexpr const char* kRunFacts[] = {"episodes",
                                     "take_off_iteration",
                                     "greedy_length",
                                     "explored_pairs",
                                     "ik_solves",
                                     "reached_configurations",
                                     "unreachable_configurations",
                                     "planning_updates_per_step"};

// Metric columns: every metric any cell's windows define, in order of appearance.
std::vector<std::string> sweep_metric_names(const SweepPlan& plan) {
  std::vector<std::string> metric_names;
  for (const SweepCell& cell : plan.cells) {
    for (const EpisodeMetric& m : episode_metrics(metric_windows(cell.config.settings))) {
      if (std::find(metric_names.begin(), metric_names.end(), m.name) == metric_names.end()) {
        metric_names.push_back(m.name);
      }
    }
  }
  return metric_names;
}

std::string sweep_results_csv_header(const SweepPlan& plan, const std::vector<std::string>& metric_names) {
  std::string csv = "cell";
  for (const std::string& key : plan.keys) csv += fmt::format(",{}", csv_cell(key));
  csv += ",condition,run,wall_pair,seed_index,wall_seed,learning_seed";
  for (const std::string& name : metric_names) csv += fmt::format(",{}", name);
  for (const char* fact : kRunFacts) csv += fmt::format(",{}", fact);
  csv += ",plan_length,filtered_pairs\n";
  return csv;
}

// A training run after K - 1 others read the Q_grid they left beside its folder; its
// config.toml records that file's digest. A resumed sweep keeps the file: it must still be
// the one the run read, as a replay of the run's config.toml would check.
void check_preceding_q_grid(const fs::path& sweep_folder, const SweepTask& task, const fs::path& run_directory) {
  const fs::path file = sweep_folder / preceding_q_grid_file(task);
  const ExperimentConfig config = read_run_config(run_directory / "config.toml");
  const auto recorded = config.recorded_provenance.find("q_grid_sha256");
  const std::string digest = sha256_of_file(file.string(), "Q-table file");
  if (recorded == config.recorded_provenance.end() || recorded->second != digest) {
    throw InputError(
        file.string(),
        fmt::format("is not the Q_grid that {} read (sha256 {}, recorded {}): delete {} "
                    "to run it again",
                    task.folder.string(), digest,
                    recorded == config.recorded_provenance.end() ? "none" : recorded->second, run_directory.string()));
  }
}

// Cell c's runs, read back from their folders for the analysis, each appended to `csv` as
// a row of results.csv with its wall's facts.
ExperimentResult read_sweep_cell(const SweepPlan& plan, const fs::path& folder, std::size_t c,
                                 const std::vector<std::string>& metric_names, std::string& csv) {
  const SweepCell& cell = plan.cells[c];
  const ExperimentParameters& settings = cell.config.settings;
  const MetricWindows windows = metric_windows(settings);
  const std::vector<EpisodeMetric> metrics = episode_metrics(windows);
  ExperimentResult result;
  for (const Condition condition : kConditions) {
    ConditionResult& runs = result.conditions[static_cast<int>(condition)];
    for (int r = 0; r < settings.runs(); ++r) {
      const SweepTask& task = plan.tasks[run_task_index(plan, c, condition, r)];
      const fs::path directory = folder / task.folder;
      const std::string summary_file = (directory / "summary.json").string();
      const OrderedJson summary = read_summary(directory);
      if (condition == Condition::Training && settings.training_walls > 1)
        check_preceding_q_grid(folder, task, directory);
      runs.runs.push_back(
          read_run(directory, summary_iterations(summary, summary_file), settings.learning.climbing.physics.model));
      const int pair = r / settings.seeds_per_wall;
      runs.cluster_of_run.push_back(static_cast<std::size_t>(pair));
      runs.wall_of_run.push_back(static_cast<std::size_t>(pair));
      const std::string name = enum_name(condition);
      const JsonField facts = JsonField(summary_file, summary)["run_facts"][name][0];
      runs.learning_seeds.push_back(facts["learning_seed"].unsigned_integer());
      const fs::path wall_folder =
          folder / "walls" / fmt::format("g{}", cell.wall_group) /
          fmt::format("{}_{}", condition == Condition::Training ? "training" : "transfer", pair);
      const nlohmann::json wall = read_sweep_wall_facts(wall_folder);

      csv += fmt::format("{}", c);
      for (const std::string& value : cell.values) csv += fmt::format(",{}", csv_cell(value));
      csv += fmt::format(",{},{},{},{},{},{}", name, r, pair, r % settings.seeds_per_wall,
                         facts["wall_seed"].json().dump(), runs.learning_seeds.back());
      for (const std::string& metric : metric_names) {
        const auto m =
            std::find_if(metrics.begin(), metrics.end(), [&](const EpisodeMetric& e) { return e.name == metric; });
        csv += m == metrics.end() ? std::string(",") : fmt::format(",{}", m->of_run(runs.runs.back(), windows));
      }
      for (const char* fact : kRunFacts) csv += fmt::format(",{}", number_cell(facts[fact].json()));
      const nlohmann::json& wall_plan = wall.at("plan");
      csv += fmt::format(",{},{}\n", wall_plan.is_null() ? std::string() : number_cell(wall_plan.at("length")),
                         number_cell(wall.at("filtered_pairs")));
    }
  }
  return result;
}

// Cell c's entry of summary.json: its parameters, its runs' budget and its analysis.
nlohmann::ordered_json sweep_cell_entry(const SweepPlan& plan, std::size_t c, const ExperimentAnalysis& analysis) {
  const SweepCell& cell = plan.cells[c];
  const ExperimentParameters& settings = cell.config.settings;
  nlohmann::ordered_json entry;
  entry["cell"] = c;
  nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < plan.keys.size(); ++k) parameters[plan.keys[k]] = cell.values[k];
  entry["parameters"] = parameters;
  entry["wall_group"] = cell.wall_group;
  entry["seed"] = settings.seed;
  entry["wall_pairs"] = settings.wall_pairs;
  entry["seeds_per_wall"] = settings.seeds_per_wall;
  entry["iterations"] = settings.learning.iterations;
  // Taylor and Stone's total time per transfer run, for every K (crux paper's
  // iterations_spent, whose preceding walls are the sweep's walls/g<G>/preceding_*).
  const long iterations = settings.learning.iterations;
  entry["iterations_spent"] = {{"training_walls", settings.training_walls},
                               {"training", settings.training_walls * iterations},
                               {"transfer", iterations},
                               {"total", (settings.training_walls + 1) * iterations},
                               {"control", iterations}};
  entry["transfer_vs_control"] = transfer_vs_control_json(analysis);
  entry["take_off"] = take_off_json(analysis);
  entry["transfer_control_divergence"] = divergence_json(analysis);
  return entry;
}

// Holm over the cells, one family per metric: "which cells show an effect" stays at 5 %.
void add_holm_over_cells(const std::vector<std::string>& metric_names, nlohmann::ordered_json& cells) {
  for (const std::string& metric : metric_names) {
    std::vector<double> p_values;
    std::vector<std::size_t> holders;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto& comparison = cells[c]["transfer_vs_control"];
      if (!comparison.contains(metric)) continue;
      p_values.push_back(comparison[metric]["transfer_minus_control"]["p_value"].get<double>());
      holders.push_back(c);
    }
    const std::vector<double> adjusted = holm_adjusted(p_values);
    for (std::size_t i = 0; i < holders.size(); ++i) {
      cells[holders[i]]["transfer_vs_control"][metric]["transfer_minus_control"]["p_value_holm_over_cells"] =
          adjusted[i];
    }
  }
}

}  // namespace

nlohmann::ordered_json write_sweep_results(const SweepPlan& plan, const fs::path& folder,
                                           const nlohmann::ordered_json& provenance) {
  const std::vector<std::string> metric_names = sweep_metric_names(plan);
  std::string csv = sweep_results_csv_header(plan, metric_names);
  nlohmann::ordered_json cells = nlohmann::json::array();
  for (std::size_t c = 0; c < plan.cells.size(); ++c) {
    const ExperimentResult result = read_sweep_cell(plan, folder, c, metric_names, csv);
    cells.push_back(sweep_cell_entry(plan, c, analyse_experiment(result, plan.cells[c].config.settings)));
  }
  add_holm_over_cells(metric_names, cells);
  return write_sweep_results_files(folder, csv, provenance, plan.keys, cells);
}

std::vector<fs::path> write_sweep_report(const SweepPlan& plan, const fs::path& folder,
                                         const nlohmann::ordered_json& summary) {
  std::vector<std::string> figures;
  for (std::size_t c = 0; c < plan.cells.size(); ++c) {
    const ExperimentParameters& settings = plan.cells[c].config.settings;
    PaperFigureData data;
    data.grid = settings.learning.climbing.grid;
    data.iterations = settings.learning.iterations;
    data.seeds_per_wall = settings.seeds_per_wall;
    // Transfer and control share the transfer walls: each wall's plan is read once.
    std::vector<int> plan_lengths;
    for (int pair = 0; pair < settings.wall_pairs; ++pair) {
      const nlohmann::json wall = read_sweep_wall_facts(
          folder / "walls" / fmt::format("g{}", plan.cells[c].wall_group) / fmt::format("transfer_{}", pair));
      plan_lengths.push_back(wall.at("plan").is_null() ? -1 : wall.at("plan").at("length").get<int>());
    }
    for (const Condition condition : {Condition::Transfer, Condition::Control}) {
      PaperConditionData runs;
      runs.condition = condition;
      for (int r = 0; r < settings.runs(); ++r) {
        PaperRunData run;
        run.wall_pair = r / settings.seeds_per_wall;
        run.episode_lengths = read_episode_lengths(folder / plan.tasks[run_task_index(plan, c, condition, r)].folder);
        run.plan_length = plan_lengths[static_cast<std::size_t>(run.wall_pair)];
        runs.runs.push_back(std::move(run));
      }
      data.conditions.push_back(std::move(runs));
    }
    figures.push_back(fig4_svg(data, sweep_cell_title(summary.at("cells").at(c))));
  }
  return write_sweep_report_files(folder, figures, sweep_report_html(summary, figures));
}

}  // namespace crux
