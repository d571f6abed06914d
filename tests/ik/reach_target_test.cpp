#include "ik/reach_target.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "body/kinematics.hpp"
#include "ik/reach_queries.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kQuerySeed = 20261124;

using Points = std::array<Eigen::Vector3d, kOperationalPointCount>;

// Hands at 2 m, feet at 0.5 m, root target 1 m up and 0.3 m from the wall.
ReachTarget sample_target() {
  ReachTarget target;
  target.hold_centres = {Eigen::Vector3d(0, 0.2, 2.0), Eigen::Vector3d(0, 0.8, 2.0), Eigen::Vector3d(0, 0.3, 0.5),
                         Eigen::Vector3d(0, 0.7, 0.5)};
  target.root = Eigen::Vector3d(0.3, 0.5, 1.0);
  return target;
}

// Each operational point off its target by a known distance:
//   root 9 cm (z), right hand 5 cm (x), left hand 5 cm (3-4-5 in y, z), right foot 0,
//   left foot 7 cm (z).
Points sample_points(const ReachTarget& t) {
  return {t.root + Eigen::Vector3d(0, 0, 0.09), t.hold_centres[0] + Eigen::Vector3d(0.05, 0, 0),
          t.hold_centres[1] + Eigen::Vector3d(0, 0.03, -0.04), t.hold_centres[2],
          t.hold_centres[3] + Eigen::Vector3d(0, 0, -0.07)};
}

TEST(ReachTarget, ResidualIsTheWorstGraspPointAndIgnoresTheRoot) {
  const ReachTarget target = sample_target();
  Points points = sample_points(target);
  EXPECT_NEAR(grasp_residual(points, target), 0.07, 1e-12) << "the left foot; the root's 9 cm do not count";
  points[0] += Eigen::Vector3d(1.0, 1.0, 1.0);
  EXPECT_NEAR(grasp_residual(points, target), 0.07, 1e-12);
  points[operational_point(Limb::RightHand)] = target.hold_centres[0] + Eigen::Vector3d(0, -0.3, 0.4);
  EXPECT_NEAR(grasp_residual(points, target), 0.5, 1e-12);
}

TEST(ReachTarget, ResidualPairsEachLimbWithItsOwnHold) {
  // Every grasp point on a hold, but hands swapped: 0.6 m off each.
  const ReachTarget target = sample_target();
  Points points = sample_points(target);
  points[operational_point(Limb::RightHand)] = target.hold_centres[static_cast<int>(Limb::LeftHand)];
  points[operational_point(Limb::LeftHand)] = target.hold_centres[static_cast<int>(Limb::RightHand)];
  EXPECT_NEAR(grasp_residual(points, target), 0.6, 1e-12);
  EXPECT_FALSE(target_reached(points, target, ReachTolerances{}));
}

TEST(ReachTarget, ExcessIsHowFarTheWorstPointLiesOutsideItsSphere) {
  const ReachTarget target = sample_target();  // hold radii 0.04
  ReachTolerances tolerances;                  // grasp 0.04, root 0.10
  // Root 9 cm off (1 cm inside its 10 cm), left foot 7 cm off (1 cm inside 8 cm).
  EXPECT_NEAR(tolerance_excess(sample_points(target), target, tolerances), -0.01, 1e-12);
  Points points = sample_points(target);
  points[operational_point(Limb::RightFoot)].y() += 0.5;  // 50 cm off: 42 cm outside
  EXPECT_NEAR(tolerance_excess(points, target, tolerances), 0.42, 1e-12);
  tolerances.root_radius = 0.01;  // the root 8 cm outside now, still less than the foot
  EXPECT_NEAR(tolerance_excess(points, target, tolerances), 0.42, 1e-12);
  points[0].x() += 1.0;
  EXPECT_NEAR(tolerance_excess(points, target, tolerances), std::sqrt(1.0 + 0.09 * 0.09) - 0.01, 1e-12);
}

TEST(ReachTarget, CostIsHalfTheSumOfSquaredDistancesOfAllFivePoints) {
  const ReachTarget target = sample_target();
  // 1/2 (0.09^2 + 0.05^2 + 0.05^2 + 0 + 0.07^2) = 1/2 (0.0081 + 0.0025 + 0.0025 + 0.0049) = 0.009
  EXPECT_NEAR(reach_cost(sample_points(target), target), 0.009, 1e-15);
  Points exact{target.root, target.hold_centres[0], target.hold_centres[1], target.hold_centres[2],
               target.hold_centres[3]};
  EXPECT_EQ(reach_cost(exact, target), 0.0);
  exact[0].x() += 2.0;  // the root counts in the cost
  EXPECT_DOUBLE_EQ(reach_cost(exact, target), 2.0);
}

