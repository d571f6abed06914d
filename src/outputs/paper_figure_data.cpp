#include "outputs/paper_figure_data.hpp"

#include <fmt/format.h>

#include "outputs/iterations_file.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/summary_file.hpp"

namespace crux {
namespace {

TransferMetricData transfer_metric(const JsonField& metric, const std::string& name) {
  TransferMetricData out;
  out.name = name;
  out.description = metric["description"].string();
  out.higher_is_better = metric["higher_is_better"].boolean();
  out.control_mean = metric["control"]["mean"].number();
  const JsonField difference = metric["transfer_minus_control"];
  out.difference = difference["mean"].number();
  const JsonField interval = difference["ci95_t_over_walls"];
  if (!interval.is_null()) {
    interval.expect_size(2);
    out.difference_ci95 = std::array<double, 2>{interval[0].number(), interval[1].number()};
  }
  out.p_value = difference["p_value"].number();
  out.walls = difference["walls"].integer(0);
  return out;
}

}  // namespace

void read_paper_summary(const std::filesystem::path& folder, PaperFigureData& data) {
  const std::string file = (folder / "summary.json").string();
  const OrderedJson json = read_summary(folder);
  const JsonField summary(file, json);
  data.iterations = summary_iterations(json, file);
  data.seeds_per_wall = summary_seeds_per_wall(json, file);

  const JsonField lengths = summary["episode_lengths"];
  lengths.expect_object();
  for (const Condition condition : kConditions) {
    const std::string name = enum_name(condition);
    if (!lengths.contains(name)) continue;
    PaperConditionData c;
    c.condition = condition;
    const JsonField run_lengths = lengths[name];
    const JsonField facts = summary["run_facts"][name];
    facts.expect_size(run_lengths.size());
    for (std::size_t i = 0; i < run_lengths.size(); ++i) {
      PaperRunData run;
      run.wall_pair = facts[i]["wall_pair"].integer(0);
      run.plan_length = facts[i]["plan_length"].integer(-1);
      const JsonField episodes = run_lengths[i];
      for (std::size_t e = 0; e < episodes.size(); ++e) run.episode_lengths.push_back(episodes[e].integer(1));
      c.runs.push_back(std::move(run));
    }
    for (int l = 0; l < kLimbCount; ++l) {
      const JsonField map = summary["qgrid_maps"][name][enum_name(static_cast<Limb>(l))];
      map.expect_size(static_cast<std::size_t>(data.grid.tile_count()));
      for (std::size_t t = 0; t < map.size(); ++t) c.q_grid_maps[l].push_back(map[t].number());
    }
    data.conditions.push_back(std::move(c));
  }
  if (data.conditions.empty()) summary.fail("episode_lengths holds none of training, transfer, control");

  const JsonField metrics = summary["transfer_vs_control"];
  metrics.expect_object();
  for (const auto& [name, value] : json["transfer_vs_control"].items()) {
    data.transfer_metrics.push_back(transfer_metric(metrics[name], name));
  }
}

PaperFigureData read_paper_figure_data(const std::filesystem::path& folder) {
  PaperFigureData data;
  const ExperimentConfig config = read_run_config(folder / "config.toml");
  data.grid = config.settings.learning.climbing.grid;
  read_paper_summary(folder, data);
  for (PaperConditionData& condition : data.conditions) {
    for (std::size_t i = 0; i < condition.runs.size(); ++i) {
      const std::filesystem::path file =
          folder / "runs" / fmt::format("{}_{}", enum_name(condition.condition), i) / "iterations.csv";
      for (const RunStep& step :
           read_iterations_file(file, data.iterations, config.settings.learning.climbing.physics.model))
        condition.runs[i].regimes.push_back(step.regime);
    }
  }
  return data;
}

}  // namespace crux
