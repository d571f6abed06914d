#include "climbing/climbing_mdp.hpp"

#include <gtest/gtest.h>

#include "common/checkpoint_stream.hpp"

#include <map>

#include "common/input_error.hpp"

#include "body/urdf_loader.hpp"
#include "common/random.hpp"
#include "support/jug_ladder.hpp"
#include "support/kdl_reference.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

struct Fixture {
  const BodyModel& model = testing::human_model();
  Wall wall = generate_random_wall(1);
  ClimbingParameters parameters;
};

TEST(ClimbingMdp, StartsInTheStartConfigurationWithTheRightHandFree) {
  Fixture f;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  EXPECT_EQ(mdp.configuration().free_limb(), Limb::RightHand);
  EXPECT_EQ(mdp.configuration().holds[1], f.wall.start[1]);
  EXPECT_FALSE(mdp.candidates().empty());
  for (const ActionCandidate& c : mdp.candidates()) {
    EXPECT_TRUE(passes_filter(f.wall, mdp.configuration().with(Limb::RightHand, c.wall), f.parameters.filter));
  }
}

// Issue 26: every right-handed tool showed the climber mirrored. On 5 walls, the start
// posture and the postures of 30 random moves each, read back by KDL from the URDF,
// stand on the climber's side of the wall (x < 0) with the trunk facing it (+x), and the
// left hand and foot on the body's left (up x forward).
TEST(ClimbingMdp, SolvedPosturesFaceTheWallWithTheirLeftLimbsOnTheirLeft) {
  const BodyModel& model = testing::human_model();
  testing::KdlReference kdl(default_body_model_path(), model);
  constexpr std::uint64_t kSeed = 26;
  Random random(kSeed);
  int postures = 0;
  for (std::uint64_t wall_seed = 1; wall_seed <= 5; ++wall_seed) {
    const Wall wall = generate_random_wall(wall_seed);
    ClimbingMdp mdp(model, wall, ClimbingParameters{});
    for (int move = 0; move <= 30; ++move) {
      if (move > 0) {
        const auto candidates = mdp.candidates();
        if (candidates.empty()) break;
        const StepOutcome outcome = mdp.step(candidates[random.below(candidates.size())].wall);
        if (!outcome.reached) continue;
        if (outcome.finished) break;
      }
      const Posture& g = mdp.posture();
      const testing::BodySides sides = kdl.body_sides(g);
      ASSERT_LT(g[0], 0.0) << "seed " << kSeed << " wall " << wall_seed << " move " << move;
      ASSERT_GT(sides.forward.x(), 0.5) << "seed " << kSeed << " wall " << wall_seed << " move " << move;
      ASSERT_GT(sides.hands, 0.0) << "seed " << kSeed << " wall " << wall_seed << " move " << move;
      ASSERT_GT(sides.feet, 0.0) << "seed " << kSeed << " wall " << wall_seed << " move " << move;
      ++postures;
    }
  }
  EXPECT_GT(postures, 50);
}

// The MDP offers exactly its candidates, and refuses to step to any other hold (one the
// filter ruled out, one that is not on the wall) without changing its state.
TEST(ClimbingMdp, OffersItsCandidatesAndStepsToNoOtherHold) {
  Fixture f;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  int offered = 0;
  for (ActionCode hold = 0; hold < mdp.wall_action_count(); ++hold) {
    bool candidate = false;
    for (const ActionCandidate& c : mdp.candidates()) candidate = candidate || c.wall == hold;
    EXPECT_EQ(mdp.offers(hold), candidate) << "hold index " << hold;
    offered += candidate ? 1 : 0;
  }
  EXPECT_EQ(offered, static_cast<int>(mdp.candidates().size()));
  ASSERT_LT(offered, mdp.wall_action_count()) << "the start offers every hold: no refused step to test";
  ActionCode refused = 0;
  while (mdp.offers(refused)) ++refused;
  const StateCouple before = mdp.state();
  EXPECT_THROW(mdp.step(refused), std::invalid_argument);
  EXPECT_THROW(mdp.step(-1), std::invalid_argument);
  EXPECT_THROW(mdp.step(mdp.wall_action_count()), std::invalid_argument);
  EXPECT_EQ(mdp.state().wall, before.wall);
  EXPECT_EQ(mdp.state().grid, before.grid);
}

