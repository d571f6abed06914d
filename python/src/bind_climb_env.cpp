// ClimbMdp: the climbing MDP (sections III-C, III-D) with Gymnasium's conventions,
// reset() -> (obs, info) and step(action) -> (obs, reward, terminated, truncated, info),
// without needing the gymnasium package (crux.gym wraps it as a gymnasium.Env). An action
// is a hold index; action_mask() says which the state offers (the geometric filter's
// possible actions).

#include <limits>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "bindings.hpp"
#include "climb_episode.hpp"
#include "common/input_error.hpp"
#include "conversions.hpp"
#include "python_config.hpp"

namespace crux::python {

namespace {

class ClimbMdp {
 public:
  ClimbMdp(Wall wall, const py::handle& config, const py::handle& max_steps, const py::handle& model) {
    // None leaves truncation to the caller (crux.gym: Gymnasium's TimeLimit).
    if (!max_steps.is_none()) {
      max_steps_ = static_cast<int>(integer_from(max_steps, 1, std::numeric_limits<int>::max(), "max_steps"));
    }
    const ExperimentConfig c = config_from_python(config, kClimbMdpKeys, "ClimbMdp");
    BodyModelPtr body = body_from(model, c.urdf);
    py::gil_scoped_release release;
    episode_ = std::make_unique<ClimbEpisode>(std::move(body), std::move(wall), c.settings.learning.climbing,
                                              c.settings.learning.dyna.rates.gamma);
  }

  py::tuple reset(const py::handle& seed, const py::handle&) {
    // Gymnasium's seed is None or an integer; whatever else is a mistake, refused though unused.
    if (!seed.is_none()) uint64_from(seed, "seed");
    episode_->reset();
    steps_ = 0;
    over_ = false;
    py::dict info;
    info["centre_of_mass"] = to_array(episode_->centre_of_mass());
    return py::make_tuple(observation(), info);
  }

  py::tuple step(const py::handle& action_handle) {
    if (over_) throw std::logic_error("the episode is over (terminated or truncated): call reset() first");
    const int action = checked_action(action_handle);
    const EpisodeStep outcome = episode_->step(action);
    ++steps_;
    const bool truncated = !outcome.terminated && max_steps_ && steps_ >= *max_steps_;
    over_ = outcome.terminated || truncated;
    py::dict info;
    // The hold as the CLI and the run files name it (their ids); the action is its index.
    info["hold_id"] = wall().holds[action].id;
    info["reached"] = outcome.reached;
    info["fell"] = outcome.fell;
    info["root_rise"] = outcome.root_rise_m;
    info["centre_of_mass"] = to_array(episode_->centre_of_mass());
    return py::make_tuple(observation(), outcome.reward, outcome.terminated, truncated, info);
  }

  // The C++ steps alone, for the cost of the binding (bench/python_step_overhead.py).
  double replay_actions(const py::handle& actions_handle) {
    const auto actions = integer_array_from(actions_handle, "actions");
    std::vector<int> checked(actions.size());
    for (py::ssize_t i = 0; i < actions.size(); ++i) {
      if (actions.data()[i] < 0 || actions.data()[i] >= wall().hold_count()) {
        throw InputError("actions", "holds a value that is not a hold index");
      }
      checked[i] = static_cast<int>(actions.data()[i]);
    }
    double total = 0.0;
    py::gil_scoped_release release;
    ClimbingMdp& mdp = episode_->mdp();
    for (const int action : checked) {
      if (!mdp.offers(action)) throw InputError("actions", fmt::format("hold {} is not a possible action", action));
      total += mdp.step(action).reward;
    }
    return total;
  }

  py::array_t<bool> action_mask() const {
    py::array_t<bool> mask(wall().hold_count());
    bool* out = mask.mutable_data();
    std::fill(out, out + wall().hold_count(), false);
    for (const int hold : episode_->offered_holds()) out[hold] = true;
    return mask;
  }

