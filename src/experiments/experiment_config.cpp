#include "experiments/experiment_config.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include "agent_space/grid_keys.hpp"
#include "climbing/climbing_keys.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/printable.hpp"
#include "configurations/configuration_keys.hpp"
#include "experiments/stance_survey.hpp"
#include "ik/ik_keys.hpp"
#include "learning/learning_keys.hpp"
#include "physics/physics_keys.hpp"
#include "physics/strength_profile.hpp"
#include "simulation/perform_keys.hpp"
#include "wall/random_wall_keys.hpp"

namespace crux {

namespace {

// Runs per condition: the statistics keep each run's record in memory (about 1 kB each).
constexpr int kMaxRunsPerCondition = 1000000;
// Each training run learns K times its iterations: beyond this a typo, not an experiment.
constexpr int kMaxTrainingWalls = 1000;

// The one declaration of every key, for a config or a const one, section by section in
// config.toml's order. Units and bounds go in their columns, not in the help, which says
// what the key means.
template <typename Config>
using FieldOf = ConfigFieldOf<std::is_const_v<Config>>;

// The [experiment] keys: the experiment's design, its inputs and its analysis.
template <typename Config>
void experiment_keys(std::vector<FieldOf<Config>>& keys, Config& c) {
  auto& s = c.settings;
  auto& l = c.settings.learning;
  keys.insert(
      keys.end(),
      {
          {"experiment.urdf", "URDF file of the body (default: the installed crux_human.urdf)", &c.urdf, "", {}, true},
          {"experiment.seed", "Seed: the experiment's walls and runs, a run's learning or the queries derive from it",
           &s.seed},
          {"experiment.runs", "N walls with one seed each: sets walls = N and seeds_per_wall = 1", &c.runs, "",
           work_size(1, kMaxRunsPerCondition)},
          {"experiment.walls", "Wall pairs (training and transfer wall); the unit of the statistics", &s.wall_pairs, "",
           work_size(1, kMaxRunsPerCondition)},
          {"experiment.seeds_per_wall", "Learning seeds per wall pair", &s.seeds_per_wall, "",
           work_size(1, kMaxRunsPerCondition)},
          {"experiment.training_walls",
           "Walls each training run learns Q_grid on in sequence before transfer (docs/TRANSFER.md): the last is the "
           "pair's training wall",
           &s.training_walls, "", work_size(1, kMaxTrainingWalls)},
          {"experiment.threads", "Worker threads (0: all cores); results do not depend on it", &s.threads, "",
           work_size(0, kMaxThreads, "0: all cores")},
          {"experiment.iterations", "Learning iterations (real actions) per run", &l.iterations, "",
           work_size(1, kMaxIterations, "a run keeps every iteration's record in memory")},
          {"experiment.beginning",
           "Iterations of Table I's beginning window and of the early and late windows of the metrics (0: 2000, or all "
           "iterations if fewer)",
           &c.beginning, "", closed_range(0, kMaxIterations, "a window inside the run")},
          {"experiment.threshold_length",
           "Episode length (iterations) that counts as climbing well: time to threshold and take-off",
           &s.analysis.threshold_length, "", closed_range(1, kMaxIterations, "an episode lies inside the run")},
          {"experiment.bootstrap_resamples", "Resamples of the cluster bootstrap over walls",
           &s.analysis.bootstrap_resamples, "", work_size(100, 10000000)},
          {"experiment.plan", "Compute each wall's exact shortest climb", &s.plan},
          {"experiment.plan_max_solves",
           "IK solves the exact planner may spend on a wall; it stops there without a plan (12-20 us each on average)",
           &s.plan_search.max_ik_solves, "", work_size(1, 100000000, "at most about half an hour a wall")},
          {"experiment.plan_max_replans",
           "Dynamic model: plans searched again after a move failed in MuJoCo, each refusing the moves that failed",
           &s.plan_search.max_replans, "", work_size(0, 10000, "one climb performed each")},
          {"experiment.plan_check_moves",
           "Static model: the exact planner also refuses a move whose IK path (the replay's 16 postures) does not hold "
           "still on the three holds kept",
           &s.plan_search.check_moves},
          {"experiment.greedy_cap", "Actions allowed to the greedy policy's evaluation climb", &l.greedy_cap, "",
           work_size(1, 100000, "the climb keeps each action's posture")},
          {"experiment.checkpoint_every",
           "Iterations between checkpoints of a run (0: none); the same command started again resumes from the last",
           &c.checkpoint_every, "", closed_range(0, kMaxIterations, "an iteration of the run")},
          {"experiment.run",
           "crux perform: a run folder (of crux train or transfer, or runs/<condition>_<i> of crux paper's) whose "
           "climb is performed, on the run's wall under the run's parameters, instead of a wall's plan",
           &c.run,
           "",
           {},
           true},
          {"experiment.climb",
           "crux perform --run: the run's climb to perform: greedy (the default: the learnt policy's climb when it "
           "finishes, else the last), last (the last completed episode's) or an episode number N from 1",
           &c.climb},
          {"experiment.q_grid",
           "Q_grid file (q_grid.bin of a training run) that transfer starts from",
           &c.q_grid,
           "",
           {},
           true},
          {"experiment.policy",
           "Policy file (JSON, of examples/python/policy_baseline.py train) whose scores of each state's moves order "
           "crux train's exploration under experiment.transfer = network",
           &c.policy,
           "",
           {},
           true},
      });
  transfer_keys(keys, l.dyna);
}

// The [wall] and [training_wall] keys: the wall and the random walls' generator.
template <typename Config>
void wall_keys(std::vector<FieldOf<Config>>& keys, Config& c) {
  auto& s = c.settings;
  auto& tw = c.training_wall;
  keys.insert(keys.end(), {
                              {"wall.file", "Wall file (JSON)", &c.wall_file, "", {}, true},
                              {"wall.seed", "Seed of a random wall", &c.wall_seed},
                          });
  random_wall_keys(keys, s.walls);
  keys.insert(
      keys.end(),
      {
          {"training_wall.columns", "Tiles across a training wall (unset: wall.columns)", &tw.columns, "", kWallTiles},
          {"training_wall.rows", "Tiles up a training wall (unset: wall.rows)", &tw.rows, "", kWallTiles},
          {"training_wall.tile_width", "Tile width of a training wall (unset: wall.tile_width)", &tw.tile_width, "m",
           kTileSize},
          {"training_wall.tile_height", "Tile height of a training wall (unset: wall.tile_height)", &tw.tile_height,
           "m", kTileSize},
          {"training_wall.sigma", "Standard deviation of a training wall's hold displacement (unset: wall.sigma)",
           &tw.sigma, "m", kHoldScatter},
          {"training_wall.hold_radius", "Hold radius of a training wall (unset: wall.hold_radius)", &tw.hold_radius,
           "m", kHoldRadius},
          {"training_wall.finish_height",
           "Finishing height of the centre of mass on a training wall (unset: wall.finish_height)", &tw.finish_height,
           "m", kWallHeight},
          {"training_wall.incline", "Incline of a training wall from vertical (unset: wall.incline)", &tw.incline,
           "degrees", kOpenRightAngle},
      });
}

// The [output] keys: presentation only, never recorded.
template <typename Config>
void output_keys(std::vector<FieldOf<Config>>& keys, Config& c) {
  keys.insert(
      keys.end(),
      {
          {"output.progress",
           "Progress of long work on stderr: bar (redrawn on a terminal; elsewhere a line every ten seconds, none for "
           "shorter work), lines (a plain line every 10 %) or none",
           choice_of(&c.progress),
           "",
           {},
           false,
           false},
      });
}

template <typename Config>
std::vector<FieldOf<Config>> fields_of(Config& c) {
  std::vector<FieldOf<Config>> keys;
  auto& climbing = c.settings.learning.climbing;
  experiment_keys(keys, c);
  dyna_keys(keys, c.settings.learning.dyna);
  reward_keys(keys, climbing.rewards);
  reachability_keys(keys, climbing.reachability);
  physics_keys(keys, climbing.physics, c.physics_strength);
  fall_when_stuck_keys(keys, climbing);
  perform_keys(keys, climbing.perform);
  filter_keys(keys, climbing.filter);
  grid_keys(keys, climbing.grid);
  wall_keys(keys, c);
  output_keys(keys, c);
  return keys;
}

}  // namespace

std::vector<ConfigField> config_fields(ExperimentConfig& config) { return fields_of(config); }
std::vector<ConstConfigField> config_fields(const ExperimentConfig& config) { return fields_of(config); }

const ConfigField* find_field(const std::vector<ConfigField>& fields, std::string_view key) {
  const auto found = std::find_if(fields.begin(), fields.end(), [&](const ConfigField& f) { return f.key == key; });
  return found == fields.end() ? nullptr : &*found;
}

std::string flag_for_key(const std::string& key) {
  const std::size_t dot = key.find('.');
  const std::string section = key.substr(0, dot);
  std::string flag = "--" + (section == "experiment" ? std::string() : section + "-") + key.substr(dot + 1);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

bool ParameterSet::accepts(const std::string& key) const {
  const std::string section = key.substr(0, key.find('.'));
  const auto listed = [&](const std::vector<std::string>& list) {
    return std::find(list.begin(), list.end(), key) != list.end() ||
           std::find(list.begin(), list.end(), section) != list.end();
  };
  return listed(include) && std::find(exclude.begin(), exclude.end(), key) == exclude.end();
}

namespace {

std::string toml_double(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

// TOML integers are signed 64-bit: larger seeds are written, and read, as strings.
std::optional<std::uint64_t> read_seed(const toml::node& node) {
  if (const auto v = node.as_integer(); v && v->get() >= 0) return static_cast<std::uint64_t>(v->get());
  if (const auto v = node.as_string()) {
    const std::string& text = v->get();
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    try {
      std::size_t used = 0;
      const std::uint64_t value = std::stoull(text, &used);
      if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
  }
  return std::nullopt;
}

// "unknown solver 'x' (expected fast or paper)": the key's last word names what it chooses.
std::string unknown_choice(const ConfigField& field, const std::string& text) {
  std::string noun = field.key.substr(field.key.rfind('.') + 1);
  std::replace(noun.begin(), noun.end(), '_', ' ');
  return fmt::format("unknown {} '{}' (expected {})", noun, printable(text),
                     std::get<ChoiceTarget<false>>(field.target).type->choices());
}

void assign(const std::string& path, const ConfigField& field, const toml::node& node) {
  const auto fail = [&](const std::string& expected) {
    throw InputError(path, fmt::format("line {}: {} must be {}", node.source().begin.line, field.key, expected));
  };
  std::visit(
      [&](auto target) {
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) {
          const auto v = node.value<double>();
          if (!v || !std::isfinite(*v)) fail("a finite number");
          *target = *v;
        } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) {
          const auto v = node.as_integer();
          if (!v) fail("an integer");
          if (v->get() < std::numeric_limits<int>::min() || v->get() > std::numeric_limits<int>::max()) {
            fail("an integer from -2147483648 to 2147483647");
          }
          *target = static_cast<int>(v->get());
        } else if constexpr (std::is_same_v<T, std::uint64_t> || std::is_same_v<T, std::optional<std::uint64_t>>) {
          const auto v = read_seed(node);
          if (!v) fail("an integer from 0 to 18446744073709551615");
          *target = *v;
        } else if constexpr (std::is_same_v<T, bool>) {
          const auto v = node.as_boolean();
          if (!v) fail("true or false");
          *target = v->get();
        } else if constexpr (std::is_same_v<T, std::string>) {
          const auto v = node.as_string();
          if (!v) fail("a string");
          *target = v->get();
        } else {
          const auto v = node.as_string();
          if (!v) fail("one of " + target.type->choices());
          if (!target.type->parse(target.target, v->get())) {
            throw InputError(path, fmt::format("line {}: {}: {}", node.source().begin.line, field.key,
                                               unknown_choice(field, v->get())));
          }
        }
      },
      field.target);
}

}  // namespace

ConfigLines apply_config_file(const std::string& path, ExperimentConfig& config, const ParameterSet& accepted,
                              const std::string& command, const ListChoice& choice) {
  return apply_config_text(read_input_file(path, "config file"), path, config, accepted, command, choice);
}

struct ConfigDocument::Table {
  toml::table value;
};

namespace {

std::atomic<std::size_t> config_parse_count{0};

toml::table parse_config(const std::string& text, const std::string& path) {
  ++config_parse_count;
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const std::string description(e.description());
    if (e.source().begin.line == 0) throw InputError(path, "cannot read the config file: " + description);
    throw InputError(path, fmt::format("TOML syntax error at line {}, column {}: {}", e.source().begin.line,
                                       e.source().begin.column, description));
  }
}

// Keys whose list would not make a sweep: the body is loaded once, threads change no
// result, and runs is shorthand for walls and seeds_per_wall (list those).
bool may_be_listed(const std::string& key) {
  return key != "experiment.urdf" && key != "experiment.threads" && key != "experiment.runs";
}

}  // namespace

ConfigDocument::ConfigDocument(const std::string& text, std::string source)
    : source_(std::move(source)), table_(std::make_unique<Table>(Table{parse_config(text, source_)})) {}
ConfigDocument::ConfigDocument(ConfigDocument&&) noexcept = default;
ConfigDocument& ConfigDocument::operator=(ConfigDocument&&) noexcept = default;
ConfigDocument::~ConfigDocument() = default;

std::size_t ConfigDocument::parses() { return config_parse_count; }

std::optional<int> ConfigDocument::line_of(const std::string& key) const {
  const toml::node* node = table_->value.at_path(key).node();
  if (node == nullptr) return std::nullopt;
  return static_cast<int>(node->source().begin.line);
}

std::vector<ListedKey> listed_keys(const ConfigDocument& document, const ParameterSet& accepted) {
  const toml::table& table = document.table().value;
  const std::string& path = document.source();
  std::vector<ListedKey> listed;
  ExperimentConfig probe;
  for (const ConfigField& field : config_fields(probe)) {
    if (!accepted.accepts(field.key)) continue;
    const std::size_t dot = field.key.find('.');
    const toml::node* node = table.at_path(toml::path(field.key.substr(0, dot))).node();
    const toml::table* section = node != nullptr ? node->as_table() : nullptr;
    const toml::node* value = section != nullptr ? section->get(field.key.substr(dot + 1)) : nullptr;
    const toml::array* list = value != nullptr ? value->as_array() : nullptr;
    if (list == nullptr) continue;
    const int line = static_cast<int>(value->source().begin.line);
    if (!may_be_listed(field.key)) {
      throw InputError(path, fmt::format("line {}: {} takes one value, not a list", line, field.key));
    }
    if (list->empty()) throw InputError(path, fmt::format("line {}: {} lists no value", line, field.key));
    listed.push_back({field.key, list->size()});
  }
  return listed;
}

ConfigLines apply_config_text(const std::string& text, const std::string& path, ExperimentConfig& config,
                              const ParameterSet& accepted, const std::string& command, const ListChoice& choice) {
  return apply_config_document(ConfigDocument(text, path), config, accepted, command, choice);
}

ConfigLines apply_config_document(const ConfigDocument& document, ExperimentConfig& config,
                                  const ParameterSet& accepted, const std::string& command, const ListChoice& choice) {
  return apply_config_document(document, config, {}, accepted, command, choice);
}

ConfigLines apply_config_document(const ConfigDocument& document, ExperimentConfig& config,
                                  std::span<const ConfigField> command_fields, const ParameterSet& accepted,
                                  const std::string& command, const ListChoice& choice) {
  const toml::table& table = document.table().value;
  const std::string& path = document.source();
  std::vector<ConfigField> fields = config_fields(config);
  fields.insert(fields.end(), command_fields.begin(), command_fields.end());
  ConfigLines lines;
  for (const auto& [section, section_node] : table) {
    const toml::table* entries = section_node.as_table();
    if (entries == nullptr) {
      throw InputError(
          path, fmt::format("line {}: '{}' must be a [section]", section_node.source().begin.line, section.str()));
    }
    for (const auto& [name, node] : *entries) {
      const std::string key = std::string(section.str()) + "." + std::string(name.str());
      const int line = static_cast<int>(node.source().begin.line);
      if (section.str() == "provenance") {
        const auto text = node.as_string();
        if (!text) throw InputError(path, fmt::format("line {}: {} must be a string", line, key));
        config.recorded_provenance[std::string(name.str())] = text->get();
        continue;
      }
      const auto field = std::find_if(fields.begin(), fields.end(), [&](const ConfigField& f) { return f.key == key; });
      if (field == fields.end()) {
        // Keys of crux 0.1's config files.
        static const std::map<std::string, std::string> renamed_sections{{"walls", "wall"}, {"rewards", "reward"}};
        std::string now;
        if (const auto r = renamed_sections.find(std::string(section.str())); r != renamed_sections.end()) {
          now = r->second + "." + std::string(name.str());
        } else if (key == "experiment.beginning_iterations") {
          now = "experiment.beginning";
        }
        throw InputError(path, fmt::format("line {}: unknown key {}{}", line, printable(key),
                                           now.empty() ? std::string() : " (it is now " + now + ")"));
      }
      if (!accepted.accepts(key)) {
        throw InputError(path, fmt::format("line {}: crux {} does not take {}", line, command, key));
      }
      if (const toml::array* list = node.as_array(); list != nullptr) {
        const auto chosen = choice.find(key);
        if (chosen == choice.end()) {
          throw InputError(path, fmt::format("line {}: {} must be one value; only crux sweep takes lists", line, key));
        }
        assign(path, *field, *list->get(chosen->second));
      } else {
        assign(path, *field, node);
      }
      lines[key] = line;
      config.given.insert(key);
    }
  }
  return lines;
}

namespace {

void require(bool ok, const std::string& key, const std::string& problem) {
  if (!ok) throw InputError(key, problem);
}

// What the bounds of a random wall's generator keys cannot say, for `section` ("wall" or
// "training_wall"): the start holds lie on the wall, and its holds are not too many.
void require_wall_generator(const RandomWallParameters& walls, const std::string& section) {
  int start_columns = 0, start_rows = 0;
  for (const auto& vertex : walls.start_vertices) {
    start_columns = std::max(start_columns, vertex[0]);
    start_rows = std::max(start_rows, vertex[1]);
  }
  const auto key = [&](const char* name) { return section + "." + name; };
  require(walls.columns >= start_columns, key("columns"), "must reach the start holds (at least 3 tiles)");
  require(walls.rows >= start_rows, key("rows"), "must reach the start holds (at least 3 tiles)");
  require((walls.columns + 1LL) * (walls.rows + 1LL) <= kMaxHoldCount, key("columns"),
          fmt::format("(columns + 1) x (rows + 1) holds must be at most {}", kMaxHoldCount));
}

// The transfer walls' parameters with every [training_wall] key set; none when no key is
// set, so that the default stays one set of parameters for both kinds of wall.
std::optional<RandomWallParameters> training_wall_parameters(const ExperimentConfig::TrainingWallKeys& keys,
                                                             const RandomWallParameters& walls) {
  if (!keys.columns && !keys.rows && !keys.tile_width && !keys.tile_height && !keys.sigma && !keys.hold_radius &&
      !keys.finish_height && !keys.incline) {
    return std::nullopt;
  }
  RandomWallParameters out = walls;
  out.columns = keys.columns.value_or(walls.columns);
  out.rows = keys.rows.value_or(walls.rows);
  out.tile_width = keys.tile_width.value_or(walls.tile_width);
  out.tile_height = keys.tile_height.value_or(walls.tile_height);
  out.sigma = keys.sigma.value_or(walls.sigma);
  out.hold_radius = keys.hold_radius.value_or(walls.hold_radius);
  out.finish_height = keys.finish_height.value_or(walls.finish_height);
  out.incline_deg = keys.incline.value_or(walls.incline_deg);
  return out;
}

}  // namespace

bool is_wall_generator_key(const std::string& key) {
  return key.starts_with("wall.") && key != "wall.file" && key != "wall.seed" && key != "wall.name" &&
         key != "wall.count";
}

// Flags may spell nan or inf: no parameter means anything then.
void require_within_bounds(std::span<const ConfigField> fields) {
  for (const ConfigField& field : fields) {
    std::optional<double> value;
    std::visit(
        [&](auto target) {
          using T = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int>) {
            value = static_cast<double>(*target);
          } else if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>>) {
            if (*target) value = static_cast<double>(**target);
          }
        },
        field.target);
    if (!value) continue;
    require(std::isfinite(*value), field.key, "must be a finite number");
    require(field.bounds.contains(*value), field.key, field.bounds.problem(field.is_integer()));
  }
}