TEST(ClimbingMdp, UnreachableStaysWithMinus1000AndReachableRotatesTheFreeLimb) {
  Fixture f;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  const StateCouple before = mdp.state();
  int reachable = -1, unreachable = -1;
  for (const ActionCandidate& c : mdp.candidates()) {
    ClimbingMdp probe(f.model, f.wall, f.parameters);
    const StepOutcome o = probe.step(c.wall);
    if (o.reached && !o.finished && reachable < 0) reachable = c.wall;
    if (!o.reached && unreachable < 0) unreachable = c.wall;
  }
  ASSERT_GE(reachable, 0);
  ASSERT_GE(unreachable, 0);
  const StepOutcome failed = mdp.step(unreachable);
  EXPECT_EQ(failed.reward, -1000.0);
  EXPECT_EQ(failed.root_rise_m, 0.0);
  EXPECT_EQ(mdp.state().wall, before.wall);
  EXPECT_EQ(mdp.state().grid, before.grid);
  const Posture posture_before = mdp.posture();
  const StepOutcome moved = mdp.step(reachable);
  EXPECT_EQ(moved.reward, -1.0);
  EXPECT_EQ(mdp.configuration().free_limb(), Limb::LeftHand);
  EXPECT_EQ(mdp.configuration().holds[0], reachable);
  EXPECT_DOUBLE_EQ(moved.root_rise_m, mdp.posture()[2] - posture_before[2]);
}

// Under the static model a state can offer no reachable hold: on random wall 7, once the
// right hand takes hold 14 and the left hand hold 20, every stance of the right foot
// holds on four holds but none on the three left when the left foot lets go next (the
// foot lies outside the hands' span: docs/PHYSICS.md). The climber tries each, and the
// last failure is a fall: the MDP is back at the start. No earlier failure falls.
TEST(ClimbingMdp, UnderTheStaticModelADeadEndIsAFallBackToTheStart) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(7);
  ClimbingParameters parameters;
  parameters.physics.model = PhysicsModel::Static;
  parameters.reachability.ik.wall = WallRule::Avoid;
  ClimbingMdp mdp(model, wall, parameters);
  ASSERT_TRUE(mdp.step(wall.index_of(14)).reached);
  ASSERT_TRUE(mdp.step(wall.index_of(20)).reached);
  ASSERT_EQ(mdp.configuration().free_limb(), Limb::RightFoot);
  const HoldConfiguration dead_end = mdp.configuration();
  std::vector<ActionCode> holds;
  for (const ActionCandidate& c : mdp.candidates()) holds.push_back(c.wall);
  ASSERT_GT(holds.size(), 3u);
  for (std::size_t i = 0; i < holds.size(); ++i) {
    const StepOutcome outcome = mdp.step(holds[i]);
    ASSERT_FALSE(outcome.reached) << "hold " << wall.holds[holds[i]].id;
    EXPECT_EQ(outcome.reward, -1000.0);
    EXPECT_EQ(outcome.fell, i + 1 == holds.size()) << "hold " << wall.holds[holds[i]].id;
    if (!outcome.fell) {
      EXPECT_EQ(mdp.configuration().holds, dead_end.holds);
    }
  }
  EXPECT_EQ(mdp.configuration().holds, start_configuration(wall).with(Limb::RightHand, kFree).holds);
  EXPECT_EQ(mdp.posture(), mdp.start_posture());
}

// Under the kinematic model the hold just left is always reachable again (its
// 4-configuration was reached), so no state is a dead end: 3000 random moves never fall.
TEST(ClimbingMdp, TheKinematicModelNeverFalls) {
  Fixture f;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  Random pick(20261126);
  int failures = 0;
  for (int step = 0; step < 3000; ++step) {
    const auto candidates = mdp.candidates();
    const StepOutcome outcome = mdp.step(candidates[pick.below(candidates.size())].wall);
    ASSERT_FALSE(outcome.fell) << "step " << step;
    failures += !outcome.reached;
  }
  EXPECT_GT(failures, 300) << "the walk met many unreachable holds";
}

