#include "physics/least_squares_holding.hpp"

#include <Eigen/Dense>

#include "body/kinematics.hpp"

namespace crux {

LeastSquaresHolding least_squares_holding(const BodyModel& model, BodyData& data, const Posture& g,
                                          std::span<const PointContact> contacts, const Eigen::Vector3d& gravity) {
  const GeneralisedForce tau_g = gravity_forces(model, data, g, gravity);
  const Eigen::Vector3d& com = centre_of_mass(model, data);
  const Eigen::Vector3d root = data.points[0];
  operational_jacobians(model, data);
  // Rows: the force and the moment about the root; columns: each contact's three forces.
  const int columns = 3 * static_cast<int>(contacts.size());
  Eigen::MatrixXd balance = Eigen::MatrixXd::Zero(6, columns);
  for (int c = 0; c < static_cast<int>(contacts.size()); ++c) {
    const Eigen::Vector3d lever = data.points[operational_point(contacts[c].limb)] - root;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d unit = Eigen::Vector3d::Unit(k);
      balance.block<3, 1>(0, 3 * c + k) = unit;
      balance.block<3, 1>(3, 3 * c + k) = lever.cross(unit);
    }
  }
  Eigen::Matrix<double, 6, 1> needed;
  needed << -tau_g.head<kRootDof>(), -model.total_mass * (com - root).cross(gravity);
  const Eigen::VectorXd forces = balance.completeOrthogonalDecomposition().solve(needed);
  LeastSquaresHolding holding;
  holding.contact_forces.fill(Eigen::Vector3d::Zero());  // Eigen leaves a default vector unset
  GeneralisedForce contact_forces = GeneralisedForce::Zero();
  for (int c = 0; c < static_cast<int>(contacts.size()); ++c) {
    const Eigen::Vector3d force = forces.segment<3>(3 * c);
    holding.contact_forces[static_cast<int>(contacts[c].limb)] = force;
    contact_forces.noalias() += data.jacobians[operational_point(contacts[c].limb)].transpose() * force;
  }
  holding.joint_torques = -(tau_g + contact_forces);
  holding.joint_torques.head<kRootDof>().setZero();
  return holding;
}

}  // namespace crux
