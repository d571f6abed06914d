#include "support/kdl_reference.hpp"

#include <stdexcept>

#include <Eigen/Geometry>

#include <kdl_parser/kdl_parser.hpp>

namespace crux::testing {

namespace {

KDL::Tree parse_tree(const std::string& urdf_path) {
  KDL::Tree tree;
  if (!kdl_parser::treeFromFile(urdf_path, tree)) throw std::runtime_error("kdl_parser rejected " + urdf_path);
  return tree;
}

}  // namespace

KdlReference::KdlReference(const std::string& urdf_path, const BodyModel& model)
    : tree_(parse_tree(urdf_path)), kdl_index_(kConfigurationDof), fk_(tree_), jacobian_solver_(tree_) {
  if (tree_.getNrOfJoints() != static_cast<unsigned>(kConfigurationDof)) {
    throw std::runtime_error("KDL sees a different number of joints");
  }
  for (int i = 0; i < kConfigurationDof; ++i) {
    bool found = false;
    for (const auto& [name, element] : tree_.getSegments()) {
      const KDL::Segment& segment = GetTreeElementSegment(element);
      if (segment.getJoint().getName() == model.joints[i].name) {
        kdl_index_[i] = GetTreeElementQNr(element);
        found = true;
      }
    }
    if (!found) throw std::runtime_error("KDL has no joint " + model.joints[i].name);
  }
  // The root body is the child link of the last root translation (the torso).
  for (const auto& [name, element] : tree_.getSegments()) {
    if (GetTreeElementSegment(element).getJoint().getName() == model.joints[kRootDof - 1].name) segments_[0] = name;
  }
  for (int limb = 0; limb < kLimbCount; ++limb) segments_[1 + limb] = model.grasp_frame_names[limb];
}

KDL::JntArray KdlReference::to_kdl(const Posture& g) const {
  KDL::JntArray q(kConfigurationDof);
  for (int i = 0; i < kConfigurationDof; ++i) q(kdl_index_[i]) = g[i];
  return q;
}

Posture KdlReference::from_kdl(const KDL::JntArray& q) const {
  Posture g;
  for (int i = 0; i < kConfigurationDof; ++i) g[i] = q(kdl_index_[i]);
  return g;
}

Eigen::Vector3d KdlReference::point(const Posture& g, int k) {
  KDL::Frame frame;
  if (fk_.JntToCart(to_kdl(g), frame, segments_[k]) < 0) throw std::runtime_error("KDL FK failed");
  return {frame.p.x(), frame.p.y(), frame.p.z()};
}

Eigen::Vector3d KdlReference::segment_origin(const Posture& g, const std::string& segment) {
  KDL::Frame frame;
  if (fk_.JntToCart(to_kdl(g), frame, segment) < 0) throw std::runtime_error("KDL FK failed for " + segment);
  return {frame.p.x(), frame.p.y(), frame.p.z()};
}

BodySides KdlReference::body_sides(const Posture& g) {
  const auto limb = [&](Limb l) { return point(g, operational_point(l)); };
  // The trunk's facing: where the toes point when every joint below the root stands at 0
  // (a solved posture may turn a foot anywhere its joints allow).
  const Posture standing = standing_posture(g.head<kRootDof>());
  const Eigen::Vector3d toes =
      point(standing, operational_point(Limb::RightFoot)) + point(standing, operational_point(Limb::LeftFoot)) -
      segment_origin(standing, "right_ankle_link") - segment_origin(standing, "left_ankle_link");
  BodySides sides;
  sides.forward = Eigen::Vector3d(toes.x(), toes.y(), 0.0).normalized();
  sides.left = Eigen::Vector3d::UnitZ().cross(sides.forward);
  sides.hands = (limb(Limb::LeftHand) - limb(Limb::RightHand)).dot(sides.left);
  sides.feet = (limb(Limb::LeftFoot) - limb(Limb::RightFoot)).dot(sides.left);
  return sides;
}

OperationalJacobian KdlReference::jacobian(const Posture& g, int k) {
  KDL::Jacobian full(kConfigurationDof);
  if (jacobian_solver_.JntToJac(to_kdl(g), full, segments_[k]) < 0) throw std::runtime_error("KDL Jacobian failed");
  OperationalJacobian out;
  for (int i = 0; i < kConfigurationDof; ++i) out.col(i) = full.data.block<3, 1>(0, kdl_index_[i]);
  return out;
}

Eigen::Vector3d KdlReference::centre_of_mass(const Posture& g) {
  const KDL::JntArray q = to_kdl(g);
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  double mass = 0.0;
  for (const auto& [name, element] : tree_.getSegments()) {
    const KDL::RigidBodyInertia& inertia = GetTreeElementSegment(element).getInertia();
    if (inertia.getMass() <= 0.0) continue;
    KDL::Frame frame;
    if (fk_.JntToCart(q, frame, name) < 0) throw std::runtime_error("KDL FK failed");
    const KDL::Vector cog = frame * inertia.getCOG();
    weighted += inertia.getMass() * Eigen::Vector3d(cog.x(), cog.y(), cog.z());
    mass += inertia.getMass();
  }
  return weighted / mass;
}

}  // namespace crux::testing
