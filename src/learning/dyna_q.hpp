#pragma once
// Dyna-Q with two Q-tables learnt in parallel (paper, Algorithm 2): Q_wall on
// problem-space couples and Q_grid on agent-space couples. Real steps update both;
// the deterministic model, learnt in problem space, replays experienced pairs (50 per
// real step by default) into both.

#include <span>
#include <unordered_map>
#include <vector>

#include "learning/action_selection.hpp"
#include "learning/deterministic_model.hpp"
#include "learning/q_learning.hpp"

namespace crux {

struct DynaSettings {
  QLearningRates rates;
  int planning_steps = 50;
  double epsilon = 0.1;  // Algorithm 3; the paper gives no value (spec item 19)
};

class DynaQAgent {
 public:
  DynaQAgent(int wall_action_count, int grid_action_count, const DynaSettings& settings);

  // Starts from a Q_grid learnt elsewhere (transfer); its visit counts say what has
  // "already been taken" in agent space.
  void set_q_grid(QTable q_grid);

  // Remembers which actions a state offers, for the max of the updates that lead to it:
  // every candidate's wall action, and the grid actions that map back to a candidate.
  void observe(const StateCouple& state, std::span<const ActionCandidate> candidates);

  ActionChoice choose(const StateCouple& state, std::span<const ActionCandidate> candidates, Random& random) const {
    return select_action(q_wall_, q_grid_, state, candidates, settings_.epsilon, random);
  }

  // Algorithm 2, lines 22-29. The next state must have been observed.
  void learn(const Experience& experience, Random& random);

  const QTable& q_wall() const { return q_wall_; }
  const QTable& q_grid() const { return q_grid_; }
  const DeterministicModel& model() const { return model_; }

 private:
  void update_both(const Experience& e);
  std::span<const ActionCode> available(const std::unordered_map<StateCode, std::vector<ActionCode>>& known,
                                        StateCode state) const;

  DynaSettings settings_;
  QTable q_wall_, q_grid_;
  DeterministicModel model_;
  std::unordered_map<StateCode, std::vector<ActionCode>> wall_actions_, grid_actions_;
};

}  // namespace crux
