#include "simulation/mjcf_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "body/wall_penetration.hpp"
#include "common/xml_escaped.hpp"
#include "wall/hold_support.hpp"
#include "wall/incline.hpp"

namespace crux {

namespace {

// The segments that crux keeps out of the wall (body/wall_penetration: all but the hands
// and feet, which touch the wall where they hold) collide with it (contype 1 against the
// wall's conaffinity 1), never with each other (no geom of the body has a conaffinity). A
// foot touches a hold's top through a small sphere at its grasp point (bit 4), a point
// contact as the static model's; a hand holds through its grasp constraint, not by contact.
constexpr int kSegmentContype = 1;
// The contacts' and grasps' time constant, s: MuJoCo's soft constraints give way in
// proportion to it (2 cm under a climber's weight at its default 0.02), and it may not
// be below two steps of 2 ms.
constexpr double kConstraintTimeConstant = 0.005;
constexpr int kFootContype = 4;
constexpr int kWallConaffinity = 1;
constexpr int kFootingConaffinity = 4;
constexpr double kFootingSize = 0.04;  // half the side of a footing's top face, m

std::string_view site_of(std::string_view joint) {
  for (const std::string_view side : {"right_", "left_"}) {
    if (joint.substr(0, side.size()) == side) joint.remove_prefix(side.size());
  }
  const auto last = joint.rfind('_');
  return last == std::string_view::npos ? joint : joint.substr(0, last);
}

std::string vector_text(const Eigen::Vector3d& v) { return fmt::format("{} {} {}", v.x(), v.y(), v.z()); }

// MuJoCo's w x y z, with w >= 0 so that one rotation has one text.
std::string quaternion_text(const Eigen::Matrix3d& rotation) {
  Eigen::Quaterniond q(rotation);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  return fmt::format("{} {} {} {}", q.w(), q.x(), q.y(), q.z());
}

// The rotation that takes +z to `direction` (unit), about their common normal.
Eigen::Matrix3d z_to(const Eigen::Vector3d& direction) {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), direction).toRotationMatrix();
}

struct MassProperties {
  double mass = 0.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about `centre`
};

// Two rigidly joined parts expressed in one frame, as one (parallel axes).
MassProperties combined(const MassProperties& a, const MassProperties& b) {
  if (b.mass == 0.0) return a;
  if (a.mass == 0.0) return b;
  MassProperties out;
  out.mass = a.mass + b.mass;
  out.centre = (a.mass * a.centre + b.mass * b.centre) / out.mass;
  const auto shifted = [&](const MassProperties& part) -> Eigen::Matrix3d {
    const Eigen::Vector3d d = part.centre - out.centre;
    return part.inertia + part.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  };
  out.inertia = shifted(a) + shifted(b);
  return out;
}

MassProperties of_joint(const BodyJoint& joint) { return {joint.mass, joint.centre_of_mass_local, joint.inertia}; }

class MjcfWriter {
 public:
  MjcfWriter(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics, const StrengthProfile& limits,
             const ServoParameters& servo)
      : model_(model),
        wall_(wall),
        physics_(physics),
        limits_(limits),
        servo_(servo),
        to_world_(wall_to_world(wall.incline_deg)) {
    children_.resize(model.joints.size());
    for (int i = kRootDof; i < static_cast<int>(model.joints.size()); ++i)
      children_[model.joints[i].parent].push_back(i);
  }

  std::string write(const Posture& start) {
    out_ += fmt::format("<mujoco model=\"{} on {}\">\n", xml_escaped(model_.name), xml_escaped(wall_.name));
    // Radians as crux's; masses and inertias from the <inertial> elements alone, the
    // visuals being shapes to draw and to collide; a nanogram on each massless link, as
    // the URDF's own <mujoco> element sets, since MuJoCo refuses massless moving bodies.
    // Implicit integration takes the servos' damping; noslip iterations keep MuJoCo's soft
    // frictional contacts from creeping under a steady load (without them a planned
    // stance's foot crept 1.5 cm in 0.8 s).
    out_ +=
        "  <compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"1e-12\" boundinertia=\"1e-14\"/>\n"
        "  <option timestep=\"0.002\" gravity=\"0 0 -9.81\" cone=\"pyramidal\" integrator=\"implicit\" "
        "noslip_iterations=\"10\"/>\n";
    out_ += fmt::format(
        "  <default>\n    <geom condim=\"3\" friction=\"{0} 0.005 0.0001\" solref=\"{1} 1\"/>\n"
        "    <equality solref=\"{1} 1\"/>\n  </default>\n",
        physics_.friction, kConstraintTimeConstant);
    out_ += "  <worldbody>\n";
    write_wall();
    write_root(start);
    out_ += "  </worldbody>\n";
    write_grasps();
    write_motors();
    write_keyframe(start);
    out_ += "</mujoco>\n";
    return std::move(out_);
  }

