#include "body/urdf_loader.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <mutex>
#include <optional>
#include <set>

#include <console_bridge/console.h>
#include <dlfcn.h>
#include <fmt/format.h>
#include <link.h>
#include <urdf_parser/urdf_parser.h>
#include <Eigen/Geometry>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "body/reach_envelope.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"

namespace crux {

namespace {

// urdfdom reports parse errors through console_bridge; keep the first one so that it
// becomes part of our single error line instead of going to stderr. Some of them (an
// unreadable mass) it survives by dropping the element: crux refuses the file then too.
class FirstErrorCapture : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error.empty()) first_error = text;
  }
  std::string first_error;
};

urdf::ModelInterfaceSharedPtr parse_urdf(const std::string& xml, const std::string& source) {
  static std::mutex parser_mutex;  // console_bridge's handler is process-wide
  std::lock_guard lock(parser_mutex);
  FirstErrorCapture capture;
  console_bridge::useOutputHandler(&capture);
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
  urdf::ModelInterfaceSharedPtr parsed;
  try {
    parsed = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    capture.first_error = e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  if (!parsed || !capture.first_error.empty()) {
    std::string why = capture.first_error.empty() ? "not a valid URDF document" : capture.first_error;
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    throw InputError(source, "invalid URDF: " + why);
  }
  return parsed;
}

Eigen::Matrix3d to_rotation(const urdf::Rotation& r) {
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
}

Eigen::Vector3d to_vector(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

struct RigidTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  RigidTransform then(const urdf::Pose& pose) const {
    return {rotation * to_rotation(pose.rotation), translation + rotation * to_vector(pose.position)};
  }
};

const char* joint_type_name(int type) {
  switch (type) {
    case urdf::Joint::REVOLUTE:
      return "revolute";
    case urdf::Joint::CONTINUOUS:
      return "continuous";
    case urdf::Joint::PRISMATIC:
      return "prismatic";
    case urdf::Joint::FLOATING:
      return "floating";
    case urdf::Joint::PLANAR:
      return "planar";
    case urdf::Joint::FIXED:
      return "fixed";
    default:
      return "unknown";
  }
}

class ModelBuilder {
 public:
  ModelBuilder(const urdf::ModelInterface& urdf, const std::string& source, const GraspFrameNames& names)
      : urdf_(urdf), source_(source), names_(names) {}

  BodyModel build() {
    model_.source = source_;
    model_.name = urdf_.getName();
    const urdf::LinkConstSharedPtr torso = read_root_chain();
    visit(*torso, kRootDof - 1, RigidTransform{});
    finish();
    return std::move(model_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw InputError(source_, problem); }

  // The root must be 3 prismatic joints along world x, y, z so that G[0..2] = e0.
  urdf::LinkConstSharedPtr read_root_chain() {
    urdf::LinkConstSharedPtr link = urdf_.getRoot();
    static const char* const axis_names[kRootDof] = {"x", "y", "z"};
    for (int i = 0; i < kRootDof; ++i) {
      if (link->child_joints.size() != 1) {
        fail(fmt::format("root link '{}' must have exactly one child joint (prismatic along {}), found {}", link->name,
                         axis_names[i], link->child_joints.size()));
      }
      const urdf::Joint& joint = *link->child_joints.front();
      if (joint.type != urdf::Joint::PRISMATIC) {
        fail(fmt::format("joint '{}' has type {}, expected the root translation along {} (prismatic)", joint.name,
                         joint_type_name(joint.type), axis_names[i]));
      }
      Eigen::Vector3d expected = Eigen::Vector3d::Zero();
      expected[i] = 1.0;
      if ((to_vector(joint.axis) - expected).norm() > 1e-12) {
        fail(fmt::format("root joint '{}' must translate along {} (axis {} {} {})", joint.name, axis_names[i],
                         expected.x(), expected.y(), expected.z()));
      }
      const urdf::Pose& origin = joint.parent_to_joint_origin_transform;
      if (to_vector(origin.position).norm() > 1e-12 ||
          (to_rotation(origin.rotation) - Eigen::Matrix3d::Identity()).norm() > 1e-12) {
        fail(fmt::format("root joint '{}' must have a zero origin so that the root position is e0", joint.name));
      }
      BodyJoint out;
      out.name = joint.name;
      out.parent = i - 1;
      out.origin_rotation.setIdentity();
      out.origin_translation.setZero();
      out.axis = expected;
      out.prismatic = true;
      out.lower = -std::numeric_limits<double>::infinity();
      out.upper = std::numeric_limits<double>::infinity();
      model_.joints.push_back(out);
      link = urdf_.getLink(joint.child_link_name);
      if (i + 1 < kRootDof) add_mass(*link, i, RigidTransform{});
    }
    return link;
  }

  void add_mass(const urdf::Link& link, int carrier, const RigidTransform& in_carrier) {
    if (!link.inertial) return;
    if (!std::isfinite(link.inertial->mass) || link.inertial->mass < 0.0) {
      fail(fmt::format("link '{}' has mass {}; a mass is a finite number, 0 or more", link.name, link.inertial->mass));
    }
    if (link.inertial->mass == 0.0) return;
    const urdf::Inertial& inertial = *link.inertial;
    Eigen::Matrix3d inertia;
    inertia << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz, inertial.ixz,
        inertial.iyz, inertial.izz;
    if (!inertia.allFinite() || inertia.diagonal().minCoeff() < 0.0) {
      fail(fmt::format("link '{}' has an inertia that is not finite or has a negative moment", link.name));
    }
    BodyJoint& joint = model_.joints[carrier];
    const RigidTransform frame = in_carrier.then(inertial.origin);
    const Eigen::Vector3d com = frame.translation;
    // Summed about the joint origin (parallel axes), taken to the joint's centre of mass
    // once every link is in (finish()).
    inertia_about_origin_.resize(model_.joints.size(), Eigen::Matrix3d::Zero());
    inertia_about_origin_[carrier] +=
        frame.rotation * inertia * frame.rotation.transpose() +
        inertial.mass * (com.squaredNorm() * Eigen::Matrix3d::Identity() - com * com.transpose());
    const double mass = joint.mass + inertial.mass;
    joint.centre_of_mass_local = (joint.mass * joint.centre_of_mass_local + inertial.mass * com) / mass;
    joint.mass = mass;
  }

  // Not inlined: visit() recurses once per link, and this frame's locals would make each
  // level's stack frame several times larger (a 1000-link chain overflowed under ASan).
  [[gnu::noinline]] void add_visuals(const urdf::Link& link, int carrier, const RigidTransform& in_carrier) {
    for (const urdf::VisualSharedPtr& visual : link.visual_array) {
      if (!visual || !visual->geometry) continue;
      BodyVisual out;
      out.link = link.name;
      out.joint = carrier;
      const RigidTransform pose = in_carrier.then(visual->origin);
      out.rotation = pose.rotation;
      out.translation = pose.translation;
      switch (visual->geometry->type) {
        case urdf::Geometry::BOX: {
          const auto& box = static_cast<const urdf::Box&>(*visual->geometry);
          out.shape = VisualShape::Box;
          out.size = to_vector(box.dim);
          break;
        }
        case urdf::Geometry::CYLINDER: {
          const auto& cylinder = static_cast<const urdf::Cylinder&>(*visual->geometry);
          out.shape = VisualShape::Cylinder;
          out.size = {cylinder.radius, cylinder.length, 0.0};
          break;
        }
        case urdf::Geometry::SPHERE:
          out.shape = VisualShape::Sphere;
          out.size = {static_cast<const urdf::Sphere&>(*visual->geometry).radius, 0.0, 0.0};
          break;
        default:
          continue;  // meshes need files and a mesh reader; crux draws primitives only
      }
      if (!out.size.allFinite() || (out.size.array() < 0.0).any()) {
        fail(fmt::format("link '{}' has a visual of invalid size", link.name));
      }
      urdf::MaterialSharedPtr material = visual->material;
      if (!material && !visual->material_name.empty()) material = urdf_.getMaterial(visual->material_name);
      if (material) {
        const urdf::Color& c = material->color;
        out.rgba = {c.r, c.g, c.b, c.a};
      }
      model_.visuals.push_back(std::move(out));
    }
  }

  // Depth-first from `link`, which moves with joint `carrier` at `in_carrier`; `depth`
  // links below the root. Bounded, and each link once: a cycle or a very long chain would
  // otherwise recurse without end or overflow the stack.
  void visit(const urdf::Link& link, int carrier, const RigidTransform& in_carrier, int depth = 0) {
    if (!visited_.insert(link.name).second) {
      fail(fmt::format("link '{}' is reached twice: its joints form a cycle", link.name));
    }
    if (depth > kMaxTreeDepth) fail(fmt::format("the kinematic tree is deeper than {} links", kMaxTreeDepth));
    add_mass(link, carrier, in_carrier);
    add_visuals(link, carrier, in_carrier);
    frames_.push_back({link.name, {carrier, in_carrier.translation}});
    for (const urdf::JointSharedPtr& joint : link.child_joints) {
      const urdf::LinkConstSharedPtr child = urdf_.getLink(joint->child_link_name);
      if (!child)
        fail(
            fmt::format("joint '{}' names a child link '{}' that does not exist", joint->name, joint->child_link_name));
      const RigidTransform origin = in_carrier.then(joint->parent_to_joint_origin_transform);
      switch (joint->type) {
        case urdf::Joint::FIXED:
          visit(*child, carrier, origin, depth + 1);
          break;
        case urdf::Joint::REVOLUTE: {
          if (!joint->limits) fail(fmt::format("joint '{}' has no limits", joint->name));
          const double lower = joint->limits->lower, upper = joint->limits->upper;
          if (!std::isfinite(lower) || !std::isfinite(upper) || !(lower < upper)) {
            fail(fmt::format("joint '{}' has invalid limits [{}, {}]", joint->name, lower, upper));
          }
          const Eigen::Vector3d axis = to_vector(joint->axis);
          if (!(axis.norm() > 0.0)) fail(fmt::format("joint '{}' has a zero axis", joint->name));
          BodyJoint out;
          out.name = joint->name;
          out.parent = carrier;
          out.origin_rotation = origin.rotation;
          out.origin_translation = origin.translation;
          out.origin_rotation_is_identity = origin.rotation == Eigen::Matrix3d::Identity();
          out.axis = axis.normalized();
          for (int k = 0; k < 3; ++k) {
            if (std::abs(out.axis[k]) == 1.0) {
              out.principal_axis = k;
              out.principal_sign = out.axis[k];
            }
          }
          out.lower = lower;
          out.upper = upper;
          model_.joints.push_back(out);
          visit(*child, static_cast<int>(model_.joints.size()) - 1, RigidTransform{}, depth + 1);
          break;
        }
        default:
          fail(
              fmt::format("joint '{}' has type {}; crux accepts revolute and fixed joints below the root "
                          "(and exactly 3 prismatic root joints)",
                          joint->name, joint_type_name(joint->type)));
      }
    }
  }

  void finish() {
    const int revolute = static_cast<int>(model_.joints.size()) - kRootDof;
    if (revolute != kRevoluteDof) {
      fail(fmt::format("the body must have exactly {} revolute joints, found {}", kRevoluteDof, revolute));
    }
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const std::string& wanted = names_.frames[limb];
      const auto found = find_frame(wanted);
      if (!found) {
        fail(fmt::format("grasp frame '{}' ({}) does not exist", wanted, enum_name(static_cast<Limb>(limb))));
      }
      model_.grasp_points[limb] = *found;
      model_.grasp_frame_names[limb] = wanted;
    }
    for (int k = 0; k < kOperationalPointCount; ++k) {
      int joint = k == 0 ? kRootDof - 1 : model_.grasp_points[k - 1].joint;
      std::vector<int>& chain = model_.chains[k];
      for (; joint >= 0; joint = model_.joints[joint].parent) chain.insert(chain.begin(), joint);
    }
    for (int i = 0; i < static_cast<int>(model_.joints.size()); ++i) {
      for (const auto& chain : model_.chains) {
        if (std::find(chain.begin(), chain.end(), i) != chain.end()) {
          model_.operational_joints.push_back(i);
          break;
        }
      }
    }
    inertia_about_origin_.resize(model_.joints.size(), Eigen::Matrix3d::Zero());
    for (int i = 0; i < kConfigurationDof; ++i) {
      BodyJoint& joint = model_.joints[i];
      model_.lower_limits[i] = joint.lower;
      model_.upper_limits[i] = joint.upper;
      model_.total_mass += joint.mass;
      const Eigen::Vector3d& c = joint.centre_of_mass_local;
      joint.inertia =
          inertia_about_origin_[i] - joint.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    }
    if (!(model_.total_mass > 0.0)) fail("the body has no mass (no <inertial> with a positive mass)");

    BodyData data(model_);
    forward_kinematics(model_, data, standing_posture(Eigen::Vector3d::Zero()));
    const double soles = std::min(data.points[operational_point(Limb::RightFoot)].z(),
                                  data.points[operational_point(Limb::LeftFoot)].z());
    model_.root_height_above_soles = -soles;
    model_.reach_envelope = compute_reach_envelope(model_);
    if (const auto head = find_frame(model_.head_top_frame)) {
      const JointPlacement& carrier = data.placements[head->joint];
      model_.stature = (carrier.origin + carrier.rotation * head->offset).z() - soles;
    }
  }

  std::optional<AttachedPoint> find_frame(const std::string& name) const {
    for (const auto& [frame_name, point] : frames_) {
      if (frame_name == name) return point;
    }
    return std::nullopt;
  }

  const urdf::ModelInterface& urdf_;
  const std::string& source_;
  const GraspFrameNames& names_;
  BodyModel model_;
  std::vector<std::pair<std::string, AttachedPoint>> frames_;
  std::vector<Eigen::Matrix3d> inertia_about_origin_;  // per joint, while links are added
  std::set<std::string> visited_;
  static constexpr int kMaxTreeDepth = 1000;
};

// urdfdom parses with TinyXML 2.6.2, which in UTF-8 mode steps over a character by the
// length its lead byte announces, even across the string's terminating NUL
// (TiXmlBase::GetChar): a lead byte among the last three bytes of the text sends the
// parser past the end of the buffer. Such text, and text with a NUL (where TinyXML would
// silently stop), is refused before urdfdom sees it.
void check_parser_safe(const std::string& xml, const std::string& source) {
  if (const std::size_t nul = xml.find('\0'); nul != std::string::npos) {
    throw InputError(source, fmt::format("invalid URDF: a NUL byte at offset {}", nul));
  }
  const auto announced_length = [](unsigned char lead) -> std::size_t {
    if (lead >= 0xc2 && lead <= 0xdf) return 2;
    if (lead >= 0xe0 && lead <= 0xef) return 3;
    if (lead >= 0xf0 && lead <= 0xf4) return 4;
    return 1;
  };
  for (std::size_t i = xml.size() >= 3 ? xml.size() - 3 : 0; i < xml.size(); ++i) {
    if (i + announced_length(static_cast<unsigned char>(xml[i])) > xml.size()) {
      throw InputError(source, "invalid URDF: the file ends inside a UTF-8 character");
    }
  }
}

}  // namespace

