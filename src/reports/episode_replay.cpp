#include "reports/episode_replay.hpp"

#include <charconv>

#include <fmt/format.h>

#include "common/input_error.hpp"

namespace crux {

RecordedClimb replay_episode(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                             int episode, const std::string& flag) {
  const int episodes = folder.steps.empty() ? 0 : folder.steps.back().episode + 1;
  if (episode < 0 || episode >= episodes) {
    throw InputError(flag, fmt::format("the run has episodes 0 to {}, not {}", episodes - 1, episode));
  }
  const std::string iterations_file = (folder.directory / "iterations.csv").string();
  ClimbingMdp mdp(model, folder.wall, parameters);
  RecordedClimb climb{"episode", episode, false, {}, {}};
  int due_episode = 0;  // the MDP's: one more after each finishing move
  for (const RunStep& step : folder.steps) {
    if (step.episode != due_episode) {
      throw InputError(iterations_file, fmt::format("iteration {}: episode {} where the MDP is in episode {}; the "
                                                    "run was not written with this folder's body and config",
                                                    step.iteration, step.episode, due_episode));
    }
    if (step.episode > episode) break;
    if (step.episode == episode && climb.postures.empty()) climb.postures.push_back(mdp.posture());
    const ActionCode hold = folder.wall.index_of(step.hold_id);
    if (!mdp.offers(hold)) {
      throw InputError(iterations_file, fmt::format("iteration {}: hold {} is not a possible action there; the "
                                                    "run was not written with this folder's wall and config",
                                                    step.iteration, step.hold_id));
    }
    const StepOutcome outcome = mdp.step(hold);
    if (outcome.reached != step.success) {
      throw InputError(iterations_file, fmt::format("iteration {}: the move {} where the run's {}; the run was not "
                                                    "written with this folder's body and config",
                                                    step.iteration, outcome.reached ? "reaches" : "fails",
                                                    step.success ? "reached" : "failed"));
    }
    if (outcome.finished) ++due_episode;
    if (step.episode != episode) continue;
    climb.steps.push_back(step);
    if (outcome.reached) climb.postures.push_back(*outcome.posture);
    climb.finished = outcome.finished;
  }
  return climb;
}

RecordedClimb climb_to_show(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                            const std::string& choice, const std::string& flag) {
  if (choice == "greedy" || choice == "last") return chosen_climb(folder, choice);
  int episode = -1;
  const auto [end, error] = std::from_chars(choice.data(), choice.data() + choice.size(), episode);
  if (error != std::errc() || end != choice.data() + choice.size() || choice.empty()) {
    throw InputError(flag, fmt::format("expected greedy, last or an episode number, got '{}'", choice.substr(0, 40)));
  }
  return replay_episode(folder, model, parameters, episode, flag);
}

}  // namespace crux
