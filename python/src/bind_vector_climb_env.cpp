// VectorClimbEnv: num_envs climbing environments stepped in one call, with the GIL
// released, on TBB's threads (as crux paper runs its runs). Each environment owns its
// episodes (a ClimbEpisode: its MDP, posture cache and kinematics workspace) and shares
// only the immutable body and walls, so that threads share nothing they write, and each
// environment's numbers are those of a single ClimbMdp whatever thread steps it.
// crux.gym.VectorClimbEnv wraps it as a gymnasium.vector.VectorEnv: it draws the walls
// (from each environment's np_random, as the single environment does) and names them
// here before the step that resets (next-step autoreset), and assembles the infos.

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "bindings.hpp"
#include "climb_episode.hpp"
#include "common/input_error.hpp"
#include "conversions.hpp"
#include "python_config.hpp"

namespace crux::python {

namespace {

// What one call writes, as numpy arrays with one row per environment, and the raw
// pointers the threads write through (taken with the GIL held).
struct VectorBatch {
  // max_candidates: the numeric or reach form's slots, none for the paper's codes.
  VectorBatch(py::ssize_t envs, int action_count, std::optional<int> max_candidates, bool reach)
      : wall_state(envs),
        grid_state(envs),
        free_limb(envs),
        rewards(envs),
        terminated(envs),
        truncated(envs),
        stepped(envs),
        reached(envs),
        fell(envs),
        hold_id(envs),
        root_rise(envs),
        centre_of_mass({envs, py::ssize_t{3}}),
        action_mask({envs, py::ssize_t{action_count}}) {
    if (max_candidates) {
      numeric.emplace(envs, *max_candidates, reach);
      candidate_holds = py::array_t<std::int64_t>({envs, py::ssize_t{*max_candidates}});
    }
  }

  std::optional<NumericObservationArrays> numeric;  // or the paper's codes:
  py::array_t<std::int64_t> wall_state, grid_state, free_limb;
  py::array_t<double> rewards;
  py::array_t<bool> terminated, truncated, stepped, reached, fell;
  py::array_t<std::int64_t> hold_id;
  py::array_t<double> root_rise, centre_of_mass;
  py::array_t<std::int8_t> action_mask;
  py::array_t<std::int64_t> candidate_holds;
};

struct BatchRows {
  explicit BatchRows(VectorBatch& b)
      : rewards(b.rewards.mutable_data()),
        terminated(b.terminated.mutable_data()),
        truncated(b.truncated.mutable_data()),
        stepped(b.stepped.mutable_data()),
        reached(b.reached.mutable_data()),
        fell(b.fell.mutable_data()),
        hold_id(b.hold_id.mutable_data()),
        root_rise(b.root_rise.mutable_data()),
        centre_of_mass(b.centre_of_mass.mutable_data()),
        action_mask(b.action_mask.mutable_data()),
        wall_state(b.wall_state.mutable_data()),
        grid_state(b.grid_state.mutable_data()),
        free_limb(b.free_limb.mutable_data()),
        candidate_holds(b.numeric ? b.candidate_holds.mutable_data() : nullptr),
        numeric(b.numeric ? &*b.numeric : nullptr) {}

  double* rewards;
  bool *terminated, *truncated, *stepped, *reached, *fell;
  std::int64_t* hold_id;
  double *root_rise, *centre_of_mass;
  std::int8_t* action_mask;
  std::int64_t *wall_state, *grid_state, *free_limb, *candidate_holds;
  const NumericObservationArrays* numeric;
};

class VectorClimbEnv {
 public:
  VectorClimbEnv(const py::handle& num_envs, const py::list& walls, const std::string& observation,
                 const py::handle& action_count, const py::handle& max_episode_steps, const py::handle& config,
                 const py::handle& model)
      : numeric_(observation != "paper"), reach_(observation == "reach") {
    if (observation != "paper" && observation != "numeric" && observation != "reach") {
      throw py::value_error("observation: unknown form '" + observation + "' (numeric, reach, paper)");
    }
    for (const py::handle wall : walls) walls_.push_back(wall.cast<Wall>());
    const auto envs = integer_from(num_envs, 1, 1 << 20, "num_envs");
    action_count_ = static_cast<int>(integer_from(action_count, 1, std::numeric_limits<int>::max(), "action_count"));
    // None: no truncation, as the single environment without TimeLimit.
    if (!max_episode_steps.is_none()) {
      max_steps_ =
          static_cast<int>(integer_from(max_episode_steps, 1, std::numeric_limits<int>::max(), "max_episode_steps"));
    }
    const ExperimentConfig c = config_from_python(config, kClimbMdpKeys, "VectorClimbEnv");
    parameters_ = c.settings.learning.climbing;
    discount_ = c.settings.learning.dyna.rates.gamma;
    model_ = body_from(model, c.urdf);
    slots_.resize(static_cast<std::size_t>(envs));
    for (Slot& slot : slots_) slot.listed.resize(walls_.size());
  }