namespace {

// The keys that only mean something together with others.
void require_consistent_keys(const ExperimentConfig& config) {
  const ExperimentParameters& s = config.settings;
  const bool is_static = checks_stances(s.learning.climbing.physics.model);
  require(s.learning.climbing.rewards.effort == 0.0 || is_static, "reward.effort",
          "needs physics.model = static: the kinematic model has no effort");
  require(s.plan_search.max_replans == PlanParameters{}.max_replans ||
              s.learning.climbing.physics.model == PhysicsModel::Dynamic,
          "experiment.plan_max_replans", "needs physics.model = dynamic: only the dynamic model plans again");
  require(!s.plan_search.check_moves || is_static, "experiment.plan_check_moves",
          "needs physics.model = static or dynamic: the kinematic model checks no stance");
  // The static model's stances are solved with the body kept out of the wall.
  require(!is_static || s.learning.climbing.reachability.ik.wall == WallRule::Avoid, "ik.wall",
          fmt::format("must be avoid under physics.model = {} (its default there): a stance that holds still keeps "
                      "the body out of the wall",
                      enum_name(s.learning.climbing.physics.model)));
  require(static_cast<long long>(s.wall_pairs) * s.seeds_per_wall <= kMaxRunsPerCondition, "experiment.walls",
          "walls x seeds_per_wall must be at most 1000000 runs per condition");
  const auto& ik = s.learning.climbing.reachability.ik;
  require(ik.paper.timeout_s / ik.time_step_s <= kMaxIkIterations, "ik.timeout",
          fmt::format("must be at most {} x ik.time_step: the paper's solver iterates timeout / time_step times",
                      kMaxIkIterations));
  require(config.beginning <= s.learning.iterations, "experiment.beginning",
          "must not exceed the run's iterations (the window lies inside the run)");
  const GridParameters& grid = s.learning.climbing.grid;
  static const char* const anchor_keys[kLimbCount] = {"grid.right_hand_anchor_column", "grid.left_hand_anchor_column",
                                                      "grid.right_foot_anchor_column", "grid.left_foot_anchor_column"};
  // The reach agent space has no anchors.
  for (int limb = 0; limb < kLimbCount && grid.space == AgentSpaceKind::Grid; ++limb) {
    const auto& anchor = grid.anchors[limb];
    require(anchor[0] >= 0 && anchor[0] < grid.columns && anchor[1] >= 0 && anchor[1] < grid.rows, anchor_keys[limb],
            "every grid anchor must be a tile of the grid");
  }
  const double state_codes =
      4.0 * std::pow(static_cast<double>(grid.columns) * grid.rows + 1.0, 3.0);  // no int overflow
  require(state_codes < 4294967296.0, "grid.columns", "the grid has too many tiles for 32-bit agent-state codes");
}

}  // namespace

