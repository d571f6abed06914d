#include "cli/parameter_binding.hpp"

#include <algorithm>
#include <iostream>
#include <set>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "experiments/config_key_json.hpp"

namespace crux::cli {

namespace {

// CLI11 reads "-1" as 2^64 - 1 and wraps overflows; a seed is written in digits only.
const CLI::Validator kSeedDigits(
    [](std::string& text) -> std::string {
      const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
      if (digits && (text.size() < 20 || (text.size() == 20 && text <= "18446744073709551615"))) return {};
      return fmt::format("'{}' is not an integer from 0 to 18446744073709551615", text);
    },
    "SEED");

std::set<std::string>& command_owned_keys() {
  static std::set<std::string> keys;
  return keys;
}

}  // namespace

void ParameterBinding::register_command_keys(const std::vector<ConfigField>& fields) {
  for (const ConfigField& field : fields) command_owned_keys().insert(field.key);
}

void ParameterBinding::refuse_other_commands_keys() {
  for (const std::string& key : command_owned_keys()) {
    const bool own = std::any_of(command_fields_.begin(), command_fields_.end(),
                                 [&](const ConfigField& field) { return field.key == key; });
    if (own) continue;
    if (const std::optional<int> line = document().line_of(key)) {
      throw InputError(config_path_, fmt::format("line {}: crux {} does not take {}", *line, command_, key));
    }
  }
}

ParameterBinding::ParameterBinding(std::string command, ParameterSet accepted, ExperimentConfig defaults)
    : command_(std::move(command)),
      accepted_(std::move(accepted)),
      defaults_(defaults),
      from_flags_(std::move(defaults)) {}

void ParameterBinding::bind_field(CLI::App* command, const ConfigField& field) {
  if (!accepted_.accepts(field.key)) return;
  const std::string help = field.described_help();
  std::visit(
      [&](auto target) {
        using T = std::remove_pointer_t<decltype(target)>;
        CLI::Option* option = nullptr;
        if constexpr (std::is_same_v<T, ChoiceTarget<false>>) {
          std::string& text = choice_texts_[field.key];
          option = command->add_option(flag_for_key(field.key), text, help);
          option->default_str(target.type->text(target.target));
        } else {
          option = command->add_option(flag_for_key(field.key), *target, help);
          if constexpr (std::is_same_v<T, std::uint64_t> || std::is_same_v<T, std::optional<std::uint64_t>>) {
            option->check(kSeedDigits);
          }
          if constexpr (std::is_same_v<T, std::optional<std::uint64_t>> || std::is_same_v<T, std::optional<int>> ||
                        std::is_same_v<T, std::optional<double>>) {
            if (target->has_value()) option->default_str(fmt::format("{}", **target));
          } else if constexpr (std::is_same_v<T, std::string>) {
            if (!target->empty()) option->capture_default_str();
          } else {
            option->capture_default_str();
          }
        }
        options_.emplace_back(field.key, option);
      },
      field.target);
}

void ParameterBinding::bind(CLI::App* command, bool dry_run) {
  command_app_ = command;
  if (dry_run) {
    command->add_flag("--dry-run", dry_run_,
                      "Check every parameter, print the effective ones (TOML that --config reads; with --json each "
                      "key's value, type and bounds) and exit, running nothing");
  }
  command->add_option("--config", config_path_,
                      "TOML config file, keys as in the config.toml crux writes (flags override it)");
  for (const ConfigField& field : config_fields(from_flags_)) bind_field(command, field);
  for (const ConfigField& field : command_flag_fields_) bind_field(command, field);
  if (CLI::Option* progress = option("output.progress"); progress != nullptr) {
    command->add_flag("-q,--quiet", quiet_, "Show no progress on stderr (output.progress = \"none\")")
        ->excludes(progress);
  }
  // A wall is a file or a seed.
  if (CLI::Option* file = option("wall.file"); file != nullptr) {
    if (CLI::Option* seed = option("wall.seed"); seed != nullptr) file->excludes(seed);
  }
}

CLI::Option* ParameterBinding::option(const std::string& key) const {
  for (const auto& [k, option] : options_) {
    if (k == key) return option;
  }
  return nullptr;
}

std::string ParameterBinding::where(const std::string& key) const {
  const CLI::Option* given = option(key);
  if (given != nullptr && given->count() > 0) return flag_for_key(key);
  if (const auto line = lines_.find(key); line != lines_.end()) {
    return fmt::format("{}: line {}: {}", config_path_, line->second, key);
  }
  return given != nullptr ? flag_for_key(key) : key;
}

bool ParameterBinding::is_set(const std::string& key) const {
  const CLI::Option* given = option(key);
  return (given != nullptr && given->count() > 0) || lines_.contains(key);
}

const ConfigDocument& ParameterBinding::document() {
  if (!document_) document_.emplace(read_input_file(config_path_, "config file"), config_path_);
  return *document_;
}

std::vector<ListedKey> ParameterBinding::listed_keys() {
  if (config_path_.empty()) return {};
  std::vector<ListedKey> listed = crux::listed_keys(document(), accepted_);
  std::erase_if(listed, [&](const ListedKey& k) {
    const CLI::Option* given = option(k.key);
    return given != nullptr && given->count() > 0;
  });
  return listed;
}

void ParameterBinding::take_flag(const ConfigField& flag, const ConfigField& field, ExperimentConfig& config) {
  const CLI::Option* given = option(field.key);
  if (given == nullptr || given->count() == 0) return;
  config.given.insert(field.key);
  std::visit(
      [&](auto destination) {
        if constexpr (std::is_pointer_v<decltype(destination)>) {
          *destination = *std::get<decltype(destination)>(flag.target);
        } else {
          try {
            assign_text(field, choice_texts_.at(field.key));
          } catch (const InputError& e) {
            throw InputError(where(e.source()), e.problem());
          }
        }
      },
      field.target);
}

ExperimentConfig ParameterBinding::resolve(const ListChoice& choice) {
  ExperimentConfig config = defaults_;
  // A flag replaces a key's list as it replaces a value.
  ListChoice effective = choice;
  for (const auto& [key, given] : options_) {
    if (given->count() > 0) effective.emplace(key, 0);
  }
  if (reset_command_options_) reset_command_options_();
  if (!config_path_.empty()) {
    refuse_other_commands_keys();
    lines_ = apply_config_document(document(), config, command_fields_, accepted_, command_, effective);
  }
  const auto flags = config_fields(from_flags_);
  const auto fields = config_fields(config);
  for (std::size_t i = 0; i < fields.size(); ++i) take_flag(flags[i], fields[i], config);
  for (std::size_t i = 0; i < command_fields_.size(); ++i)
    take_flag(command_flag_fields_[i], command_fields_[i], config);
  if (quiet_) config.progress = ProgressDisplay::None;
  // A wall flag replaces the config file's wall of the other kind.
  if (const CLI::Option* seed = option("wall.seed"); seed != nullptr && seed->count() > 0) config.wall_file.clear();
  if (const CLI::Option* file = option("wall.file"); file != nullptr && file->count() > 0) config.wall_seed.reset();
  // An input named on the command line replaces the config's: its recorded digest no
  // longer applies.
  const auto given = [&](const char* key) {
    const CLI::Option* o = option(key);
    return o != nullptr && o->count() > 0;
  };
  // A wall file on the command line replaces a config file's random wall, the wall's
  // parameters with it.
  if (given("wall.file")) {
    std::erase_if(config.given,
                  [&](const std::string& key) { return is_wall_generator_key(key) && !given(key.c_str()); });
  }
  if (given("experiment.urdf")) config.recorded_provenance.erase("urdf_sha256");
  if (given("wall.file") || given("wall.seed")) config.recorded_provenance.erase("wall_sha256");
  if (given("experiment.q_grid")) config.recorded_provenance.erase("q_grid_sha256");
  if (given("experiment.policy")) config.recorded_provenance.erase("policy_sha256");
  if (!config.wall_file.empty() && config.wall_seed) {
    throw InputError(where("wall.seed"), "give a wall file or a wall seed, not both");
  }
  try {
    require_within_bounds(command_fields_);
    finalize_config(config);
    require_physics_model_taken(config, accepted_, "crux " + command_);
  } catch (const InputError& e) {
    throw InputError(where(e.source()), e.problem());
  }
  if (dry_run_) print_dry_run(config);
  return config;
}

void ParameterBinding::print_dry_run(const ExperimentConfig& config) const {
  std::vector<ConstConfigField> fields;
  for (const ConstConfigField& field : config_fields(config)) {
    if (accepted_.accepts(field.key)) fields.push_back(field);
  }
  for (const ConfigField& field : command_fields_) fields.push_back(as_const(field));
  const CLI::Option* json = command_app_->get_option_no_throw("--json");
  if (json != nullptr && json->count() > 0) {
    nlohmann::ordered_json keys = nlohmann::ordered_json::array();
    for (const ConstConfigField& field : fields) keys.push_back(config_key_json(field));
    std::cout << nlohmann::ordered_json{{"command", command_}, {"keys", std::move(keys)}}.dump(2) << '\n';
  } else {
    // Dotted keys, so that the text is a config file any command reads.
    std::cout << fmt::format("# crux {} --dry-run: the effective parameters; nothing ran\n", command_);
    for (const ConstConfigField& field : fields) {
      const std::string value = field_value_text(field);
      if (!value.empty()) std::cout << fmt::format("{} = {}  # {}\n", field.key, value, field.described_help());
    }
  }
  std::cout.flush();
  throw DryRunDone{};
}

}  // namespace crux::cli
