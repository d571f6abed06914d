#include "reports/episode_replay.hpp"

#include <charconv>

#include <fmt/format.h>

#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "common/printable.hpp"

namespace crux {

RecordedClimb replay_episode(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                             int episode, const std::string& flag) {
  const int episodes = folder.steps.empty() ? 0 : folder.steps.back().episode + 1;
  if (episode < 0 || episode >= episodes) {
    throw InputError(flag, episodes == 0 ? std::string("the run has no episode")
                                         : fmt::format("the run has episodes 1 to {}, not {}", episodes, episode + 1));
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
    if (outcome.fell) {  // the episode's climb starts again: show its last attempt
      climb.steps.clear();
      climb.postures.assign(1, mdp.posture());
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

RecordedClimb climb_to_show(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                            const std::string& choice, const std::string& flag) {
  if (choice == "greedy" || choice == "last") return chosen_climb(folder, choice);
  int number = 0;
  const auto [end, error] = std::from_chars(choice.data(), choice.data() + choice.size(), number);
  if (error != std::errc() || end != choice.data() + choice.size() || choice.empty()) {
    throw InputError(flag, fmt::format("expected greedy, last or an episode number (from 1), got '{}'",
                                       printable(choice.substr(0, 40))));
  }
  if (number < 1) throw InputError(flag, fmt::format("episodes are numbered from 1, not {}", number));
  return replay_episode(folder, model, parameters, number - 1, flag);
}

std::string shown_climb_reason(const RunFolder& folder, const RecordedClimb& shown, const std::string& choice,
                               int greedy_cap, const std::string& flag) {
  const std::string last = fmt::format("the last completed episode (episode {})", folder.last.episode + 1);
  if (shown.kind == "greedy") {
    return fmt::format("the greedy policy's climb after learning, which reaches the top in {}",
                       counted(shown.steps.size(), "action"));
  }
  if (choice == "greedy") {
    const std::string unfinished = fmt::format(
        "the greedy policy did not reach the top within {} (experiment.greedy_cap)", counted(greedy_cap, "action"));
    return shown.postures.empty() ? unfinished + " and the run completed no episode"
                                  : fmt::format("{}, since {}", last, unfinished);
  }
  if (choice == "last") {
    return shown.postures.empty() ? std::string("the run completed no episode")
                                  : fmt::format("{}, as {} last asks", last, flag);
  }
  return fmt::format("episode {}, as {} {} asks{}", shown.episode + 1, flag, choice,
                     shown.finished ? "" : "; the run ended during it, so it does not reach the top");
}

}  // namespace crux