void require_physics_model_taken(const ExperimentConfig& config, const ParameterSet& accepted,
                                 const std::string& caller) {
  require(config.settings.learning.climbing.physics.model != PhysicsModel::Dynamic || accepted.takes_dynamic_physics,
          "physics.model",
          fmt::format("dynamic is not taken by {}: only crux plan and crux perform perform moves in MuJoCo (static "
                      "checks the same stances without performing them)",
                      caller));
}

void refuse_keys_off_default(const ExperimentConfig& config, std::initializer_list<std::string_view> keys,
                             std::string_view why) {
  static const ExperimentConfig defaults;
  const std::vector<ConstConfigField> given = config_fields(config), unset = config_fields(defaults);
  for (std::size_t i = 0; i < given.size(); ++i) {
    const std::string& key = given[i].key;
    const bool listed = std::any_of(
        keys.begin(), keys.end(), [&](std::string_view k) { return k.ends_with('.') ? key.starts_with(k) : key == k; });
    if (listed && field_value_text(given[i]) != field_value_text(unset[i])) throw InputError(key, std::string(why));
  }
}

void require_perform_keys_used(const ExperimentConfig& config, const std::string& caller) {
  if (config.settings.learning.climbing.physics.model == PhysicsModel::Dynamic) return;
  refuse_keys_off_default(config, {"perform."},
                          fmt::format("needs physics.model = dynamic: {} performs nothing in MuJoCo under the other "
                                      "models (crux perform performs their plans)",
                                      caller));
}

