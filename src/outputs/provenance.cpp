#include "outputs/provenance.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "common/build_info.hpp"
#include "common/input_error.hpp"
#include "common/sha256.hpp"
#include "experiments/run_inputs.hpp"

namespace crux {

namespace {

std::string absolute_path(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

}  // namespace

std::string configured_urdf(const ExperimentConfig& config) { return absolute_path(configured_urdf_path(config)); }

Provenance record_provenance(const ExperimentConfig& config) {
  Provenance p;
  p.crux_version = crux_version();
  p.git_commit = git_commit();
  p.urdf = configured_urdf(config);
  p.urdf_sha256 = sha256_of_file(p.urdf, "URDF file");
  if (!config.wall_file.empty()) {
    p.wall_file = absolute_path(config.wall_file);
    p.wall_sha256 = sha256_of_file(config.wall_file, "wall file");
  } else {
    p.wall_seed = config.wall_seed;
  }
  if (!config.q_grid.empty()) {
    p.q_grid = absolute_path(config.q_grid);
    p.q_grid_sha256 = sha256_of_file(config.q_grid, "Q-table file");
  }
  if (!config.policy.empty()) {
    p.policy = absolute_path(config.policy);
    p.policy_sha256 = sha256_of_file(config.policy, "policy file");
  }
  return p;
}

std::string provenance_toml(const Provenance& p) {
  std::string out = "\n[provenance]  # what produced this folder; a replay checks the digests\n";
  const auto line = [&](const char* key, const std::string& value) {
    if (!value.empty()) out += fmt::format("{} = {}\n", key, toml_quoted(value));
  };
  line("crux_version", p.crux_version);
  line("git_commit", p.git_commit);
  line("produced_by", p.produced_by);
  line("urdf", p.urdf);
  line("urdf_sha256", p.urdf_sha256);
  line("wall_file", p.wall_file);
  line("wall_sha256", p.wall_sha256);
  line("q_grid", p.q_grid);
  line("q_grid_sha256", p.q_grid_sha256);
  line("policy", p.policy);
  line("policy_sha256", p.policy_sha256);
  return out;
}

nlohmann::ordered_json provenance_json(const Provenance& p) {
  const auto text_or_null = [](const std::string& value) {
    return value.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(value);
  };
  nlohmann::ordered_json out;
  out["crux_version"] = p.crux_version;
  out["git_commit"] = text_or_null(p.git_commit);
  out["produced_by"] = text_or_null(p.produced_by);
  out["urdf"] = p.urdf;
  out["urdf_sha256"] = p.urdf_sha256;
  out["wall_file"] = text_or_null(p.wall_file);
  out["wall_sha256"] = text_or_null(p.wall_sha256);
  out["wall_seed"] = p.wall_seed ? nlohmann::ordered_json(*p.wall_seed) : nlohmann::ordered_json(nullptr);
  out["q_grid"] = text_or_null(p.q_grid);
  out["q_grid_sha256"] = text_or_null(p.q_grid_sha256);
  if (!p.policy.empty()) {  // only the network mode's runs have one: the others' summaries stay as they were
    out["policy"] = p.policy;
    out["policy_sha256"] = p.policy_sha256;
  }
  return out;
}

void check_recorded_provenance(const ExperimentConfig& config, const Provenance& now, const std::string& config_path) {
  struct Digest {
    const char* key;
    const char* what;
    const std::string& file;
    const std::string& sha256;
  };
  for (const Digest& d : {Digest{"urdf_sha256", "URDF", now.urdf, now.urdf_sha256},
                          Digest{"wall_sha256", "wall file", now.wall_file, now.wall_sha256},
                          Digest{"q_grid_sha256", "Q_grid file", now.q_grid, now.q_grid_sha256},
                          Digest{"policy_sha256", "policy file", now.policy, now.policy_sha256}}) {
    const auto recorded = config.recorded_provenance.find(d.key);
    if (recorded == config.recorded_provenance.end() || recorded->second == d.sha256) continue;
    throw InputError(config_path,
                     fmt::format("provenance.{}: the {} {} is not the one this config was written with (sha256 {}, "
                                 "recorded {}); delete that line to run with it anyway",
                                 d.key, d.what, d.file.empty() ? "(none)" : d.file, d.sha256.empty() ? "-" : d.sha256,
                                 recorded->second));
  }
}

}  // namespace crux
