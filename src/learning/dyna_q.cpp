#include "learning/dyna_q.hpp"

#include <algorithm>
#include <cmath>

#include "common/checkpoint_stream.hpp"

namespace crux {

DynaQAgent::DynaQAgent(int wall_action_count, int grid_action_count, const DynaParameters& parameters,
                       std::uint64_t seed)
    : settings_(parameters),
      selection_streams_(seed),
      planning_stream_(seed, "planning"),
      q_wall_(wall_action_count),
      q_grid_(grid_action_count),
      model_(parameters.planner == Planner::Prioritized) {}

void DynaQAgent::set_q_grid(QTable q_grid) {
  if (settings_.transfer == TransferMode::Seeded || settings_.transfer == TransferMode::Ordered) transferred_ = q_grid;
  if (settings_.transfer == TransferMode::Shaping) potential_ = GridPotential(q_grid);
  q_grid_ = std::move(q_grid);
}

void DynaQAgent::observe(const StateCouple& state, std::span<const ActionCandidate> candidates) {
  const auto [known, first_seen] = wall_actions_.try_emplace(state.wall);
  if (first_seen && transferred_ && settings_.transfer == TransferMode::Seeded) {
    for (const ActionCandidate& c : candidates) {
      if (c.grid != kNoAction && transferred_->taken(state.grid, c.grid)) {
        q_wall_.set_value(state.wall, c.wall, transferred_->value(state.grid, c.grid));
      }
    }
  }
  std::vector<ActionCode>& wall = known->second;
  wall.clear();
  for (const ActionCandidate& c : candidates) wall.push_back(c.wall);
  std::vector<ActionCode>& grid = grid_actions_[state.grid];
  grid.clear();
  for (const ActionCandidate& c : candidates) {
    if (c.represents_grid_action) grid.push_back(c.grid);
  }
}

ActionChoice DynaQAgent::choose(const StateCouple& state, std::span<const ActionCandidate> candidates,
                                std::span<const double> scores) {
  SelectionRule rule;
  if (settings_.transfer == TransferMode::Informed || settings_.transfer == TransferMode::Prior) {
    grid_excluded_.assign(candidates.size(), 0);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      // Only representatives can be g-greedy's choice: the others need no model look-up.
      if (!candidates[i].represents_grid_action) continue;
      // The deterministic model's outcome of the pair; a failed move leaves the state.
      const Experience* known = model_.find(state.wall, candidates[i].wall);
      grid_excluded_[i] =
          (known != nullptr && known->next_wall_state == state.wall) || candidates[i].returns_to_left_hold;
    }
    rule.grid_excluded = grid_excluded_;
    rule.grid_taken_only = settings_.transfer == TransferMode::Prior;
  } else if (settings_.transfer == TransferMode::Seeded || settings_.transfer == TransferMode::Ordered ||
             settings_.transfer == TransferMode::Network) {
    rule.wall_requires_taken = false;
    rule.grid_greedy = false;
    // Without a transferred table or scores there is nothing to order ties by: the seeded rule.
    if (settings_.transfer == TransferMode::Ordered && transferred_) rule.wall_tie_order = &*transferred_;
    if (settings_.transfer == TransferMode::Network) rule.wall_tie_scores = scores;
  }
  return select_action(q_wall_, q_grid_, state, candidates, settings_.epsilon, selection_streams_, steps_, rule);
}

std::span<const ActionCode> DynaQAgent::available(const absl::flat_hash_map<StateCode, std::vector<ActionCode>>& known,
                                                  StateCode state) const {
  const auto it = known.find(state);
  return it == known.end() ? std::span<const ActionCode>() : std::span<const ActionCode>(it->second);
}

double DynaQAgent::wall_reward(const Experience& e) const {
  if (settings_.transfer != TransferMode::Shaping) return e.reward;
  return e.reward + potential_.shaping(e.grid_state, e.next_grid_state, settings_.rates.gamma);
}

void DynaQAgent::update_both(const Experience& e) {
  q_learning_update(q_wall_, e.wall_state, e.wall_action, wall_reward(e), e.next_wall_state,
                    available(wall_actions_, e.next_wall_state), settings_.rates);
  if (e.grid_action != kNoAction) {
    q_learning_update(q_grid_, e.grid_state, e.grid_action, e.reward, e.next_grid_state,
                      available(grid_actions_, e.next_grid_state), settings_.rates);
  }
}