void finalize_config(ExperimentConfig& config) {
  ExperimentParameters& s = config.settings;
  if (!config.wall_file.empty()) {
    for (const std::string& key : config.given) {
      if (is_wall_generator_key(key)) {
        throw InputError(key, "shapes a random wall, and the wall file gives the wall itself: drop one of them");
      }
    }
  }
  require_within_bounds(config_fields(config));
  PhysicsParameters& physics = s.learning.climbing.physics;
  // Derived values, each recorded in config.toml as what ran.
  if (checks_stances(physics.model) && !config.given.contains("ik.wall")) {
    s.learning.climbing.reachability.ik.wall = WallRule::Avoid;
  }
  if (!config.physics_strength.empty() && !config.given.contains("physics.grip")) {
    physics.grip = find_climbing_level(config.physics_strength)->grip_n;
  }
  if (config.runs) {
    s.wall_pairs = *config.runs;
    s.seeds_per_wall = 1;
    config.runs.reset();
  }
  require_consistent_keys(config);
  s.analysis.beginning =
      config.beginning > 0 ? config.beginning : std::min(AnalysisParameters{}.beginning, s.learning.iterations);
  require_wall_generator(s.walls, "wall");
  s.training_wall = training_wall_parameters(config.training_wall, s.walls);
  if (s.training_wall) require_wall_generator(*s.training_wall, "training_wall");
}

