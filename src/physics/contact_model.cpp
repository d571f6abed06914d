#include "physics/contact_model.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "common/input_error.hpp"

namespace crux {

namespace {

// The contact plane's axes of the pyramid's edges: up projected onto it, then n x that.
std::pair<Eigen::Vector3d, Eigen::Vector3d> contact_tangents(const Eigen::Vector3d& n) {
  Eigen::Vector3d first = Eigen::Vector3d::UnitZ() - n.z() * n;
  // Up is (nearly) the normal: any horizontal tangent will do; +x projected is stable.
  if (first.norm() < 1e-9) first = Eigen::Vector3d::UnitX() - n.x() * n;
  first.normalize();
  return {first, n.cross(first)};
}

}  // namespace

FrictionConeGenerators friction_cone_generators(const PointContact& contact) {
  const Eigen::Vector3d& n = contact.support_direction;
  const auto [first, second] = contact_tangents(n);
  FrictionConeGenerators generators;
  for (int k = 0; k < kFrictionConeFaces; ++k) {
    const double angle = 2.0 * M_PI * k / kFrictionConeFaces;
    generators[k] = n + contact.friction * (std::cos(angle) * first + std::sin(angle) * second);
  }
  return generators;
}

bool inside_friction_cone(const PointContact& contact, const Eigen::Vector3d& force, double tolerance) {
  const double normal = force.dot(contact.support_direction);
  const double tangential = (force - normal * contact.support_direction).norm();
  return normal >= -tolerance && tangential <= contact.friction * normal + tolerance;
}

bool inside_friction_pyramid(const PointContact& contact, const Eigen::Vector3d& force, double tolerance) {
  static_assert(kFrictionConeFaces == 4, "the test below is that of the four-edge pyramid");
  const auto [first, second] = contact_tangents(contact.support_direction);
  const double normal = force.dot(contact.support_direction);
  return normal >= -tolerance &&
         std::abs(force.dot(first)) + std::abs(force.dot(second)) <= contact.friction * normal + tolerance;
}

void check_contact(const PointContact& contact, const std::string& source) {
  const double length = contact.support_direction.norm();
  if (!std::isfinite(length) || std::abs(length - 1.0) > 1e-9) {
    throw InputError(source, fmt::format("the support direction of the {} must be a unit vector, not of length {}",
                                         enum_name(contact.limb), length));
  }
  if (!std::isfinite(contact.friction) || contact.friction < 0.0) {
    throw InputError(source, fmt::format("the friction coefficient of the {} must be finite and >= 0, not {}",
                                         enum_name(contact.limb), contact.friction));
  }
  if (std::isnan(contact.normal_force_limit) || contact.normal_force_limit < 0.0) {
    throw InputError(source, fmt::format("the normal force limit of the {} must be >= 0 N, not {}",
                                         enum_name(contact.limb), contact.normal_force_limit));
  }
}

}  // namespace crux