  int num_envs() const { return static_cast<int>(slots_.size()); }

  // The wall env's next episode climbs: an index into the walls given, whose episodes
  // the environment keeps (with their posture cache) from one episode to the next as the
  // single environment does, or a crux.Wall for that episode alone.
  void set_next_wall(int env, const py::handle& wall) {
    Slot& slot = slot_at(env);
    if (py::isinstance<Wall>(wall)) {
      slot.next_wall = wall.cast<Wall>();
      slot.next_index.reset();
    } else {
      const auto last = static_cast<long long>(walls_.size()) - 1;
      slot.next_index = static_cast<int>(integer_from(wall, 0, last, "wall"));
      slot.next_wall.reset();
    }
  }

  // Which environments the next step resets instead of stepping (their last step ended
  // the episode): each needs its next wall.
  py::array_t<bool> needs_reset() const {
    py::array_t<bool> out(num_envs());
    for (int env = 0; env < num_envs(); ++env) out.mutable_data()[env] = slots_[env].autoreset;
    return out;
  }

  py::tuple reset() {
    for (Slot& slot : slots_) slot.autoreset = true;
    return run(nullptr);
  }

  py::tuple step(const py::handle& actions_handle) {
    const auto actions = integer_array_from(actions_handle, "actions");
    if (actions.ndim() != 1 || actions.shape(0) != num_envs()) {
      throw InputError("actions", fmt::format("must be {} integers, one per environment", num_envs()));
    }
    std::vector<int> checked(slots_.size());
    for (int env = 0; env < num_envs(); ++env) {
      const Slot& slot = slots_[env];
      if (slot.autoreset) continue;  // that environment resets: its action is not used
      const std::int64_t action = actions.data()[env];
      if (action < 0 || action >= action_count_ || !offers(*slot.episode, static_cast<int>(action))) {
        throw InputError("actions", fmt::format("env {}: {} is not a possible action of its state (see "
                                                "info['action_mask'][{}])",
                                                env, action, env));
      }
      checked[env] = static_cast<int>(action);
    }
    return run(checked.data());
  }

 private:
  struct Slot {
    std::vector<std::unique_ptr<ClimbEpisode>> listed;  // per wall given, built when first drawn
    std::unique_ptr<ClimbEpisode> drawn;                // a random or named wall's, for one episode
    ClimbEpisode* episode = nullptr;
    std::optional<int> next_index;
    std::optional<Wall> next_wall;
    int steps = 0;
    bool autoreset = true;
  };

  Slot& slot_at(int env) {
    if (env < 0 || env >= num_envs()) throw InputError("env", fmt::format("must be from 0 to {}", num_envs() - 1));
    return slots_[env];
  }

  bool offers(const ClimbEpisode& episode, int action) const {
    return numeric_ ? action < static_cast<int>(episode.offered_holds().size()) : episode.offers(action);
  }

  void start_episode(Slot& slot) const {
    if (slot.next_wall) {
      slot.drawn = std::make_unique<ClimbEpisode>(model_, std::move(*slot.next_wall), parameters_, discount_);
      slot.episode = slot.drawn.get();
    } else if (slot.next_index) {
      std::unique_ptr<ClimbEpisode>& listed = slot.listed[*slot.next_index];
      if (!listed) listed = std::make_unique<ClimbEpisode>(model_, walls_[*slot.next_index], parameters_, discount_);
      slot.episode = listed.get();
      slot.drawn.reset();
    } else {
      throw std::logic_error("VectorClimbEnv: an environment resets with no next wall (set_next_wall)");
    }
    slot.next_wall.reset();
    slot.next_index.reset();
    slot.episode->reset();
    slot.steps = 0;
  }

  // Resets the environments that need it, steps the others by `actions` (null: none).
  py::tuple run(const int* actions) {
    VectorBatch batch(num_envs(), action_count_, numeric_ ? std::optional<int>(action_count_) : std::nullopt, reach_);
    const BatchRows rows(batch);
    {
      py::gil_scoped_release release;
      tbb::parallel_for(0, num_envs(), [&](int env) { advance(env, actions, rows); });
    }
    py::dict info;
    info["stepped"] = batch.stepped;
    info["reached"] = batch.reached;
    info["fell"] = batch.fell;
    info["hold_id"] = batch.hold_id;
    info["root_rise"] = batch.root_rise;
    info["centre_of_mass"] = batch.centre_of_mass;
    info["action_mask"] = batch.action_mask;
    py::object obs;
    if (numeric_) {
      obs = batch.numeric->dict();
      info["candidate_holds"] = batch.candidate_holds;
    } else {
      py::dict codes;
      codes["wall_state"] = batch.wall_state;
      codes["grid_state"] = batch.grid_state;
      codes["free_limb"] = batch.free_limb;
      obs = codes;
    }
    return py::make_tuple(obs, batch.rewards, batch.terminated, batch.truncated, info);
  }

