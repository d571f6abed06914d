#pragma once
// Every parameter of a crux command, settable by command-line flag, TOML config file
// (flags win) or Python dict, and written back as the effective config.toml. Each key is
// declared once, by the layer whose parameter struct it sets (ik/ik_keys, ...; the
// experiment's own keys here), and config_fields gathers them: its type (an enum is
// parsed into the parameter struct's own enum where the flag, file or dict gives it), its
// unit, its bounds and its help (common/config_field). The flags with their --help, the TOML reader and writer with
// config.toml's comments, Python's dicts and crux.config_keys() all come from that declaration. The key "section.name"
// is the flag "--section-name" ("--name" for the section experiment), underscores becoming dashes. A command takes a
// subset of the keys (ParameterSet); any other is refused.

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "common/config_field.hpp"
#include "common/progress_display.hpp"
#include "experiments/paper_experiment.hpp"

namespace crux {

struct ExperimentConfig {
  ExperimentParameters settings;
  std::string urdf;    // empty: the default body model
  std::string q_grid;  // transfer: the Q_grid learnt by a training run
  std::string policy;  // train under experiment.transfer = network: the policy network's file
  std::string wall_file;
  std::optional<std::uint64_t> wall_seed;
  int checkpoint_every = 0;  // train, transfer: iterations between checkpoints (run_checkpoint.hpp)
  // crux perform: a run folder whose climb (greedy, last or an episode N; empty: greedy)
  // is performed instead of a wall's plan; empty: the plan. Unset, neither is written to
  // config.toml.
  std::string run;
  std::string climb;
  // N walls with one seed each, the paper's design, when given: finalize_config turns it
  // into walls = N, seeds_per_wall = 1 and clears it.
  std::optional<int> runs;
  // [training_wall]: each key unset follows its [wall] key; finalize_config resolves
  // them into settings.training_wall.
  struct TrainingWallKeys {
    std::optional<int> columns, rows;
    std::optional<double> tile_width, tile_height, sigma, hold_radius, finish_height, incline;
  } training_wall;
  // Table I's beginning window; 0: the paper's 2000 iterations, or all of them when a
  // run is shorter (kept as 0, so that a replay with fewer iterations still works).
  int beginning = 0;
  // physics.strength: a climbing level whose grip finalize_config sets, unless physics.grip
  // is given; empty (unset, and then not written to config.toml): physics.grip alone.
  std::string physics_strength;
  // output.progress: how long commands show their progress on stderr (no result depends on it).
  ProgressDisplay progress = ProgressDisplay::Bar;
  // The [provenance] table of a config file read back (key -> value), to be checked
  // against the inputs of the replay.
  std::map<std::string, std::string> recorded_provenance;
  // The keys a config file, a flag or a Python dict set (the rest are defaults):
  // finalize_config refuses those that a given wall file makes meaningless.
  std::set<std::string> given;
};

// The random wall generator's keys (wall.columns ... wall.finish_height): a wall file
// gives its holds and finishing height itself, so none applies to it.
bool is_wall_generator_key(const std::string& key);

// The fields of `config`, in a fixed order (the same for every config object): the one
// declaration of every key.
std::vector<ConfigField> config_fields(ExperimentConfig& config);
std::vector<ConstConfigField> config_fields(const ExperimentConfig& config);

// `field` as a read-only field (a command's own fields are declared over mutable options).
ConstConfigField as_const(const ConfigField& field);

// `field`'s value as config.toml writes it ("" when unset), or, with `toml` false, as
// plain text (a string without quotes).
std::string field_value_text(const ConstConfigField& field, bool toml = true);

// `key`'s field, or null.
const ConfigField* find_field(const std::vector<ConfigField>& fields, std::string_view key);

// Every number of `fields` within its declared bounds (and finite); unset optional numbers
// are not checked. InputError(key, problem) otherwise.
void require_within_bounds(std::span<const ConfigField> fields);

// Sets a choice or text field from text as a flag or a Python string gives it (numbers
// reach their fields typed, through CLI11 or Python). Throws InputError(key, problem) for
// a name that is not one of the choices, or for a field of another type.
void assign_text(const ConfigField& field, const std::string& text);

// "--section-name" for "section.name", "--name" for "experiment.name".
std::string flag_for_key(const std::string& key);

// The keys a command takes: those equal to, or in a section named by, an entry of
// `include` ("ik" takes every ik.* key, "experiment.seed" that key), minus `exclude`.
struct ParameterSet {
  std::vector<std::string> include;
  std::vector<std::string> exclude;
  // physics.model = dynamic performs moves in MuJoCo: the commands that plan and single
  // learning runs take it; those that run many do not.
  bool takes_dynamic_physics = false;
  bool accepts(const std::string& key) const;
};

// InputError("physics.model", ...) when `config` asks for a physics model that `caller`
// (a command's name, or crux.<function> in Python) does not take.
void require_physics_model_taken(const ExperimentConfig& config, const ParameterSet& accepted,
                                 const std::string& caller);

// InputError(key, why) for the first key of `config` in `keys` (a key, or a section such as
// "wall.") that is not at its default: a key the caller would not use, refused rather
// than ignored. A config.toml written without using them records them at their defaults,
// so that it replays.
void refuse_keys_off_default(const ExperimentConfig& config, std::initializer_list<std::string_view> keys,
                             std::string_view why);

// InputError(key, ...) for a perform.* key given another value than its default while
// physics.model is not dynamic: under the other models `caller` performs nothing in
// MuJoCo, so the key is refused rather than ignored (a config.toml records the keys at
// their defaults, and replays).
void require_perform_keys_used(const ExperimentConfig& config, const std::string& caller);

// A config file's TOML, parsed once: a sweep applies it once per cell, so that expanding
// a sweep costs one parse and grows linearly with its cells.
class ConfigDocument {
 public:
  // InputError(source, ...) for a TOML syntax error.
  ConfigDocument(const std::string& text, std::string source);
  ConfigDocument(ConfigDocument&&) noexcept;
  ConfigDocument& operator=(ConfigDocument&&) noexcept;
  ~ConfigDocument();

