#pragma once
// What an IK query asks for: the four hold spheres of a 4-configuration and the root
// target e0_des = H(C4), with the termination test of Algorithm 1 (paper, III-B).

#include <array>

#include <Eigen/Core>

#include "body/body_model.hpp"

namespace crux {

struct ReachTarget {
  std::array<Eigen::Vector3d, kLimbCount> hold_centres;  // limb order
  std::array<double, kLimbCount> hold_radii{0.04, 0.04, 0.04, 0.04};
  Eigen::Vector3d root = Eigen::Vector3d::Zero();  // e0_des
};

struct ReachTolerances {
  double grasp_radius = 0.04;  // grasp sphere at each hand and foot (docs/MODEL.md, choice C3)
  double root_radius = 0.10;   // tolerance sphere of the root (docs/MODEL.md, choice C4)
};

// Largest distance from a grasp point to its hold centre.
double grasp_residual(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target);

// Algorithm 1's termination test: every grasp sphere intersects its hold sphere and the
// root lies inside its tolerance sphere.
bool target_reached(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target,
                    const ReachTolerances& tolerances);

// True when some hold lies beyond its limb's reach envelope from every root inside the
// root's tolerance sphere: then no posture passes target_reached, and IK need not run.
bool beyond_reach(const ReachEnvelope& envelope, const ReachTarget& target, const ReachTolerances& tolerances);

// How far the worst operational point lies outside its sphere (the root's tolerance
// sphere, or its hold's sphere grown by the grasp radius); negative when all are inside.
double tolerance_excess(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target,
                        const ReachTolerances& tolerances);

// f(E) = sum over the 5 operational points of 1/2 |e_i - e_i_des|^2 (paper, III-B).
double reach_cost(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target);

}  // namespace crux
