#pragma once
// Every parameter of a learning experiment, settable by command-line flag or by TOML
// config file (flags win), and written back as the effective config.toml. One table of
// fields serves the flags, the reader and the writer.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "experiments/paper_experiment.hpp"

namespace crux {

struct ExperimentConfig {
  ExperimentSettings settings;
  // N walls with one seed each, the paper's design; 0: walls and seeds_per_wall apply.
  // finalize_config turns it into walls = N, seeds_per_wall = 1 and clears it.
  int runs = 0;
  std::string solver = "fast";
  std::string planner = planner_name(Planner::Uniform);
  std::string reading = reading_name(FilterParameters{}.feet_above_hands);
};

using ConfigTarget = std::variant<double*, int*, std::uint64_t*, bool*, std::string*>;

struct ConfigField {
  std::string key;   // TOML "section.name"
  std::string flag;  // command-line "--name"
  std::string help;
  ConfigTarget target;
};

// The fields of `config`, in a fixed order (the same for every config object).
std::vector<ConfigField> config_fields(ExperimentConfig& config);

// Applies a TOML file over `config`. Throws InputError(path, problem) for syntax errors
// (with the line), unknown keys, and values of the wrong type or range.
void apply_config_file(const std::string& path, ExperimentConfig& config);

// Parses the textual choices into the settings and checks ranges; InputError on errors.
void finalize_config(ExperimentConfig& config);

std::string config_to_toml(ExperimentConfig& config);

}  // namespace crux