TEST(ReachTarget, ReachedWhenEveryGraspSphereMeetsItsHoldAndTheRootIsWithinTolerance) {
  const ReachTarget target = sample_target();
  const ReachTolerances tolerances;  // grasp 4 cm + hold 4 cm: contact within 8 cm; root within 10 cm
  Points points = sample_points(target);
  EXPECT_TRUE(target_reached(points, target, tolerances));

  Points foot_off = points;
  foot_off[operational_point(Limb::LeftFoot)] = target.hold_centres[3] + Eigen::Vector3d(0, 0, -0.09);
  EXPECT_FALSE(target_reached(foot_off, target, tolerances)) << "9 cm: the spheres do not meet";

  Points root_off = points;
  root_off[0] = target.root + Eigen::Vector3d(0, 0, 0.11);
  EXPECT_FALSE(target_reached(root_off, target, tolerances)) << "root 11 cm off";

  ReachTolerances wide_root = tolerances;
  wide_root.root_radius = 0.12;
  EXPECT_TRUE(target_reached(root_off, target, wide_root));
}

TEST(ReachTarget, ContactUsesEachHoldsOwnRadius) {
  ReachTarget target = sample_target();
  Points points = sample_points(target);
  points[operational_point(Limb::LeftFoot)] = target.hold_centres[3] + Eigen::Vector3d(0, 0, -0.09);
  EXPECT_FALSE(target_reached(points, target, ReachTolerances{}));
  target.hold_radii[static_cast<int>(Limb::LeftFoot)] = 0.06;  // 4 + 6 = 10 cm of contact
  EXPECT_TRUE(target_reached(points, target, ReachTolerances{}));
  target.hold_radii[static_cast<int>(Limb::RightFoot)] = 0.0;  // the right foot sits on its centre
  EXPECT_TRUE(target_reached(points, target, ReachTolerances{}));
}

TEST(ReachTarget, SpheresThatJustTouchCount) {
  // Radii and offsets exact in binary: 0.25 + 0.25 of contact, 0.5 away.
  ReachTarget target = sample_target();
  target.hold_radii = {0.25, 0.25, 0.25, 0.25};
  target.root.x() = 0.25;  // 0.25 + 0.5 - 0.25 is exact
  const ReachTolerances tolerances{0.25, 0.5};
  Points points{target.root + Eigen::Vector3d(0.5, 0, 0), target.hold_centres[0] + Eigen::Vector3d(0.5, 0, 0),
                target.hold_centres[1], target.hold_centres[2], target.hold_centres[3]};
  EXPECT_TRUE(target_reached(points, target, tolerances));
  points[1].x() = std::nextafter(0.5, 1.0);
  EXPECT_FALSE(target_reached(points, target, tolerances));
}

TEST(ReachTarget, ANanPostureIsNeverReached) {
  const ReachTarget target = sample_target();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ASSERT_TRUE(target_reached(sample_points(target), target, ReachTolerances{})) << "reached but for the NaN";
  for (int point = 0; point < kOperationalPointCount; ++point) {
    Points points = sample_points(target);
    points[point].y() = nan;
    EXPECT_FALSE(target_reached(points, target, ReachTolerances{})) << "point " << point;
  }
}

// A hold exactly at the limit of the termination test is kept, one millimetre beyond is not.
TEST(ReachEnvelope, RulesOutOnlyBeyondTheLimit) {
  ReachEnvelope envelope;
  envelope.chain_base = {Eigen::Vector3d(0, -0.2, 0.4), Eigen::Vector3d(0, 0.2, 0.4), Eigen::Vector3d(0, -0.1, 0),
                         Eigen::Vector3d(0, 0.1, 0)};
  envelope.radius = {0.7, 0.7, 1.0, 1.0};
  ReachTarget target;
  target.root = Eigen::Vector3d(0.3, 0.5, 1.0);
  for (int limb = 0; limb < kLimbCount; ++limb) target.hold_centres[limb] = target.root + envelope.chain_base[limb];
  const ReachTolerances tolerances;  // root 0.10, grasp 0.04; holds 0.04
  EXPECT_FALSE(beyond_reach(envelope, target, tolerances));
  // Left hand: 0.10 + 0.7 + 0.04 + 0.04 = 0.88 m from its chain base, straight up.
  target.hold_centres[1].z() += 0.88;
  EXPECT_FALSE(beyond_reach(envelope, target, tolerances));
  target.hold_centres[1].z() += 0.001;
  EXPECT_TRUE(beyond_reach(envelope, target, tolerances));
  target.hold_radii[1] = 0.05;  // a larger hold is grasped farther away
  EXPECT_FALSE(beyond_reach(envelope, target, tolerances));
  envelope.radius[1] = std::numeric_limits<double>::infinity();
  target.hold_centres[1].z() += 100.0;
  EXPECT_FALSE(beyond_reach(envelope, target, tolerances)) << "an unbounded chain rules nothing out";
}