  void advance(int env, const int* actions, const BatchRows& out) {
    Slot& slot = slots_[env];
    const bool resets = slot.autoreset || actions == nullptr;
    out.stepped[env] = !resets;
    out.rewards[env] = 0.0;
    out.terminated[env] = out.truncated[env] = out.reached[env] = out.fell[env] = false;
    out.hold_id[env] = 0;
    out.root_rise[env] = 0.0;
    if (resets) {
      start_episode(slot);
    } else {
      ClimbEpisode& episode = *slot.episode;
      const int hold = numeric_ ? episode.offered_holds()[actions[env]] : actions[env];
      const EpisodeStep outcome = episode.step(hold);
      ++slot.steps;
      out.rewards[env] = outcome.reward;
      out.terminated[env] = outcome.terminated;
      // As Gymnasium's TimeLimit: truncated at the limit, whether or not it also terminated.
      out.truncated[env] = max_steps_ && slot.steps >= *max_steps_;
      out.reached[env] = outcome.reached;
      out.fell[env] = outcome.fell;
      out.hold_id[env] = episode.wall().holds[hold].id;
      out.root_rise[env] = outcome.root_rise_m;
    }
    slot.autoreset = out.terminated[env] || out.truncated[env];
    describe(*slot.episode, env, out);
  }

  void describe(ClimbEpisode& episode, int env, const BatchRows& out) const {
    for (int k = 0; k < 3; ++k) out.centre_of_mass[3 * env + k] = episode.centre_of_mass()[k];
    const auto offered = episode.offered_holds();
    std::int8_t* mask = out.action_mask + static_cast<std::ptrdiff_t>(env) * action_count_;
    std::fill_n(mask, action_count_, std::int8_t{0});
    if (numeric_) {
      episode.write_numeric_observation(action_count_, out.numeric->rows(env));
      std::int64_t* slots = out.candidate_holds + static_cast<std::ptrdiff_t>(env) * action_count_;
      std::fill_n(slots, action_count_, std::int64_t{-1});
      for (std::size_t i = 0; i < offered.size(); ++i) {
        mask[i] = 1;
        slots[i] = offered[i];
      }
    } else {
      for (const int hold : offered) mask[hold] = 1;
      out.wall_state[env] = static_cast<std::int64_t>(episode.codes().wall);
      out.grid_state[env] = static_cast<std::int64_t>(episode.codes().grid);
      out.free_limb[env] = static_cast<int>(episode.configuration().free_limb());
    }
  }

  std::vector<Wall> walls_;
  bool numeric_;  // the numeric or the reach form: candidate slots, not hold indices
  bool reach_;
  int action_count_ = 0;  // the numeric form's max_candidates, or the paper's hold count
  std::optional<int> max_steps_;
  ClimbingParameters parameters_;
  double discount_ = 0.0;  // learning.gamma: the height shaping's
  BodyModelPtr model_;
  std::vector<Slot> slots_;
};

}  // namespace

void bind_vector_climb_env(py::module_& m) {
  py::class_<VectorClimbEnv>(m, "VectorClimbEnv",
                             "num_envs climbing environments stepped in one call across threads; "
                             "crux.gym.VectorClimbEnv makes it a gymnasium.vector.VectorEnv")
      .def(py::init<const py::handle&, const py::list&, const std::string&, const py::handle&, const py::handle&,
                    const py::handle&, const py::handle&>(),
           py::arg("num_envs"), py::arg("walls"), py::arg("observation"), py::arg("action_count"),
           py::arg("max_episode_steps"), py::arg("config") = py::none(), py::arg("model") = py::none(),
           "walls: the walls set_next_wall's indices name; observation: 'numeric' or 'reach' (candidate slots, "
           "action_count being max_candidates) or 'paper' (the paper's codes and a hold index as the action); "
           "max_episode_steps: the truncation, None for none")
      .def_property_readonly("num_envs", &VectorClimbEnv::num_envs)
      .def("set_next_wall", &VectorClimbEnv::set_next_wall, py::arg("env"), py::arg("wall"),
           "The wall of env's next episode: an index into walls (its episodes kept from one to the next) or a "
           "crux.Wall (for that episode)")
      .def("needs_reset", &VectorClimbEnv::needs_reset,
           "bool per environment: whether the next step resets it (next-step autoreset)")
      .def("reset", &VectorClimbEnv::reset, "Resets every environment: (obs, rewards, terminated, truncated, info)")
      .def("step", &VectorClimbEnv::step, py::arg("actions"),
           "Steps every environment (or resets those whose last step ended an episode, ignoring their action): "
           "(obs, rewards, terminated, truncated, info), info holding arrays and 'stepped'");
}

}  // namespace crux::python
