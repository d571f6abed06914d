#include "learning/prioritized_sweeping.hpp"

#include <gtest/gtest.h>

#include "learning/dyna_q.hpp"

namespace crux {
namespace {

TEST(PrioritizedSweeping, QueuePopsHighestFirstRaisesAndNeverLowers) {
  PriorityQueue queue;
  queue.push(0, 1.0);
  queue.push(1, 3.0);
  queue.push(2, 3.0);
  queue.push(0, 5.0);  // raised
  queue.push(1, 2.0);  // a lower priority leaves 3.0
  EXPECT_EQ(queue.size(), 3u) << "each entry is queued once";
  EXPECT_EQ(queue.pop(), 0u);
  EXPECT_EQ(queue.pop(), 1u) << "equal priorities: the pair learnt first";
  EXPECT_EQ(queue.pop(), 2u);
  EXPECT_TRUE(queue.empty());
  queue.push(2, 0.5);  // queued again after its pop
  EXPECT_EQ(queue.pop(), 2u);
  EXPECT_TRUE(queue.empty());
}

// A two-step chain 0 -> 1 -> 2, state 2 offering nothing (its value is 0); alpha 0.5,
// gamma 0.9, 5 planning updates per real step. Worked by hand:
// Step 1, (0, 0) -> 1 with r = -1. Real update: Q(0,0) = 0.5 (-1) = -0.5. Its error
//   |-1 - (-0.5)| = 0.5 queues it; state 0 has no predecessor. Pop (0,0):
//   Q(0,0) = -0.5 + 0.5 (-1 + 0.5) = -0.75. The queue is empty: 1 update, not 5.
// Step 2, (1, 0) -> 2 with r = 10. Real update: Q(1,0) = 5. Its error 5 queues it; its
//   predecessor (0,0) has error |-1 + 0.9 x 5 - (-0.75)| = 4.25. Pop (1,0) (5 > 4.25):
//   Q(1,0) = 7.5, which raises (0,0) to |-1 + 0.9 x 7.5 + 0.75| = 6.5. Pop (0,0):
//   Q(0,0) = -0.75 + 0.5 (5.75 + 0.75) = 2.5. The queue is empty.
TEST(PrioritizedSweeping, DynaSweepsPredecessorsAsComputedByHand) {
  DynaSettings settings;
  settings.rates = {0.5, 0.9};
  settings.planning_steps = 5;
  settings.planner = Planner::Prioritized;
  DynaQAgent agent(1, 1, settings, 1);
  const ActionCandidate only[1] = {{0, 0, true}};
  agent.observe({0, 0}, only);
  agent.observe({1, 1}, only);
  agent.observe({2, 2}, {});
  agent.learn({0, 0, 0, 0, -1.0, 1, 1});
  EXPECT_DOUBLE_EQ(agent.q_wall().value(0, 0), -0.75);
  agent.learn({1, 1, 0, 0, 10.0, 2, 2});
  for (const QTable* q : {&agent.q_wall(), &agent.q_grid()}) {
    EXPECT_DOUBLE_EQ(q->value(1, 0), 7.5);
    EXPECT_DOUBLE_EQ(q->value(0, 0), 2.5);
  }
}

TEST(PrioritizedSweeping, ModelKnowsEachStatesPredecessorsAfterAChangedTransition) {
  DeterministicModel model;
  EXPECT_EQ(model.record({0, 0, 0, 0, -1.0, 5, 5}), 0u);
  EXPECT_EQ(model.record({1, 1, 0, 0, -1.0, 5, 5}), 1u);
  EXPECT_EQ(model.predecessors(5).size(), 2u);
  EXPECT_EQ(model.record({0, 0, 0, 0, -1.0, 6, 6}), 0u) << "the same pair keeps its index";
  ASSERT_EQ(model.predecessors(5).size(), 1u);
  EXPECT_EQ(model.predecessors(5)[0], 1u);
  ASSERT_EQ(model.predecessors(6).size(), 1u);
  EXPECT_EQ(model.predecessors(6)[0], 0u);
  EXPECT_TRUE(model.predecessors(7).empty());
}

TEST(PrioritizedSweeping, PlannerNamesRoundTrip) {
  for (const Planner p : {Planner::Uniform, Planner::Prioritized}) EXPECT_EQ(parse_planner(planner_name(p)), p);
  EXPECT_FALSE(parse_planner("sweeping"));
}

}  // namespace
}  // namespace crux
