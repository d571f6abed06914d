// crux filter-stats: how many hold configurations pass the geometric filter (III-C).

#include <iostream>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/progress_bar.hpp"
#include "common/input_error.hpp"
#include "common/random.hpp"
#include "configurations/filter_statistics.hpp"
#include "cli/parameter_binding.hpp"
#include "reports/paper_reference.hpp"
#include "wall/random_wall.hpp"

namespace crux::cli {

namespace {

// Random walls from wall.seed (wall i from a seed derived from it and i) and the filter.
const ParameterSet kFilterStatsParameters{{"wall", "filter"},
                                          {"wall.file", "wall.name", "wall.hold_radius", "wall.finish_height"}};

ExperimentConfig filter_stats_defaults() {
  ExperimentConfig defaults;
  defaults.wall_seed = 1;
  return defaults;
}

struct FilterStatsCommand {
  ParameterBinding binding{"filter-stats", kFilterStatsParameters, filter_stats_defaults()};
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    const int walls = config.wall_count;
    const std::uint64_t seed = *config.wall_seed;
    const FilterParameters& parameters = config.settings.learning.climbing.filter;
    const std::string& reading = config.reading;
    const FeetAboveHandsReading selected = parameters.feet_above_hands;
    std::vector<Wall> generated;
    for (int i = 0; i < walls; ++i) generated.push_back(generate_random_wall(derive_seed(seed, i), config.settings.walls));
    ProgressBar progress("filter-stats", walls);
    const auto counts = filter_statistics(generated, parameters, [&](int done) { progress.update(done); });
    progress.finish();
    std::size_t chosen = 0;
    for (std::size_t r = 0; r < kFeetAboveHandsReadings.size(); ++r) {
      if (kFeetAboveHandsReadings[r] == selected) chosen = r;
    }
    const FilterCounts& c = counts[chosen];
    if (json) {
      nlohmann::ordered_json out;
      out["wall_count"] = walls;
      out["wall_seed"] = seed;
      out["reading"] = reading;
      out["max_span_m"] = parameters.max_span_m;
      out["pass3"] = c.share3();
      out["pass4"] = c.share4();
      out["passing3"] = c.pass3;
      out["configurations3"] = c.configurations3;
      out["passing4"] = c.pass4;
      out["configurations4"] = c.configurations4;
      out["paper_pass3"] = kPaperFilterPass3;
      out["paper_pass4"] = kPaperFilterPass4;
      out["readings"] = nlohmann::json::array();
      for (std::size_t r = 0; r < counts.size(); ++r) {
        out["readings"].push_back({{"reading", reading_name(kFeetAboveHandsReadings[r])},
                                   {"pass3", counts[r].share3()},
                                   {"pass4", counts[r].share4()}});
      }
      std::cout << out.dump(2) << '\n';
      return;
    }
    std::cout << fmt::format("{} random walls (seed {}), span <= {} m, crossed arms and legs rejected\n", walls, seed,
                             parameters.max_span_m)
              << fmt::format("{:<34} {:>14} {:>14}\n", "reading of 'both feet above the hands'", "3-configs",
                             "4-configs");
    for (std::size_t r = 0; r < counts.size(); ++r) {
      std::cout << fmt::format("{:<34} {:>13.2f}% {:>13.2f}%{}\n", reading_name(kFeetAboveHandsReadings[r]),
                               100 * counts[r].share3(), 100 * counts[r].share4(), r == chosen ? "  <- selected" : "");
    }
    std::cout << fmt::format("{:<34} {:>13.1f}% {:>13.1f}%\n", "paper (section III-C)", 100 * kPaperFilterPass3,
                             100 * kPaperFilterPass4)
              << fmt::format("selected: {} of {} 3-configurations and {} of {} 4-configurations pass\n", c.pass3,
                             c.configurations3, c.pass4, c.configurations4);
  }
};

}  // namespace

void add_filter_stats_command(CLI::App& app) {
  auto cmd = std::make_shared<FilterStatsCommand>();
  auto* command = app.add_subcommand(
      "filter-stats", "Share of 3- and 4-configurations passing the geometric filter over random walls (paper III-C)");
  cmd->binding.bind(command);
  command->add_flag("--json", cmd->json, "Print JSON instead of text");
  command->callback([cmd] { cmd->run(); });
}

}  // namespace crux::cli
