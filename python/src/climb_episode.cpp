#include "climb_episode.hpp"

#include <algorithm>

#include "agent_space/agent_descriptor.hpp"
#include "body/kinematics.hpp"

namespace crux::python {

ClimbEpisode::ClimbEpisode(BodyModelPtr model, Wall wall, const ClimbingParameters& parameters, double discount)
    : model_(std::move(model)),
      wall_(std::move(wall)),
      parameters_(parameters),
      mdp_(std::make_unique<ClimbingMdp>(*model_, wall_, parameters_, discount)),
      data_(*model_) {
  forward_kinematics(*model_, data_, mdp_->start_posture());
  start_centre_of_mass_ = crux::centre_of_mass(*model_, data_);
  reset();
}

void ClimbEpisode::reset() {
  mdp_->reset();
  finish_.reset();
  failed_.clear();
  centre_of_mass_ = start_centre_of_mass_;
  list_offered_holds();
}

EpisodeStep ClimbEpisode::step(int hold) {
  const HoldConfiguration before = mdp_->configuration();
  const Posture before_posture = mdp_->posture();
  const StateCouple before_codes = mdp_->state();
  const StepOutcome outcome = mdp_->step(hold);
  if (outcome.reached) {
    centre_of_mass_ = outcome.centre_of_mass;
    failed_.clear();
  } else {
    failed_.push_back(hold);
  }
  if (outcome.finished) {
    enter_finishing_state(before, hold, *outcome.posture);
  } else if (outcome.fell) {
    enter_dead_end(before, before_posture, before_codes);
  } else {
    list_offered_holds();
  }
  return {outcome.reward, outcome.finished || outcome.fell, outcome.reached, outcome.fell, outcome.root_rise_m};
}

void ClimbEpisode::enter_dead_end(const HoldConfiguration& before, const Posture& posture, const StateCouple& codes) {
  FinishingState f{before, posture, codes};
  offered_.resize(wall_.hold_count());
  offered_.resize(possible_actions(wall_, before, parameters_.filter, offered_));
  std::sort(offered_.begin(), offered_.end());
  finish_ = f;
}

void ClimbEpisode::enter_finishing_state(const HoldConfiguration& before, int hold, const Posture& posture) {
  const Limb next = next_free_limb(before.free_limb());
  FinishingState f;
  f.configuration = before.with(before.free_limb(), hold).with(next, kFree);
  f.posture = posture;
  forward_kinematics(*model_, data_, posture);
  const GridPlacement placement = place_grid(parameters_.grid, next, data_.points[operational_point(next)]);
  f.codes.wall = encode(f.configuration, wall_.hold_count());
  f.codes.grid = encode(describe_state(wall_, f.configuration, placement), parameters_.grid);
  offered_.resize(wall_.hold_count());
  offered_.resize(possible_actions(wall_, f.configuration, parameters_.filter, offered_));
  std::sort(offered_.begin(), offered_.end());
  finish_ = f;
}

void ClimbEpisode::list_offered_holds() {
  offered_.clear();
  for (const ActionCandidate& candidate : mdp_->candidates()) offered_.push_back(candidate.wall);
  std::sort(offered_.begin(), offered_.end());
}

void ClimbEpisode::write_numeric_observation(int max_candidates, const NumericObservationRows& out) {
  crux::write_numeric_observation(
      *model_, data_,
      {wall_, configuration(), posture(), centre_of_mass_, offered_, parameters_.filter.max_span_m, failed_},
      max_candidates, out);
}

namespace {

py::array_t<float> observation_array(py::ssize_t envs, std::vector<py::ssize_t> shape) {
  if (envs >= 0) shape.insert(shape.begin(), envs);
  return py::array_t<float>(shape);
}

}  // namespace

NumericObservationArrays::NumericObservationArrays(py::ssize_t envs, int max_candidates, bool reach)
    : free_limb_(observation_array(envs, {kLimbCount})),
      held_(observation_array(envs, {kLimbCount, 3})),
      candidates_(observation_array(envs, {max_candidates, 3})),
      candidate_mask_(observation_array(envs, {max_candidates})),
      posture_(observation_array(envs, {kConfigurationDof})),
      centre_of_mass_(observation_array(envs, {3})),
      to_finish_(observation_array(envs, {1})),
      first_{free_limb_.mutable_data(),      held_.mutable_data(),    candidates_.mutable_data(),
             candidate_mask_.mutable_data(), posture_.mutable_data(), centre_of_mass_.mutable_data(),
             to_finish_.mutable_data()},
      max_candidates_(max_candidates) {
  if (reach) {
    candidate_reach_ = observation_array(envs, {max_candidates, kReachFeatures});
    candidate_failed_ = observation_array(envs, {max_candidates});
    first_.candidate_reach = candidate_reach_->mutable_data();
    first_.candidate_failed = candidate_failed_->mutable_data();
  }
}

NumericObservationRows NumericObservationArrays::rows(py::ssize_t env) const {
  const py::ssize_t k = max_candidates_;
  return {first_.free_limb + env * kLimbCount,
          first_.held + env * 3 * kLimbCount,
          first_.candidates + env * 3 * k,
          first_.candidate_mask + env * k,
          first_.posture + env * kConfigurationDof,
          first_.centre_of_mass + env * 3,
          first_.to_finish + env,
          first_.candidate_reach ? first_.candidate_reach + env * kReachFeatures * k : nullptr,
          first_.candidate_failed ? first_.candidate_failed + env * k : nullptr};
}

py::dict NumericObservationArrays::dict() const {
  py::dict out;
  out["free_limb"] = free_limb_;
  out["held"] = held_;
  out["candidates"] = candidates_;
  out["candidate_mask"] = candidate_mask_;
  out["posture"] = posture_;
  out["centre_of_mass"] = centre_of_mass_;
  out["to_finish"] = to_finish_;
  if (candidate_reach_) {
    out["candidate_reach"] = *candidate_reach_;
    out["candidate_failed"] = *candidate_failed_;
  }
  return out;
}

}  // namespace crux::python