void DynaQAgent::learn(const Experience& experience) {
  update_both(experience);
  q_wall_.add_visit(experience.wall_state, experience.wall_action);
  if (experience.grid_action != kNoAction) q_grid_.add_visit(experience.grid_state, experience.grid_action);
  const std::size_t entry = model_.record(experience);
  if (settings_.planner == Planner::Uniform) {
    plan_uniformly();
  } else {
    sweep(experience.wall_state, entry);
  }
  ++steps_;
}

void DynaQAgent::plan_uniformly() {
  for (int i = 0; i < settings_.planning_steps; ++i) {
    update_both(model_.at(planning_stream_.below(model_.size(), steps_, static_cast<std::uint64_t>(i))));
  }
  planning_updates_ += static_cast<std::uint64_t>(settings_.planning_steps);
}

void DynaQAgent::prioritize(std::size_t entry, bool exact) {
  const Experience& e = model_.at(entry);
  const double target =
      wall_reward(e) +
      settings_.rates.gamma * q_wall_.best_value(e.next_wall_state, available(wall_actions_, e.next_wall_state));
  const double priority = std::abs(target - q_wall_.value(e.wall_state, e.wall_action));
  if (priority > settings_.priority_threshold) {
    exact ? queue_.set(entry, priority) : queue_.push(entry, priority);
  } else if (exact) {
    queue_.remove(entry);
  }
}

// Sutton and Barto's prioritized sweeping with Algorithm 2's real update kept: the real
// step has changed Q(s, a), so (s, a) is queued at the error it has left and s's
// predecessors at theirs; then up to planning_steps pairs are popped and replayed, each
// queued again at the error its step of alpha left (the model is deterministic, so
// Moore and Atkeson's full backup is the aim) and queueing its state's predecessors.
void DynaQAgent::sweep(StateCode real_state, std::size_t real_entry) {
  prioritize(real_entry, true);
  for (const std::size_t p : model_.predecessors(real_state)) prioritize(p, false);
  for (int i = 0; i < settings_.planning_steps && !queue_.empty(); ++i) {
    const std::size_t entry = queue_.pop();
    const Experience& e = model_.at(entry);
    update_both(e);
    ++planning_updates_;
    prioritize(entry, true);
    for (const std::size_t p : model_.predecessors(e.wall_state)) prioritize(p, false);
  }
}

namespace {

// A state -> actions map in state order, so that the file does not depend on hashing.
void save_actions(CheckpointWriter& out, const absl::flat_hash_map<StateCode, std::vector<ActionCode>>& known) {
  const std::vector<StateCode> states = sorted_keys(known);
  out.vector(states);
  for (const StateCode state : states) out.vector(known.at(state));
}

void load_actions(CheckpointReader& in, absl::flat_hash_map<StateCode, std::vector<ActionCode>>& known,
                  int action_count) {
  known.clear();
  for (const StateCode state : in.vector<StateCode>()) {
    std::vector<ActionCode> actions = in.vector<ActionCode>();
    for (const ActionCode a : actions) {
      if (a < 0 || a >= action_count) in.fail();
    }
    known[state] = std::move(actions);
  }
}

}  // namespace

void DynaQAgent::save_state(CheckpointWriter& out) const {
  out.value(steps_);
  out.value(planning_updates_);
  q_wall_.save_state(out);
  q_grid_.save_state(out);
  model_.save_state(out);
  queue_.save_state(out);
  save_actions(out, wall_actions_);
  save_actions(out, grid_actions_);
}

void DynaQAgent::load_state(CheckpointReader& in) {
  steps_ = in.value<std::uint64_t>();
  planning_updates_ = in.value<std::uint64_t>();
  q_wall_.load_state(in);
  q_grid_.load_state(in);
  model_.load_state(in, q_wall_.action_count(), q_grid_.action_count());
  queue_.load_state(in, model_.size());
  load_actions(in, wall_actions_, q_wall_.action_count());
  load_actions(in, grid_actions_, q_grid_.action_count());
}

}  // namespace crux
