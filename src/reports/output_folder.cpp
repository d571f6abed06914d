#include "reports/output_folder.hpp"

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "reports/figure_tables.hpp"
#include "reports/run_files.hpp"
#include "wall/wall_file.hpp"

namespace crux {

namespace fs = std::filesystem;

std::string config_file_text(ExperimentConfig& config, const ParameterSet& accepted, const Provenance& provenance) {
  return config_to_toml(config, accepted) + provenance_toml(provenance);
}

void write_experiment_folder(const fs::path& directory, const ExperimentResult& result,
                             const ExperimentSettings& settings, const BodyModel& model, const std::string& config_toml,
                             const nlohmann::ordered_json& summary) {
  make_output_directory(directory);
  write_file_atomically(directory / "config.toml", config_toml);
  make_output_directory(directory / "walls");
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
  make_output_directory(directory / "figures");
  write_file_atomically(directory / "figures" / "fig3_regimes.csv", fig3_csv(result, settings.learning.iterations));
  write_file_atomically(directory / "figures" / "fig4_episode_lengths.csv", fig4_csv(result));
  write_file_atomically(directory / "figures" / "fig2b_qgrid_maps.csv",
                        fig2b_csv(result, settings.learning.climbing.grid));
  write_file_atomically(directory / "summary.json", summary.dump(2) + "\n");
}

void write_run_folder(const fs::path& directory, const ExperimentResult& result, const BodyModel& model,
                      const std::string& config_toml, const nlohmann::ordered_json& summary) {
  for (const ConditionResult& c : result.conditions) {
    if (!c.runs.empty()) write_run_files(directory, c.runs.front(), model);
  }
  write_file_atomically(directory / "config.toml", config_toml);
  save_wall((directory / "wall.json").string(), result.walls.front().wall);
  write_file_atomically(directory / "summary.json", summary.dump(2) + "\n");
}

}  // namespace crux