TEST(ClimbingMdp, IkRunsOncePer4Configuration) {
  Fixture f;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  const ActionCode hold = mdp.candidates()[0].wall;
  mdp.step(hold);
  const std::size_t solves = mdp.reacher().solves();
  mdp.reset();
  mdp.step(hold);
  EXPECT_EQ(mdp.reacher().solves(), solves) << "the verdict comes from the cache, reached or not";
}

TEST(ClimbingMdp, PassingTheFinishingHeightEndsTheEpisodeAndResets) {
  Fixture f;
  f.wall.finish_height = -10.0;  // any reachable move finishes
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  const StateCouple start = mdp.state();
  for (const ActionCandidate& c : mdp.candidates()) {
    const StepOutcome o = mdp.step(c.wall);
    if (!o.reached) continue;
    EXPECT_TRUE(o.finished);
    EXPECT_EQ(o.reward, 200000.0);
    EXPECT_EQ(mdp.state().wall, start.wall);
    EXPECT_EQ(mdp.configuration().free_limb(), Limb::RightHand);
    return;
  }
  FAIL() << "no reachable move from the start";
}

TEST(ClimbingMdp, AWallWhoseStartIsUnreachableIsRefused) {
  Fixture f;
  RandomWallParameters far;
  far.tile_height = 1.5;  // hands 4.5 m above the feet
  const Wall wall = generate_random_wall(1, far);
  EXPECT_THROW(ClimbingMdp(f.model, wall, f.parameters), InputError);
}

TEST(ClimbingMdp, AStartWithoutPossibleActionsIsRefused) {
  Fixture f;
  f.parameters.filter.max_span_m = 0.2;  // no hold is near enough to any other
  EXPECT_THROW(ClimbingMdp(f.model, f.wall, f.parameters), InputError);
}

TEST(ClimbingMdp, EveryGridActionHasExactlyOneRepresentative) {
  Fixture f;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  std::map<ActionCode, int> representatives;
  for (const ActionCandidate& c : mdp.candidates()) {
    if (c.grid != kNoAction) {
      representatives[c.grid] += c.represents_grid_action;
    } else {
      EXPECT_FALSE(c.represents_grid_action);
    }
  }
  for (const auto& [tile, count] : representatives) EXPECT_EQ(count, 1) << "tile " << tile;
}

// An MDP restored mid-climb, under either model, offers the same state and candidates, answers the same
// steps with the same postures and rewards, and keeps the reacher's cache, its efforts
// (the static model's, in the rewards when reward.effort is set) and solve count.
TEST(ClimbingMdp, ARestoredMdpContinuesAsTheSavedOne) {
  Fixture f;
  for (const PhysicsModel physics : {PhysicsModel::Kinematic, PhysicsModel::Static}) {
    SCOPED_TRACE(enum_name(physics));
    f.parameters.physics.model = physics;
    f.parameters.reachability.ik.wall = physics == PhysicsModel::Static ? WallRule::Avoid : WallRule::Ignore;
    f.parameters.rewards.effort = physics == PhysicsModel::Static ? 2.0 : 0.0;
    ClimbingMdp mdp(f.model, f.wall, f.parameters);
    const auto first_reachable = [](ClimbingMdp& m) {
      for (const ActionCandidate& c : std::vector<ActionCandidate>(m.candidates().begin(), m.candidates().end())) {
        if (m.step(c.wall).reached) return;
      }
    };
    first_reachable(mdp);
    first_reachable(mdp);
    CheckpointWriter out;
    mdp.save_state(out);
    const std::string bytes = out.take();
    ClimbingMdp restored(f.model, f.wall, f.parameters);
    CheckpointReader in(bytes, "test");
    restored.load_state(in);
    EXPECT_TRUE(in.at_end());
    EXPECT_EQ(restored.state().wall, mdp.state().wall);
    EXPECT_EQ(restored.state().grid, mdp.state().grid);
    EXPECT_EQ(restored.posture(), mdp.posture());
    EXPECT_EQ(restored.left_hold(), mdp.left_hold());
    EXPECT_EQ(restored.reacher().solves(), mdp.reacher().solves());
    ASSERT_EQ(restored.candidates().size(), mdp.candidates().size());
    for (std::size_t i = 0; i < mdp.candidates().size(); ++i) {
      EXPECT_EQ(restored.candidates()[i].wall, mdp.candidates()[i].wall);
      EXPECT_EQ(restored.candidates()[i].grid, mdp.candidates()[i].grid);
      EXPECT_EQ(restored.candidates()[i].represents_grid_action, mdp.candidates()[i].represents_grid_action);
    }
    int reached = 0;
    for (int step = 0; step < 12 && !mdp.candidates().empty(); ++step) {
      const ActionCode hold = mdp.candidates()[static_cast<std::size_t>(step) % mdp.candidates().size()].wall;
      const StepOutcome a = mdp.step(hold), b = restored.step(hold);
      ASSERT_EQ(a.reached, b.reached) << "step " << step;
      EXPECT_EQ(a.reward, b.reward) << "step " << step;
      EXPECT_EQ(a.effort, b.effort) << "step " << step;
      if (a.reached) {
        EXPECT_EQ(*a.posture, *b.posture);
        ++reached;
      }
      EXPECT_EQ(restored.state().wall, mdp.state().wall);
    }
    EXPECT_GT(reached, 0);
    EXPECT_EQ(restored.reacher().solves(), mdp.reacher().solves());
  }
}