  const std::string& source() const { return source_; }
  struct Table;
  const Table& table() const { return *table_; }
  // The line that sets `key` ("section.name"), if the document sets it.
  std::optional<int> line_of(const std::string& key) const;

  // The config texts this process has parsed so far (tests count parses with it).
  static std::size_t parses();

 private:
  std::string source_;
  std::unique_ptr<Table> table_;
};

// Where each key of a config file was set: key -> line.
using ConfigLines = std::map<std::string, int>;

// A sweep's file may give a key a list of values (crux sweep): which value of each
// listed key to apply, by key.
using ListChoice = std::map<std::string, std::size_t>;

// Applies a TOML file over `config`. Throws InputError(path, problem) for syntax errors
// (with the line), keys this command does not take (`command` names it), and values of
// the wrong type. A list takes its `choice`th value; a list without a choice is an
// error. The [provenance] table goes to config.recorded_provenance.
ConfigLines apply_config_file(const std::string& path, ExperimentConfig& config, const ParameterSet& accepted,
                              const std::string& command, const ListChoice& choice = {});
// The same for TOML text already read; `source` names it in errors.
ConfigLines apply_config_text(const std::string& text, const std::string& source, ExperimentConfig& config,
                              const ParameterSet& accepted, const std::string& command, const ListChoice& choice = {});
// The same for a parsed document.
ConfigLines apply_config_document(const ConfigDocument& document, ExperimentConfig& config,
                                  const ParameterSet& accepted, const std::string& command,
                                  const ListChoice& choice = {});
// ... with a command's own keys besides (declared beside the command, over its own options:
// `command_fields`), which the file may set as it sets the others.
ConfigLines apply_config_document(const ConfigDocument& document, ExperimentConfig& config,
                                  std::span<const ConfigField> command_fields, const ParameterSet& accepted,
                                  const std::string& command, const ListChoice& choice = {});

// The accepted keys given a list of values in TOML `text`, in the order of
// config_fields: InputError(source, ...) for an empty list or a key that takes one value.
struct ListedKey {
  std::string key;
  std::size_t values = 0;
};
std::vector<ListedKey> listed_keys(const ConfigDocument& document, const ParameterSet& accepted);

// Upper bounds of finalize_config. Threads: more than any machine crux runs on has cores
// (a thread per value would abort when the system refuses to start them). Iterations:
// a run keeps ~135 bytes per iteration (1.35 GB at the bound), 1250 times the paper's 8000.
inline constexpr int kMaxThreads = 1024;
inline constexpr int kMaxIterations = 10000000;

// Checks every number against its declared bounds and the keys against each other, and
// derives what follows from them (runs, the beginning window, physics.strength's grip,
// the static model's ik.wall when not given, the training walls). Throws
// InputError(key, problem), `key` being the config key at fault ("experiment.runs").
void finalize_config(ExperimentConfig& config);

// The accepted keys of `config` as TOML, sections in table order; unset optional values
// and empty file names are left out. A key of `lists` is written with that value text
// (a sweep's list) instead of config's.
std::string config_to_toml(const ExperimentConfig& config, const ParameterSet& accepted,
                           const std::map<std::string, std::string>& lists = {});

// `key`'s value in `config` as config_to_toml writes it ("" when unset), or, with
// `toml` false, as plain text (a string without quotes).
std::string config_value_text(const ExperimentConfig& config, const std::string& key, bool toml = true);

// `value` as a TOML basic string (quotes, backslashes and control characters escaped).
std::string toml_quoted(const std::string& value);

}  // namespace crux
