#pragma once
// The immutable kinematic model of the virtual human (paper, section III-A):
// a translating root body (e0, no rotation) and 32 revolute joints, with four grasp
// points. Loaded once from URDF and shared read-only by every thread; the mutable
// workspace is BodyData.

#include <array>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include "body/body_visual.hpp"
#include "body/limb.hpp"

namespace crux {

// G = [e0, q]: 3 root translations then the revolute angles (paper, section III-A).
inline constexpr int kRootDof = 3;
inline constexpr int kRevoluteDof = 32;
inline constexpr int kConfigurationDof = kRootDof + kRevoluteDof;
using Posture = Eigen::Matrix<double, kConfigurationDof, 1>;

// The URDF frames that stand for the grasp points; another humanoid is mapped onto
// crux by naming its own frames here.
struct GraspFrameNames {
  std::array<std::string, kLimbCount> frames{"right_palm", "left_palm", "right_foot_ball", "left_foot_ball"};
};

struct BodyJoint {
  std::string name;
  int parent = -1;                  // index into BodyModel::joints, -1 for the world
  Eigen::Matrix3d origin_rotation;  // joint frame in the parent joint's frame
  Eigen::Vector3d origin_translation;
  bool origin_rotation_is_identity = true;  // lets FK skip a 3 x 3 product
  Eigen::Vector3d axis;                     // unit, in the joint frame
  // When the axis is +-x, +-y or +-z: its index (else -1) and sign, for a cheaper FK.
  int principal_axis = -1;
  double principal_sign = 1.0;
  bool prismatic = false;
  double lower = 0.0, upper = 0.0;                                 // radians or metres
  double mass = 0.0;                                               // of the links rigidly attached after this joint
  Eigen::Vector3d centre_of_mass_local = Eigen::Vector3d::Zero();  // in the joint frame
  // Their rotational inertia about that centre of mass, in the joint frame (kg m^2): what
  // a dynamics engine needs beyond crux's statics (simulation/mjcf_model).
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

// How far each limb can reach, whatever its angles: the root does not rotate (section
// III-A), so a limb's chain starts at a point fixed relative to the root, and its grasp
// point stays within the sum of the chain's link lengths of that point. A bound for
// ruling out IK targets without iterating (beyond_reach in ik/reach_target.hpp).
struct ReachEnvelope {
  // Where each limb's chain starts (its first joint past the root), relative to the root.
  std::array<Eigen::Vector3d, kLimbCount> chain_base{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                     Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // The farthest its grasp point can be from chain_base: infinite when the chain slides
  // (a prismatic joint past the root).
  // Until computed, nothing is ruled out.
  std::array<double, kLimbCount> radius{kUnbounded, kUnbounded, kUnbounded, kUnbounded};
  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
};

// A fixed frame, expressed in the frame of the moving joint that carries it.
struct AttachedPoint {
  int joint = -1;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

struct BodyModel {
  std::string source;  // the file it was loaded from, for messages
  std::string name;
  // Topological order (every parent before its children); index i is coordinate i of
  // G, so joints 0..2 are the root translations along x, y, z.
  std::vector<BodyJoint> joints;
  std::array<AttachedPoint, kLimbCount> grasp_points;
  std::array<std::string, kLimbCount> grasp_frame_names;
  // For each operational point, the coordinates whose motion moves it; Jacobian
  // columns outside this list are always zero.
  std::array<std::vector<int>, kOperationalPointCount> chains;
  // The union of the chains in increasing order: the joints IK has to place (the neck,
  // for one, moves no operational point).
  std::vector<int> operational_joints;
  Posture lower_limits, upper_limits;  // root limits are +-infinity: the root is free
  double total_mass = 0.0;
  // Measured on the zero (natural standing) posture with the root at the origin.
  double root_height_above_soles = 0.0;  // used by the root heuristic H(C4)
  double stature = 0.0;                  // top of the head above the soles, if framed
  ReachEnvelope reach_envelope;
  std::string head_top_frame = "head_top";
  // The box, cylinder and sphere <visual> elements, for drawing; mesh visuals are skipped.
  std::vector<BodyVisual> visuals;
};

// The natural standing posture (all joint angles 0) with the root at `root`.
Posture standing_posture(const Eigen::Vector3d& root);

bool within_limits(const BodyModel& model, const Posture& g);

}  // namespace crux
