#include "climbing/climbing_mdp.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"

namespace crux {

ClimbingMdp::ClimbingMdp(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                         double discount)
    : wall_(wall),
      parameters_(parameters),
      discount_(discount),
      reacher_(model, wall, parameters.reachability, parameters.physics),
      possible_(wall.hold_count()),
      candidates_(wall.hold_count()),
      tile_representative_(parameters.grid.tile_count()),
      tile_best_distance_(parameters.grid.tile_count()),
      stuck_possible_(wall.hold_count()) {
  if (parameters.physics.model == PhysicsModel::Dynamic) {
    trials_ =
        std::make_unique<MoveTrials>(model, wall, parameters.physics, parameters.reachability, parameters.perform);
  }
  limb_bases_ = model.reach_envelope.chain_base;
  start_posture_ = reacher_.require_start(wall_.name);
  reset();
  // Every later state offers at least the hold its free limb just left; the start must
  // be checked (a wall file or the filter's parameters can leave it without actions).
  if (candidate_count_ == 0) {
    throw InputError(wall_.name,
                     "the start configuration with the right hand free has no possible action under the "
                     "geometric filter");
  }
}

void ClimbingMdp::reset() {
  left_hold_ = start_configuration(wall_).hold(Limb::RightHand);
  configuration_ = start_configuration(wall_).with(Limb::RightHand, kFree);
  posture_ = start_posture_;
  describe(reacher_.place(posture_));
}

void ClimbingMdp::describe(const BodyData& body) {
  const Limb free = configuration_.free_limb();
  placement_ = parameters_.grid.space == AgentSpaceKind::Reach
                   ? place_reach_sectors(parameters_.grid, body.points[0] + limb_bases_[static_cast<int>(free)])
                   : place_grid(parameters_.grid, free, body.points[operational_point(free)]);
  state_.wall = encode(configuration_, wall_.hold_count());
  state_.grid = encode(describe_state(wall_, configuration_, placement_), parameters_.grid);

  candidate_count_ = static_cast<std::size_t>(possible_actions(wall_, configuration_, parameters_.filter, possible_));
  std::fill(tile_representative_.begin(), tile_representative_.end(), -1);
  std::fill(tile_best_distance_.begin(), tile_best_distance_.end(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < candidate_count_; ++i) {
    const Eigen::Vector3d& position = wall_.holds[possible_[i]].position;
    const int tile = placement_.tile_of(position);
    candidates_[i] = {possible_[i], tile == kOutsideGrid ? kNoAction : tile, false, possible_[i] == left_hold_};
    if (tile == kOutsideGrid) continue;
    // Grid -> wall: the possible hold nearest the tile's centre (first listed on ties).
    const double distance = placement_.squared_distance_to_centre(tile, position);
    if (distance < tile_best_distance_[tile]) {
      tile_best_distance_[tile] = distance;
      tile_representative_[tile] = static_cast<int>(i);
    }
  }
  for (const int representative : tile_representative_) {
    if (representative >= 0) candidates_[representative].represents_grid_action = true;
  }
}

bool ClimbingMdp::offers(ActionCode hold) const {
  const auto offered = candidates();
  return std::any_of(offered.begin(), offered.end(), [hold](const ActionCandidate& c) { return c.wall == hold; });
}

StepOutcome ClimbingMdp::step(ActionCode hold) {
  if (!offers(hold)) throw std::invalid_argument("ClimbingMdp::step: the state does not offer this hold");
  // Without shaping the paper's rewards are returned untouched, to the last bit.
  if (parameters_.rewards.height == 0.0) return unshaped_step(hold);
  const double potential_before = height_potential();
  StepOutcome outcome = unshaped_step(hold);
  // After the finishing move the climb is over: the terminal state's potential is 0.
  const double potential_after = outcome.finished ? 0.0 : height_potential();
  outcome.reward += discount_ * potential_after - potential_before;
  return outcome;
}

double ClimbingMdp::height_potential() const {
  double height_sum = 0.0;
  int held = 0;
  for (const int hold : configuration_.holds) {
    if (hold == kFree) continue;
    height_sum += wall_.holds[hold].position.z();
    ++held;
  }
  return parameters_.rewards.height * height_sum / held;
}

StepOutcome ClimbingMdp::unshaped_step(ActionCode hold) {
  const Limb free = configuration_.free_limb();
  const HoldConfiguration complete = configuration_.with(free, hold);
  StepOutcome outcome;
  const Posture* reached = reacher_.reach(posture_, complete, next_free_limb(free));
  if (reached != nullptr && trials_ && !performed(complete, hold, *reached)) reached = nullptr;
  if (reached == nullptr) {
    outcome.reward = parameters_.rewards.unreachable;
    if (at_dead_end() || (parameters_.fall_when_stuck && stuck_in_stance())) {
      outcome.fell = true;
      reset();
    }
    return outcome;
  }
  outcome.reached = true;
  outcome.posture = reached;
  outcome.effort = reacher_.effort(complete, next_free_limb(free));
  outcome.root_rise_m = (*reached)[2] - posture_[2];  // G[2] is e0's height
  const BodyData& body = reacher_.place(*reached);
  outcome.centre_of_mass = body.centre_of_mass;
  if (body.centre_of_mass.z() >= wall_.finish_height) {
    outcome.finished = true;
    outcome.reward = parameters_.rewards.finish - parameters_.rewards.effort * outcome.effort;
    reset();
    return outcome;
  }
  outcome.reward = parameters_.rewards.step - parameters_.rewards.effort * outcome.effort;
  posture_ = *reached;
  left_hold_ = complete.hold(next_free_limb(free));
  configuration_ = complete.with(next_free_limb(free), kFree);
  describe(body);
  return outcome;
}

bool ClimbingMdp::known_unreachable(const HoldConfiguration& complete, Limb next_to_move) const {
  if (reacher_.known_unreachable(complete, next_to_move)) return true;
  if (!trials_) return false;  // only the dynamic model keeps verdicts of its own
  const auto found = performed_.find(reacher_.cache_key(complete, next_to_move));
  return found != performed_.end() && !found->second;
}

bool ClimbingMdp::performed(const HoldConfiguration& complete, int hold, const Posture& reached) {
  const Limb free = configuration_.free_limb();
  const auto [entry, added] = performed_.try_emplace(reacher_.cache_key(complete, next_free_limb(free)), false);
  if (added) entry->second = trials_->perform(posture_, reached, configuration_, left_hold_, hold).performed();
  return entry->second;
}

std::size_t ClimbingMdp::moves_performed() const {
  return static_cast<std::size_t>(
      std::count_if(performed_.begin(), performed_.end(), [](const auto& entry) { return entry.second; }));
}

bool ClimbingMdp::at_dead_end() const {
  const Limb free = configuration_.free_limb();
  const Limb next = next_free_limb(free);
  for (const ActionCandidate& candidate : candidates()) {
    if (!known_unreachable(configuration_.with(free, candidate.wall), next)) return false;
  }
  return true;
}

bool ClimbingMdp::stuck_in_stance() {
  const HoldConfiguration stance = configuration_.with(configuration_.free_limb(), left_hold_);
  for (int index = 0; index < kLimbCount; ++index) {
    const Limb limb = static_cast<Limb>(index);
    const HoldConfiguration three = stance.with(limb, kFree);
    const int count = possible_actions(wall_, three, parameters_.filter, stuck_possible_);
    for (int i = 0; i < count; ++i) {
      const int hold = stuck_possible_[static_cast<std::size_t>(i)];
      if (hold == stance.hold(limb)) continue;
      if (!known_unreachable(three.with(limb, hold), next_free_limb(limb))) return false;
    }
  }
  return true;
}

void ClimbingMdp::save_state(CheckpointWriter& out) const {
  reacher_.save_state(out);
  out.value(configuration_.holds);
  out.value<std::int64_t>(left_hold_);
  save_posture(out, posture_);
  // The dynamic model's verdicts, so that a resumed run performs no move twice (the other
  // models' checkpoints keep their bytes).
  if (!trials_) return;
  out.value<std::uint64_t>(performed_.size());
  for (const auto& [key, performed] : performed_) {
    out.value(key);
    out.value<std::uint8_t>(performed ? 1 : 0);
  }
}

void ClimbingMdp::load_state(CheckpointReader& in) {
  reacher_.load_state(in);
  configuration_.holds = in.value<decltype(configuration_.holds)>();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const int hold = configuration_.holds[limb];
    if (hold != kFree && (hold < 0 || hold >= wall_.hold_count())) in.fail();
    for (int other = 0; other < limb; ++other) {
      if (hold != kFree && configuration_.holds[other] == hold) in.fail();
    }
  }
  if (configuration_.free_count() != 1) in.fail();
  const std::int64_t left = in.value<std::int64_t>();
  if (left != kFree && (left < 0 || left >= wall_.hold_count())) in.fail();
  left_hold_ = static_cast<int>(left);
  posture_ = load_posture(in);
  if (trials_) {
    performed_.clear();
    const auto count = in.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < count; ++i) {
      const auto key = in.value<std::uint64_t>();
      const auto performed = in.value<std::uint8_t>();
      if (performed > 1 || !performed_.emplace(key, performed == 1).second) in.fail();
    }
  }
  // A step describes the state with the body placed at the posture it moved to.
  describe(reacher_.place(posture_));
  if (candidate_count_ == 0) in.fail();  // every state a run reaches offers a hold
}

}  // namespace crux
