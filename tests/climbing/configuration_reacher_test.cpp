#include "climbing/configuration_reacher.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"
#include "common/random.hpp"
#include "configurations/geometric_filter.hpp"
#include "configurations/possible_actions.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kSeed = 20261124;

// The static model's reachability: the body kept out of the wall, as finalize_config sets it.
ReachabilityParameters kept_out_of_the_wall() {
  ReachabilityParameters parameters;
  parameters.ik.wall = WallRule::Avoid;
  return parameters;
}

TEST(ConfigurationReacher, TheStaticModelRefusesAWallRuleOtherThanAvoidInsteadOfChangingIt) {
  const Wall wall = generate_random_wall(3);
  for (const WallRule rule : {WallRule::Ignore, WallRule::Reject}) {
    ReachabilityParameters parameters;
    parameters.ik.wall = rule;
    EXPECT_THROW(
        ConfigurationReacher(testing::human_model(), wall, parameters, PhysicsParameters{PhysicsModel::Static}),
        std::invalid_argument)
        << enum_name(rule);
    EXPECT_NO_THROW(ConfigurationReacher(testing::human_model(), wall, parameters)) << "the kinematic model takes any";
  }
}

// crux wall's start check (solve_start) and the learning's (reach_start) are one test:
// the same verdict and the same posture, for any settings.
TEST(ConfigurationReacher, StartIsSolveStartAnsweredThroughTheCache) {
  const BodyModel& model = testing::human_model();
  ReachabilityParameters strict;
  strict.ik.tolerances.grasp_radius = 0.001;
  strict.ik.fast.max_iterations = 3;
  ReachabilityParameters paper;
  paper.ik.solver = IkSolverKind::Paper;
  int reached = 0, refused = 0;
  for (const ReachabilityParameters& parameters : {ReachabilityParameters{}, strict, paper}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const Wall wall = generate_random_wall(seed);
      BodyData data(model);
      const IkResult direct = solve_start(model, data, wall, parameters);
      ConfigurationReacher reacher(model, wall, parameters);
      const Posture* start = reacher.reach_start();
      ASSERT_EQ(start != nullptr, direct.reached) << "seed " << seed;
      if (start != nullptr) {
        EXPECT_EQ(*start, direct.posture) << "seed " << seed;
        EXPECT_EQ(&reacher.require_start("wall.json"), start) << "seed " << seed;
        ++reached;
      } else {
        try {
          reacher.require_start("wall.json");
          ADD_FAILURE() << "seed " << seed << ": an unreachable start is an input error";
        } catch (const InputError& error) {
          EXPECT_STREQ(error.what(),
                       "wall.json: the start configuration is not reachable: the IK finds no posture grasping its "
                       "four holds")
              << "seed " << seed;
        }
        ++refused;
      }
      reacher.reach_start();
      EXPECT_EQ(reacher.solves(), 1u) << "the second start check is a cache hit";
    }
  }
  EXPECT_GT(reached, 0);
  EXPECT_GT(refused, 0) << "the strict settings refuse some starts";
}

