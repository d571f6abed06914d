#include "physics/least_squares_holding.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "common/random.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kSeed = 20261129;

std::array<PointContact, kLimbCount> four_contacts() {
  std::array<PointContact, kLimbCount> contacts;
  for (int limb = 0; limb < kLimbCount; ++limb) contacts[limb].limb = static_cast<Limb>(limb);
  return contacts;
}

// Four contacts balance any posture's weight and moment: the forces cancel gravity's
// force and moment about the root exactly, the torques are what the joints then supply, and
// any other balancing forces (the first plus a self-balancing set) are larger.
TEST(LeastSquaresHolding, FourContactsBalanceTheWeightWithTheSmallestForces) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  Random random(kSeed);
  const auto contacts = four_contacts();
  for (int sample = 0; sample < 20; ++sample) {
    const Posture g = testing::random_posture(model, random);
    const LeastSquaresHolding holding = least_squares_holding(model, data, g, contacts);
    const GeneralisedForce tau_g = gravity_forces(model, data, g);
    const Eigen::Vector3d com = centre_of_mass(model, data);
    operational_jacobians(model, data);
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    GeneralisedForce through_contacts = GeneralisedForce::Zero();
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const Eigen::Vector3d& f = holding.contact_forces[limb];
      force += f;
      moment += (data.points[operational_point(limb)] - data.points[0]).cross(f);
      through_contacts += data.jacobians[operational_point(limb)].transpose() * f;
    }
    const double weight = model.total_mass * kStandardGravity.norm();
    ASSERT_LT((force + tau_g.head<kRootDof>()).norm(), 1e-9 * weight) << "seed " << kSeed << " sample " << sample;
    ASSERT_LT((moment + model.total_mass * (com - data.points[0]).cross(kStandardGravity)).norm(), 1e-9 * weight)
        << "seed " << kSeed << " sample " << sample;
    const GeneralisedForce residual = holding.joint_torques + tau_g + through_contacts;
    ASSERT_LT(residual.tail<kRevoluteDof>().cwiseAbs().maxCoeff(), 1e-9 * weight);
    ASSERT_EQ(holding.joint_torques.head<kRootDof>(), Eigen::Vector3d::Zero());
    // Two hands pulling apart along the line between them balance themselves.
    const Eigen::Vector3d apart =
        (data.points[operational_point(Limb::RightHand)] - data.points[operational_point(Limb::LeftHand)]).normalized();
    double norm = 0.0, other = 0.0;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      Eigen::Vector3d f = holding.contact_forces[limb];
      norm += f.squaredNorm();
      if (limb == static_cast<int>(Limb::RightHand)) f += 10.0 * apart;
      if (limb == static_cast<int>(Limb::LeftHand)) f -= 10.0 * apart;
      other += f.squaredNorm();
    }
    ASSERT_LT(norm, other);
  }
}

TEST(LeastSquaresHolding, AFreeLimbCarriesNothing) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  auto contacts = four_contacts();
  const LeastSquaresHolding holding =
      least_squares_holding(model, data, standing_posture({-0.4, 0.0, 1.0}), std::span(contacts).first(3));
  EXPECT_EQ(holding.contact_forces[static_cast<int>(Limb::LeftFoot)], Eigen::Vector3d::Zero());
  EXPECT_GT(holding.contact_forces[static_cast<int>(Limb::RightFoot)].z(), 0.0);
}

}  // namespace
}  // namespace crux