// reward.effort: a reached move's reward is reward.step minus the penalty times its
// stance's effort, the larger of the efforts on four holds and on the three left
// (StanceCheck::effort, recomputed here); unreached moves keep reward.unreachable.
TEST(ClimbingMdp, TheEffortPenaltyIsProportionalToTheStancesEffort) {
  Fixture f;
  f.parameters.physics.model = PhysicsModel::Static;
  f.parameters.reachability.ik.wall = WallRule::Avoid;
  f.parameters.rewards.effort = 3.0;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  StanceCheck check(f.model, f.wall, f.parameters.physics);
  Random pick(20261126);
  int reached = 0;
  for (int step = 0; step < 200 && reached < 10; ++step) {
    const auto candidates = mdp.candidates();
    const ActionCode hold = candidates[pick.below(candidates.size())].wall;
    const Limb free = mdp.configuration().free_limb();
    const HoldConfiguration complete = mdp.configuration().with(free, hold);
    const StepOutcome outcome = mdp.step(hold);
    if (!outcome.reached) {
      EXPECT_EQ(outcome.reward, -1000.0);
      EXPECT_EQ(outcome.effort, 0.0);
      continue;
    }
    ++reached;
    const double effort = check.effort(*outcome.posture, complete, next_free_limb(free));
    EXPECT_NEAR(outcome.effort, effort, 1e-9) << "step " << step;
    EXPECT_GT(outcome.effort, 0.0);
    EXPECT_LE(outcome.effort, 1.0);
    const double base = outcome.finished ? 200000.0 : -1.0;
    EXPECT_DOUBLE_EQ(outcome.reward, base - 3.0 * outcome.effort) << "step " << step;
  }
  EXPECT_EQ(reached, 10);
}

// The height shaping's potential by hand: reward.height times the mean height of the
// holds a 3-configuration holds.
double mean_held_height(const Wall& wall, const HoldConfiguration& configuration) {
  double sum = 0.0;
  int held = 0;
  for (const int hold : configuration.holds) {
    if (hold == kFree) continue;
    sum += wall.holds[hold].position.z();
    ++held;
  }
  return sum / held;
}

// reward.height (docs/MODEL.md, choice C29): along a random walk under the static model
// (with falls), every reward is the unshaped twin's plus gamma phi(s') - phi(s), phi
// being 10 times the mean height of the held holds: an unreachable move that stays
// pays (gamma - 1) phi(s), a fall lands at the start's potential.
TEST(ClimbingMdp, TheHeightShapingAddsGammaPhiOfTheNextStateMinusPhiOfTheState) {
  Fixture f;
  f.parameters.physics.model = PhysicsModel::Static;
  f.parameters.reachability.ik.wall = WallRule::Avoid;
  ClimbingMdp unshaped(f.model, f.wall, f.parameters);
  f.parameters.rewards.height = 10.0;
  ClimbingMdp shaped(f.model, f.wall, f.parameters, 0.8);
  Random pick(20261126);
  int stayed = 0, moved = 0;
  for (int step = 0; step < 300; ++step) {
    const auto candidates = shaped.candidates();
    const ActionCode hold = candidates[pick.below(candidates.size())].wall;
    const double phi = 10.0 * mean_held_height(f.wall, shaped.configuration());
    const StepOutcome a = unshaped.step(hold), b = shaped.step(hold);
    ASSERT_EQ(a.reached, b.reached) << "step " << step;
    ASSERT_FALSE(b.finished) << "the walk stays below the top";
    const double phi_next = 10.0 * mean_held_height(f.wall, shaped.configuration());
    EXPECT_NEAR(b.reward, a.reward + 0.8 * phi_next - phi, 1e-9) << "step " << step;
    (b.reached ? moved : stayed) += 1;
  }
  EXPECT_GT(moved, 30);
  EXPECT_GT(stayed, 30);
}

