#include "experiments/shortest_plan.hpp"

#include <deque>
#include <optional>
#include <unordered_map>

#include "climbing/stance_check.hpp"
#include "configurations/reachability.hpp"
#include "ik/ik_path.hpp"

namespace crux {

namespace {

struct Node {
  HoldConfiguration configuration;  // a 3-configuration
  const Posture* posture;
  long parent;
  int hold;  // the hold taken to get here (index), -1 at the start
};

}  // namespace

Plan shortest_plan(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                   const PlanParameters& search, const RefusedMoves& refused) {
  // The planner needs verdicts only: under the static model, the cheaper program.
  ConfigurationReacher reacher(model, wall, parameters.reachability, parameters.physics, StanceQuestion::HoldsStill);
  const Posture* start = &reacher.require_start(wall.name);
  std::vector<Node> nodes{{start_configuration(wall).with(Limb::RightHand, kFree), start, -1, -1}};
  std::unordered_map<std::uint64_t, bool> seen{{encode(nodes[0].configuration, wall.hold_count()), true}};
  std::deque<std::size_t> frontier{0};
  std::vector<int> possible(wall.hold_count());
  Plan plan;
  plan.physics_model = parameters.physics.model;
  // The path's postures are checked on the three holds kept during the move; its first
  // posture is the last stance, which holds on them.
  std::optional<StanceCheck> move_check;
  if (search.check_moves) move_check.emplace(model, wall, parameters.physics);
  plan.checked_moves = search.check_moves;
  BodyData path_data(model);
  std::vector<Posture> path, samples;
  const auto holds_on_the_way = [&](const Node& node, const HoldConfiguration& complete, const Posture& reached) {
    const ReachTarget target = reach_target(model, wall, complete, parameters.reachability.root);
    ik_path_samples(model, path_data, *node.posture, reached, target, parameters.reachability.ik, search.move_samples,
                    path, samples);
    for (std::size_t s = 1; s + 1 < samples.size(); ++s) {
      if (!move_check->solve(samples[s], node.configuration).feasible) return false;
    }
    return true;
  };
  const auto finish = [&](std::size_t parent, int hold, const Posture& last) {
    plan.found = true;
    std::vector<std::pair<int, Limb>> steps{{hold, nodes[parent].configuration.free_limb()}};
    std::vector<const Posture*> postures{&last};
    for (long n = static_cast<long>(parent); nodes[n].parent >= 0; n = nodes[n].parent) {
      steps.push_back({nodes[n].hold, nodes[nodes[n].parent].configuration.free_limb()});
      postures.push_back(nodes[n].posture);
    }
    postures.push_back(start);
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
      plan.hold_ids.push_back(wall.holds[it->first].id);
      plan.limbs.push_back(it->second);
    }
    for (auto it = postures.rbegin(); it != postures.rend(); ++it) plan.postures.push_back(**it);
    plan.length = static_cast<int>(plan.hold_ids.size());
  };
  while (!frontier.empty() && !plan.found) {
    if (reacher.solves() >= static_cast<std::size_t>(search.max_ik_solves)) {
      plan.stopped_at_limit = true;
      break;
    }
    const std::size_t current = frontier.front();
    frontier.pop_front();
    const Node node = nodes[current];
    ++plan.expanded_states;
    const Limb free = node.configuration.free_limb();
    const int count = possible_actions(wall, node.configuration, parameters.filter, possible);
    for (int i = 0; i < count && !plan.found && !plan.stopped_at_limit; ++i) {
      if (reacher.solves() >= static_cast<std::size_t>(search.max_ik_solves)) {
        plan.stopped_at_limit = true;
        break;
      }
      if (!refused.empty() && refused.contains({encode(node.configuration, wall.hold_count()), possible[i]})) continue;
      const HoldConfiguration complete = node.configuration.with(free, possible[i]);
      const Posture* reached = reacher.reach(*node.posture, complete, next_free_limb(free));
      if (reached == nullptr) continue;
      if (move_check && !holds_on_the_way(node, complete, *reached)) {
        ++plan.moves_refused_on_the_way;
        continue;
      }
      if (reacher.place(*reached).centre_of_mass.z() >= wall.finish_height) {
        finish(current, possible[i], *reached);
        break;
      }
      const HoldConfiguration next = complete.with(next_free_limb(free), kFree);
      if (!seen.emplace(encode(next, wall.hold_count()), true).second) continue;
      nodes.push_back({next, reached, static_cast<long>(current), possible[i]});
      frontier.push_back(nodes.size() - 1);
    }
  }
  plan.ik_solves = reacher.solves();
  return plan;
}

}  // namespace crux
