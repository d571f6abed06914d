#include "learning/q_learning.hpp"

namespace crux {

double q_learning_update(QTable& q, StateCode s, ActionCode a, double reward, StateCode next,
                         std::span<const ActionCode> next_available, const QLearningRates& rates) {
  const double current = q.value(s, a);
  const double target = reward + rates.gamma * q.best_value(next, next_available);
  const double updated = current + rates.alpha * (target - current);
  q.set_value(s, a, updated);
  return updated;
}

}  // namespace crux
