#include "physics/balance_precheck.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace crux {
namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

HeldContact held_at(const Eigen::Vector3d& point, const Eigen::Vector3d& support, double friction, double limit) {
  PointContact contact;
  contact.support_direction = support.normalized();
  contact.friction = friction;
  return {point, friction_cone_generators(contact), limit};
}

// The force and moment a body of 700 N whose centre of mass hangs 0.3 m off the wall
// (x = -0.3) needs from its contacts: 700 N up, and 700 x 0.3 = 210 N m about +y.
const Eigen::Vector3d kNeededForce(0.0, 0.0, 700.0);
const Eigen::Vector3d kNeededMoment = Eigen::Vector3d(-0.3, 0.0, 0.0).cross(kNeededForce);

// One hand on a jug whose grip is below the weight: the vertical projection refuses it,
// and the same hand with 1 N more grip than the weight is not refused (the four edges,
// each of weight 175 N, sum to 700 N straight up).
TEST(BalancePrecheck, AGripBelowTheWeightIsRefusedAndOneAboveItIsNot) {
  const Eigen::Vector3d under_the_body(0.0, 0.0, 0.0);
  EXPECT_TRUE(proven_unbalanced(std::vector{held_at(under_the_body, Eigen::Vector3d::UnitZ(), 0.5, 699.0)},
                                kNeededForce, Eigen::Vector3d::Zero()));
  EXPECT_FALSE(proven_unbalanced(std::vector{held_at(under_the_body, Eigen::Vector3d::UnitZ(), 0.5, 701.0)},
                                 kNeededForce, Eigen::Vector3d::Zero()));
}

// docs/PHYSICS.md, "Three holds on a plane": hands at y = -0.3 and 0.3, 0.5 m up, a foot
// 1 m down. The pulls f_x solve f_a + f_b + f_c = 0, 0.3 (f_a - f_b) + y_c f_c = 0 and
// 0.5 (f_a + f_b) - f_c = 210. Foot at y = 0.6: f_c = -140, f_a = 210, f_b = -70; a hand
// on a jug tilted 45 degrees with friction 0.5 has f_x >= 0.35 N > 0, so the right hand
// (y = -0.3) cannot be pushed off: refused, whatever the grip, by the moment about the
// line through the left hand and the foot. Foot at y = 0: both hands pull 70 N, the foot's
// friction takes 140 N out of the wall: not refused.
TEST(BalancePrecheck, AFootOutsideTheHandsSpanSwingsTheBodyOpenLikeADoor) {
  const Eigen::Vector3d jug(1.0, 0.0, 1.0);
  const auto stance = [&](double foot_y) {
    return std::vector{held_at({0.0, -0.3, 0.5}, jug, 0.5, kNoLimit), held_at({0.0, 0.3, 0.5}, jug, 0.5, kNoLimit),
                       held_at({0.0, foot_y, -1.0}, Eigen::Vector3d::UnitZ(), 1.0, kNoLimit)};
  };
  EXPECT_TRUE(proven_unbalanced(stance(0.6), kNeededForce, kNeededMoment));
  EXPECT_FALSE(proven_unbalanced(stance(0.0), kNeededForce, kNeededMoment));
}

// Exactness: the force and moment of forces the contacts admit, built from random
// weights on random contacts, some at the normal force limit exactly, are never refused.
TEST(BalancePrecheck, NeverRefusesWhatTheContactsCanExert) {
  std::mt19937_64 random(20261126);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), share(0.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    const int count = 1 + static_cast<int>(random() % 4);
    std::vector<HeldContact> contacts;
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (int c = 0; c < count; ++c) {
      Eigen::Vector3d support(unit(random), unit(random), unit(random));
      if (support.norm() < 1e-3) support = Eigen::Vector3d::UnitZ();
      // Contacts on the wall plane, as holds are, or anywhere within a metre.
      const Eigen::Vector3d point(trial % 2 == 0 ? 0.0 : unit(random), unit(random), unit(random));
      const double limit = random() % 3 == 0 ? kNoLimit : 100.0 + 900.0 * share(random);
      contacts.push_back(held_at(point, support, 1.5 * share(random), limit));
      // Weights summing to the limit (a third of the time) or to less.
      std::vector<double> weights(kFrictionConeFaces);
      double sum = 0.0;
      for (double& w : weights) sum += (w = share(random));
      const double normal = std::isfinite(limit) ? limit * (random() % 3 == 0 ? 1.0 : share(random)) : 2000.0;
      Eigen::Vector3d f = Eigen::Vector3d::Zero();
      for (int k = 0; k < kFrictionConeFaces; ++k) f += normal * weights[k] / sum * contacts.back().generators[k];
      force += f;
      moment += point.cross(f);
    }
    EXPECT_FALSE(proven_unbalanced(contacts, force, moment)) << "trial " << trial;
  }
}

}  // namespace
}  // namespace crux