  py::dict observation() const {
    const HoldConfiguration& c = episode_->configuration();
    const StateCouple& codes = episode_->codes();
    py::array_t<double> holds({kLimbCount, 3});
    double* h = holds.mutable_data();
    for (int limb = 0; limb < kLimbCount; ++limb) {
      for (int k = 0; k < 3; ++k) {
        h[3 * limb + k] =
            c.holds[limb] == kFree ? std::numeric_limits<double>::quiet_NaN() : wall().holds[c.holds[limb]].position[k];
      }
    }
    py::dict obs;
    obs["wall_state"] = codes.wall;
    obs["grid_state"] = codes.grid;
    obs["free_limb"] = static_cast<int>(c.free_limb());
    obs["configuration"] = to_array(c);
    obs["holds"] = holds;
    obs["posture"] = to_array(episode_->posture());
    return obs;
  }

  py::dict numeric_observation(const py::handle& max_candidates_handle, bool reach) {
    const auto max_candidates =
        static_cast<int>(integer_from(max_candidates_handle, 1, std::numeric_limits<int>::max(), "max_candidates"));
    const NumericObservationArrays arrays(-1, max_candidates, reach);
    episode_->write_numeric_observation(max_candidates, arrays.rows(0));
    return arrays.dict();
  }

  int action_count() const { return wall().hold_count(); }
  int grid_action_count() const { return episode_->grid_action_count(); }
  const Wall& wall() const { return episode_->wall(); }
  BodyModelPtr model() const { return episode_->model(); }
  double max_span() const { return episode_->parameters().filter.max_span_m; }
  py::object max_steps() const { return max_steps_ ? py::object(py::int_(*max_steps_)) : py::object(py::none()); }
  int steps() const { return steps_; }

 private:
  int checked_action(const py::handle& handle) const {
    const auto action = static_cast<int>(integer_from(handle, 0, wall().hold_count() - 1, "action"));
    if (episode_->offers(action)) return action;
    throw InputError("action",
                     fmt::format("hold {} is not a possible action of this state (see action_mask())", action));
  }

  std::unique_ptr<ClimbEpisode> episode_;
  std::optional<int> max_steps_;
  int steps_ = 0;
  bool over_ = false;
};

}  // namespace

void bind_climb_env(py::module_& m) {
  py::class_<ClimbMdp>(m, "ClimbMdp",
                       "The climbing MDP as a Gymnasium-style environment: an action is a hold index for the free "
                       "limb; see action_mask()")
      .def(py::init<Wall, const py::handle&, const py::handle&, const py::handle&>(), py::arg("wall"),
           py::arg("config") = py::none(), py::arg("max_steps") = 1000, py::arg("model") = py::none(),
           "config takes the keys of config.toml's [reward], [ik], [physics], [filter] and [grid] tables, "
           "experiment.urdf and "
           "learning.gamma (the discount of reward.height's shaping); "
           "an episode is truncated after max_steps actions, never when max_steps is None")
      .def("reset", &ClimbMdp::reset, py::arg("seed") = py::none(), py::arg("options") = py::none(),
           "Back to the start configuration with the right hand free: (obs, info). The environment draws no random "
           "number, so the seed (None or an integer from 0 to 2^64 - 1) changes nothing.")
      .def("step", &ClimbMdp::step, py::arg("action"), "(obs, reward, terminated, truncated, info)")
      .def("action_mask", &ClimbMdp::action_mask, "bool array over hold indices: the possible actions of the state")
      .def("observation", &ClimbMdp::observation)
      .def("numeric_observation", &ClimbMdp::numeric_observation, py::arg("max_candidates"), py::arg("reach") = false,
           "crux.gym's numeric observation of the state, its candidates in max_candidates slots: a dict of float32 "
           "arrays (docs/PYTHON.md); reach: the reach form's, with candidate_reach and candidate_failed")
      .def("replay_actions", &ClimbMdp::replay_actions, py::arg("actions"),
           "Steps through possible actions in C++, returning the summed reward and nothing else (the baseline of "
           "bench/python_step_overhead.py); leaves steps and the episode's end as they were")
      .def_property_readonly("action_count", &ClimbMdp::action_count, "the number of actions: the wall's holds")
      .def_property_readonly("grid_action_count", &ClimbMdp::grid_action_count)
      .def_property_readonly("wall", &ClimbMdp::wall)
      .def_property_readonly("max_span", &ClimbMdp::max_span, "filter.max_span, in metres")
      .def_property_readonly("model", &ClimbMdp::model)
      .def_property_readonly("max_steps", &ClimbMdp::max_steps)
      .def_property_readonly("steps", &ClimbMdp::steps, "actions since the last reset");
}

}  // namespace crux::python
