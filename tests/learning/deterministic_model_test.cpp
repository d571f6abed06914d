#include "learning/deterministic_model.hpp"

#include <gtest/gtest.h>

#include "common/checkpoint_stream.hpp"

#include <algorithm>
#include <vector>

namespace crux {
namespace {

// A transition of problem-space pair (state, action) to `next`, with agent-space
// descriptors derived from them so that a test can tell which experience is stored.
Experience experience(StateCode state, ActionCode action, StateCode next, double reward = -1.0) {
  Experience e;
  e.wall_state = state;
  e.wall_action = action;
  e.next_wall_state = next;
  e.grid_state = 1000 + state;
  e.grid_action = 100 + action;
  e.next_grid_state = 1000 + next;
  e.reward = reward;
  return e;
}

std::vector<std::size_t> sorted(std::span<const std::size_t> indices) {
  std::vector<std::size_t> out(indices.begin(), indices.end());
  std::sort(out.begin(), out.end());
  return out;
}

void expect_same(const Experience& stored, const Experience& expected) {
  EXPECT_EQ(stored.wall_state, expected.wall_state);
  EXPECT_EQ(stored.grid_state, expected.grid_state);
  EXPECT_EQ(stored.wall_action, expected.wall_action);
  EXPECT_EQ(stored.grid_action, expected.grid_action);
  EXPECT_EQ(stored.reward, expected.reward);
  EXPECT_EQ(stored.next_wall_state, expected.next_wall_state);
  EXPECT_EQ(stored.next_grid_state, expected.next_grid_state);
}

TEST(DeterministicModel, StoresEachProblemSpacePairOnceInFirstSeenOrder) {
  DeterministicModel model;
  EXPECT_EQ(model.size(), 0u);
  EXPECT_EQ(model.record(experience(4, 2, 5)), 0u);
  EXPECT_EQ(model.record(experience(4, 3, 6)), 1u) << "another action of the same state is another pair";
  EXPECT_EQ(model.record(experience(9, 2, 4)), 2u) << "the same action of another state is another pair";
  EXPECT_EQ(model.size(), 3u);
  expect_same(model.at(0), experience(4, 2, 5));
  expect_same(model.at(1), experience(4, 3, 6));
  expect_same(model.at(2), experience(9, 2, 4));
}

TEST(DeterministicModel, KeepsTheLastOutcomeOfAPairAtItsFirstIndex) {
  DeterministicModel model;
  model.record(experience(1, 0, 2));
  model.record(experience(3, 1, 3, -1000.0));  // a failure: s' = s
  // Pair (1, 0) again, now leading elsewhere with another reward and grid descriptors.
  Experience later = experience(1, 0, 7, 200000.0);
  later.grid_state = 55;
  later.grid_action = kNoAction;  // the hold now lies outside the grid
  EXPECT_EQ(model.record(later), 0u);
  EXPECT_EQ(model.size(), 2u) << "no new pair";
  expect_same(model.at(0), later);
  expect_same(model.at(1), experience(3, 1, 3, -1000.0));
}

TEST(DeterministicModel, PairsAreKeyedByTheProblemSpaceOnly) {
  // The same wall pair seen from two grid states is one pair of the model: Dyna's model
  // is learnt in problem space.
  DeterministicModel model;
  Experience a = experience(2, 1, 3);
  Experience b = a;
  b.grid_state = 999;
  b.grid_action = 7;
  model.record(a);
  EXPECT_EQ(model.record(b), 0u);
  EXPECT_EQ(model.size(), 1u);
  EXPECT_EQ(model.at(0).grid_state, 999u);
}

TEST(DeterministicModel, IndicesCoverZeroToSizeSoAUniformDrawReachesEveryPairOnce) {
  // Dyna draws an index uniformly in [0, size()); the model promises each pair one
  // index there, whatever the order in which pairs and repeats arrive.
  DeterministicModel model;
  const std::vector<std::pair<StateCode, ActionCode>> seen{{5, 0}, {5, 1}, {5, 0}, {2, 3}, {5, 1}, {8, 0}, {2, 3}};
  for (const auto& [s, a] : seen) model.record(experience(s, a, s + 1));
  ASSERT_EQ(model.size(), 4u);
  const std::vector<std::pair<StateCode, ActionCode>> expected{{5, 0}, {5, 1}, {2, 3}, {8, 0}};
  for (std::size_t i = 0; i < model.size(); ++i) {
    EXPECT_EQ(model.at(i).wall_state, expected[i].first) << "index " << i;
    EXPECT_EQ(model.at(i).wall_action, expected[i].second) << "index " << i;
  }
}

TEST(DeterministicModel, NoPredecessorsUnlessTracked) {
  DeterministicModel model;
  model.record(experience(1, 0, 2));
  model.record(experience(3, 0, 2));
  EXPECT_TRUE(model.predecessors(2).empty());
}

TEST(DeterministicModel, TrackedPredecessorsFollowEachPairsLastNextState) {
  DeterministicModel model(true);
  model.record(experience(1, 0, 5));  // 0
  model.record(experience(2, 0, 5));  // 1
  model.record(experience(2, 1, 6));  // 2
  model.record(experience(5, 0, 5));  // 3: a failure stays in 5, its own predecessor
  EXPECT_EQ(sorted(model.predecessors(5)), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(sorted(model.predecessors(6)), (std::vector<std::size_t>{2}));
  EXPECT_TRUE(model.predecessors(1).empty()) << "nothing leads to 1";

  // The same outcome again: no duplicate.
  model.record(experience(1, 0, 5, -3.0));
  EXPECT_EQ(sorted(model.predecessors(5)), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(model.at(0).reward, -3.0) << "but the entry takes the new reward";

  // Pair 1 now leads to 6: it leaves 5's list and joins 6's.
  EXPECT_EQ(model.record(experience(2, 0, 6)), 1u);
  EXPECT_EQ(sorted(model.predecessors(5)), (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(sorted(model.predecessors(6)), (std::vector<std::size_t>{1, 2}));

  // And back again.
  model.record(experience(2, 0, 5));
  EXPECT_EQ(sorted(model.predecessors(5)), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(sorted(model.predecessors(6)), (std::vector<std::size_t>{2}));
  EXPECT_EQ(model.size(), 4u);
}

TEST(DeterministicModel, TrackingPredecessorsStoresTheSameEntries) {
  // Prioritized sweeping and the uniform planner must replay the same model.
  DeterministicModel plain, tracked(true);
  const std::vector<Experience> stream{experience(1, 0, 2), experience(2, 1, 2, -1000.0), experience(1, 0, 3),
                                       experience(4, 0, 1), experience(2, 1, 5, 7.0)};
  for (const Experience& e : stream) EXPECT_EQ(plain.record(e), tracked.record(e));
  ASSERT_EQ(plain.size(), tracked.size());
  for (std::size_t i = 0; i < plain.size(); ++i) expect_same(tracked.at(i), plain.at(i));
}

TEST(DeterministicModel, ACheckpointRestoresPairsIndicesAndPredecessors) {
  DeterministicModel model(true);
  model.record({1, 1, 0, 0, -1.0, 2, 2});
  model.record({2, 2, 1, 1, -1.0, 3, 3});
  model.record({1, 1, 0, 0, -1.0, 3, 3});  // moves pair 0's next state
  CheckpointWriter out;
  model.save_state(out);
  const std::string bytes = out.take();
  DeterministicModel restored(true);
  CheckpointReader in(bytes, "test");
  restored.load_state(in, 2, 2);
  EXPECT_TRUE(in.at_end());
  ASSERT_EQ(restored.size(), 2u);
  EXPECT_EQ(restored.at(0).next_wall_state, 3u);
  EXPECT_EQ(std::vector<std::size_t>(restored.predecessors(3).begin(), restored.predecessors(3).end()),
            (std::vector<std::size_t>{1, 0}));
  EXPECT_TRUE(restored.predecessors(2).empty());
  EXPECT_EQ(restored.record({2, 2, 1, 1, -1.0, 3, 3}), 1u) << "a known pair keeps its index";
  EXPECT_EQ(restored.record({5, 5, 0, 0, -1.0, 1, 1}), 2u);
  DeterministicModel untracked(false);
  CheckpointReader other(bytes, "test");
  EXPECT_ANY_THROW(untracked.load_state(other, 2, 2));
  DeterministicModel narrower(true);
  CheckpointReader narrow(bytes, "test");
  EXPECT_ANY_THROW(narrower.load_state(narrow, 1, 2)) << "wall action 1 of a 1-action wall";
}

TEST(DeterministicModel, FindGivesThePairsLastExperience) {
  DeterministicModel model;
  model.record(experience(3, 1, 4));
  model.record(experience(3, 1, 3, -1000.0));
  ASSERT_NE(model.find(3, 1), nullptr);
  EXPECT_EQ(model.find(3, 1)->next_wall_state, 3u);
  EXPECT_EQ(model.find(3, 1)->reward, -1000.0);
  EXPECT_EQ(model.find(3, 2), nullptr);
  EXPECT_EQ(model.find(4, 1), nullptr);
}

}  // namespace
}  // namespace crux
