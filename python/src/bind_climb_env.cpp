// ClimbEnv: the climbing MDP (sections III-C, III-D) with Gymnasium's conventions,
// reset() -> (obs, info) and step(action) -> (obs, reward, terminated, truncated, info),
// without needing the gymnasium package (crux.gym wraps it as a gymnasium.Env). An action
// is a hold index; action_mask() says which the state offers (the geometric filter's
// possible actions).

#include <limits>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "agent_space/agent_descriptor.hpp"
#include "bindings.hpp"
#include "body/kinematics.hpp"
#include "climbing/climbing_mdp.hpp"
#include "common/input_error.hpp"
#include "conversions.hpp"
#include "python_config.hpp"

namespace crux::python {

namespace {

const ParameterSet kEnvKeys{{"experiment.urdf", "reward", "ik", "physics", "filter", "grid"}, {}};

// Where the finishing move left the climber, described as any state: the MDP itself is
// back at the start (Algorithm 2), but Gymnasium's terminal observation is this one.
struct FinishingState {
  HoldConfiguration configuration;  // the 3-configuration with the next limb free
  Posture posture;
  StateCouple codes;
  std::vector<int> possible;  // its possible actions
};

class ClimbEnv {
 public:
  ClimbEnv(Wall wall, const py::handle& config, const py::handle& max_steps, const py::handle& model)
      : wall_(std::move(wall)) {
    // None leaves truncation to the caller (crux.gym: Gymnasium's TimeLimit).
    if (!max_steps.is_none()) {
      max_steps_ = static_cast<int>(integer_from(max_steps, 1, std::numeric_limits<int>::max(), "max_steps"));
    }
    const ExperimentConfig c = config_from_python(config, kEnvKeys, "ClimbEnv");
    parameters_ = c.settings.learning.climbing;
    model_ = body_from(model, c.urdf);
    {
      py::gil_scoped_release release;
      mdp_ = std::make_unique<ClimbingMdp>(*model_, wall_, c.settings.learning.climbing);
      BodyData data(*model_);
      forward_kinematics(*model_, data, mdp_->start_posture());
      start_centre_of_mass_ = centre_of_mass(*model_, data);
    }
    centre_of_mass_ = start_centre_of_mass_;
  }

  // Holds the MDP, which keeps a reference to wall_: never copied nor moved.
  ClimbEnv(const ClimbEnv&) = delete;
  ClimbEnv& operator=(const ClimbEnv&) = delete;

  py::tuple reset(const py::handle& seed, const py::handle&) {
    // Gymnasium's seed is None or an integer; whatever else is a mistake, refused though unused.
    if (!seed.is_none()) uint64_from(seed, "seed");
    mdp_->reset();
    steps_ = 0;
    over_ = false;
    finish_.reset();
    centre_of_mass_ = start_centre_of_mass_;
    py::dict info;
    info["centre_of_mass"] = to_array(centre_of_mass_);
    return py::make_tuple(observation(), info);
  }

  py::tuple step(const py::handle& action_handle) {
    if (over_) throw std::logic_error("the episode is over (terminated or truncated): call reset() first");
    const int action = checked_action(action_handle);
    const HoldConfiguration before = mdp_->configuration();
    const StepOutcome outcome = mdp_->step(action);
    ++steps_;
    if (outcome.reached) centre_of_mass_ = outcome.centre_of_mass;
    const bool terminated = outcome.finished;
    const bool truncated = !terminated && max_steps_ && steps_ >= *max_steps_;
    over_ = terminated || truncated;
    py::dict info;
    // The hold as the CLI and the run files name it (their ids); the action is its index.
    info["hold_id"] = wall_.holds[action].id;
    info["reached"] = outcome.reached;
    info["root_rise"] = outcome.root_rise_m;
    info["centre_of_mass"] = to_array(centre_of_mass_);
    if (terminated) finish_ = finishing_state(before, action, *outcome.posture);
    return py::make_tuple(observation(), outcome.reward, terminated, truncated, info);
  }

  // The C++ steps alone, for the cost of the binding (bench/python_step_overhead.py).
  double replay_actions(const py::handle& actions_handle) {
    const auto actions = integer_array_from(actions_handle, "actions");
    std::vector<int> checked(actions.size());
    for (py::ssize_t i = 0; i < actions.size(); ++i) {
      if (actions.data()[i] < 0 || actions.data()[i] >= wall_.hold_count()) {
        throw InputError("actions", "holds a value that is not a hold index");
      }
      checked[i] = static_cast<int>(actions.data()[i]);
    }
    double total = 0.0;
    py::gil_scoped_release release;
    for (const int action : checked) {
      if (!mdp_->offers(action)) throw InputError("actions", fmt::format("hold {} is not a possible action", action));
      total += mdp_->step(action).reward;
    }
    return total;
  }

  py::array_t<bool> action_mask() const {
    py::array_t<bool> mask(wall_.hold_count());
    bool* out = mask.mutable_data();
    std::fill(out, out + wall_.hold_count(), false);
    if (finish_) {
      for (const int hold : finish_->possible) out[hold] = true;
    } else {
      for (const ActionCandidate& candidate : mdp_->candidates()) out[candidate.wall] = true;
    }
    return mask;
  }

