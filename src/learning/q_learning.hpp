#pragma once
// The standard Q-learning update (paper, section III-D):
// Q(s, a) <- Q(s, a) + alpha (r + gamma max_a' Q(s', a') - Q(s, a)),
// the max taken over the actions available in s'.

#include "learning/q_table.hpp"

namespace crux {

struct QLearningRates {
  double alpha = 0.1;
  double gamma = 0.9;
};

// Returns the new Q(s, a).
double q_learning_update(QTable& q, StateCode s, ActionCode a, double reward, StateCode next,
                         std::span<const ActionCode> next_available, const QLearningRates& rates);

}  // namespace crux
