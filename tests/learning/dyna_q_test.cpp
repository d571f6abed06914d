#include "learning/dyna_q.hpp"

#include <gtest/gtest.h>

#include "common/checkpoint_stream.hpp"

#include <algorithm>
#include <set>
#include <vector>

namespace crux {
namespace {

// Two states, two actions each, deterministic, continuing with a reset like the
// climbing MDP: in A, "stay" (-1, A) or "go" (-1, B); in B, "finish" (+10, back to A) or
// "back" (-1, A). With gamma = 0.9: V(A) = -1 + 0.9 V(B), V(B) = 10 + 0.9 V(A), so
// V(A) = 8 / 0.19 and V(B) = 10 + 0.9 V(A).
constexpr StateCode A = 0, B = 1;
const double kValueA = 8.0 / 0.19;
const double kValueB = 10.0 + 0.9 * kValueA;

Experience transition(StateCode s, ActionCode a) {
  if (s == A) return {A, A, a, a, -1.0, a == 0 ? A : B, a == 0 ? A : B};
  return {B, B, a, a, a == 0 ? 10.0 : -1.0, A, A};
}

TEST(DynaQ, PlanningConvergesToTheKnownOptimalValuesInBothTables) {
  constexpr std::uint64_t seed = 8;
  DynaQAgent agent(2, 2, DynaParameters{}, seed);
  const ActionCandidate both[2] = {{0, 0, true}, {1, 1, true}};
  agent.observe({A, A}, both);
  agent.observe({B, B}, both);
  for (int round = 0; round < 400; ++round) {
    for (const StateCode s : {A, B}) {
      for (const ActionCode a : {0, 1}) agent.learn(transition(s, a));
    }
  }
  for (const QTable* q : {&agent.q_wall(), &agent.q_grid()}) {
    EXPECT_NEAR(q->value(A, 1), kValueA, 1e-6) << "seed " << seed;
    EXPECT_NEAR(q->value(A, 0), -1.0 + 0.9 * kValueA, 1e-6);
    EXPECT_NEAR(q->value(B, 0), kValueB, 1e-6);
    EXPECT_NEAR(q->value(B, 1), -1.0 + 0.9 * kValueA, 1e-6);
  }
  EXPECT_EQ(agent.model().size(), 4u);
  EXPECT_EQ(agent.q_wall().visits(A, 1), 400u) << "planning does not count as taking an action";
}

TEST(DynaQ, OneRealStepPlusPlanningOnASingleExperience) {
  DynaParameters settings;
  settings.planning_steps = 3;
  DynaQAgent agent(2, 2, settings, 1);
  const ActionCandidate one[1] = {{0, 0, true}};
  agent.observe({A, A}, one);
  agent.observe({B, B}, one);
  agent.learn({A, A, 0, 0, -1.0, B, B});
  // Four updates of Q(A,0) with Q(B,.) = 0: q <- q + 0.1 (-1 - q), from 0.
  double q = 0.0;
  for (int i = 0; i < 4; ++i) q += 0.1 * (-1.0 - q);
  EXPECT_DOUBLE_EQ(agent.q_wall().value(A, 0), q);
  EXPECT_DOUBLE_EQ(agent.q_grid().value(A, 0), q);
}

TEST(DynaQ, AGridActionOutsideTheGridUpdatesOnlyTheWallTable) {
  DynaParameters settings;
  settings.planning_steps = 0;
  DynaQAgent agent(2, 2, settings, 1);
  agent.learn({A, A, 1, kNoAction, -1000.0, A, A});
  EXPECT_DOUBLE_EQ(agent.q_wall().value(A, 1), -100.0);
  EXPECT_EQ(agent.q_grid().state_count(), 0u);
}

// A table transferred to the agent: in agent-space state A, action 1 taken at 30.
QTable transferred_table() {
  QTable q(2);
  q.set_value(A, 1, 30.0);
  q.add_visit(A, 1);
  return q;
}

// An agent restored from a checkpoint continues as the saved one does: the same choices
// and the same tables after more steps, with either planner.
TEST(DynaQ, ARestoredAgentContinuesAsTheSavedOne) {
  for (const TransferMode mode : {TransferMode::Paper, TransferMode::Informed, TransferMode::Prior,
                                  TransferMode::Seeded, TransferMode::Shaping, TransferMode::Ordered})
    for (const Planner planner : {Planner::Uniform, Planner::Prioritized}) {
      SCOPED_TRACE(enum_name(mode));
      DynaParameters settings;
      settings.planner = planner;
      settings.epsilon = 0.3;
      settings.transfer = mode;
      // A transferred table, given again to the restored agent as a run's resume does.
      DynaQAgent agent(2, 2, settings, 11);
      agent.set_q_grid(transferred_table());
      const ActionCandidate both[2] = {{0, 0, true}, {1, 1, true}};
      agent.observe({A, A}, both);
      agent.observe({B, B}, both);
      StateCode s = A;
      const auto step = [&](DynaQAgent& a, StateCode& state) {
        const ActionChoice choice = a.choose({state, state}, both);
        const Experience e = transition(state, static_cast<ActionCode>(choice.candidate));
        a.learn(e);
        state = e.next_wall_state;
        return choice.candidate;
      };
      for (int i = 0; i < 30; ++i) step(agent, s);
      CheckpointWriter out;
      agent.save_state(out);
      const std::string bytes = out.take();
      DynaQAgent restored(2, 2, settings, 11);
      restored.set_q_grid(transferred_table());
      CheckpointReader in(bytes, "test");
      restored.load_state(in);
      EXPECT_TRUE(in.at_end());
      StateCode r = s;
      for (int i = 0; i < 60; ++i) ASSERT_EQ(step(restored, r), step(agent, s)) << "step " << i;
      EXPECT_EQ(restored.planning_updates(), agent.planning_updates());
      for (const StateCode state : {A, B}) {
        for (const ActionCode action : {0, 1}) {
          EXPECT_EQ(restored.q_wall().value(state, action), agent.q_wall().value(state, action));
          EXPECT_EQ(restored.q_grid().visits(state, action), agent.q_grid().visits(state, action));
        }
      }
    }
}

TEST(DynaQ, SeededModeStartsANewStatesUntriedPairsAtTheTransferredValues) {
  DynaParameters settings;
  settings.transfer = TransferMode::Seeded;
  DynaQAgent agent(2, 2, settings, 3);
  agent.set_q_grid(transferred_table());
  const ActionCandidate both[2] = {{0, 0, true}, {1, 1, true}};
  agent.observe({A, A}, both);
  EXPECT_EQ(agent.q_wall().value(A, 1), 30.0);
  EXPECT_EQ(agent.q_wall().value(A, 0), 0.0) << "an untaken agent-space pair seeds nothing";
  EXPECT_EQ(agent.q_wall().visits(A, 1), 0u) << "a seed is not an experience";
  const ActionChoice c = agent.choose({A, A}, both);
  EXPECT_EQ(c.candidate, 1u);
  EXPECT_EQ(c.regime, Regime::WGreedy) << "the seeded value is chosen although never taken";
  agent.learn({A, A, 1, 1, -1000.0, A, A});
  agent.observe({A, A}, both);
  // One real update and 50 planning updates of Q(A,1), each from the latest value: a
  // state seen again is not seeded again.
  double q = 30.0;
  for (int i = 0; i < 51; ++i) q += 0.1 * (-1000.0 + 0.9 * std::max(q, 0.0) - q);
  EXPECT_NEAR(agent.q_wall().value(A, 1), q, 1e-9);
}

// The ordered mode seeds nothing: in A the untried tie goes to action 1, taken at 30 in
// the transferred table, whatever the seed; once action 1 has failed, the untried action
// 0 comes first; in B, which the table has never seen, the tie stays random.
TEST(DynaQ, OrderedModeBreaksQWallTiesByTheTransferredTable) {
  DynaParameters settings;
  settings.transfer = TransferMode::Ordered;
  settings.epsilon = 0.0;
  DynaQAgent agent(2, 2, settings, 3);
  agent.set_q_grid(transferred_table());
  const ActionCandidate both[2] = {{0, 0, true}, {1, 1, true}};
  agent.observe({A, A}, both);
  EXPECT_EQ(agent.q_wall().value(A, 1), 0.0) << "no seed";
  for (std::uint64_t i = 0; i < 20; ++i) {
    DynaQAgent fresh(2, 2, settings, i);
    fresh.set_q_grid(transferred_table());
    fresh.observe({A, A}, both);
    const ActionChoice c = fresh.choose({A, A}, both);
    EXPECT_EQ(c.candidate, 1u) << "seed " << i;
    EXPECT_EQ(c.regime, Regime::WGreedy);
  }
  agent.learn({A, A, 1, 1, -1000.0, A, A});
  agent.observe({A, A}, both);
  EXPECT_LT(agent.q_grid().value(A, 1), 0.0);
  EXPECT_EQ(agent.choose({A, A}, both).candidate, 0u) << "the untried 0 beats the failed move";
  // In B, both moves untried and Q_grid's B row empty: the transferred table does not rank them.
  agent.observe({B, B}, both);
  std::set<std::size_t> seen;
  for (int i = 0; i < 40; ++i) {
    DynaQAgent fresh(2, 2, settings, static_cast<std::uint64_t>(i));
    fresh.set_q_grid(transferred_table());
    fresh.observe({B, B}, both);
    seen.insert(fresh.choose({B, B}, both).candidate);
  }
  EXPECT_EQ(seen.size(), 2u) << "random among the unranked ties";
}

TEST(DynaQ, ShapingModeAddsGammaPhiNextMinusPhiToQWallRewardsOnly) {
  DynaParameters settings;
  settings.transfer = TransferMode::Shaping;
  settings.planning_steps = 0;
  DynaQAgent agent(2, 2, settings, 3);
  agent.set_q_grid(transferred_table());  // phi(A) = 30, phi(B) = 0
  const ActionCandidate both[2] = {{0, 0, true}, {1, 1, true}};
  agent.observe({A, A}, both);
  agent.observe({B, B}, both);
  agent.learn({A, A, 0, 0, -1.0, B, B});
  EXPECT_DOUBLE_EQ(agent.q_wall().value(A, 0), 0.1 * (-1.0 + 0.9 * 0.0 - 30.0));
  EXPECT_DOUBLE_EQ(agent.q_grid().value(A, 0), 0.1 * (-1.0 + 0.9 * 0.0)) << "Q_grid learns the raw reward";
  agent.learn({B, B, 1, 1, -1.0, A, A});
  EXPECT_DOUBLE_EQ(agent.q_wall().value(B, 1), 0.1 * (-1.0 + 0.9 * 30.0 - 0.0 + 0.9 * 0.0));
}

TEST(DynaQ, ShapingAlsoShapesThePlanningUpdates) {
  DynaParameters settings;
  settings.transfer = TransferMode::Shaping;
  settings.planning_steps = 3;
  DynaQAgent agent(2, 2, settings, 3);
  agent.set_q_grid(transferred_table());  // phi(A) = 30, phi(B) = 0
  const ActionCandidate one[1] = {{0, 0, true}};
  agent.observe({A, A}, one);
  agent.observe({B, B}, one);
  agent.learn({A, A, 0, 0, -1.0, B, B});
  // The one experience, updated four times (real + 3 replays) with r + 0.9 phi(B) - phi(A).
  double q = 0.0;
  for (int i = 0; i < 4; ++i) q += 0.1 * (-1.0 - 30.0 - q);
  EXPECT_DOUBLE_EQ(agent.q_wall().value(A, 0), q);
}

TEST(DynaQ, InformedModeKeepsGGreedyOffAPairThatFailedHere) {
  DynaParameters settings;
  settings.transfer = TransferMode::Informed;
  settings.epsilon = 0.0;
  settings.planning_steps = 0;
  QTable grid(2);  // tile 1 is the best agent-space action, tile 0 second
  grid.set_value(A, 1, 5000.0);
  grid.add_visit(A, 1);
  grid.set_value(A, 0, 10.0);
  grid.add_visit(A, 0);
  DynaQAgent informed(2, 2, settings, 5);
  settings.transfer = TransferMode::Paper;
  DynaQAgent paper(2, 2, settings, 5);
  const ActionCandidate both[2] = {{0, 0, true}, {1, 1, true}};
  for (DynaQAgent* agent : {&informed, &paper}) {
    agent->set_q_grid(grid);
    agent->observe({A, A}, both);
    agent->learn({A, A, 1, 1, -1000.0, A, A});  // action 1 failed: a self-loop
  }
  // Tile 1 keeps the best Q_grid value, 5000 + 0.1 (-1000 + 0.9 * 5000 - 5000) = 4850,
  // and Q_wall's best action (0, never taken) sends the choice to g-greedy.
  EXPECT_DOUBLE_EQ(paper.q_grid().value(A, 1), 4850.0);
  const ActionChoice by_paper = paper.choose({A, A}, both);
  EXPECT_EQ(by_paper.regime, Regime::GGreedy);
  EXPECT_EQ(by_paper.candidate, 1u) << "Algorithm 3 retries the failed move";
  const ActionChoice by_informed = informed.choose({A, A}, both);
  EXPECT_EQ(by_informed.regime, Regime::GGreedy);
  EXPECT_EQ(by_informed.candidate, 0u) << "the failed pair is passed over";
  const ActionCandidate returning[2] = {{0, 0, true, true}, {1, 1, true}};
  EXPECT_EQ(informed.choose({A, A}, returning).regime, Regime::Random)
      << "nor a return to the hold just left: nothing is left for g-greedy";
}

}  // namespace
}  // namespace crux