 private:
  const BodyModel& model_;
  const Wall& wall_;
  const PhysicsParameters& physics_;
  const StrengthProfile& limits_;
  const ServoParameters& servo_;
  Eigen::Matrix3d to_world_;
  std::vector<std::vector<int>> children_;
  std::vector<int> joint_order_;  // crux's coordinates in MuJoCo's qpos order
  int geom_count_ = 0;            // MuJoCo's geom names must differ
  std::string out_;

  std::string indent(int depth) const { return std::string(2 * depth, ' '); }

  // The plane x = 0 of wall coordinates, facing the climber, and the holds, all in one
  // static body turned by the incline; then the feet's footings.
  void write_wall() {
    Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = Eigen::Vector3d::Zero();
    if (!wall_.holds.empty()) low = high = wall_.holds.front().position;
    for (const Hold& hold : wall_.holds) {
      low = low.cwiseMin(hold.position);
      high = high.cwiseMax(hold.position);
    }
    low.z() = std::min(low.z(), 0.0);
    high.z() = std::max(high.z(), wall_.finish_height);
    const Eigen::Vector3d centre(0.0, (low.y() + high.y()) / 2, (low.z() + high.z()) / 2);
    constexpr double kMargin = 1.0;
    out_ += fmt::format("    <body name=\"wall\" quat=\"{}\">\n", quaternion_text(to_world_));
    // A plane's normal is its local +z: turned about y onto -x, towards the climber. It
    // stands kMjcfWallDepth behind x = 0: the IK leaves segments anywhere up to the skin's
    // margin in the wall (body/wall_penetration), often just there, and a segment at the
    // plane would share the load with the holds (MuJoCo's contacts are soft).
    const Eigen::Vector3d plane = centre + kMjcfWallDepth * Eigen::Vector3d::UnitX();
    out_ += fmt::format(
        "      <geom name=\"wall\" type=\"plane\" pos=\"{}\" quat=\"{}\" size=\"{} {} 0.1\" contype=\"0\" "
        "conaffinity=\"{}\" rgba=\"0.80 0.78 0.72 1\"/>\n",
        vector_text(plane), quaternion_text(z_to(-Eigen::Vector3d::UnitX())), (high.z() - low.z()) / 2 + kMargin,
        (high.y() - low.y()) / 2 + kMargin, kWallConaffinity);
    for (const Hold& hold : wall_.holds) {
      out_ += fmt::format("      <body name=\"{}\" pos=\"{}\">\n", mjcf_hold_name(hold.id), vector_text(hold.position));
      out_ += fmt::format(
          "        <geom type=\"sphere\" size=\"{}\" contype=\"0\" conaffinity=\"0\" rgba=\"0.45 0.30 0.20 1\"/>\n",
          hold.radius);
      out_ += "      </body>\n";
    }
    out_ += "    </body>\n";
    // Each foot's footing (simulation/footing): a box whose top face is the plane the foot
    // stands on, placed where the foot takes its hold, parked out of reach meanwhile.
    for (const Limb foot : {Limb::RightFoot, Limb::LeftFoot}) {
      out_ += fmt::format(
          "    <body name=\"{}\" mocap=\"true\" pos=\"{}\">\n      <geom type=\"box\" pos=\"0 0 {}\" size=\"{} {} {}\" "
          "contype=\"0\" conaffinity=\"{}\" rgba=\"0.35 0.30 0.25 0.4\"/>\n    </body>\n",
          mjcf_footing_name(foot), vector_text(kParkedFooting), -kFootingSize / 4, kFootingSize, kFootingSize,
          kFootingSize / 4, kFootingConaffinity);
    }
  }

