#pragma once
// What produced an output folder: crux's version and git commit, the command or Python
// function that ran it, and the input files
// with their SHA-256 digests (or the wall's seed). config.toml carries it as a
// [provenance] table, summary.json as "provenance"; a replay checks the digests.

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "experiments/experiment_config.hpp"

namespace crux {

struct Provenance {
  std::string crux_version, git_commit;
  std::string produced_by;  // the command or function that wrote the folder: "crux train", "crux.run_learning", ...
  std::string urdf, urdf_sha256;  // absolute path
  std::string wall_file, wall_sha256;
  std::optional<std::uint64_t> wall_seed;
  std::string q_grid, q_grid_sha256;
  std::string policy, policy_sha256;  // the network transfer mode's policy file
};

// The body model path (the default one when none is configured), made absolute.
std::string configured_urdf(const ExperimentConfig& config);

// Reads the configured input files to digest them; InputError naming an unreadable one.
Provenance record_provenance(const ExperimentConfig& config);

std::string provenance_toml(const Provenance& provenance);
nlohmann::ordered_json provenance_json(const Provenance& provenance);

// When `config` was read from a file with a [provenance] table, every digest recorded
// there must match the file used now: InputError(config_path, ...) otherwise.
void check_recorded_provenance(const ExperimentConfig& config, const Provenance& now, const std::string& config_path);

}  // namespace crux
