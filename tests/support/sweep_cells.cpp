#include "support/sweep_cells.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>

#include "jobs/command_keys.hpp"
#include "support/test_models.hpp"

namespace crux::testing {

ExperimentConfig small_sweep_config(int walls, int iterations, const std::string& toml) {
  ExperimentConfig config;
  config.settings.wall_pairs = walls;
  config.settings.learning.iterations = iterations;
  config.settings.plan = false;
  config.settings.analysis.bootstrap_resamples = 200;
  if (!toml.empty()) apply_config_text(toml, "test.toml", config, kPaperKeys, "sweep");
  finalize_config(config);
  return config;
}

SweepCell sweep_cell(ExperimentConfig config, std::vector<std::string> values) {
  SweepCell cell;
  cell.config = std::move(config);
  cell.values = std::move(values);
  return cell;
}

std::map<std::string, std::string> folder_contents(const std::filesystem::path& folder) {
  std::map<std::string, std::string> contents;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    contents[std::filesystem::relative(entry.path(), folder).string()] = bytes.str();
  }
  return contents;
}

std::filesystem::path sweep_scratch(const std::string& name) {
  const std::filesystem::path dir = test_folder() / "sweep" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir.parent_path());
  return dir;
}

}  // namespace crux::testing