  py::dict observation() const {
    const HoldConfiguration& c = finish_ ? finish_->configuration : mdp_->configuration();
    const StateCouple& codes = finish_ ? finish_->codes : mdp_->state();
    py::array_t<double> holds({kLimbCount, 3});
    double* h = holds.mutable_data();
    for (int limb = 0; limb < kLimbCount; ++limb) {
      for (int k = 0; k < 3; ++k) {
        h[3 * limb + k] =
            c.holds[limb] == kFree ? std::numeric_limits<double>::quiet_NaN() : wall_.holds[c.holds[limb]].position[k];
      }
    }
    py::dict obs;
    obs["wall_state"] = codes.wall;
    obs["grid_state"] = codes.grid;
    obs["free_limb"] = static_cast<int>(c.free_limb());
    obs["configuration"] = to_array(c);
    obs["holds"] = holds;
    obs["posture"] = to_array(finish_ ? finish_->posture : mdp_->posture());
    return obs;
  }

  int action_count() const { return wall_.hold_count(); }
  int grid_action_count() const { return mdp_->grid_action_count(); }
  const Wall& wall() const { return wall_; }
  BodyModelPtr model() const { return model_; }
  py::object max_steps() const { return max_steps_ ? py::object(py::int_(*max_steps_)) : py::object(py::none()); }
  int steps() const { return steps_; }

 private:
  // The 3-configuration the climb would go on from had the finishing move not ended it.
  FinishingState finishing_state(const HoldConfiguration& before, int hold, const Posture& posture) const {
    const Limb free = before.free_limb();
    const Limb next = next_free_limb(free);
    FinishingState f;
    f.configuration = before.with(free, hold).with(next, kFree);
    f.posture = posture;
    BodyData body(*model_);
    forward_kinematics(*model_, body, posture);
    const GridPlacement placement = place_grid(parameters_.grid, next, body.points[operational_point(next)]);
    f.codes.wall = encode(f.configuration, wall_.hold_count());
    f.codes.grid = encode(describe_state(wall_, f.configuration, placement), parameters_.grid);
    f.possible.resize(wall_.hold_count());
    f.possible.resize(possible_actions(wall_, f.configuration, parameters_.filter, f.possible));
    return f;
  }

  int checked_action(const py::handle& handle) const {
    const auto action = static_cast<int>(integer_from(handle, 0, wall_.hold_count() - 1, "action"));
    if (mdp_->offers(action)) return action;
    throw InputError("action",
                     fmt::format("hold {} is not a possible action of this state (see action_mask())", action));
  }

  BodyModelPtr model_;
  Wall wall_;  // before mdp_, which keeps a reference to it
  std::unique_ptr<ClimbingMdp> mdp_;
  ClimbingParameters parameters_;
  std::optional<FinishingState> finish_;  // set by the finishing step until reset()
  std::optional<int> max_steps_;
  int steps_ = 0;
  bool over_ = false;
  Eigen::Vector3d start_centre_of_mass_, centre_of_mass_;
};

}  // namespace

void bind_climb_env(py::module_& m) {
  py::class_<ClimbEnv>(m, "ClimbEnv",
                       "The climbing MDP as a Gymnasium-style environment: an action is a hold index for the free "
                       "limb; see action_mask()")
      .def(py::init<Wall, const py::handle&, const py::handle&, const py::handle&>(), py::arg("wall"),
           py::arg("config") = py::none(), py::arg("max_steps") = 1000, py::arg("model") = py::none(),
           "config takes the keys of config.toml's [reward], [ik], [filter] and [grid] tables and experiment.urdf; "
           "an episode is truncated after max_steps actions, never when max_steps is None")
      .def("reset", &ClimbEnv::reset, py::arg("seed") = py::none(), py::arg("options") = py::none(),
           "Back to the start configuration with the right hand free: (obs, info). The environment draws no random "
           "number, so the seed (None or an integer from 0 to 2^64 - 1) changes nothing.")
      .def("step", &ClimbEnv::step, py::arg("action"), "(obs, reward, terminated, truncated, info)")
      .def("action_mask", &ClimbEnv::action_mask, "bool array over hold indices: the possible actions of the state")
      .def("observation", &ClimbEnv::observation)
      .def("replay_actions", &ClimbEnv::replay_actions, py::arg("actions"),
           "Steps through possible actions in C++, returning the summed reward and nothing else (the baseline of "
           "bench/python_step_overhead.py); leaves steps and the episode's end as they were")
      .def_property_readonly("action_count", &ClimbEnv::action_count, "the number of actions: the wall's holds")
      .def_property_readonly("grid_action_count", &ClimbEnv::grid_action_count)
      .def_property_readonly("wall", &ClimbEnv::wall)
      .def_property_readonly("model", &ClimbEnv::model)
      .def_property_readonly("max_steps", &ClimbEnv::max_steps)
      .def_property_readonly("steps", &ClimbEnv::steps, "actions since the last reset");
}

}  // namespace crux::python
