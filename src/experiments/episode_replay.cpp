#include "experiments/episode_replay.hpp"

#include <fmt/format.h>

#include "common/input_error.hpp"

namespace crux {

RecordedClimb replay_episode(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                             std::span<const RunStep> steps, int episode, const std::string& steps_file,
                             const std::string& flag) {
  const int episodes = steps.empty() ? 0 : steps.back().episode + 1;
  if (episode < 0 || episode >= episodes) {
    throw InputError(flag, episodes == 0 ? std::string("the run has no episode")
                                         : fmt::format("the run has episodes 1 to {}, not {}", episodes, episode + 1));
  }
  ClimbingMdp mdp(model, wall, parameters);
  RecordedClimb climb{"episode", episode, false, {}, {}};
  int due_episode = 0;  // the MDP's: one more after each finishing move
  for (const RunStep& step : steps) {
    if (step.episode != due_episode) {
      throw InputError(steps_file, fmt::format("iteration {}: episode {} where the MDP is in episode {}; the "
                                               "run was not written with this folder's body and config",
                                               step.iteration, step.episode, due_episode));
    }
    if (step.episode > episode) break;
    if (step.episode == episode && climb.postures.empty()) climb.postures.push_back(mdp.posture());
    const ActionCode hold = wall.index_of(step.hold_id);
    if (!mdp.offers(hold)) {
      throw InputError(steps_file, fmt::format("iteration {}: hold {} is not a possible action there; the "
                                               "run was not written with this folder's wall and config",
                                               step.iteration, step.hold_id));
    }
    const StepOutcome outcome = mdp.step(hold);
    if (outcome.reached != step.success) {
      throw InputError(steps_file, fmt::format("iteration {}: the move {} where the run's {}; the run was not "
                                               "written with this folder's body and config",
                                               step.iteration, outcome.reached ? "reaches" : "fails",
                                               step.success ? "reached" : "failed"));
    }
    if (outcome.finished) ++due_episode;
    if (step.episode != episode) continue;
    climb.steps.push_back(step);
    if (outcome.reached) climb.postures.push_back(*outcome.posture);
    if (outcome.fell) {  // the episode's climb starts again: show its last attempt
      climb.start_again();
      climb.postures.push_back(mdp.posture());
    }
    climb.finished = outcome.finished;
  }
  return climb;
}

std::vector<HoldConfiguration> climb_configurations(const Wall& wall, const RecordedClimb& climb) {
  std::vector<HoldConfiguration> configurations{start_configuration(wall)};
  HoldConfiguration held = configurations.back().with(Limb::RightHand, kFree);
  for (const RunStep& step : climb.steps) {
    if (!step.success) continue;
    const Limb free = held.free_limb();
    configurations.push_back(held.with(free, wall.index_of(step.hold_id)));
    held = configurations.back().with(next_free_limb(free), kFree);
  }
  return configurations;
}

}  // namespace crux