TEST(ReachEnvelope, UntilComputedRulesNothingOut) {
  ReachTarget target = sample_target();
  target.hold_centres[0].z() += 1000.0;
  EXPECT_FALSE(beyond_reach(ReachEnvelope{}, target, ReachTolerances{}));
}

// A point uniform in the ball of radius `radius` around `centre`, or on its sphere.
Eigen::Vector3d point_in_ball(Random& random, const Eigen::Vector3d& centre, double radius, bool on_sphere) {
  const Eigen::Vector3d direction = Eigen::Vector3d(random.normal(), random.normal(), random.normal()).normalized();
  return centre + (on_sphere ? radius : radius * std::cbrt(random.uniform())) * direction;
}

// Soundness without a solver: every target that some posture satisfies (its root and
// grasp points inside their tolerance spheres, here on them half the time) is kept.
TEST(ReachEnvelope, NeverRulesOutATargetThatAPosturePasses) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  Random random(kQuerySeed);
  ReachTolerances tolerances;
  for (int sample = 0; sample < 20000; ++sample) {
    // Every other posture is near the zero posture, where the limbs are nearly straight,
    // so that grasp points come close to the bound.
    Posture g = testing::random_posture(model, random);
    if (sample % 4 >= 2) {
      for (int i = kRootDof; i < kConfigurationDof; ++i) g[i] = 0.05 * random.uniform(-1.0, 1.0);
      g = g.cwiseMax(model.lower_limits).cwiseMin(model.upper_limits);
    }
    forward_kinematics(model, data, g);
    tolerances.root_radius = random.uniform(0.0, 0.2);
    tolerances.grasp_radius = random.uniform(0.0, 0.08);
    const bool on_sphere = sample % 2 == 0;
    ReachTarget target;
    target.root = point_in_ball(random, data.points[0], tolerances.root_radius, on_sphere);
    for (int limb = 0; limb < kLimbCount; ++limb) {
      target.hold_radii[limb] = random.uniform(0.0, 0.08);
      target.hold_centres[limb] = point_in_ball(random, data.points[operational_point(limb)],
                                                tolerances.grasp_radius + target.hold_radii[limb], on_sphere);
    }
    ASSERT_TRUE(target_reached(data.points, target, tolerances) || on_sphere)
        << "sample " << sample << ", seed " << kQuerySeed;
    ASSERT_FALSE(beyond_reach(model.reach_envelope, target, tolerances))
        << "sample " << sample << ", seed " << kQuerySeed;
  }
}

// On climbing-like queries: no query a solver reaches is ruled out, and every query
// generated as clearly unreachable is.
TEST(ReachEnvelope, KeepsEveryReachedQueryAndRulesOutTheFarOnes) {
  const BodyModel& model = testing::human_model();
  const ReachEnvelope& envelope = model.reach_envelope;
  IkParameters settings;
  settings.rule_out_beyond_reach = false;  // the solver iterates on every query
  const auto queries = climbing_reach_queries(model, settings, 400, kQuerySeed);
  BodyData data(model);
  int reached = 0, far = 0, ruled_out = 0;
  for (const ReachQuery& query : queries) {
    const bool beyond = beyond_reach(envelope, query.target, settings.tolerances);
    ruled_out += beyond;
    if (query.far_move) {
      ++far;
      EXPECT_TRUE(beyond) << "seed " << kQuerySeed;
    }
    if (solve_ik(model, data, query.start, query.target, settings).reached) {
      ++reached;
      EXPECT_FALSE(beyond) << "seed " << kQuerySeed;
    }
  }
  EXPECT_GT(reached, 100);
  EXPECT_GT(far, 20);
  EXPECT_GE(ruled_out, far);
}

}  // namespace
}  // namespace crux
