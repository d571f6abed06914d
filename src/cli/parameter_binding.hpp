#pragma once
// Binds a command's parameters (a ParameterSet of the config table) to flags and to
// --config FILE. Flags given on the command line override the file, which overrides the
// command's defaults. Every error names what the user typed: the flag, or the file, its
// line and the key.

#include <functional>
#include <map>
#include <memory>
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

// wall.count, the random walls filter-stats and stances count over: a key of those two
// commands, declared once for both.
inline ConfigField wall_count_field(int& count) {
  return {"wall.count", "Random walls to count over", &count, "", work_size(1, 100000)};
}

// Thrown by resolve() under --dry-run once it has printed the effective parameters: the
// command ends there, having run nothing and written no file (main returns 0).
struct DryRunDone {};

class ParameterBinding {
 public:
  ParameterBinding(std::string command, ParameterSet accepted, ExperimentConfig defaults = {});

  // A command's own keys, declared beside the command by `fields` over its own `options`,
  // which resolve() fills as it fills the config: the defaults `options` holds now, then
  // --config, then the flags. Call before bind().
  template <typename Options>
  void add_command_options(Options& options, std::vector<ConfigField> (*fields)(Options&)) {
    auto from_flags = std::make_shared<Options>(options);
    command_flag_fields_ = fields(*from_flags);
    command_fields_ = fields(options);
    register_command_keys(command_fields_);
    command_from_flags_ = std::move(from_flags);
    reset_command_options_ = [&options, defaults = options] { options = defaults; };
  }

  // The flags, --config, --quiet for a command that shows progress, and --dry-run unless
  // `dry_run` is false (crux sweep, which resolves once per cell).
  void bind(CLI::App* command, bool dry_run = true);
  CLI::Option* option(const std::string& key) const;

  // The effective parameters, finalized (finalize_config); a list in the config file
  // (crux sweep) takes the value `choice` names. Under --dry-run it prints them instead
  // (as TOML, or with the command's --json as every key's declaration and value) and
  // throws DryRunDone.
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
  bool quiet_ = false;  // --quiet: output.progress = "none"
  bool dry_run_ = false;
  const CLI::App* command_app_ = nullptr;
  std::vector<std::pair<std::string, CLI::Option*>> options_;  // key, its flag
  // A choice's flag text by key, parsed by resolve() so that its error names the flag.
  std::map<std::string, std::string> choice_texts_;
  ConfigLines lines_;
  // The config file, read and parsed at its first use: a sweep resolves every cell from it.
  std::optional<ConfigDocument> document_;
  // add_command_options': the flags' copy of the options, its fields, the options' own.
  std::shared_ptr<void> command_from_flags_;
  std::vector<ConfigField> command_flag_fields_, command_fields_;
  std::function<void()> reset_command_options_;

  // Every command's own keys, so that a config file giving one to another command is told
  // that this command does not take it, not that the key is unknown.
  static void register_command_keys(const std::vector<ConfigField>& fields);
  void refuse_other_commands_keys();

  void bind_field(CLI::App* command, const ConfigField& field);
  // `field` takes the value its flag gave `flag`'s target, if the flag was given.
  void take_flag(const ConfigField& flag, const ConfigField& field, ExperimentConfig& config);

  const ConfigDocument& document();
  [[noreturn]] void print_dry_run(const ExperimentConfig& config) const;
};

}  // namespace crux::cli
