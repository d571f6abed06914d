#include "climbing/stance_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "body/urdf_loader.hpp"
#include "climbing/climbing_mdp.hpp"
#include "common/input_error.hpp"
#include "support/test_models.hpp"
#include "wall/incline.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct ReachedStance {
  Posture posture;
  HoldConfiguration complete;
  Limb next;
};

// Stances a kinematic climber reaches with its body kept out of the wall: a random walk's.
std::vector<ReachedStance> reached_stances(const Wall& wall, int steps) {
  ClimbingParameters parameters;
  parameters.reachability.ik.wall = WallRule::Avoid;
  ClimbingMdp mdp(testing::human_model(), wall, parameters);
  std::mt19937_64 pick(20261126);
  std::vector<ReachedStance> stances;
  for (int step = 0; step < steps; ++step) {
    const auto candidates = mdp.candidates();
    const ActionCode hold = candidates[pick() % candidates.size()].wall;
    const Limb free = mdp.configuration().free_limb();
    const HoldConfiguration complete = mdp.configuration().with(free, hold);
    const StepOutcome outcome = mdp.step(hold);
    if (outcome.reached) stances.push_back({*outcome.posture, complete, next_free_limb(free)});
  }
  return stances;
}

// Random wall `seed` leaned `incline` degrees, and the stances of a random walk on it.
struct InclinedWalk {
  Wall wall;
  std::vector<ReachedStance> stances;
};
InclinedWalk inclined_walk(std::uint64_t seed, double incline, int steps) {
  InclinedWalk walk{generate_random_wall(seed), {}};
  walk.wall.incline_deg = incline;
  walk.stances = reached_stances(walk.wall, steps);
  return walk;
}

// What the check must build, written out: a hand hooks the incut lip of a jug (up and
// support_angle into the wall, +x), bounded by the grip; a foot stands on the hold's top
// (+z), unbounded; a hold's own support direction replaces either.
std::vector<PointContact> expected_contacts(const Wall& wall, const HoldConfiguration& configuration,
                                            const PhysicsParameters& physics) {
  const double angle = physics.support_angle_deg * M_PI / 180.0;
  std::vector<PointContact> contacts;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const int hold = configuration.holds[limb];
    if (hold == kFree) continue;
    const bool hand = limb < 2;
    PointContact contact;
    contact.limb = static_cast<Limb>(limb);
    contact.support_direction = wall.holds[hold].support.value_or(
        hand ? Eigen::Vector3d(std::sin(angle), 0.0, std::cos(angle)) : Eigen::Vector3d::UnitZ());
    contact.friction = physics.friction;
    contact.normal_force_limit = hand ? physics.grip : kUnbounded;
    contacts.push_back(contact);
  }
  return contacts;
}

void expect_same(const StaticEquilibriumResult& actual, const StaticEquilibriumResult& expected, int stance) {
  ASSERT_EQ(actual.balanced, expected.balanced) << "stance " << stance;
  EXPECT_EQ(actual.feasible, expected.feasible) << "stance " << stance;
  if (!expected.balanced) return;
  // The least effort is unique, the forces that give it often not (warm starts from other
  // bases reach other optimal vertices): StaticEquilibrium's tests re-check the forces.
  EXPECT_NEAR(actual.effort, expected.effort, 1e-9) << "stance " << stance;
}

// The check is the equilibrium of the contacts written out above, on four holds and on the
// three left once the next limb lets go; holds_still needs both. Most stances of the walk
// hold on four; some, not on three (the three-hold test is what the static model adds).
TEST(StanceCheck, ChecksTheFourHoldsAndTheThreeLeftWithTheDescribedContacts) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(2);
  const std::vector<ReachedStance> stances = reached_stances(wall, 120);
  ASSERT_GT(stances.size(), 20u);
  const PhysicsParameters physics{PhysicsModel::Static};
  StanceCheck check(model, wall, physics);
  StaticEquilibrium reference(model, published_strength_profile(model, model.total_mass, model.stature));
  BodyData data(model);
  int four_held = 0, three_failed = 0;
  for (int i = 0; i < static_cast<int>(stances.size()); ++i) {
    const ReachedStance& s = stances[i];
    const HoldConfiguration three = s.complete.with(s.next, kFree);
    const bool four_ok = check.solve(s.posture, s.complete).feasible;
    expect_same(check.solve(s.posture, s.complete),
                reference.solve(data, s.posture, expected_contacts(wall, s.complete, physics)), i);
    const bool three_ok = check.solve(s.posture, three).feasible;
    expect_same(check.solve(s.posture, three),
                reference.solve(data, s.posture, expected_contacts(wall, three, physics)), i);
    EXPECT_EQ(check.holds_still(s.posture, s.complete, s.next), four_ok && three_ok) << "stance " << i;
    four_held += four_ok;
    three_failed += four_ok && !three_ok;
  }
  EXPECT_GT(four_held, static_cast<int>(stances.size()) / 2);
  EXPECT_GT(three_failed, 0);
}

