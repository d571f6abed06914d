#include "climbing/configuration_reacher.hpp"

#include "body/kinematics.hpp"
#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"

namespace crux {

ConfigurationReacher::ConfigurationReacher(const BodyModel& model, const Wall& wall,
                                           const ReachabilityParameters& parameters, const PhysicsParameters& physics)
    : model_(model), wall_(wall), parameters_(parameters), data_(model) {
  if (physics.model == PhysicsModel::Static) {
    parameters_.ik.wall = WallRule::Avoid;
    stance_.emplace(model, wall, physics);
  }
}

std::uint64_t ConfigurationReacher::cache_key(const HoldConfiguration& complete, Limb next_to_move) const {
  // The static verdict depends on the limb that lets go next: it is part of the key.
  const std::uint64_t configuration_code = encode(complete, wall_.hold_count());
  return stance_ ? configuration_code * kLimbCount + static_cast<std::uint64_t>(next_to_move) : configuration_code;
}

bool ConfigurationReacher::known_unreachable(const HoldConfiguration& complete, Limb next_to_move) const {
  return cache_.known_unreachable(cache_key(complete, next_to_move));
}

const Posture* ConfigurationReacher::reach(const Posture& from, const HoldConfiguration& complete, Limb next_to_move) {
  const std::uint64_t code = cache_key(complete, next_to_move);
  if (const Posture* cached = cache_.reached(code)) return cached;
  if (cache_.known_unreachable(code)) return nullptr;
  const ReachTarget target = reach_target(model_, wall_, complete, parameters_.root);
  const IkResult result = solve_ik(model_, data_, from, target, parameters_.ik);
  ++solves_;
  if (result.reached && (!stance_ || stance_->holds_still(result.posture, complete, next_to_move))) {
    cache_.store_reached(code, result.posture);
    return cache_.reached(code);
  }
  if (parameters_.cache_unreachable) cache_.store_unreachable(code);
  return nullptr;
}

const Posture* ConfigurationReacher::reach_start() {
  // solve_start's problem, answered through the cache.
  // The right hand moves first (docs/MODEL.md, choice C5).
  return reach(start_guess(model_, wall_, parameters_.root), start_configuration(wall_), Limb::RightHand);
}

const Posture& ConfigurationReacher::require_start(const std::string& source) {
  const Posture* start = reach_start();
  if (start == nullptr) throw InputError(source, "the start configuration is not reachable");
  return *start;
}

const BodyData& ConfigurationReacher::place(const Posture& posture) {
  forward_kinematics(model_, data_, posture);
  centre_of_mass(model_, data_);
  return data_;
}

void ConfigurationReacher::save_state(CheckpointWriter& out) const {
  cache_.save_state(out);
  out.value<std::uint64_t>(solves_);
}

void ConfigurationReacher::load_state(CheckpointReader& in) {
  cache_.load_state(in);
  solves_ = in.value<std::uint64_t>();
}

}  // namespace crux
