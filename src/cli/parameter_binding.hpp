#pragma once
// Binds a command's parameters (a ParameterSet of the config table) to flags and to
// --config FILE. Flags given on the command line override the file, which overrides the
// command's defaults. Every error names what the user typed: the flag, or the file, its
// line and the key.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "experiments/experiment_config.hpp"

namespace crux::cli {

// `keys` and output.progress: the set of a command that shows its progress.
inline ParameterSet with_progress(ParameterSet keys) {
  keys.include.push_back("output.progress");
  return keys;
}

class ParameterBinding {
 public:
  ParameterBinding(std::string command, ParameterSet accepted, ExperimentConfig defaults = {});

  void bind(CLI::App* command);
  CLI::Option* option(const std::string& key) const;

  // The effective parameters, finalized (finalize_config); a list in the config file
  // (crux sweep) takes the value `choice` names.
  ExperimentConfig resolve(const ListChoice& choice = {});
  // The config file's keys given a list of values, minus those a flag sets to one value.
  std::vector<ListedKey> listed_keys();

  const ParameterSet& accepted() const { return accepted_; }
  const std::string& config_path() const { return config_path_; }
  // How the user named `key`: its flag when given (or never set), else file:line:key.
  std::string where(const std::string& key) const;
  // Whether `key` was given, by flag or by the config file (after resolve()).
  bool is_set(const std::string& key) const;

 private:
  std::string command_;
  ParameterSet accepted_;
  ExperimentConfig defaults_;
  ExperimentConfig from_flags_;
  std::string config_path_;
  std::vector<std::pair<std::string, CLI::Option*>> options_;  // key, its flag
  // A choice's flag text by key, parsed by resolve() so that its error names the flag.
  std::map<std::string, std::string> choice_texts_;
  ConfigLines lines_;
  // The config file, read and parsed at its first use: a sweep resolves every cell from it.
  std::optional<ConfigDocument> document_;

  const ConfigDocument& document();
};

}  // namespace crux::cli