// The reach envelope only saves time: on 4-configurations of a wall that move one
// limb of the start to any hold, or put every limb on any hold, every verdict and
// posture equals a solve that iterates whatever the target.
// Under the static model a start can fail two ways, and the error says which: a wall whose
// start the IK reaches with the body out of the wall but whose stance does not hold, and
// one whose start the IK does not reach at all.
TEST(ConfigurationReacher, AnUnreachableStartSaysWhichTestFailed) {
  const BodyModel& model = testing::human_model();
  RandomWallParameters overhang;
  overhang.incline_deg = 40.0;
  const auto error_of = [&](ConfigurationReacher& reacher) {
    try {
      reacher.require_start("wall.json");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  bool stance_failed = false, ik_failed = false;
  for (std::uint64_t seed = 1; seed <= 40 && !(stance_failed && ik_failed); ++seed) {
    const Wall wall = generate_random_wall(seed, overhang);
    BodyData data(model);
    const bool ik_reaches = solve_start(model, data, wall, kept_out_of_the_wall()).reached;
    ConfigurationReacher reacher(model, wall, kept_out_of_the_wall(), PhysicsParameters{PhysicsModel::Static});
    const std::string error = error_of(reacher);
    if (error.empty()) continue;
    if (ik_reaches) {
      stance_failed = true;
      EXPECT_EQ(error,
                "wall.json: the IK reaches the start configuration, but its stance does not hold still under the "
                "static model (on its four holds and on the three left when the right hand lets go)")
          << "seed " << seed;
    } else {
      ik_failed = true;
      EXPECT_EQ(error,
                "wall.json: the start configuration is not reachable: the IK finds no posture grasping its four "
                "holds with the body kept out of the wall (ik.wall = avoid)")
          << "seed " << seed;
    }
  }
  EXPECT_TRUE(stance_failed) << "a 40-degree wall among the first 40 whose start reaches but does not hold";
  EXPECT_TRUE(ik_failed) << "a 40-degree wall among the first 40 whose start the IK does not reach";
}

TEST(ConfigurationReacher, ReachEnvelopeChangesNoVerdict) {
  const BodyModel& model = testing::human_model();
  ReachabilityParameters paper;
  paper.ik.solver = IkSolverKind::Paper;
  for (const auto& [parameters, samples] : {std::pair{ReachabilityParameters{}, 300}, std::pair{paper, 60}}) {
    const Wall wall = generate_random_wall(kSeed);
    ConfigurationReacher reacher(model, wall, parameters);
    const Posture from = *reacher.reach_start();
    IkParameters iterating = parameters.ik;
    iterating.rule_out_beyond_reach = false;
    BodyData data(model);
    Random random(kSeed);
    int reached = 0, ruled_out = 0;
    for (int sample = 0; sample < samples; ++sample) {
      const auto any_hold = [&] {
        return static_cast<int>(random.below(static_cast<std::uint64_t>(wall.hold_count())));
      };
      HoldConfiguration complete = start_configuration(wall);
      if (sample % 3 == 0) {
        for (int& hold : complete.holds) hold = any_hold();
      } else {
        complete.holds[random.below(kLimbCount)] = any_hold();
      }
      const ReachTarget target = reach_target(model, wall, complete, parameters.root);
      const IkResult direct = solve_ik(model, data, from, target, iterating);
      const Posture* posture = reacher.reach(from, complete, Limb::RightHand);
      ASSERT_EQ(posture != nullptr, direct.reached) << "seed " << kSeed << " sample " << sample;
      if (posture != nullptr) {
        EXPECT_EQ(*posture, direct.posture) << "seed " << kSeed << " sample " << sample;
      }
      reached += direct.reached;
      ruled_out += beyond_reach(model.reach_envelope, target, parameters.ik.tolerances);
    }
    EXPECT_GT(reached, samples / 20);
    EXPECT_GT(ruled_out, samples / 2) << "most holds are out of reach";
  }
}

// Under the static model a verdict depends on the limb that lets go next (the stance
// must hold on the three holds left), so the cache keeps one per limb; the body is kept
// out of the wall (ik.wall = avoid). The kinematic model keeps one verdict per
// configuration. Random wall 7, after the right hand takes hold 14 and the left hand
// hold 20: the right foot on hold 2 holds on four holds but not on three once the left
// foot lets go (ClimbingMdp.UnderTheStaticModelADeadEndIsAFallBackToTheStart).
TEST(ConfigurationReacher, StaticVerdictsAreKeptPerLimbThatLetsGoNext) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(7);
  const HoldConfiguration complete = start_configuration(wall)
                                         .with(Limb::RightHand, wall.index_of(14))
                                         .with(Limb::LeftHand, wall.index_of(20))
                                         .with(Limb::RightFoot, wall.index_of(2));
  ConfigurationReacher kinematic(model, wall, ReachabilityParameters{});  // ik.wall = ignore, the paper's
  ConfigurationReacher stance(model, wall, kept_out_of_the_wall(), PhysicsParameters{PhysicsModel::Static});
  const Posture& from = kinematic.require_start(wall.name);
  ASSERT_NE(kinematic.reach(from, complete, Limb::LeftFoot), nullptr);
  EXPECT_EQ(stance.reach(from, complete, Limb::LeftFoot), nullptr);
  EXPECT_TRUE(stance.known_unreachable(complete, Limb::LeftFoot));
  EXPECT_FALSE(stance.known_unreachable(complete, Limb::RightHand)) << "another limb's verdict is not known yet";
  const std::size_t solves = stance.solves();
  stance.reach(from, complete, Limb::RightHand);
  EXPECT_EQ(stance.solves(), solves + 1) << "a new verdict for another next limb";
  stance.reach(from, complete, Limb::LeftFoot);
  EXPECT_EQ(stance.solves(), solves + 1) << "the cached verdict";
  EXPECT_FALSE(kinematic.known_unreachable(complete, Limb::RightHand));

  ConfigurationReacher avoiding(model, wall, kept_out_of_the_wall());
  const Posture* avoided = avoiding.reach(from, complete, Limb::RightHand);
  const Posture* held = stance.reach(from, complete, Limb::RightHand);
  ASSERT_EQ(avoided != nullptr, held != nullptr || !avoiding.known_unreachable(complete, Limb::RightHand));
  if (held != nullptr) {
    EXPECT_EQ(*held, *avoided) << "the static model solves the IK as ik.wall = avoid does";
  }
}

// The exact planner asks only whether a stance holds (StanceQuestion::HoldsStill): on
// wall 3 under the static model, every move from the first states of a breadth-first
// search gets the verdict and posture of a reacher that computes efforts, and the first
// has no efforts to give or checkpoint.
TEST(ConfigurationReacher, AskingOnlyWhetherStancesHoldGivesTheSameVerdicts) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(3);
  const PhysicsParameters physics{PhysicsModel::Static};
  ConfigurationReacher efforts(model, wall, kept_out_of_the_wall(), physics);
  ConfigurationReacher verdicts(model, wall, kept_out_of_the_wall(), physics, StanceQuestion::HoldsStill);
  ASSERT_NE(verdicts.reach_start(), nullptr);
  std::vector<std::pair<HoldConfiguration, const Posture*>> states{
      {start_configuration(wall).with(Limb::RightHand, kFree), efforts.reach_start()}};
  ASSERT_NE(states[0].second, nullptr);
  std::vector<int> possible(wall.hold_count());
  int reached = 0, refused = 0;
  for (std::size_t n = 0; n < states.size() && n < 12; ++n) {
    const auto [configuration, from] = states[n];
    const Limb free = configuration.free_limb(), next = next_free_limb(free);
    const int count = possible_actions(wall, configuration, FilterParameters{}, possible);
    for (int i = 0; i < count; ++i) {
      const HoldConfiguration complete = configuration.with(free, possible[i]);
      const Posture* with_effort = efforts.reach(*from, complete, next);
      const Posture* verdict = verdicts.reach(*from, complete, next);
      ASSERT_EQ(with_effort != nullptr, verdict != nullptr) << "state " << n << ", hold " << possible[i];
      if (with_effort == nullptr) {
        ++refused;
        continue;
      }
      ++reached;
      EXPECT_EQ(*with_effort, *verdict) << "state " << n << ", hold " << possible[i];
      EXPECT_LE(efforts.effort(complete, next), 1.0);
      EXPECT_THROW(verdicts.effort(complete, next), std::logic_error);
      states.emplace_back(complete.with(next, kFree), with_effort);
    }
  }
  EXPECT_GT(reached, 20);
  EXPECT_GT(refused, 20);
  CheckpointWriter out;
  EXPECT_THROW(verdicts.save_state(out), std::logic_error);
}

