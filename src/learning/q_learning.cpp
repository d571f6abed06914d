#include "learning/q_learning.hpp"

namespace crux {

double q_learning_update(QTable& q, StateCode s, ActionCode a, double reward, StateCode next,
                         std::span<const ActionCode> next_available, const QLearningRates& rates) {
  const double target = reward + rates.gamma * q.best_value(next, next_available);
  double& value = q.value_slot(s, a);  // after best_value: it may create a row
  value += rates.alpha * (target - value);
  return value;
}

}  // namespace crux