BodyModel load_body_model_from_string(const std::string& urdf_xml, const std::string& source,
                                      const GraspFrameNames& frames) {
  if (urdf_xml.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(source, "the file is empty");
  check_parser_safe(urdf_xml, source);
  const urdf::ModelInterfaceSharedPtr parsed = parse_urdf(urdf_xml, source);
  // urdfdom links own their children through shared pointers, so joints that form a cycle
  // would keep the whole graph alive; cutting those edges lets the parsed model be freed.
  struct ChildLinkRelease {
    urdf::ModelInterface& urdf;
    ~ChildLinkRelease() {
      for (auto& entry : urdf.links_) entry.second->child_links.clear();
    }
  } release{*parsed};
  return ModelBuilder(*parsed, source, frames).build();
}

BodyModel load_body_model(const std::string& urdf_path, const GraspFrameNames& frames) {
  return load_body_model_from_string(read_input_file(urdf_path, "URDF file"), urdf_path, frames);
}

std::string default_body_model_path() {
  namespace fs = std::filesystem;
  if (const char* dir = std::getenv("CRUX_MODEL_DIR"); dir != nullptr && *dir != '\0') {
    return (fs::path(dir) / "crux_human.urdf").string();
  }
  // The file that holds this code: the crux binary, or the Python module crux/_crux.so.
  // Installed, they live in <prefix>/bin and <prefix>/lib/python3.X/dist-packages/crux,
  // beside <prefix>/share/crux; the build tree mirrors that layout under the build
  // folder, for the binaries at its top, in its subfolders (tests/, bench/) and in
  // python/crux/. So the first folder up from it that has share/crux/models is the one.
  // For the main program dladdr names argv[0], which may be a bare command name: the
  // executable's own path then comes from /proc/self/exe.
  Dl_info info{};
  link_map* object = nullptr;
  std::error_code error;
  fs::path code_file;
  if (dladdr1(reinterpret_cast<const void*>(&default_body_model_path), &info, reinterpret_cast<void**>(&object),
              RTLD_DL_LINKMAP) != 0 &&
      object != nullptr && object->l_name != nullptr && object->l_name[0] != '\0') {
    code_file = fs::canonical(object->l_name, error);
  }
  if (code_file.empty()) code_file = fs::read_symlink("/proc/self/exe", error);
  const fs::path relative = fs::path("share") / "crux" / "models" / "crux_human.urdf";
  constexpr int kFoldersUp = 5;
  fs::path base = code_file.parent_path();
  for (int up = 0; up < kFoldersUp && !base.empty(); ++up, base = base.parent_path()) {
    if (fs::exists(base / relative, error)) return (base / relative).string();
    if (base == base.root_path()) break;
  }
  return (code_file.parent_path().parent_path() / relative).string();  // named by the error that follows
}

}  // namespace crux