void assign_text(const ConfigField& field, const std::string& text) {
  const auto fail = [&](const char* expected) { throw InputError(field.key, fmt::format("must be {}", expected)); };
  std::visit(
      [&](auto target) {
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, std::string>) {
          *target = text;
        } else if constexpr (std::is_same_v<T, ChoiceTarget<false>>) {
          if (!target.type->parse(target.target, text)) throw InputError(field.key, unknown_choice(field, text));
        } else {
          fail("given by a flag or a config file");
        }
      },
      field.target);
}

std::string toml_quoted(const std::string& value) {
  std::string out = "\"";
  for (const char ch : value) {
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned char>(ch));
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string field_value_text(const ConstConfigField& field, bool toml) {
  std::string value;
  std::visit(
      [&](auto target) {
        using T = std::remove_cvref_t<std::remove_pointer_t<decltype(target)>>;
        const auto seed_text = [&](std::uint64_t seed) {
          return toml && seed > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())
                     ? fmt::format("\"{}\"", seed)
                     : fmt::format("{}", seed);
        };
        if constexpr (std::is_same_v<T, double>) {
          value = toml_double(*target);
        } else if constexpr (std::is_same_v<T, bool>) {
          value = *target ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          if (target->empty()) return;
          const std::string text =
              field.is_path ? std::filesystem::absolute(*target).lexically_normal().string() : *target;
          value = toml ? toml_quoted(text) : text;
        } else if constexpr (std::is_same_v<T, ChoiceTarget<true>>) {
          const std::string text = target.type->text(target.target);
          if (!text.empty()) value = toml ? toml_quoted(text) : text;
        } else if constexpr (std::is_same_v<T, std::uint64_t>) {
          value = seed_text(*target);
        } else if constexpr (std::is_same_v<T, std::optional<std::uint64_t>>) {
          if (*target) value = seed_text(**target);
        } else if constexpr (std::is_same_v<T, std::optional<int>>) {
          if (*target) value = fmt::format("{}", **target);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          if (*target) value = toml_double(**target);
        } else {
          value = fmt::format("{}", *target);
        }
      },
      field.target);
  return value;
}