// ik.guess = standing (docs/MODEL.md, choice C30): on random wall 1 under the static
// model, every move of one limb of the start to another hold gets the same verdict, and
// when reached the same posture, whichever posture the climber held before (the start's,
// or a first reached move's); with the paper's guess some postures differ.
TEST(ConfigurationReacher, WithTheStandingGuessAVerdictDoesNotDependOnThePostureBefore) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(1);
  const PhysicsParameters physics{PhysicsModel::Static};
  const HoldConfiguration start = start_configuration(wall);
  const auto moves = [&](ConfigurationReacher& probe, const Posture& start_posture) {
    std::vector<HoldConfiguration> found;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      for (int hold = 0; hold < wall.hold_count(); ++hold) {
        const HoldConfiguration complete = start.with(static_cast<Limb>(limb), hold);
        if (std::find(start.holds.begin(), start.holds.end(), hold) != start.holds.end() ||
            !passes_filter(wall, complete, FilterParameters{}))
          continue;
        if (probe.reach(start_posture, complete, Limb::RightHand) != nullptr) found.push_back(complete);
      }
    }
    return found;
  };
  for (const IkGuess guess : {IkGuess::Standing, IkGuess::Previous}) {
    SCOPED_TRACE(enum_name(guess));
    ReachabilityParameters parameters = kept_out_of_the_wall();
    parameters.guess = guess;
    ConfigurationReacher finder(model, wall, parameters, physics);
    const Posture start_posture = finder.require_start(wall.name);
    const std::vector<HoldConfiguration> reached = moves(finder, start_posture);
    ASSERT_GT(reached.size(), 3u);
    const Posture other = *finder.reach(start_posture, reached.front(), Limb::RightHand);
    ConfigurationReacher from_start(model, wall, parameters, physics), from_other(model, wall, parameters, physics);
    int compared = 0, differing = 0;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      for (int hold = 0; hold < wall.hold_count(); ++hold) {
        const HoldConfiguration complete = start.with(static_cast<Limb>(limb), hold);
        if (std::find(start.holds.begin(), start.holds.end(), hold) != start.holds.end() ||
            !passes_filter(wall, complete, FilterParameters{}))
          continue;
        const Posture* a = from_start.reach(start_posture, complete, Limb::RightHand);
        const Posture* b = from_other.reach(other, complete, Limb::RightHand);
        ++compared;
        if (guess == IkGuess::Standing) {
          ASSERT_EQ(a != nullptr, b != nullptr) << "limb " << limb << ", hold " << hold;
          if (a != nullptr) {
            EXPECT_EQ(*a, *b) << "limb " << limb << ", hold " << hold;
          }
        }
        differing += (a == nullptr) != (b == nullptr) || (a != nullptr && *a != *b);
      }
    }
    EXPECT_GT(compared, 10);
    if (guess == IkGuess::Previous) {
      EXPECT_GT(differing, 0) << "the paper's guess depends on the posture before";
    }
  }
}

}  // namespace
}  // namespace crux
