#pragma once
// One environment's climbing MDP as Gymnasium sees it, without Python: what the single
// ClimbEnv and each environment of VectorClimbEnv step (the vector env on its worker
// threads, with the GIL released). It adds to the MDP the finishing state (Gymnasium's
// terminal observation is where the finishing move left the climber, while the MDP is
// already back at the start; after a fall, the dead end the climber fell from), the
// centre of mass of the observed state, and the offered
// holds in ascending order (the numeric form's candidate slots).

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <pybind11/numpy.h>

#include "climbing/climbing_mdp.hpp"
#include "climbing/numeric_observation.hpp"
#include "conversions.hpp"

namespace crux::python {

struct EpisodeStep {
  double reward = 0.0;
  bool terminated = false;
  bool reached = false;
  bool fell = false;  // the static model's dead end (docs/MODEL.md, choice C27): terminated
  double root_rise_m = 0.0;
};

class ClimbEpisode {
 public:
  // Solves the start configuration (InputError naming the wall if it cannot). discount:
  // the learner's gamma, which the height shaping uses (ClimbingMdp).
  ClimbEpisode(BodyModelPtr model, Wall wall, const ClimbingParameters& parameters, double discount);

  // Holds the MDP, which keeps a reference to wall_: never copied nor moved.
  ClimbEpisode(const ClimbEpisode&) = delete;
  ClimbEpisode& operator=(const ClimbEpisode&) = delete;

  void reset();
  bool offers(int hold) const { return !finish_ && mdp_->offers(hold); }
  // Requires offers(hold).
  EpisodeStep step(int hold);

  const HoldConfiguration& configuration() const { return finish_ ? finish_->configuration : mdp_->configuration(); }
  const StateCouple& codes() const { return finish_ ? finish_->codes : mdp_->state(); }
  const Posture& posture() const { return finish_ ? finish_->posture : mdp_->posture(); }
  const Eigen::Vector3d& centre_of_mass() const { return centre_of_mass_; }
  // The holds the observed state offers, ascending.
  std::span<const int> offered_holds() const { return offered_; }
  // The holds whose move failed since the climber entered the observed state.
  std::span<const int> failed_holds() const { return failed_; }

  void write_numeric_observation(int max_candidates, const NumericObservationRows& out);

  const Wall& wall() const { return wall_; }
  const BodyModelPtr& model() const { return model_; }
  const ClimbingParameters& parameters() const { return parameters_; }
  int grid_action_count() const { return mdp_->grid_action_count(); }
  ClimbingMdp& mdp() { return *mdp_; }

 private:
  // Where the finishing move left the climber, or the dead end it fell from, described as
  // any state.
  struct FinishingState {
    HoldConfiguration configuration;  // the 3-configuration with the next limb free
    Posture posture;
    StateCouple codes;
  };

  // The 3-configuration the climb would go on from had the finishing move not ended it.
  void enter_finishing_state(const HoldConfiguration& before, int hold, const Posture& posture);
  // The state before the failed move that ended in a fall.
  void enter_dead_end(const HoldConfiguration& before, const Posture& posture, const StateCouple& codes);
  void list_offered_holds();

  BodyModelPtr model_;
  Wall wall_;  // before mdp_, which keeps a reference to it
  ClimbingParameters parameters_;
  std::unique_ptr<ClimbingMdp> mdp_;
  BodyData data_;                         // the observation's workspace, apart from the MDP's
  std::optional<FinishingState> finish_;  // set by the finishing step until reset()
  Eigen::Vector3d start_centre_of_mass_, centre_of_mass_;
  std::vector<int> offered_;
  std::vector<int> failed_;
};

// crux.gym's numeric (or reach) observation as numpy float32 arrays, with a leading axis of one row
// per environment (or none for the single environment). Built with the GIL held; rows()
// takes none, so the vector env's threads write into them.
class NumericObservationArrays {
 public:
  // envs < 0: no leading axis, one observation. reach: the reach form's two more arrays.
  NumericObservationArrays(py::ssize_t envs, int max_candidates, bool reach);
  NumericObservationRows rows(py::ssize_t env) const;
  py::dict dict() const;

 private:
  py::array_t<float> free_limb_, held_, candidates_, candidate_mask_, posture_, centre_of_mass_, to_finish_;
  std::optional<py::array_t<float>> candidate_reach_, candidate_failed_;
  NumericObservationRows first_;
  int max_candidates_;
};

}  // namespace crux::python