// The finishing move ends the climb: the terminal state's potential is 0, so the move
// earns reward.finish - phi(s), whatever the start's potential is.
TEST(ClimbingMdp, TheHeightShapingOfTheFinishingMoveLeavesNoPotential) {
  Fixture f;
  f.wall.finish_height = -10.0;  // any reachable move finishes
  f.parameters.rewards.height = 100.0;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  const double phi_start = 100.0 * mean_held_height(f.wall, mdp.configuration());
  ASSERT_GT(phi_start, 10.0);
  for (const ActionCandidate& c : mdp.candidates()) {
    const StepOutcome o = mdp.step(c.wall);
    if (!o.reached) continue;
    ASSERT_TRUE(o.finished);
    EXPECT_DOUBLE_EQ(o.reward, 200000.0 - phi_start);
    return;
  }
  FAIL() << "no reachable move from the start";
}

// Potential-based: with gamma = 1 the shaping terms of a walk add up to phi(last state) -
// phi(first), so no cycle of states can earn a shaping bonus (Ng, Harada and Russell 1999).
TEST(ClimbingMdp, WithoutDiscountTheHeightShapingOfAWalkTelescopes) {
  Fixture f;
  ClimbingMdp unshaped(f.model, f.wall, f.parameters);
  f.parameters.rewards.height = 50.0;
  ClimbingMdp shaped(f.model, f.wall, f.parameters, 1.0);
  const double phi_first = 50.0 * mean_held_height(f.wall, shaped.configuration());
  Random pick(7);
  double shaping_sum = 0.0;
  for (int step = 0; step < 200; ++step) {
    const auto candidates = shaped.candidates();
    const ActionCode hold = candidates[pick.below(candidates.size())].wall;
    const StepOutcome a = unshaped.step(hold), b = shaped.step(hold);
    ASSERT_FALSE(b.finished);
    shaping_sum += b.reward - a.reward;
  }
  const double phi_last = 50.0 * mean_held_height(f.wall, shaped.configuration());
  EXPECT_NE(phi_last, phi_first) << "the walk went somewhere";
  EXPECT_NEAR(shaping_sum, phi_last - phi_first, 1e-6);
}

// physics.fall_when_stuck (docs/MODEL.md, choice C31): random wall 1's four start holds
// and two more, 1.4 and 1.7 m to the left of the left hand's and 0.3 m above it, which
// only the left hand may take (the right hand would cross the arms, a foot would be above
// the hands) and which it cannot reach. The climber can only let go and grasp again the hold it holds, limb
// after limb; every other move fails. Stuck falls when the second far hold has failed
// too, not before; without the rule it never falls (the start's holds stay reachable).
TEST(ClimbingMdp, AClimberStuckInItsStanceFallsWhenTheRuleIsOn) {
  const BodyModel& model = testing::human_model();
  const Wall random_wall = generate_random_wall(1);
  Wall wall;
  wall.name = "stance with two far holds";
  for (const int index : random_wall.start) wall.holds.push_back(random_wall.holds[index]);
  const Eigen::Vector3d left_hand = random_wall.holds[random_wall.start[1]].position;
  wall.holds.push_back({1001, left_hand + Eigen::Vector3d(0.0, 1.4, 0.3), 0.04});
  wall.holds.push_back({1002, left_hand + Eigen::Vector3d(0.0, 1.7, 0.3), 0.04});
  wall.start = {0, 1, 2, 3};
  for (const bool rule : {false, true}) {
    SCOPED_TRACE(rule ? "fall_when_stuck" : "C27 only");
    ClimbingParameters parameters;
    parameters.fall_when_stuck = rule;
    ClimbingMdp mdp(model, wall, parameters);
    ASSERT_EQ(mdp.candidates().size(), 1u) << "the right hand may only take its own hold again";
    ASSERT_TRUE(mdp.step(0).reached);
    ASSERT_EQ(mdp.configuration().free_limb(), Limb::LeftHand);
    ASSERT_EQ(mdp.candidates().size(), 3u) << "its own hold and the two far ones";
    const StepOutcome first = mdp.step(4), second = mdp.step(5);
    EXPECT_FALSE(first.reached);
    EXPECT_FALSE(first.fell) << "the other far hold is not known yet";
    EXPECT_FALSE(second.reached);
    EXPECT_EQ(second.fell, rule);
    EXPECT_EQ(mdp.configuration().free_limb(), rule ? Limb::RightHand : Limb::LeftHand);
  }
}