// The balance precheck refuses only stances the program refuses: every stance of the walk,
// on four holds and on three, at 0, 20 and 40 degrees, gets the verdict and effort of the
// program alone (physics/balance_precheck; its own tests build the refusals by hand).
TEST(StanceCheck, TheBalancePrecheckRefusesOnlyWhatTheProgramRefuses) {
  const BodyModel& model = testing::human_model();
  const StrengthProfile strength = published_strength_profile(model, model.total_mass, model.stature);
  for (const double incline : {0.0, 20.0, 40.0}) {
    const auto [wall, stances] = inclined_walk(4, incline, 200);
    ASSERT_GT(stances.size(), 40u);
    const PhysicsParameters physics{PhysicsModel::Static};
    const Eigen::Vector3d gravity = wall_to_world(incline).transpose() * kStandardGravity;
    StaticEquilibrium checked(model, strength, EquilibriumPrecheck::On);
    StaticEquilibrium program_alone(model, strength, EquilibriumPrecheck::Off);
    BodyData data(model);
    int unbalanced = 0;
    for (int i = 0; i < static_cast<int>(stances.size()); ++i) {
      const ReachedStance& s = stances[i];
      for (const HoldConfiguration& held : {s.complete, s.complete.with(s.next, kFree)}) {
        const std::vector<PointContact> contacts = expected_contacts(wall, held, physics);
        const StaticEquilibriumResult expected = program_alone.solve(data, s.posture, contacts, gravity);
        expect_same(checked.solve(data, s.posture, contacts, gravity), expected, i);
        unbalanced += !expected.balanced;
      }
    }
    EXPECT_GT(unbalanced, 0) << "incline " << incline;
  }
}

// One program decides a stance: the four-hold program relaxes the three-hold one (the
// fourth limb's forces may be zero), so its effort is never larger, and the stance's
// effort is the three-hold effort. Checked on every stance of the walk against both
// programs solved apart.
TEST(StanceCheck, TheThreeHoldEffortIsTheStancesEffort) {
  const BodyModel& model = testing::human_model();
  for (const double incline : {0.0, 40.0}) {
    const auto [wall, stances] = inclined_walk(3, incline, 120);
    ASSERT_GT(stances.size(), 20u);
    const PhysicsParameters physics{PhysicsModel::Static};
    StanceCheck check(model, wall, physics);
    StanceCheck apart(model, wall, physics);
    int three_failed = 0, both_held = 0;
    for (int i = 0; i < static_cast<int>(stances.size()); ++i) {
      const ReachedStance& s = stances[i];
      const double on_four = apart.solve(s.posture, s.complete).effort;
      const double on_three = apart.solve(s.posture, s.complete.with(s.next, kFree)).effort;
      const double effort = check.effort(s.posture, s.complete, s.next);
      if (std::isfinite(on_three)) {
        EXPECT_LE(on_four, on_three + 1e-9) << "incline " << incline << ", stance " << i;
        EXPECT_NEAR(effort, std::max(on_four, on_three), 1e-9) << "incline " << incline << ", stance " << i;
      } else {
        EXPECT_EQ(effort, on_three) << "incline " << incline << ", stance " << i;
      }
      three_failed += on_four <= 1.0 && !(on_three <= 1.0);
      both_held += on_three <= 1.0;
    }
    EXPECT_GT(three_failed, 0) << "incline " << incline;
    EXPECT_GT(both_held, 0) << "incline " << incline;
  }
}

