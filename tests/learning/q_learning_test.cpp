#include "learning/q_learning.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace crux {
namespace {

TEST(QLearning, UpdateMatchesHandComputedNumbers) {
  QTable q(3);
  q.set_value(7, 1, 5.0);  // best available next value
  q.set_value(7, 2, 9.0);  // larger but not available in the next state
  const std::vector<ActionCode> next_available{0, 1};
  const QLearningRates rates{0.1, 0.9};
  // 0 + 0.1 * (-1 + 0.9 * 5 - 0) = 0.35
  EXPECT_DOUBLE_EQ(q_learning_update(q, 3, 0, -1.0, 7, next_available, rates), 0.35);
  // 0.35 + 0.1 * (-1 + 4.5 - 0.35) = 0.665
  EXPECT_DOUBLE_EQ(q_learning_update(q, 3, 0, -1.0, 7, next_available, rates), 0.665);
  // An unreachable move: stay in place (next state = this state, whose best is 0.665),
  // reward -1000: 0.665 + 0.1 * (-1000 + 0.5985 - 0.665) = -99.34165.
  EXPECT_NEAR(q_learning_update(q, 3, 0, -1000.0, 3, std::vector<ActionCode>{0}, rates), -99.34165, 1e-12);
}

TEST(QLearning, MaxOverNothingAvailableIsZero) {
  QTable q(2);
  q.set_value(1, 0, -50.0);
  EXPECT_DOUBLE_EQ(q.best_value(1, {}), 0.0);
  EXPECT_DOUBLE_EQ(q.best_value(1, std::vector<ActionCode>{0}), -50.0);
  EXPECT_DOUBLE_EQ(q.best_value(99, std::vector<ActionCode>{0, 1}), 0.0) << "unseen states are worth 0";
}

TEST(QTable, CountsVisitsAndListsRowsInStateOrder) {
  QTable q(2);
  q.add_visit(9, 1);
  q.add_visit(9, 1);
  q.set_value(4, 0, 1.5);
  EXPECT_EQ(q.visits(9, 1), 2u);
  EXPECT_TRUE(q.taken(9, 1));
  EXPECT_FALSE(q.taken(9, 0));
  EXPECT_FALSE(q.taken(123, 0));
  std::vector<StateCode> order;
  q.for_each_row([&](StateCode s, auto, auto) { order.push_back(s); });
  EXPECT_EQ(order, (std::vector<StateCode>{4, 9}));
}

}  // namespace
}  // namespace crux