  // The root body: crux's three root translations carry the torso's links; in MuJoCo a
  // free joint, placed at the start posture's root, turned with the wall.
  void write_root(const Posture& start) {
    MassProperties root = of_joint(model_.joints[0]);
    for (int i = 1; i < kRootDof; ++i) root = combined(root, of_joint(model_.joints[i]));
    const Eigen::Vector3d position = to_world_ * Eigen::Vector3d(start[0], start[1], start[2]);
    out_ += fmt::format("    <body name=\"{}\" pos=\"{}\" quat=\"{}\">\n", kMjcfRoot, vector_text(position),
                        quaternion_text(to_world_));
    out_ += fmt::format("      <freejoint name=\"{}\"/>\n", kMjcfRoot);
    write_contents(kRootDof - 1, root, 3);
    out_ += "    </body>\n";
  }

  void write_body(int joint, int depth) {
    const BodyJoint& j = model_.joints[joint];
    joint_order_.push_back(joint);
    out_ += fmt::format("{}<body name=\"{}\" pos=\"{}\" quat=\"{}\">\n", indent(depth), xml_escaped(j.name),
                        vector_text(j.origin_translation), quaternion_text(j.origin_rotation));
    out_ += fmt::format("{}  <joint name=\"{}\" type=\"hinge\" axis=\"{}\" limited=\"true\" range=\"{} {}\"/>\n",
                        indent(depth), xml_escaped(j.name), vector_text(j.axis), j.lower, j.upper);
    write_contents(joint, of_joint(j), depth + 1);
    out_ += fmt::format("{}</body>\n", indent(depth));
  }

