#include "experiments/experiment_config.hpp"

#include <cmath>
#include <limits>
#include <algorithm>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "common/input_error.hpp"

namespace crux {

std::vector<ConfigField> config_fields(ExperimentConfig& c) {
  ExperimentSettings& s = c.settings;
  LearningParameters& l = s.learning;
  ClimbingParameters& m = l.climbing;
  IkSettings& ik = m.reachability.ik;
  return {
      {"experiment.runs", "--runs",
       "N walls with one seed each (sets walls = N, seeds_per_wall = 1); 0: use walls and seeds_per_wall", &c.runs},
      {"experiment.walls", "--walls", "Wall pairs (training and transfer wall); the unit of the statistics", &s.wall_pairs},
      {"experiment.seeds_per_wall", "--seeds-per-wall", "Learning seeds per wall pair", &s.seeds_per_wall},
      {"experiment.seed", "--seed", "Experiment seed; walls and runs derive from it", &s.seed},
      {"experiment.threads", "--threads", "Worker threads (0: all cores)", &s.threads},
      {"experiment.iterations", "--iterations", "Learning iterations (real actions) per run", &l.iterations},
      {"experiment.beginning_iterations", "--beginning",
       "Iterations of Table I's beginning window, and of the early and late windows of the metrics",
       &s.analysis.beginning},
      {"experiment.threshold_length", "--threshold-length",
       "Episode length (iterations) that counts as climbing well: time to threshold and take-off",
       &s.analysis.threshold_length},
      {"experiment.bootstrap_resamples", "--bootstrap-resamples", "Resamples of the cluster bootstrap over walls",
       &s.analysis.bootstrap_resamples},
      {"experiment.plan", "--plan", "Compute each wall's exact shortest climb", &s.plan},
      {"experiment.greedy_cap", "--greedy-cap", "Actions allowed to the greedy policy's evaluation climb",
       &l.greedy_cap},
      {"learning.alpha", "--learning-rate", "Q-learning step size alpha", &l.dyna.rates.alpha},
      {"learning.gamma", "--gamma", "Discount factor gamma", &l.dyna.rates.gamma},
      {"learning.planning_steps", "--planning-steps", "Dyna planning updates per real step", &l.dyna.planning_steps},
      {"learning.epsilon", "--epsilon", "Exploration rate of Algorithm 3", &l.dyna.epsilon},
      {"learning.planner", "--planner",
       "Dyna planning: uniform (Algorithm 2) or prioritized (prioritized sweeping, same number of updates)",
       &c.planner},
      {"learning.priority_threshold", "--priority-threshold",
       "Prioritized sweeping queues pairs whose |TD error| exceeds this", &l.dyna.priority_threshold},
      {"rewards.unreachable", "--reward-unreachable", "Reward of an unreachable 4-configuration",
       &m.rewards.unreachable},
      {"rewards.step", "--reward-step", "Reward of a reachable 4-configuration", &m.rewards.step},
      {"rewards.finish", "--reward-finish", "Reward when the centre of mass passes the finishing height",
       &m.rewards.finish},
      {"ik.solver", "--solver", "IK solver: fast or paper (Algorithm 1)", &c.solver},
      {"ik.alpha", "--ik-alpha", "Step size of the paper's gradient descent", &ik.paper.step_size},
      {"ik.time_step", "--ik-time-step", "Simulated seconds per IK iteration", &ik.time_step_s},
      {"ik.timeout", "--ik-timeout", "Delta_t: simulated seconds before IK gives up", &ik.paper.timeout_s},
      {"ik.fast_max_iterations", "--fast-max-iterations", "Iteration cap of the fast solver", &ik.fast.max_iterations},
      {"ik.grasp_radius", "--grasp-radius", "Radius of the grasp spheres (m)", &ik.tolerances.grasp_radius},
      {"ik.root_tolerance", "--root-tolerance", "Radius of the root tolerance sphere (m)", &ik.tolerances.root_radius},
      {"ik.wall_distance", "--wall-distance", "x of the root target H(C4) (m)", &m.reachability.root.distance_from_wall},
      {"ik.cache_unreachable", "--cache-unreachable", "Cache unreachable verdicts", &m.reachability.cache_unreachable},
      {"filter.max_span", "--max-span", "Largest distance between two holds of a configuration (m)",
       &m.filter.max_span_m},
      {"filter.reading", "--reading", "Reading of 'both feet above the hands'", &c.reading},
      {"grid.columns", "--grid-columns", "Columns of the moving grid", &m.grid.columns},
      {"grid.rows", "--grid-rows", "Rows of the moving grid", &m.grid.rows},
      {"grid.tile_width", "--grid-tile-width", "Tile width of the moving grid (m)", &m.grid.tile_width},
      {"grid.tile_height", "--grid-tile-height", "Tile height of the moving grid (m)", &m.grid.tile_height},
      {"grid.right_hand_anchor_column", "--rh-anchor-column", "Right hand's anchor tile P_1: column", &m.grid.anchors[0][0]},
      {"grid.right_hand_anchor_row", "--rh-anchor-row", "Right hand's anchor tile P_1: row", &m.grid.anchors[0][1]},
      {"grid.left_hand_anchor_column", "--lh-anchor-column", "Left hand's anchor tile P_2: column", &m.grid.anchors[1][0]},
      {"grid.left_hand_anchor_row", "--lh-anchor-row", "Left hand's anchor tile P_2: row", &m.grid.anchors[1][1]},
      {"grid.right_foot_anchor_column", "--rf-anchor-column", "Right foot's anchor tile P_3: column", &m.grid.anchors[2][0]},
      {"grid.right_foot_anchor_row", "--rf-anchor-row", "Right foot's anchor tile P_3: row", &m.grid.anchors[2][1]},
      {"grid.left_foot_anchor_column", "--lf-anchor-column", "Left foot's anchor tile P_4: column", &m.grid.anchors[3][0]},
      {"grid.left_foot_anchor_row", "--lf-anchor-row", "Left foot's anchor tile P_4: row", &m.grid.anchors[3][1]},
      {"walls.columns", "--wall-columns", "Tiles across a random wall", &s.walls.columns},
      {"walls.rows", "--wall-rows", "Tiles up a random wall", &s.walls.rows},
      {"walls.tile_width", "--wall-tile-width", "Tile width of a random wall (m)", &s.walls.tile_width},
      {"walls.tile_height", "--wall-tile-height", "Tile height of a random wall (m)", &s.walls.tile_height},
      {"walls.sigma", "--wall-sigma", "Standard deviation of hold displacement (m)", &s.walls.sigma},
      {"walls.hold_radius", "--hold-radius", "Hold radius (m)", &s.walls.hold_radius},
      {"walls.finish_height", "--finish-height", "Finishing height of the centre of mass (m)", &s.walls.finish_height},
  };
}

namespace {

std::string toml_double(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

std::string toml_string(const std::string& value) {
  std::string out = "\"";
  for (const char ch : value) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

void assign(const std::string& path, const ConfigField& field, const toml::node& node) {
  const auto where = [&] {
    return fmt::format("line {}: {}", node.source().begin.line, field.key);
  };
  std::visit(
      [&](auto* target) {
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, double>) {
          if (const auto v = node.value<double>(); v && std::isfinite(*v)) {
            *target = *v;
            return;
          }
          throw InputError(path, where() + " must be a finite number");
        } else if constexpr (std::is_same_v<T, int>) {
          if (const auto v = node.as_integer(); v && v->get() >= std::numeric_limits<int>::min() &&
                                                v->get() <= std::numeric_limits<int>::max()) {
            *target = static_cast<int>(v->get());
            return;
          }
          throw InputError(path, where() + " must be an integer");
        } else if constexpr (std::is_same_v<T, std::uint64_t>) {
          if (const auto v = node.as_integer(); v && v->get() >= 0) {
            *target = static_cast<std::uint64_t>(v->get());
            return;
          }
          // TOML integers are signed 64-bit: larger seeds are written as strings.
          if (const auto v = node.as_string()) {
            const std::string& text = v->get();
            std::size_t used = 0;
            try {
              if (!text.empty() && text[0] != '-') *target = std::stoull(text, &used);
            } catch (const std::exception&) {
              used = 0;
            }
            if (used > 0 && used == text.size()) return;
          }
          throw InputError(path, where() + " must be a non-negative integer");
        } else if constexpr (std::is_same_v<T, bool>) {
          if (const auto v = node.as_boolean()) {
            *target = v->get();
            return;
          }
          throw InputError(path, where() + " must be true or false");
        } else {
          if (const auto v = node.as_string()) {
            *target = v->get();
            return;
          }
          throw InputError(path, where() + " must be a string");
        }
      },
      field.target);
}

}  // namespace

void apply_config_file(const std::string& path, ExperimentConfig& config) {
  toml::table table;
  try {
    table = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    const std::string description(e.description());
    if (e.source().begin.line == 0) throw InputError(path, "cannot read the config file: " + description);
    throw InputError(path, fmt::format("TOML syntax error at line {}, column {}: {}", e.source().begin.line,
                                       e.source().begin.column, description));
  }
  std::map<std::string, const ConfigField*> known;
  const std::vector<ConfigField> fields = config_fields(config);
  for (const ConfigField& field : fields) known[field.key] = &field;
  for (const auto& [section, section_node] : table) {
    const toml::table* entries = section_node.as_table();
    if (entries == nullptr) {
      throw InputError(path, fmt::format("line {}: '{}' must be a [section]", section_node.source().begin.line,
                                         section.str()));
    }
    for (const auto& [name, node] : *entries) {
      const std::string key = std::string(section.str()) + "." + std::string(name.str());
      const auto it = known.find(key);
      if (it == known.end()) throw InputError(path, fmt::format("line {}: unknown key {}", node.source().begin.line, key));
      assign(path, *it->second, node);
    }
  }
}

namespace {
constexpr long long kMaxRunsPerCondition = 1000000;
}  // namespace

void finalize_config(ExperimentConfig& config) {
  ExperimentSettings& s = config.settings;
  const auto solver = parse_ik_solver(config.solver);
  if (!solver) throw InputError("ik.solver", fmt::format("unknown solver '{}' (expected fast or paper)", config.solver));
  s.learning.climbing.reachability.ik.solver = *solver;
  const auto planner = parse_planner(config.planner);
  if (!planner) {
    throw InputError("learning.planner", fmt::format("unknown planner '{}' (expected uniform or prioritized)", config.planner));
  }
  s.learning.dyna.planner = *planner;
  const auto reading = parse_reading(config.reading);
  if (!reading) throw InputError("filter.reading", fmt::format("unknown reading '{}'", config.reading));
  s.learning.climbing.filter.feet_above_hands = *reading;
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw InputError("config", what);
  };
  require(config.runs >= 0, "experiment.runs must be 0 or positive");
  if (config.runs > 0) {
    s.wall_pairs = config.runs;
    s.seeds_per_wall = 1;
    config.runs = 0;
  }
  require(s.wall_pairs > 0, "experiment.walls must be positive");
  require(s.seeds_per_wall > 0, "experiment.seeds_per_wall must be positive");
  require(static_cast<long long>(s.wall_pairs) * s.seeds_per_wall <= kMaxRunsPerCondition,
          "experiment.walls x experiment.seeds_per_wall must be at most 1000000 runs per condition");
  require(s.threads >= 0, "experiment.threads must be 0 (all cores) or positive");
  require(s.learning.iterations > 0, "experiment.iterations must be positive");
  require(s.analysis.beginning > 0, "experiment.beginning_iterations must be positive");
  require(s.analysis.threshold_length > 0, "experiment.threshold_length must be positive");
  require(s.analysis.bootstrap_resamples >= 100 && s.analysis.bootstrap_resamples <= 10000000,
          "experiment.bootstrap_resamples must be in [100, 10000000]");
  require(s.learning.dyna.rates.alpha > 0 && s.learning.dyna.rates.alpha <= 1, "learning.alpha must be in (0, 1]");
  require(s.learning.dyna.rates.gamma >= 0 && s.learning.dyna.rates.gamma < 1, "learning.gamma must be in [0, 1)");
  require(s.learning.dyna.planning_steps >= 0, "learning.planning_steps must be >= 0");
  require(s.learning.dyna.epsilon >= 0 && s.learning.dyna.epsilon <= 1, "learning.epsilon must be in [0, 1]");
  require(s.learning.dyna.priority_threshold >= 0, "learning.priority_threshold must be >= 0");
  const GridParameters& grid = s.learning.climbing.grid;
  require(grid.columns > 0 && grid.rows > 0, "grid columns and rows must be positive");
  for (const auto& anchor : grid.anchors) {
    require(anchor[0] >= 0 && anchor[0] < grid.columns && anchor[1] >= 0 && anchor[1] < grid.rows,
            "every grid anchor must be a tile of the grid");
  }
  int start_columns = 0, start_rows = 0;
  for (const auto& vertex : s.walls.start_vertices) {
    start_columns = std::max(start_columns, vertex[0]);
    start_rows = std::max(start_rows, vertex[1]);
  }
  require(s.walls.columns >= start_columns && s.walls.rows >= start_rows,
          "walls.columns and walls.rows must reach the start holds (at least 3 tiles each)");
  require(s.walls.tile_width > 0 && s.walls.tile_height > 0, "walls tile sizes must be positive");
  require(grid.tile_width > 0 && grid.tile_height > 0, "grid tile sizes must be positive");
  const double state_codes = 4.0 * std::pow(grid.tile_count() + 1.0, 3.0);
  require(state_codes < 4294967296.0, "the grid has too many tiles for 32-bit agent-state codes");
  require(s.walls.hold_radius > 0, "walls.hold_radius must be positive");
  const IkSettings& ik = s.learning.climbing.reachability.ik;
  require(ik.paper.step_size > 0 && ik.time_step_s > 0 && ik.paper.timeout_s > 0,
          "ik.alpha, ik.time_step and ik.timeout must be positive");
}

std::string config_to_toml(ExperimentConfig& config) {
  std::ostringstream out;
  out << "# crux effective configuration: every parameter of this run (docs/OUTPUTS.md)\n";
  std::string section;
  for (const ConfigField& field : config_fields(config)) {
    const std::string field_section = field.key.substr(0, field.key.find('.'));
    if (field_section != section) {
      out << (section.empty() ? "" : "\n") << '[' << field_section << "]\n";
      section = field_section;
    }
    out << field.key.substr(field.key.find('.') + 1) << " = ";
    std::visit(
        [&](auto* target) {
          using T = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<T, double>) {
            out << toml_double(*target);
          } else if constexpr (std::is_same_v<T, bool>) {
            out << (*target ? "true" : "false");
          } else if constexpr (std::is_same_v<T, std::string>) {
            out << toml_string(*target);
          } else if constexpr (std::is_same_v<T, std::uint64_t>) {
            if (*target > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
              out << '"' << *target << '"';
            } else {
              out << *target;
            }
          } else {
            out << *target;
          }
        },
        field.target);
    out << "  # " << field.help << '\n';
  }
  return out.str();
}

}  // namespace crux
