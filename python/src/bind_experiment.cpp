// The paper's agent and experiment: one learning run (Algorithm 2), and the experiment
// of section IV, returning what the CLI's summary.json holds.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "common/input_error.hpp"
#include "conversions.hpp"
#include "experiments/climb_graph.hpp"
#include "experiments/config_key_json.hpp"
#include "interruption.hpp"
#include "jobs/command_keys.hpp"
#include "jobs/learning_job.hpp"
#include "jobs/paper_job.hpp"
#include "jobs/perform_job.hpp"
#include "python_config.hpp"
#include "reports/plan_description.hpp"

namespace crux::python {

namespace {

py::object json_to_python(const nlohmann::ordered_json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

py::array_t<double> postures_array(const std::vector<Posture>& postures) {
  py::array_t<double> out({static_cast<py::ssize_t>(postures.size()), py::ssize_t{kConfigurationDof}});
  for (std::size_t i = 0; i < postures.size(); ++i) {
    std::copy(postures[i].data(), postures[i].data() + kConfigurationDof, out.mutable_data() + i * kConfigurationDof);
  }
  return out;
}

struct LearningRun {
  RunResult run;
  py::object summary;
  int resumed_at = 0;
};

// A job's output folder: none for None.
std::optional<std::filesystem::path> output_from(const py::handle& output) {
  if (output.is_none()) return std::nullopt;
  const std::string folder = path_from(output);
  if (folder.empty()) throw InputError("output", "the output folder name is empty");
  return folder;
}

py::dict iterations_dict(const RunResult& run) {
  const auto n = static_cast<py::ssize_t>(run.iterations.size());
  py::array_t<int> episode(n), hold_id(n);
  py::array_t<bool> success(n);
  py::array_t<double> reward(n), root_rise(n);
  py::list regime;
  for (py::ssize_t i = 0; i < n; ++i) {
    const IterationRecord& r = run.iterations[i];
    episode.mutable_at(i) = r.episode;
    hold_id.mutable_at(i) = r.hold_id;
    success.mutable_at(i) = r.success;
    reward.mutable_at(i) = r.reward;
    root_rise.mutable_at(i) = r.root_rise_m;
    regime.append(enum_name(r.regime));
  }
  py::dict out;
  out["episode"] = episode;
  out["regime"] = regime;
  out["hold_id"] = hold_id;
  out["success"] = success;
  out["reward"] = reward;
  out["root_rise_m"] = root_rise;
  return out;
}

// A wall given as an object leaves the random wall's keys nothing to shape.
void refuse_wall_generator_keys(const ExperimentConfig& config) {
  for (const std::string& key : config.given) {
    if (is_wall_generator_key(key)) {
      throw InputError(key, "shapes a random wall, and the wall argument gives the wall itself: drop one of them");
    }
  }
}

// crux.run_learning is crux train and crux transfer in one: crux transfer's keys, and
// crux train's policy file of the network transfer mode.
ParameterSet run_learning_keys() {
  ParameterSet keys = kTransferKeys;
  keys.include.push_back("experiment.policy");
  return keys;
}

// A config given as a file replays a folder: its recorded digests must match the inputs.
bool config_is_file(const py::handle& config) { return !config.is_none() && !py::isinstance<py::dict>(config); }

LearningRun run_learning_py(const py::handle& wall_handle, const py::handle& config_handle,
                            const py::handle& seed_handle, const py::handle& q_grid_handle,
                            const py::handle& model_handle, const py::handle& output, bool overwrite) {
  LearningJob job;
  static const ParameterSet keys = run_learning_keys();
  job.config = config_from_python(config_handle, keys, "run_learning");
  ExperimentConfig& config = job.config;
  if (!wall_handle.is_none()) {
    if (!config.wall_file.empty() || config.wall_seed) {
      throw InputError("wall", "give the wall as wall or as config's wall.file or wall.seed, not both");
    }
    refuse_wall_generator_keys(config);
    job.wall = wall_handle.cast<Wall>();
  }
  if (!seed_handle.is_none()) config.settings.seed = uint64_from(seed_handle, "seed");
  const BodyModelPtr model = body_from(model_handle, config.urdf);
  if (!model_handle.is_none()) config.urdf = model->source;  // what the provenance records: the body used
  job.model = model.get();
  if (!q_grid_handle.is_none()) {
    if (!config.q_grid.empty()) {
      throw InputError("q_grid", "give the Q_grid as q_grid or as config's experiment.q_grid, not both");
    }
    if (py::isinstance<QTable>(q_grid_handle)) {
      job.q_grid = q_grid_handle.cast<QTable>();
    } else {
      config.q_grid = path_from(q_grid_handle);
    }
  }
  const bool transfer = job.q_grid || !config.q_grid.empty();
  job.condition = transfer ? Condition::Transfer : Condition::Training;
  if (config_is_file(config_handle)) job.config_path = path_from(config_handle);
  job.output = output_from(output);
  job.overwrite = overwrite;
  InterruptGuard guard;
  LearningRun out;
  nlohmann::ordered_json summary;
  {
    py::gil_scoped_release release;
    const Condition condition = job.condition;
    LearningJobOutcome outcome =
        run_learning_job(std::move(job), {"crux.run_learning", {}, [&guard] { guard.poll(); }, {}});
    summary = std::move(outcome.summary);
    out.resumed_at = outcome.resumed_at;
    out.run = std::move(outcome.result.conditions[static_cast<int>(condition)].runs.front());
  }
  out.summary = json_to_python(summary);
  return out;
}

py::object run_experiment_py(const py::handle& config_handle, const py::handle& output, bool overwrite) {
  PaperJob job{config_from_python(config_handle, kPaperKeys, "run_experiment")};
  if (config_is_file(config_handle)) job.config_path = path_from(config_handle);
  job.output = output_from(output);
  job.overwrite = overwrite;
  InterruptGuard guard;
  nlohmann::ordered_json summary;
  {
    py::gil_scoped_release release;
    summary = run_paper_job(std::move(job), {"crux.run_experiment", {}, [&guard] { guard.poll(); }, {}}).summary;
  }
  return json_to_python(summary);
}

py::object perform_py(const py::handle& wall_handle, const py::handle& config_handle, const py::handle& output,
                      bool overwrite) {
  PerformJob job{config_from_python(config_handle, kPerformKeys, "perform", perform_defaults()), {}, {}, false, {}};
  ExperimentConfig& config = job.config;
  if (!wall_handle.is_none()) {
    if (!config.wall_file.empty() || config.wall_seed || !config.run.empty()) {
      throw InputError("wall",
                       "give the wall as wall, or as config's wall.file, wall.seed or experiment.run, not both");
    }
    refuse_wall_generator_keys(config);
    job.wall = wall_handle.cast<Wall>();
  } else if (config.wall_file.empty() && !config.wall_seed && config.run.empty()) {
    throw InputError("wall", "give a wall (a Wall, or config's wall.file or wall.seed) or a run (experiment.run)");
  }
  if (config_is_file(config_handle)) job.config_path = path_from(config_handle);
  job.output = output_from(output);
  job.overwrite = overwrite;
  InterruptGuard guard;
  nlohmann::ordered_json record;
  {
    py::gil_scoped_release release;
    PerformJobOutcome outcome = run_perform_job(std::move(job), {"crux.perform", {}, [&guard] { guard.poll(); }, {}});
    record = std::move(outcome.record);
    record["wall_s"] = outcome.wall_s;
  }
  return json_to_python(record);
}

// What crux.plan takes: crux plan's keys but the wall's, which the wall argument gives,
// and the dynamic model's repairs, which need MuJoCo (crux.perform does them).
const ParameterSet kPythonPlanKeys{
    {"experiment.urdf", "experiment.plan_max_solves", "experiment.plan_check_moves", "ik", "physics", "filter"},
    {"physics.fall_when_stuck"}};

py::object plan_py(const Wall& wall, const py::handle& config_handle, const py::handle& model_handle) {
  const ExperimentConfig config = config_from_python(config_handle, kPythonPlanKeys, "plan");
  const BodyModelPtr model = body_from(model_handle, config.urdf);
  nlohmann::ordered_json record;
  {
    py::gil_scoped_release release;
    record =
        plan_json(wall, shortest_plan(*model, wall, config.settings.learning.climbing, config.settings.plan_search));
  }
  return json_to_python(record);
}

// What crux.climb_graph takes: the rules of a climb (crux.plan's keys without the plan's
// budget and move check: the graph has its own budget and checks stances only).
const ParameterSet kPythonClimbGraphKeys{{"experiment.urdf", "ik", "physics", "filter"}, {"physics.fall_when_stuck"}};

// crux.climb_graph: the graph's states and moves as arrays, each move marked optimal or not.
py::dict climb_graph_py(const Wall& wall, const py::handle& config_handle, const py::handle& model_handle,
                        const py::handle& max_solves_handle) {
  const ExperimentConfig config = config_from_python(config_handle, kPythonClimbGraphKeys, "climb_graph");
  const BodyModelPtr model = body_from(model_handle, config.urdf);
  const auto max_solves =
      static_cast<int>(integer_from(max_solves_handle, 1, std::numeric_limits<int>::max(), "max_ik_solves"));
  ClimbGraph graph;
  {
    py::gil_scoped_release release;
    graph = explore_climbs(*model, wall, config.settings.learning.climbing, max_solves);
  }
  const auto state_count = static_cast<py::ssize_t>(graph.states.size());
  py::array_t<int> configurations({state_count, py::ssize_t{kLimbCount}});
  py::array_t<int> distances(state_count);
  std::vector<int> moves;  // (state, hold, target, optimal) rows
  for (py::ssize_t s = 0; s < state_count; ++s) {
    const GraphState& state = graph.states[s];
    std::copy(state.configuration.holds.begin(), state.configuration.holds.end(),
              configurations.mutable_data() + s * kLimbCount);
    distances.mutable_data()[s] = state.distance;
    const std::vector<int> best = optimal_holds(graph, state);
    for (const GraphMove& move : state.moves) {
      const bool optimal = std::find(best.begin(), best.end(), move.hold) != best.end();
      moves.insert(moves.end(), {static_cast<int>(s), move.hold, move.target, optimal ? 1 : 0});
    }
  }
  py::array_t<int> move_rows({static_cast<py::ssize_t>(moves.size() / 4), py::ssize_t{4}});
  std::copy(moves.begin(), moves.end(), move_rows.mutable_data());
  py::dict out;
  out["configurations"] = configurations;
  out["distances"] = distances;
  out["moves"] = move_rows;
  out["stopped_at_limit"] = graph.stopped_at_limit;
  out["expanded_states"] = graph.expanded_states;
  out["ik_solves"] = graph.ik_solves;
  return out;
}

}  // namespace

namespace {

// One declared key as a dict (crux.config_keys): its declaration, and its default as "default".
py::dict key_dict(const ConstConfigField& field) {
  nlohmann::ordered_json declared = config_key_json(field);
  py::dict out;
  for (auto& [name, value] : declared.items()) out[py::str(name == "value" ? "default" : name)] = json_to_python(value);
  return out;
}

py::list config_keys_py() {
  static const ExperimentConfig defaults;
  py::list keys;
  for (const ConstConfigField& field : config_fields(defaults)) keys.append(key_dict(field));
  return keys;
}

}  // namespace

void bind_experiment(py::module_& m) {
  py::class_<LearningRun>(m, "LearningRun", "One learning run (Algorithm 2) and its summary")
      .def_readonly("summary", &LearningRun::summary, "what crux train (or transfer) writes to summary.json")
      .def_readonly("resumed_at", &LearningRun::resumed_at,
                    "the iteration a checkpoint in `output` resumed the run from; 0 when it ran from the start")
      .def_property_readonly("episode_lengths",
                             [](const LearningRun& r) {
                               return py::array_t<int>(static_cast<py::ssize_t>(r.run.episode_lengths.size()),
                                                       r.run.episode_lengths.data());
                             })
      .def_property_readonly(
          "iterations", [](const LearningRun& r) { return iterations_dict(r.run); },
          "per iteration: episode, regime, hold_id, success, reward, root_rise_m")
      .def_property_readonly(
          "q_grid", [](LearningRun& r) -> QTable& { return r.run.q_grid; }, py::return_value_policy::reference_internal)
      .def_property_readonly(
          "greedy_length", [](const LearningRun& r) { return r.run.greedy_length; },
          "actions of the learnt greedy policy's climb, -1 if it did not finish")
      .def_property_readonly("greedy_climb", [](const LearningRun& r) { return postures_array(r.run.greedy_climb); })
      .def_property_readonly("last_climb", [](const LearningRun& r) { return postures_array(r.run.last_climb); });

  m.def("config_keys", &config_keys_py,
        "Every config key, as crux declares it once for flags, config files and these dicts: a list of dicts with "
        "key, flag, type (number, integer, seed, boolean, text, path or choice), default (None when unset), unit, "
        "min and max (None when unbounded) with min_open and max_open, sizes_work (its maximum may take hours), "
        "choices and help");
  m.def("run_learning", &run_learning_py, py::arg("wall") = py::none(), py::arg("config") = py::none(),
        py::arg("seed") = py::none(), py::arg("q_grid") = py::none(), py::arg("model") = py::none(),
        py::arg("output") = py::none(), py::arg("overwrite") = false,
        "One learning run on a wall (a Wall, or config's wall.file or wall.seed), from empty tables or from a "
        "transferred Q_grid (a QTable or a q_grid.bin path): crux train, or crux transfer. config takes their keys; "
        "seed overrides experiment.seed. Writes their run folder to `output` when given (with checkpoints when "
        "experiment.checkpoint_every is set, resuming from one found there).");
  m.def("perform", &perform_py, py::arg("wall") = py::none(), py::arg("config") = py::none(),
        py::arg("output") = py::none(), py::arg("overwrite") = false,
        "A wall's exact plan (a Wall, or config's wall.file or wall.seed), or a run's climb (config's experiment.run "
        "and experiment.climb), performed in MuJoCo from its start (crux perform; physics.model static by default, "
        "dynamic repairs the plan): returns the record crux perform --json prints; writes its folder to `output` when "
        "given.");
  m.def("plan", &plan_py, py::arg("wall"), py::arg("config") = py::none(), py::arg("model") = py::none(),
        "A wall's exact shortest climb under the learning's rules (crux plan): returns the record crux plan --json "
        "prints. config takes the keys of [ik], [physics] and [filter], experiment.urdf and experiment.plan_*.");
  m.def("climb_graph", &climb_graph_py, py::arg("wall"), py::arg("config") = py::none(), py::arg("model") = py::none(),
        py::arg("max_ik_solves") = 5000000,
        "Every climb the learning's rules allow on the wall: its states (3-configurations reachable from the start, "
        "breadth-first, the start first) and their reachable moves, as a dict of arrays: configurations (hold indices "
        "in limb order, -1 free), distances (actions to the finish, -1 when none finishes), moves (rows of state, "
        "hold index, target state or -1 when the move finishes, 1 when the move is optimal), stopped_at_limit, "
        "expanded_states and ik_solves. config takes the keys of [ik], [physics] and [filter] and experiment.urdf; "
        "max_ik_solves bounds the IK solves (a random wall takes about 50,000). When stopped_at_limit, the states "
        "from expanded_states on were never explored and the distances say nothing.");
  m.def("run_experiment", &run_experiment_py, py::arg("config") = py::none(), py::arg("output") = py::none(),
        py::arg("overwrite") = false,
        "The paper's experiment (crux paper): returns summary.json's contents; writes crux paper's folder to "
        "`output` when given. config takes crux paper's keys (a dict, or a config.toml path).");
}

}  // namespace crux::python
