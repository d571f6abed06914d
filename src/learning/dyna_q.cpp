#include "learning/dyna_q.hpp"

#include <algorithm>

namespace crux {

DynaQAgent::DynaQAgent(int wall_action_count, int grid_action_count, const DynaSettings& settings)
    : settings_(settings), q_wall_(wall_action_count), q_grid_(grid_action_count) {}

void DynaQAgent::set_q_grid(QTable q_grid) { q_grid_ = std::move(q_grid); }

void DynaQAgent::observe(const StateCouple& state, std::span<const ActionCandidate> candidates) {
  std::vector<ActionCode>& wall = wall_actions_[state.wall];
  wall.clear();
  for (const ActionCandidate& c : candidates) wall.push_back(c.wall);
  std::vector<ActionCode>& grid = grid_actions_[state.grid];
  grid.clear();
  for (const ActionCandidate& c : candidates) {
    if (c.represents_grid_action) grid.push_back(c.grid);
  }
}

std::span<const ActionCode> DynaQAgent::available(const std::unordered_map<StateCode, std::vector<ActionCode>>& known,
                                                  StateCode state) const {
  const auto it = known.find(state);
  return it == known.end() ? std::span<const ActionCode>() : std::span<const ActionCode>(it->second);
}

void DynaQAgent::update_both(const Experience& e) {
  q_learning_update(q_wall_, e.wall_state, e.wall_action, e.reward, e.next_wall_state,
                    available(wall_actions_, e.next_wall_state), settings_.rates);
  if (e.grid_action != kNoAction) {
    q_learning_update(q_grid_, e.grid_state, e.grid_action, e.reward, e.next_grid_state,
                      available(grid_actions_, e.next_grid_state), settings_.rates);
  }
}

void DynaQAgent::learn(const Experience& experience, Random& random) {
  update_both(experience);
  q_wall_.add_visit(experience.wall_state, experience.wall_action);
  if (experience.grid_action != kNoAction) q_grid_.add_visit(experience.grid_state, experience.grid_action);
  model_.record(experience);
  for (int i = 0; i < settings_.planning_steps; ++i) update_both(model_.at(random.below(model_.size())));
}

}  // namespace crux