  // What the body of `joint` carries: its mass, its geoms, the grasp sites, its children.
  void write_contents(int joint, const MassProperties& mass, int depth) {
    if (mass.mass > 0.0) {
      const Eigen::Matrix3d& I = mass.inertia;
      out_ += fmt::format("{}<inertial pos=\"{}\" mass=\"{}\" fullinertia=\"{} {} {} {} {} {}\"/>\n", indent(depth),
                          vector_text(mass.centre), mass.mass, I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
    }
    for (const BodyVisual& visual : model_.visuals) {
      if (visual.joint != joint && !(joint == kRootDof - 1 && visual.joint < kRootDof)) continue;
      write_geom(visual, counts_for_the_wall(model_, visual) ? kSegmentContype : 0, depth);
    }
    for (int limb = 0; limb < kLimbCount; ++limb) {
      if (model_.grasp_points[limb].joint != joint) continue;
      const std::string offset = vector_text(model_.grasp_points[limb].offset);
      out_ += fmt::format("{}<site name=\"{}\" pos=\"{}\" size=\"0.015\"/>\n", indent(depth),
                          xml_escaped(model_.grasp_frame_names[limb]), offset);
      if (!is_hand(static_cast<Limb>(limb))) {
        out_ += fmt::format(
            "{}<geom name=\"{}_contact\" type=\"sphere\" size=\"{}\" pos=\"{}\" contype=\"{}\" conaffinity=\"0\" "
            "rgba=\"0.2 0.2 0.2 0.5\"/>\n",
            indent(depth), xml_escaped(model_.grasp_frame_names[limb]), kFootContactRadius, offset, kFootContype);
      }
    }
    for (const int child : children_[joint]) write_body(child, depth);
  }

  void write_geom(const BodyVisual& visual, int contype, int depth) {
    std::string shape;
    switch (visual.shape) {
      case VisualShape::Box:
        shape = fmt::format("type=\"box\" size=\"{}\"", vector_text(visual.size / 2));
        break;
      case VisualShape::Cylinder:
        shape = fmt::format("type=\"cylinder\" size=\"{} {}\"", visual.size.x(), visual.size.y() / 2);
        break;
      case VisualShape::Sphere:
        shape = fmt::format("type=\"sphere\" size=\"{}\"", visual.size.x());
        break;
    }
    out_ += fmt::format(
        "{}<geom name=\"{}_{}\" {} pos=\"{}\" quat=\"{}\" contype=\"{}\" conaffinity=\"0\" "
        "rgba=\"{} {} {} {}\"/>\n",
        indent(depth), xml_escaped(visual.link), geom_count_++, shape, vector_text(visual.translation),
        quaternion_text(visual.rotation), contype, visual.rgba[0], visual.rgba[1], visual.rgba[2], visual.rgba[3]);
  }

  void write_grasps() {
    out_ += "  <equality>\n";
    for (const Limb hand : {Limb::RightHand, Limb::LeftHand}) {
      const AttachedPoint& grasp = model_.grasp_points[static_cast<int>(hand)];
      const std::string body = grasp.joint < kRootDof ? kMjcfRoot : model_.joints[grasp.joint].name;
      out_ += fmt::format("    <connect name=\"{}\" body1=\"{}\" anchor=\"{}\" active=\"false\"/>\n",
                          mjcf_grasp_name(hand), xml_escaped(body), vector_text(grasp.offset));
    }
    out_ += "  </equality>\n";
  }

  // Each joint's servo (simulation/joint_servo): a general actuator, the control being the
  // target angle with the feed-forward folded in, its force clamped at the joint's limits.
  void write_motors() {
    out_ += "  <actuator>\n";
    for (const int joint : joint_order_) {
      const JointStrength& limit = limits_.joints[joint];
      const ServoGain gain = servo_gain(limit, servo_);
      const std::string name = xml_escaped(model_.joints[joint].name);
      const std::string force_range =
          std::isfinite(limit.positive) && std::isfinite(limit.negative)
              ? fmt::format(" forcelimited=\"true\" forcerange=\"{} {}\"", -limit.negative, limit.positive)
              : std::string();  // only a body that no source measures at all (motor_limits)
      out_ += fmt::format(
          "    <general name=\"{}\" joint=\"{}\" gear=\"1\" gaintype=\"fixed\" gainprm=\"{}\" biastype=\"affine\" "
          "biasprm=\"0 {} {}\"{}/>\n",
          name, name, gain.kp, -gain.kp, -gain.kv, force_range);
    }
    out_ += "  </actuator>\n";
  }

  void write_keyframe(const Posture& start) {
    const Eigen::Vector3d position = to_world_ * Eigen::Vector3d(start[0], start[1], start[2]);
    std::string qpos = fmt::format("{} {}", vector_text(position), quaternion_text(to_world_));
    for (const int joint : joint_order_) qpos += fmt::format(" {}", start[joint]);
    out_ += fmt::format("  <keyframe>\n    <key name=\"start\" qpos=\"{}\"/>\n  </keyframe>\n", qpos);
  }
};

}  // namespace

std::string mjcf_grasp_name(Limb hand) { return fmt::format("grasp_{}", enum_name(hand)); }

std::string mjcf_hold_name(int hold_id) { return fmt::format("hold_{}", hold_id); }

std::string mjcf_footing_name(Limb foot) { return fmt::format("footing_{}", enum_name(foot)); }

StrengthProfile motor_limits(const BodyModel& model, const StrengthProfile& published) {
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  const auto measured = [&](int i) { return std::isfinite(published.joints[i].positive); };
  double weakest = kUnbounded;
  for (int i = kRootDof; i < static_cast<int>(model.joints.size()); ++i) {
    if (measured(i)) weakest = std::min({weakest, published.joints[i].positive, published.joints[i].negative});
  }
  StrengthProfile limits = published;
  for (int i = kRootDof; i < static_cast<int>(model.joints.size()); ++i) {
    if (measured(i)) continue;
    double limit = weakest;
    for (int k = kRootDof; k < static_cast<int>(model.joints.size()); ++k) {
      if (measured(k) && site_of(model.joints[k].name) == site_of(model.joints[i].name)) {
        limit = std::min(published.joints[k].positive, published.joints[k].negative);
        break;
      }
    }
    limits.joints[i] = {limit, limit};
  }
  return limits;
}

std::string mjcf_text(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                      const StrengthProfile& limits, const Posture& start, const ServoParameters& servo) {
  return MjcfWriter(model, wall, physics, limits, servo).write(start);
}

}  // namespace crux
