#pragma once
// Orocos KDL loading the same URDF through kdl_parser: the independent kinematics that
// crux is checked against in tests and measured against in benchmarks.

#include <array>
#include <string>
#include <vector>

#include <kdl/jntarray.hpp>
#include <kdl/tree.hpp>
#include <kdl/treefksolverpos_recursive.hpp>
#include <kdl/treejnttojacsolver.hpp>

#include "body/body_data.hpp"
#include "body/body_model.hpp"

namespace crux::testing {

// How the body stands at a posture, read by KDL alone: `forward` is the horizontal
// direction its toes point (from the ankles to the balls of the feet), `left` is
// up x forward, the body's left in a right-handed frame, and `hands` and `feet` are the
// left limb's offset from the right one along `left` (positive when each left limb is on
// the body's left).
struct BodySides {
  Eigen::Vector3d forward, left;
  double hands = 0, feet = 0;
};

class KdlReference {
 public:
  // Throws std::runtime_error if kdl_parser rejects the file.
  KdlReference(const std::string& urdf_path, const BodyModel& model);

  KDL::JntArray to_kdl(const Posture& g) const;
  Posture from_kdl(const KDL::JntArray& q) const;

  // Operational point k (0 root, 1..4 grasp frames) at posture g.
  Eigen::Vector3d point(const Posture& g, int k);
  OperationalJacobian jacobian(const Posture& g, int k);
  Eigen::Vector3d centre_of_mass(const Posture& g);
  // The origin of KDL segment `segment` (a URDF link) at posture g.
  Eigen::Vector3d segment_origin(const Posture& g, const std::string& segment);
  BodySides body_sides(const Posture& g);

  const KDL::Tree& tree() const { return tree_; }
  // KDL segment names of the operational points: the root body, then the grasp frames.
  const std::array<std::string, kOperationalPointCount>& segments() const { return segments_; }

 private:
  KDL::Tree tree_;
  std::vector<unsigned> kdl_index_;  // crux coordinate -> KDL q_nr
  std::array<std::string, kOperationalPointCount> segments_;
  KDL::TreeFkSolverPos_recursive fk_;
  KDL::TreeJntToJacSolver jacobian_solver_;
};

}  // namespace crux::testing
