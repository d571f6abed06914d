#pragma once
// Whether a 4-configuration is C-reachable from a posture, and with which posture,
// answered once per 4-configuration through the cache (section III-C). The climbing
// MDP and the exact planner share it, so they apply the same reachability test.

#include <string>

#include <unordered_map>

#include "body/body_data.hpp"
#include "climbing/posture_cache.hpp"
#include "climbing/stance_check.hpp"
#include "configurations/reachability.hpp"

namespace crux {

// What the static model asks of a posture the IK reached: its effort, which learning keeps
// (rewards, files and checkpoints read it), or only whether it holds still, all the exact
// planner needs, from a cheaper program (StanceCheck::holds_still).
enum class StanceQuestion { Effort, HoldsStill };

class ConfigurationReacher {
 public:
  // Under the static model (physics.model) a reached posture must hold still
  // (climbing/stance_check), and the IK must keep the body out of the wall: std::invalid_argument
  // unless parameters.ik.wall is avoid.
  ConfigurationReacher(const BodyModel& model, const Wall& wall, const ReachabilityParameters& parameters,
                       const PhysicsParameters& physics = {}, StanceQuestion question = StanceQuestion::Effort);

  // The posture grasping `complete`, solved by IK from `from` unless cached; null when
  // not reachable. `next_to_move` is the limb that lets go next (the static model checks
  // the stance on the three holds left; the kinematic model ignores it, and caches by
  // configuration alone, as the paper does). The pointer stays valid for the reacher's
  // lifetime.
  const Posture* reach(const Posture& from, const HoldConfiguration& complete, Limb next_to_move);

  // Under the static model, the effort of the stance reach() reached for `complete` and
  // `next_to_move` (StanceCheck::effort); 0 under the kinematic model, which has none.
  // reach() must have returned a posture for them, and the question must be Effort.
  double effort(const HoldConfiguration& complete, Limb next_to_move) const;

  // Whether reach() already found `complete` unreachable (with the same next limb under
  // the static model); false when ik.cache_unreachable keeps no such verdicts.
  bool known_unreachable(const HoldConfiguration& complete, Limb next_to_move) const;

  // The start configuration solved from standing (and cached); null if unreachable.
  const Posture* reach_start();

  // reach_start's posture; InputError naming `source` (the wall as the user gave it)
  // when the start is not reachable, saying which test failed: the IK (with the body kept
  // out of the wall, under ik.wall = avoid) or the static model's stance.
  const Posture& require_start(const std::string& source);

  // Forward kinematics and centre of mass of `posture`; valid until the next call.
  const BodyData& place(const Posture& posture);
  const PostureCache& cache() const { return cache_; }
  std::size_t solves() const { return solves_; }

  // The key of the verdict for `complete` with `next_to_move` to let go next.
  std::uint64_t cache_key(const HoldConfiguration& complete, Limb next_to_move) const;

  // The cache and the solve count, for a run's checkpoint (the question must be Effort).
  void save_state(CheckpointWriter& out) const;
  void load_state(CheckpointReader& in);

 private:
  // The IK's solve for `complete` from `from` (or from standing, as ik.guess says).
  IkResult solve(const Posture& from, const HoldConfiguration& complete);

  const BodyModel& model_;
  const Wall& wall_;
  ReachabilityParameters parameters_;
  BodyData data_;
  std::optional<StanceCheck> stance_;  // the static model's
  StanceQuestion question_;
  PostureCache cache_;
  // The static model's efforts of the reached stances, by cache key: kept with the
  // verdicts (and in checkpoints), so that a resumed run reads the same numbers.
  std::unordered_map<std::uint64_t, double> efforts_;
  std::size_t solves_ = 0;
};

}  // namespace crux