// After a reached move, the flag marks exactly the candidate that puts the newly freed
// limb back on the hold it held before the move (taking it would complete the same
// 4-configuration as that move).
TEST(ClimbingMdp, OnlyTheReturnToTheHoldJustLeftIsMarkedAsSuch) {
  Fixture f;
  ClimbingMdp mdp(f.model, f.wall, f.parameters);
  int checked = 0;
  for (int step = 0; step < 200 && checked < 5; ++step) {
    const HoldConfiguration before = mdp.configuration();
    const int freed_hold = before.holds[static_cast<int>(next_free_limb(before.free_limb()))];
    // Walk by the candidates in turn.
    const auto candidates = mdp.candidates();
    const StepOutcome outcome = mdp.step(candidates[static_cast<std::size_t>(step) % candidates.size()].wall);
    if (!outcome.reached || outcome.finished) continue;
    int marked = 0;
    for (const ActionCandidate& c : mdp.candidates()) {
      EXPECT_EQ(c.returns_to_left_hold, c.wall == freed_hold) << "step " << step << ", hold " << c.wall;
      marked += c.returns_to_left_hold;
    }
    EXPECT_EQ(marked, 1) << "the way back passed the filter before the move";
    ++checked;
  }
  EXPECT_EQ(checked, 5);
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

// physics.model = dynamic: the static model's reached move is reached only when MuJoCo
// performs it, once per verdict (the repeat is the cache's), and the verdicts survive a
// checkpoint; a move MuJoCo cannot perform (no time left to settle) is not reached.
TEST(ClimbingMdp, UnderTheDynamicModelAMoveIsReachedWhenMujocoPerformsIt) {
  testing::JugLadder ladder;
  ladder.finish_after_one_move();
  ClimbingParameters parameters;
  parameters.reachability = ladder.reach;
  parameters.physics = ladder.physics;
  parameters.physics.model = PhysicsModel::Dynamic;
  constexpr int kJug = 4;
  ClimbingMdp mdp(testing::human_model(), ladder.wall, parameters);
  ASSERT_TRUE(mdp.simulates());
  ASSERT_TRUE(mdp.offers(kJug));
  EXPECT_TRUE(mdp.step(kJug).finished);
  EXPECT_TRUE(mdp.step(kJug).finished) << "the same move again, from the start";
  EXPECT_EQ(mdp.moves_simulated(), 1u);
  EXPECT_EQ(mdp.moves_performed(), 1u);
  CheckpointWriter out;
  mdp.save_state(out);
  const std::string bytes = out.take();
  ClimbingMdp restored(testing::human_model(), ladder.wall, parameters);
  CheckpointReader in(bytes, "test");
  restored.load_state(in);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(restored.moves_simulated(), 1u);

  parameters.perform.move.settle_time_s = 0.0;
  ClimbingMdp hurried(testing::human_model(), ladder.wall, parameters);
  const StepOutcome outcome = hurried.step(kJug);
  EXPECT_FALSE(outcome.reached);
  EXPECT_EQ(outcome.reward, parameters.rewards.unreachable);
  EXPECT_EQ(hurried.moves_simulated(), 1u);
  EXPECT_EQ(hurried.moves_performed(), 0u);
}

}  // namespace
}  // namespace crux
