#include "climbing/configuration_reacher.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "body/kinematics.hpp"
#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"

namespace crux {

ConfigurationReacher::ConfigurationReacher(const BodyModel& model, const Wall& wall,
                                           const ReachabilityParameters& parameters, const PhysicsParameters& physics,
                                           StanceQuestion question)
    : model_(model),
      wall_(wall),
      parameters_(parameters),
      data_(model),
      stance_(stance_check_for(model, wall, physics)),
      question_(question) {
  // A stance that holds still keeps the body out of the wall: the caller says so
  // (finalize_config sets it), rather than this class changing what it was given.
  if (stance_ && parameters.ik.wall != WallRule::Avoid) {
    throw std::invalid_argument("the static model needs ik.wall = avoid (the body kept out of the wall)");
  }
}

std::uint64_t ConfigurationReacher::cache_key(const HoldConfiguration& complete, Limb next_to_move) const {
  // The static verdict depends on the limb that lets go next: it is part of the key.
  const std::uint64_t configuration_code = encode(complete, wall_.hold_count());
  return stance_ ? configuration_code * kLimbCount + static_cast<std::uint64_t>(next_to_move) : configuration_code;
}

double ConfigurationReacher::effort(const HoldConfiguration& complete, Limb next_to_move) const {
  if (!stance_) return 0.0;
  if (question_ != StanceQuestion::Effort) throw std::logic_error("this reacher asks stances whether they hold only");
  return efforts_.at(cache_key(complete, next_to_move));
}

bool ConfigurationReacher::known_unreachable(const HoldConfiguration& complete, Limb next_to_move) const {
  return cache_.known_unreachable(cache_key(complete, next_to_move));
}

IkResult ConfigurationReacher::solve(const Posture& from, const HoldConfiguration& complete) {
  const ReachTarget target = reach_target(model_, wall_, complete, parameters_.root);
  return parameters_.guess == IkGuess::Standing
             ? solve_ik(model_, data_, standing_posture(target.root), target, parameters_.ik)
             : solve_ik(model_, data_, from, target, parameters_.ik);
}

const Posture* ConfigurationReacher::reach(const Posture& from, const HoldConfiguration& complete, Limb next_to_move) {
  const std::uint64_t code = cache_key(complete, next_to_move);
  if (const Posture* cached = cache_.reached(code)) return cached;
  if (cache_.known_unreachable(code)) return nullptr;
  const IkResult result = solve(from, complete);
  ++solves_;
  if (result.reached) {
    bool holds = true;
    if (stance_ && question_ == StanceQuestion::Effort) {
      const double effort = stance_->effort(result.posture, complete, next_to_move);
      holds = effort <= 1.0;
      if (holds) efforts_.emplace(code, effort);
    } else if (stance_) {
      holds = stance_->holds_still(result.posture, complete, next_to_move);
    }
    if (holds) {
      cache_.store_reached(code, result.posture);
      return cache_.reached(code);
    }
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
  if (start != nullptr) return *start;
  // Which test failed: the IK's, or (under the static model) the stance's. The IK is solved
  // once more, without the stance check, on this error path only.
  const bool avoiding = parameters_.ik.wall == WallRule::Avoid;
  if (stance_ && solve(start_guess(model_, wall_, parameters_.root), start_configuration(wall_)).reached) {
    throw InputError(source,
                     "the IK reaches the start configuration, but its stance does not hold still under the static "
                     "model (on its four holds and on the three left when the right hand lets go)");
  }
  throw InputError(source, std::string("the start configuration is not reachable: the IK finds no posture grasping "
                                       "its four holds") +
                               (avoiding ? " with the body kept out of the wall (ik.wall = avoid)" : ""));
}

const BodyData& ConfigurationReacher::place(const Posture& posture) {
  forward_kinematics(model_, data_, posture);
  centre_of_mass(model_, data_);
  return data_;
}

void ConfigurationReacher::save_state(CheckpointWriter& out) const {
  if (question_ != StanceQuestion::Effort) throw std::logic_error("a reacher without efforts is not checkpointed");
  cache_.save_state(out);
  out.value<std::uint64_t>(solves_);
  if (!stance_) return;  // the kinematic model's checkpoints stay as they were
  std::vector<std::pair<std::uint64_t, double>> efforts(efforts_.begin(), efforts_.end());
  std::sort(efforts.begin(), efforts.end());  // the same bytes whatever the map's order
  out.value<std::uint64_t>(efforts.size());
  for (const auto& [code, effort] : efforts) {
    out.value(code);
    out.value(effort);
  }
  stance_->save_state(out);
}

void ConfigurationReacher::load_state(CheckpointReader& in) {
  cache_.load_state(in);
  solves_ = in.value<std::uint64_t>();
  efforts_.clear();
  if (!stance_) return;
  const std::uint64_t count = in.value<std::uint64_t>();
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::uint64_t code = in.value<std::uint64_t>();
    const double effort = in.value<double>();
    if (cache_.reached(code) == nullptr || !(effort >= 0.0 && effort <= 1.0)) in.fail();
    efforts_.emplace(code, effort);
  }
  if (efforts_.size() != cache_.reached_count()) in.fail();
  stance_->load_state(in);
}

}  // namespace crux