// holds_still asks the cheaper program (the effort bounded by 1, nothing minimised) and must
// give the verdict of the least effort: every stance of random walks at 0, 20 and 40
// degrees, each check with its own warm-start chain as in use (the planner's and a run's).
// The two may differ only for an effort within CLP's tolerance of 1, which none is here.
TEST(StanceCheck, HoldsStillIsAnEffortOfAtMostOne) {
  const BodyModel& model = testing::human_model();
  for (const double incline : {0.0, 20.0, 40.0}) {
    const auto [wall, stances] = inclined_walk(5, incline, 200);
    ASSERT_GT(stances.size(), 40u);
    const PhysicsParameters physics{PhysicsModel::Static};
    StanceCheck verdicts(model, wall, physics);
    StanceCheck efforts(model, wall, physics);
    int held = 0, too_weak = 0;
    for (int i = 0; i < static_cast<int>(stances.size()); ++i) {
      const ReachedStance& s = stances[i];
      const double effort = efforts.effort(s.posture, s.complete, s.next);
      EXPECT_EQ(verdicts.holds_still(s.posture, s.complete, s.next), effort <= 1.0)
          << "incline " << incline << ", stance " << i << ", effort " << effort;
      held += effort <= 1.0;
      too_weak += std::isfinite(effort) && effort > 1.0;
    }
    EXPECT_GT(held, 0) << "incline " << incline;
    EXPECT_GT(too_weak + static_cast<int>(stances.size()) - held, 0) << "incline " << incline;
  }
}

// A hold's support direction from its wall file replaces the default, and an inclined
// wall turns gravity: on a 40-degree overhang, (-g sin 40, 0, -g cos 40) in wall coordinates.
TEST(StanceCheck, AHoldsOwnSupportAndTheWallsInclineAreHonoured) {
  const BodyModel& model = testing::human_model();
  Wall wall = generate_random_wall(2);
  const std::vector<ReachedStance> stances = reached_stances(wall, 40);
  ASSERT_FALSE(stances.empty());
  const ReachedStance& s = stances.back();
  const Eigen::Vector3d sloper = Eigen::Vector3d(-0.3, 0.1, 1.0).normalized();
  for (const int hold : s.complete.holds) wall.holds[hold].support = sloper;
  wall.incline_deg = 40.0;
  const PhysicsParameters physics{PhysicsModel::Static};
  StanceCheck check(model, wall, physics);
  StaticEquilibrium reference(model, published_strength_profile(model, model.total_mass, model.stature));
  BodyData data(model);
  const std::vector<PointContact> contacts = expected_contacts(wall, s.complete, physics);
  for (const PointContact& contact : contacts) EXPECT_EQ(contact.support_direction, sloper);
  const Eigen::Vector3d overhang_gravity = wall_to_world(40.0).transpose() * kStandardGravity;
  EXPECT_NEAR(overhang_gravity.x(), -9.81 * std::sin(40.0 * M_PI / 180.0), 1e-12);
  const StaticEquilibriumResult expected = reference.solve(data, s.posture, contacts, overhang_gravity);
  expect_same(check.solve(s.posture, s.complete), expected, 0);
  const StaticEquilibriumResult upright = reference.solve(data, s.posture, contacts);
  EXPECT_TRUE(upright.balanced != expected.balanced || std::abs(upright.effort - expected.effort) > 1e-3)
      << "the incline changes the stance";
}

// The strength limits scale with the body's stature (physics/strength_profile): a body
// without the frame that gives it is refused, naming its file. (A body without masses is
// refused when it is loaded, whatever the model.)
TEST(StanceCheck, ABodyWithoutStatureIsRefusedNamingItsFile) {
  const Wall wall = generate_random_wall(2);
  const std::string urdf = testing::human_urdf_text();
  // The frame's link and the joint that carries it, renamed.
  const std::string headless =
      testing::replaced(testing::replaced(urdf, "\"head_top\"", "\"crown\""), "\"head_top\"", "\"crown\"");
  ASSERT_NE(headless, urdf);
  const BodyModel no_stature = load_body_model(testing::write_temporary("headless.urdf", headless).string());
  try {
    StanceCheck check(no_stature, wall, PhysicsParameters{PhysicsModel::Static});
    ADD_FAILURE() << "a body without stature is refused";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), no_stature.source +
                                             ": the static model (physics.model) needs the body's stature, from its "
                                             "'head_top' frame, and the body has none");
  }
  const StanceCheck human(testing::human_model(), wall, PhysicsParameters{PhysicsModel::Static});
}

TEST(StanceCheck, PhysicsModelNamesRoundTrip) {
  for (const PhysicsModel model : {PhysicsModel::Kinematic, PhysicsModel::Static, PhysicsModel::Dynamic}) {
    EXPECT_EQ(parse_enum<PhysicsModel>(enum_name(model)), model);
  }
  EXPECT_FALSE(parse_enum<PhysicsModel>("quantum").has_value());
}

}  // namespace
}  // namespace crux
