#include "experiments/experiment_config.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/printable.hpp"
#include "experiments/stance_survey.hpp"
#include "physics/strength_profile.hpp"
#include "wall/incline.hpp"

namespace crux {

std::vector<ConfigField> config_fields(ExperimentConfig& c) {
  ExperimentParameters& s = c.settings;
  LearningParameters& l = s.learning;
  ClimbingParameters& m = l.climbing;
  IkParameters& ik = m.reachability.ik;
  return {
      {"experiment.urdf", "URDF file of the body (default: the installed crux_human.urdf)", &c.urdf},
      {"experiment.seed", "Seed: the experiment's walls and runs, a run's learning or the queries derive from it",
       &s.seed},
      {"experiment.runs", "N walls with one seed each: sets walls = N and seeds_per_wall = 1", &c.runs},
      {"experiment.walls", "Wall pairs (training and transfer wall); the unit of the statistics", &s.wall_pairs},
      {"experiment.seeds_per_wall", "Learning seeds per wall pair", &s.seeds_per_wall},
      {"experiment.training_walls",
       "Walls each training run learns Q_grid on in sequence before transfer (docs/TRANSFER.md): the last is the "
       "pair's training wall",
       &s.training_walls},
      {"experiment.threads", "Worker threads (0: all cores); results do not depend on it", &s.threads},
      {"experiment.iterations", "Learning iterations (real actions) per run", &l.iterations},
      {"experiment.beginning",
       "Iterations of Table I's beginning window and of the early and late windows of the metrics (0: 2000, or all "
       "iterations if fewer)",
       &c.beginning},
      {"experiment.threshold_length",
       "Episode length (iterations) that counts as climbing well: time to threshold and take-off",
       &s.analysis.threshold_length},
      {"experiment.bootstrap_resamples", "Resamples of the cluster bootstrap over walls",
       &s.analysis.bootstrap_resamples},
      {"experiment.plan", "Compute each wall's exact shortest climb", &s.plan},
      {"experiment.plan_max_solves",
       "IK solves the exact planner may spend on a wall; it stops there without a plan (12-20 us each on average)",
       &s.plan_search.max_ik_solves},
      {"experiment.plan_check_moves",
       "Static model: the exact planner also refuses a move whose IK path (the replay's 16 postures) does not hold "
       "still on the three holds kept",
       &s.plan_search.check_moves},
      {"experiment.greedy_cap", "Actions allowed to the greedy policy's evaluation climb", &l.greedy_cap},
      {"experiment.checkpoint_every",
       "Iterations between checkpoints of a run (0: none); the same command started again resumes from the last",
       &c.checkpoint_every},
      {"experiment.q_grid", "Q_grid file (q_grid.bin of a training run) that transfer starts from", &c.q_grid},
      {"experiment.transfer",
       "How transfer uses its Q_grid (docs/TRANSFER.md): paper (Algorithm 3), informed, prior, seeded, shaping or "
       "ordered; "
       "control "
       "follows the same rule from an empty Q_grid",
       &c.transfer},
      {"learning.alpha", "Q-learning step size alpha", &l.dyna.rates.alpha},
      {"learning.gamma", "Discount factor gamma", &l.dyna.rates.gamma},
      {"learning.epsilon", "Exploration rate of Algorithm 3", &l.dyna.epsilon},
      {"learning.planning_steps", "Dyna planning updates per real step", &l.dyna.planning_steps},
      {"learning.planner",
       "Dyna planning: uniform (Algorithm 2) or prioritized (prioritized sweeping, same number of updates)",
       &c.planner},
      {"learning.priority_threshold", "Prioritized sweeping queues pairs whose |TD error| exceeds this",
       &l.dyna.priority_threshold},
      {"reward.unreachable", "Reward of an unreachable 4-configuration", &m.rewards.unreachable},
      {"reward.step", "Reward of a reachable 4-configuration", &m.rewards.step},
      {"reward.finish", "Reward when the centre of mass passes the finishing height", &m.rewards.finish},
      {"reward.effort",
       "Static model: subtracted from a reached move's reward per unit of its stance's effort (0: the paper's rewards)",
       &m.rewards.effort},
      {"reward.height",
       "Potential-based height shaping: weight per metre of the mean height of the held holds (0: the paper's "
       "rewards)",
       &m.rewards.height},
      {"ik.solver", "IK solver: fast or paper (Algorithm 1)", &c.solver},
      {"ik.alpha", "Step size of the paper's gradient descent", &ik.paper.step_size},
      {"ik.time_step", "Simulated seconds per IK iteration (both solvers)", &ik.time_step_s},
      {"ik.timeout", "Delta_t: simulated seconds before the paper's solver gives up", &ik.paper.timeout_s},
      {"ik.paper_stall_iterations",
       "Steps over which the paper's solver looks for a stall (0: it never gives up before Delta_t, as Algorithm 1)",
       &ik.paper.stall_iterations},
      {"ik.paper_stall_decrease", "It has stalled when f fell by less than this share of f over those steps...",
       &ik.paper.stall_decrease},
      {"ik.paper_stall_margin", "...while a point is more than this outside its sphere (m); it then gives up",
       &ik.paper.stall_margin_m},
      {"ik.rule_out_beyond_reach",
       "Both solvers give up before iterating when a hold lies beyond its limb's reach (the verdict cannot change)",
       &ik.rule_out_beyond_reach},
      {"ik.fast_max_iterations", "Iteration cap of the fast solver", &ik.fast.max_iterations},
      {"ik.fast_stall_decrease", "The fast solver gives up when f drops by less than this share per step...",
       &ik.fast.stall_relative_decrease},
      {"ik.fast_stall_iterations", "...this many steps in a row", &ik.fast.stall_iterations},
      {"ik.fast_aim", "The fast solver aims at this share of each tolerance radius", &ik.fast.aim_fraction},
      {"ik.grasp_radius", "Radius of the grasp spheres (m)", &ik.tolerances.grasp_radius},
      {"ik.root_tolerance", "Radius of the root tolerance sphere (m)", &ik.tolerances.root_radius},
      {"ik.wall_distance", "Distance of the root target H(C4) from the wall, on the climber's side (m)",
       &m.reachability.root.distance_from_wall},
      {"ik.cache_unreachable", "Cache unreachable verdicts", &m.reachability.cache_unreachable},
      {"ik.wall",
       "The body and the wall: ignore (the paper's kinematic model), reject a solved posture that passes through it, "
       "or avoid (keep the body out while solving)",
       &c.wall_rule},
      {"ik.guess",
       "Where the IK starts a configuration's solve: previous (the posture the climber holds, the paper's) or "
       "standing (the standing posture at the configuration's root target, so that a verdict does not depend on "
       "the climb)",
       &c.ik_guess},
      {"physics.model",
       "kinematic (the paper's: IK alone decides) or static (the body kept out of the wall and each stance held "
       "still on its holds, within friction, grip and joint torque limits; docs/PHYSICS.md)",
       &c.physics_model},
      {"physics.friction", "Static model: Coulomb friction coefficient of every contact", &m.physics.friction},
      {"physics.strength",
       fmt::format("Static model: a climbing level whose published grip sets physics.grip: {} (docs/MODEL.md); an "
                   "explicit physics.grip overrides it",
                   climbing_level_descriptions()),
       &c.physics_strength},
      {"physics.grip", "Static model: largest normal force of a hand on a hold (N)", &m.physics.grip},
      {"physics.support_angle",
       "Static model: a hold without a support direction pushes a hand up and this many degrees into the wall "
       "(a jug's incut lip)",
       &m.physics.support_angle_deg},
      {"physics.fall_when_stuck",
       "A failed move also falls when no limb can move to another hold of the stance, every such move known "
       "unreachable (a trap that C27's dead ends miss)",
       &m.fall_when_stuck},
      {"compare.queries", "Climbing-like queries that ik-compare gives both solvers", &c.compare_queries},
      {"stances.moves", "Random kinematic moves per wall whose stances crux stances checks", &c.stance_moves},
      {"compare.walk_solver", "Solver whose reached postures start the next queries of ik-compare's climbing walk",
       &c.compare_walk_solver},
      {"filter.max_span", "Largest distance between two holds of a configuration (m)", &m.filter.max_span_m},
      {"filter.reading", "Reading of 'both feet above the hands'", &c.reading},
      {"grid.agent_space",
       "Agent space (docs/TRANSFER.md): grid (the paper's moving grid) or reach (direction sectors = columns and "
       "distance rings of tile_height m = rows around the free limb's shoulder or hip)",
       &c.agent_space},
      {"grid.columns", "Columns of the moving grid", &m.grid.columns},
      {"grid.rows", "Rows of the moving grid", &m.grid.rows},
      {"grid.tile_width", "Tile width of the moving grid (m)", &m.grid.tile_width},
      {"grid.tile_height", "Tile height of the moving grid (m)", &m.grid.tile_height},
      {"grid.right_hand_anchor_column", "Right hand's anchor tile P_1: column", &m.grid.anchors[0][0]},
      {"grid.right_hand_anchor_row", "Right hand's anchor tile P_1: row", &m.grid.anchors[0][1]},
      {"grid.left_hand_anchor_column", "Left hand's anchor tile P_2: column", &m.grid.anchors[1][0]},
      {"grid.left_hand_anchor_row", "Left hand's anchor tile P_2: row", &m.grid.anchors[1][1]},
      {"grid.right_foot_anchor_column", "Right foot's anchor tile P_3: column", &m.grid.anchors[2][0]},
      {"grid.right_foot_anchor_row", "Right foot's anchor tile P_3: row", &m.grid.anchors[2][1]},
      {"grid.left_foot_anchor_column", "Left foot's anchor tile P_4: column", &m.grid.anchors[3][0]},
      {"grid.left_foot_anchor_row", "Left foot's anchor tile P_4: row", &m.grid.anchors[3][1]},
      {"wall.file", "Wall file (JSON)", &c.wall_file},
      {"wall.seed", "Seed of a random wall", &c.wall_seed},
      {"wall.name", "Name stored in a generated wall file", &c.wall_name},
      {"wall.count", "Random walls to count over", &c.wall_count},
      {"wall.columns", "Tiles across a random wall", &s.walls.columns},
      {"wall.rows", "Tiles up a random wall", &s.walls.rows},
      {"wall.tile_width", "Tile width of a random wall (m)", &s.walls.tile_width},
      {"wall.tile_height", "Tile height of a random wall (m)", &s.walls.tile_height},
      {"wall.sigma", "Standard deviation of hold displacement (m)", &s.walls.sigma},
      {"wall.hold_radius", "Hold radius (m)", &s.walls.hold_radius},
      {"wall.finish_height", "Finishing height of the centre of mass (m), measured along the wall",
       &s.walls.finish_height},
      {"wall.incline", "Incline of a random wall from vertical (degrees; > 0 overhanging, < 0 slab)",
       &s.walls.incline_deg},
      {"training_wall.columns", "Tiles across a training wall (unset: wall.columns)", &c.training_wall.columns},
      {"training_wall.rows", "Tiles up a training wall (unset: wall.rows)", &c.training_wall.rows},
      {"training_wall.tile_width", "Tile width of a training wall (m; unset: wall.tile_width)",
       &c.training_wall.tile_width},
      {"training_wall.tile_height", "Tile height of a training wall (m; unset: wall.tile_height)",
       &c.training_wall.tile_height},
      {"training_wall.sigma", "Standard deviation of a training wall's hold displacement (m; unset: wall.sigma)",
       &c.training_wall.sigma},
      {"training_wall.hold_radius", "Hold radius of a training wall (m; unset: wall.hold_radius)",
       &c.training_wall.hold_radius},
      {"training_wall.finish_height",
       "Finishing height of the centre of mass on a training wall (m; unset: wall.finish_height)",
       &c.training_wall.finish_height},
      {"training_wall.incline", "Incline of a training wall from vertical (degrees; unset: wall.incline)",
       &c.training_wall.incline},
  };
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

// Paths written absolute, so that the config replays from any working directory.
bool is_file_key(const std::string& key) {
  return key == "experiment.urdf" || key == "experiment.q_grid" || key == "wall.file";
}

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

void assign(const std::string& path, const ConfigField& field, const toml::node& node) {
  const auto fail = [&](const char* expected) {
    throw InputError(path, fmt::format("line {}: {} must be {}", node.source().begin.line, field.key, expected));
  };
  std::visit(
      [&](auto* target) {
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
        } else {
          const auto v = node.as_string();
          if (!v) fail("a string");
          *target = v->get();
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
  const toml::table& table = document.table().value;
  const std::string& path = document.source();
  const std::vector<ConfigField> fields = config_fields(config);
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

constexpr long long kMaxRunsPerCondition = 1000000;
// Each training run learns K times its iterations: beyond this a typo, not an experiment.
constexpr int kMaxTrainingWalls = 1000;

void require(bool ok, const std::string& key, const std::string& problem) {
  if (!ok) throw InputError(key, problem);
}

// The checks of a random wall's generator keys, those of `section` ("wall" or "training_wall").
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
  require(walls.tile_width > 0, key("tile_width"), "must be positive");
  require(std::abs(walls.incline_deg) < kMaxInclineDeg, key("incline"),
          "must be between -90 and 90 degrees (exclusive): 0 is vertical, > 0 overhanging");
  require(walls.tile_height > 0, key("tile_height"), "must be positive");
  require(walls.sigma >= 0, key("sigma"), "must be 0 or positive");
  require(walls.hold_radius > 0, key("hold_radius"), "must be positive");
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

void finalize_config(ExperimentConfig& config) {
  ExperimentParameters& s = config.settings;
  if (!config.wall_file.empty()) {
    for (const std::string& key : config.given) {
      if (is_wall_generator_key(key)) {
        throw InputError(key, "shapes a random wall, and the wall file gives the wall itself: drop one of them");
      }
    }
  }
  // Flags may spell nan or inf; no parameter means anything then.
  for (const ConfigField& field : config_fields(config)) {
    if (const auto* value = std::get_if<double*>(&field.target); value != nullptr && !std::isfinite(**value)) {
      throw InputError(field.key, "must be a finite number");
    }
    if (const auto* value = std::get_if<std::optional<double>*>(&field.target);
        value != nullptr && **value && !std::isfinite(***value)) {
      throw InputError(field.key, "must be a finite number");
    }
  }
  const auto solver = parse_ik_solver(config.solver);
  if (!solver)
    throw InputError("ik.solver",
                     fmt::format("unknown solver '{}' (expected fast or paper)", printable(config.solver)));
  s.learning.climbing.reachability.ik.solver = *solver;
  const auto wall_rule = parse_wall_rule(config.wall_rule);
  if (!wall_rule) {
    throw InputError("ik.wall",
                     fmt::format("unknown rule '{}' (expected ignore, reject or avoid)", printable(config.wall_rule)));
  }
  s.learning.climbing.reachability.ik.wall = *wall_rule;
  const auto ik_guess = parse_ik_guess(config.ik_guess);
  if (!ik_guess) {
    throw InputError("ik.guess",
                     fmt::format("unknown guess '{}' (expected previous or standing)", printable(config.ik_guess)));
  }
  s.learning.climbing.reachability.guess = *ik_guess;
  const auto physics_model = parse_physics_model(config.physics_model);
  if (!physics_model) {
    throw InputError("physics.model",
                     fmt::format("unknown model '{}' (expected kinematic or static)", printable(config.physics_model)));
  }
  s.learning.climbing.physics.model = *physics_model;
  const double effort_penalty = s.learning.climbing.rewards.effort;
  require(effort_penalty >= 0.0 && std::isfinite(effort_penalty), "reward.effort",
          "must be a finite number, 0 or more");
  require(effort_penalty == 0.0 || *physics_model == PhysicsModel::Static, "reward.effort",
          "needs physics.model = static: the kinematic model has no effort");
  const double height_shaping = s.learning.climbing.rewards.height;
  require(height_shaping >= 0.0 && std::isfinite(height_shaping), "reward.height",
          "must be a finite number, 0 or more");
  s.learning.climbing.rewards.discount = s.learning.dyna.rates.gamma;
  require(s.learning.climbing.physics.friction >= 0, "physics.friction", "must be at least 0");
  if (!config.physics_strength.empty()) {
    const auto level = find_climbing_level(config.physics_strength);
    if (!level) {
      throw InputError("physics.strength",
                       fmt::format("unknown level '{}' (expected {})", printable(config.physics_strength),
                                   climbing_level_descriptions()));
    }
    if (!config.given.contains("physics.grip")) s.learning.climbing.physics.grip = level->grip_n;
  }
  require(s.learning.climbing.physics.grip > 0, "physics.grip", "must be positive");
  require(std::abs(s.learning.climbing.physics.support_angle_deg) <= 90.0, "physics.support_angle",
          "must be from -90 to 90 degrees");
  const auto walk_solver = parse_ik_solver(config.compare_walk_solver);
  if (!walk_solver) {
    throw InputError("compare.walk_solver", fmt::format("unknown solver '{}' (expected fast or paper)",
                                                        printable(config.compare_walk_solver)));
  }
  config.compare_walk_solver_kind = *walk_solver;
  require(config.compare_queries > 0, "compare.queries", "must be positive");
  require(config.stance_moves > 0 && config.stance_moves <= kMaxStanceMoves, "stances.moves",
          fmt::format("must be from 1 to {}", kMaxStanceMoves));
  const auto planner = parse_planner(config.planner);
  if (!planner) {
    throw InputError("learning.planner",
                     fmt::format("unknown planner '{}' (expected uniform or prioritized)", printable(config.planner)));
  }
  s.learning.dyna.planner = *planner;
  const auto transfer = parse_transfer_mode(config.transfer);
  if (!transfer) {
    throw InputError("experiment.transfer", fmt::format("unknown transfer mode '{}' (expected {})",
                                                        printable(config.transfer), transfer_mode_names()));
  }
  s.learning.dyna.transfer = *transfer;
  const auto agent_space = parse_agent_space(config.agent_space);
  if (!agent_space) {
    throw InputError("grid.agent_space", fmt::format("unknown agent space '{}' (expected {})",
                                                     printable(config.agent_space), agent_space_names()));
  }
  s.learning.climbing.grid.space = *agent_space;
  const auto reading = parse_reading(config.reading);
  if (!reading) throw InputError("filter.reading", fmt::format("unknown reading '{}'", printable(config.reading)));
  s.learning.climbing.filter.feet_above_hands = *reading;
  if (config.runs) {
    require(*config.runs > 0, "experiment.runs", "must be positive");
    s.wall_pairs = *config.runs;
    s.seeds_per_wall = 1;
    config.runs.reset();
  }
  require(s.wall_pairs > 0, "experiment.walls", "must be positive");
  require(s.seeds_per_wall > 0, "experiment.seeds_per_wall", "must be positive");
  require(s.training_walls >= 1 && s.training_walls <= kMaxTrainingWalls, "experiment.training_walls",
          fmt::format("must be from 1 to {}", kMaxTrainingWalls));
  require(static_cast<long long>(s.wall_pairs) * s.seeds_per_wall <= kMaxRunsPerCondition, "experiment.walls",
          "walls x seeds_per_wall must be at most 1000000 runs per condition");
  require(s.threads >= 0 && s.threads <= kMaxThreads, "experiment.threads",
          fmt::format("must be 0 (all cores) or from 1 to {}", kMaxThreads));
  require(s.learning.iterations > 0 && s.learning.iterations <= kMaxIterations, "experiment.iterations",
          fmt::format("must be from 1 to {} (a run keeps every iteration's record in memory)", kMaxIterations));
  require(config.beginning >= 0, "experiment.beginning", "must be 0 (the default) or positive");
  require(config.beginning <= s.learning.iterations, "experiment.beginning",
          "must not exceed the run's iterations (the window lies inside the run)");
  s.analysis.beginning =
      config.beginning > 0 ? config.beginning : std::min(AnalysisParameters{}.beginning, s.learning.iterations);
  require(s.analysis.threshold_length > 0, "experiment.threshold_length", "must be positive");
  require(s.analysis.bootstrap_resamples >= 100 && s.analysis.bootstrap_resamples <= 10000000,
          "experiment.bootstrap_resamples", "must be in [100, 10000000]");
  require(s.plan_search.max_ik_solves > 0, "experiment.plan_max_solves", "must be positive");
  require(!s.plan_search.check_moves || s.learning.climbing.physics.model == PhysicsModel::Static,
          "experiment.plan_check_moves", "needs physics.model = static: the kinematic model checks no stance");
  require(s.learning.greedy_cap > 0, "experiment.greedy_cap", "must be positive");
  require(config.checkpoint_every >= 0, "experiment.checkpoint_every", "must be 0 (none) or positive");
  require(config.wall_count > 0, "wall.count", "must be positive");
  const DynaParameters& dyna = s.learning.dyna;
  require(dyna.rates.alpha > 0 && dyna.rates.alpha <= 1, "learning.alpha", "must be in (0, 1]");
  require(dyna.rates.gamma >= 0 && dyna.rates.gamma < 1, "learning.gamma", "must be in [0, 1)");
  require(dyna.planning_steps >= 0, "learning.planning_steps", "must be 0 or positive");
  require(dyna.epsilon >= 0 && dyna.epsilon <= 1, "learning.epsilon", "must be in [0, 1]");
  require(dyna.priority_threshold >= 0, "learning.priority_threshold", "must be 0 or positive");
  const GridParameters& grid = s.learning.climbing.grid;
  require(grid.columns > 0, "grid.columns", "must be positive");
  require(grid.rows > 0, "grid.rows", "must be positive");
  static const char* const anchor_keys[kLimbCount] = {"grid.right_hand_anchor_column", "grid.left_hand_anchor_column",
                                                      "grid.right_foot_anchor_column", "grid.left_foot_anchor_column"};
  // The reach agent space has no anchors.
  for (int limb = 0; limb < kLimbCount && grid.space == AgentSpaceKind::Grid; ++limb) {
    const auto& anchor = grid.anchors[limb];
    require(anchor[0] >= 0 && anchor[0] < grid.columns && anchor[1] >= 0 && anchor[1] < grid.rows, anchor_keys[limb],
            "every grid anchor must be a tile of the grid");
  }
  require(grid.tile_width > 0, "grid.tile_width", "must be positive");
  require(grid.tile_height > 0, "grid.tile_height", "must be positive");
  const double state_codes =
      4.0 * std::pow(static_cast<double>(grid.columns) * grid.rows + 1.0, 3.0);  // no int overflow
  require(state_codes < 4294967296.0, "grid.columns", "the grid has too many tiles for 32-bit agent-state codes");
  require_wall_generator(s.walls, "wall");
  s.training_wall = training_wall_parameters(config.training_wall, s.walls);
  if (s.training_wall) require_wall_generator(*s.training_wall, "training_wall");
  const IkParameters& ik = s.learning.climbing.reachability.ik;
  require(ik.paper.step_size > 0, "ik.alpha", "must be positive");
  require(ik.time_step_s > 0, "ik.time_step", "must be positive");
  require(ik.paper.timeout_s > 0, "ik.timeout", "must be positive");
  require(ik.paper.stall_iterations >= 0 && ik.paper.stall_iterations <= 64, "ik.paper_stall_iterations",
          "must be in [0, 64]");
  require(ik.paper.stall_decrease >= 0, "ik.paper_stall_decrease", "must be 0 or positive");
  require(ik.paper.stall_margin_m >= 0, "ik.paper_stall_margin", "must be 0 or positive");
  require(ik.fast.max_iterations > 0, "ik.fast_max_iterations", "must be positive");
  require(ik.fast.stall_relative_decrease >= 0, "ik.fast_stall_decrease", "must be 0 or positive");
  require(ik.fast.stall_iterations > 0, "ik.fast_stall_iterations", "must be positive");
  require(ik.fast.aim_fraction >= 0 && ik.fast.aim_fraction < 1, "ik.fast_aim", "must be in [0, 1)");
  require(ik.tolerances.grasp_radius > 0, "ik.grasp_radius", "must be positive");
  require(ik.tolerances.root_radius > 0, "ik.root_tolerance", "must be positive");
  require(s.learning.climbing.filter.max_span_m > 0, "filter.max_span", "must be positive");
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

namespace {

std::string value_text(const ConfigField& field, bool toml) {
  std::string value;
  std::visit(
      [&](auto* target) {
        using T = std::remove_pointer_t<decltype(target)>;
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
              is_file_key(field.key) ? std::filesystem::absolute(*target).lexically_normal().string() : *target;
          value = toml ? toml_quoted(text) : text;
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

}  // namespace

std::string config_value_text(ExperimentConfig& config, const std::string& key, bool toml) {
  for (const ConfigField& field : config_fields(config)) {
    if (field.key == key) return value_text(field, toml);
  }
  return {};
}

std::string config_to_toml(ExperimentConfig& config, const ParameterSet& accepted,
                           const std::map<std::string, std::string>& lists) {
  std::ostringstream out;
  out << "# crux effective configuration: every parameter of this run (docs/OUTPUTS.md)\n";
  std::string section;
  for (const ConfigField& field : config_fields(config)) {
    if (!accepted.accepts(field.key)) continue;
    // A wall file's run used no generator key: config.toml records what ran.
    if (!config.wall_file.empty() && is_wall_generator_key(field.key)) continue;
    const auto listed = lists.find(field.key);
    const std::string value = listed != lists.end() ? listed->second : value_text(field, true);
    if (value.empty()) continue;
    const std::string field_section = field.key.substr(0, field.key.find('.'));
    if (field_section != section) {
      out << (section.empty() ? "" : "\n") << '[' << field_section << "]\n";
      section = field_section;
    }
    out << field.key.substr(field.key.find('.') + 1) << " = " << value << "  # " << field.help << '\n';
  }
  return out.str();
}

}  // namespace crux
