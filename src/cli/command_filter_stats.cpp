// crux filter-stats: how many hold configurations pass the geometric filter (III-C).

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/progress_bar.hpp"
#include "common/random.hpp"
#include "reports/filter_description.hpp"
#include "wall/random_wall.hpp"

namespace crux::cli {

namespace {

// Random walls from wall.seed (wall i from a seed derived from it and i) and the filter.
const ParameterSet kFilterStatsKeys{{"wall", "filter", "output.progress"},
                                    {"wall.file", "wall.name", "wall.hold_radius", "wall.finish_height"}};

ExperimentConfig filter_stats_defaults() {
  ExperimentConfig defaults;
  defaults.wall_seed = 1;
  return defaults;
}

std::vector<ConfigField> filter_stats_fields(int& walls) { return {wall_count_field(walls)}; }

struct FilterStatsCommand {
  int walls = 20;  // its own key, wall.count
  ParameterBinding binding{"filter-stats", kFilterStatsKeys, filter_stats_defaults()};
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    FilterReport report;
    report.wall_count = walls;
    report.wall_seed = *config.wall_seed;
    report.parameters = config.settings.learning.climbing.filter;
    std::vector<Wall> walls;
    for (int i = 0; i < report.wall_count; ++i) {
      walls.push_back(generate_random_wall(derive_seed(report.wall_seed, i), config.settings.walls));
    }
    ProgressBar progress("filter-stats", report.wall_count, config.progress);
    report.counts = filter_statistics(walls, report.parameters, [&](int done) { progress.update(done); });
    progress.finish();
    std::cout << (json ? filter_json(report).dump(2) + "\n" : filter_text(report));
  }
};

}  // namespace

void add_filter_stats_command(CLI::App& app) {
  auto cmd = std::make_shared<FilterStatsCommand>();
  auto* command = app.add_subcommand(
      "filter-stats", "Share of 3- and 4-configurations passing the geometric filter over random walls (paper III-C)");
  cmd->binding.add_command_options(cmd->walls, filter_stats_fields);
  cmd->binding.bind(command);
  command->add_flag("--json", cmd->json, "Print JSON instead of text");
  command->callback([cmd] { cmd->run(); });
}

}  // namespace crux::cli
