#include "learning/prioritized_sweeping.hpp"

#include <gtest/gtest.h>

#include "common/checkpoint_stream.hpp"

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
// gamma 0.9, 5 planning updates per real step. A popped pair is queued again at the
// error its update left. Worked by hand:
// Step 1, (0, 0) -> 1 with r = -1. Real update: Q(0,0) = -0.5, error 0.5; no
//   predecessor. Five pops of (0,0) halve the error each time: Q(0,0) = -1 + 0.5^6 =
//   -0.984375, still queued at 0.015625.
// Step 2, (1, 0) -> 2 with r = 10. Real update: Q(1,0) = 5, queued at 5; its predecessor
//   (0,0) is raised to |-1 + 0.9 x 5 + 0.984375| = 4.484375.
//   pop (1,0): Q(1,0) = 7.5, queued at 2.5; (0,0) raised to 5.75 + 0.984375 = 6.734375.
//   pop (0,0): Q(0,0) = 2.3828125, queued at 3.3671875.
//   pop (0,0): Q(0,0) = 4.06640625, queued at 1.68359375.
//   pop (1,0) (2.5): Q(1,0) = 8.75, queued at 1.25; (0,0) raised to 6.875 - 4.06640625.
//   pop (0,0): Q(0,0) = 4.06640625 + 0.5 x 2.80859375 = 5.470703125.
TEST(PrioritizedSweeping, DynaSweepsPredecessorsAsComputedByHand) {
  DynaParameters settings;
  settings.rates = {0.5, 0.9};
  settings.planning_steps = 5;
  settings.planner = Planner::Prioritized;
  DynaQAgent agent(1, 1, settings, 1);
  const ActionCandidate only[1] = {{0, 0, true}};
  agent.observe({0, 0}, only);
  agent.observe({1, 1}, only);
  agent.observe({2, 2}, {});
  agent.learn({0, 0, 0, 0, -1.0, 1, 1});
  EXPECT_DOUBLE_EQ(agent.q_wall().value(0, 0), -0.984375);
  agent.learn({1, 1, 0, 0, 10.0, 2, 2});
  for (const QTable* q : {&agent.q_wall(), &agent.q_grid()}) {
    EXPECT_DOUBLE_EQ(q->value(1, 0), 8.75);
    EXPECT_DOUBLE_EQ(q->value(0, 0), 5.470703125);
  }
  EXPECT_EQ(agent.planning_updates(), 10u);
}

TEST(PrioritizedSweeping, AQueueThatRunsDryEndsThePlanningEarly) {
  DynaParameters settings;
  settings.rates = {1.0, 0.9};  // a full backup: nothing is left to replay
  settings.planning_steps = 5;
  settings.planner = Planner::Prioritized;
  DynaQAgent agent(1, 1, settings, 1);
  const ActionCandidate only[1] = {{0, 0, true}};
  agent.observe({0, 0}, only);
  agent.observe({1, 1}, {});
  agent.learn({0, 0, 0, 0, -1.0, 1, 1});
  EXPECT_DOUBLE_EQ(agent.q_wall().value(0, 0), -1.0);
  EXPECT_EQ(agent.planning_updates(), 0u);
}

TEST(PrioritizedSweeping, SetReplacesAPriorityAndRemoveDequeues) {
  PriorityQueue queue;
  queue.push(0, 5.0);
  queue.push(1, 3.0);
  queue.set(0, 1.0);  // lowered: the item at 5 is stale now
  EXPECT_EQ(queue.pop(), 1u);
  EXPECT_EQ(queue.pop(), 0u);
  EXPECT_TRUE(queue.empty());
  queue.push(2, 4.0);
  queue.remove(2);
  EXPECT_TRUE(queue.empty());
  // Many raises leave stale items behind; the queue still pops each live entry once.
  for (int round = 1; round <= 100; ++round) {
    for (std::size_t e = 0; e < 3; ++e) queue.push(e, round + static_cast<double>(e) / 10);
  }
  EXPECT_EQ(queue.size(), 3u);
  EXPECT_EQ(queue.pop(), 2u);
  EXPECT_EQ(queue.pop(), 1u);
  EXPECT_EQ(queue.pop(), 0u);
  EXPECT_TRUE(queue.empty());
}

TEST(PrioritizedSweeping, ModelKnowsEachStatesPredecessorsAfterAChangedTransition) {
  DeterministicModel model(true);
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
  for (const Planner p : {Planner::Uniform, Planner::Prioritized}) EXPECT_EQ(parse_enum<Planner>(enum_name(p)), p);
  EXPECT_FALSE(parse_enum<Planner>("sweeping"));
}

TEST(PrioritizedSweeping, ACheckpointedQueuePopsInTheSameOrder) {
  PriorityQueue queue;
  for (std::size_t e = 0; e < 40; ++e) queue.push(e, static_cast<double>((e * 7) % 11));
  for (std::size_t e = 0; e < 40; e += 3) queue.set(e, 0.5);  // leaves stale items
  CheckpointWriter out;
  queue.save_state(out);
  const std::string bytes = out.take();
  PriorityQueue restored;
  CheckpointReader in(bytes, "test");
  restored.load_state(in, 40);
  EXPECT_TRUE(in.at_end());
  ASSERT_EQ(restored.size(), queue.size());
  queue.push(99, 0.25);
  restored.push(99, 0.25);
  while (!queue.empty()) ASSERT_EQ(restored.pop(), queue.pop());
  EXPECT_TRUE(restored.empty());
}

}  // namespace
}  // namespace crux
