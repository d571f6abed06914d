#include "outputs/run_config_file.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/input_error.hpp"

namespace crux {

namespace {

// A run written under physics.model = dynamic records the perform.* keys too.
const std::vector<std::string> kRecordedSections{"experiment", "learning", "reward", "ik",   "physics",      "perform",
                                                 "compare",    "filter",   "grid",   "wall", "training_wall"};
const ParameterSet kEveryRecordedKey{kRecordedSections, {}, true};

ExperimentConfig read_recorded_config(const std::filesystem::path& path, const ParameterSet& keys, bool grid) {
  const std::string file = path.string();
  ExperimentConfig config;
  const ConfigLines lines = apply_config_file(file, config, keys, "the run's config");
  for (const ConfigField& field : config_fields(config)) {
    // Folders written before the reach agent space have no grid.agent_space: the grid's.
    if (grid && field.key.starts_with("grid.") && field.key != "grid.agent_space" && !lines.contains(field.key)) {
      throw InputError(file, fmt::format("{} is missing (crux writes every grid key)", field.key));
    }
  }
  // Folders written before config.toml left a wall file's unused random-wall keys out
  // recorded them all; what crux wrote it reads back.
  std::erase_if(config.given, is_wall_generator_key);
  // Folders written before config.toml recorded the static model's ik.wall as what ran
  // recorded the ignore they were given; they ran with avoid, as finalize_config now sets.
  if (checks_stances(config.settings.learning.climbing.physics.model)) config.given.erase("ik.wall");
  try {
    finalize_config(config);
  } catch (const InputError& e) {
    const auto line = lines.find(e.source());
    throw InputError(line == lines.end() ? file : fmt::format("{}: line {}: {}", file, line->second, e.source()),
                     e.problem());
  }
  return config;
}

}  // namespace

ExperimentConfig read_run_config(const std::filesystem::path& path) {
  return read_recorded_config(path, kEveryRecordedKey, true);
}

ExperimentConfig read_perform_config(const std::filesystem::path& path) {
  return read_recorded_config(path, kEveryRecordedKey, false);
}

}  // namespace crux