ConstConfigField as_const(const ConfigField& field) {
  ConstConfigField out{field.key, field.help, {}, field.unit, field.bounds, field.is_path, field.recorded};
  std::visit(
      [&](auto target) {
        if constexpr (std::is_same_v<decltype(target), ChoiceTarget<false>>) {
          out.target = ChoiceTarget<true>{target.target, target.type};
        } else {
          out.target = static_cast<const std::remove_pointer_t<decltype(target)>*>(target);
        }
      },
      field.target);
  return out;
}

std::string config_value_text(const ExperimentConfig& config, const std::string& key, bool toml) {
  for (const ConstConfigField& field : config_fields(config)) {
    if (field.key == key) return field_value_text(field, toml);
  }
  return {};
}

std::string config_to_toml(const ExperimentConfig& config, const ParameterSet& accepted,
                           const std::map<std::string, std::string>& lists) {
  std::ostringstream out;
  out << "# crux effective configuration: every parameter of this run (docs/OUTPUTS.md)\n";
  std::string section;
  for (const ConstConfigField& field : config_fields(config)) {
    if (!accepted.accepts(field.key) || !field.recorded) continue;
    // A wall file's run used no generator key: config.toml records what ran.
    if (!config.wall_file.empty() && is_wall_generator_key(field.key)) continue;
    const auto listed = lists.find(field.key);
    const std::string value = listed != lists.end() ? listed->second : field_value_text(field, true);
    if (value.empty()) continue;
    const std::string field_section = field.key.substr(0, field.key.find('.'));
    if (field_section != section) {
      out << (section.empty() ? "" : "\n") << '[' << field_section << "]\n";
      section = field_section;
    }
    out << field.key.substr(field.key.find('.') + 1) << " = " << value << "  # " << field.described_help() << '\n';
  }
  return out.str();
}

}  // namespace crux
