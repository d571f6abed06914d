#include "physics/static_equilibrium.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "ik/ik_solver.hpp"
#include "ik/root_target.hpp"
#include "support/test_models.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

constexpr double kG = 9.81;
constexpr double kUnlimited = std::numeric_limits<double>::infinity();

// A link hung from `parent` by a revolute joint about y at `origin`, its mass at `centre`.
struct ArmLink {
  std::string joint, parent;
  Eigen::Vector3d origin;
  double mass;
  Eigen::Vector3d centre;
};

// A grasp frame fixed on a link.
struct GraspFrame {
  std::string link = "torso";
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

// A body with crux's contract (3 root translations, 32 revolute joints, the four grasp
// frames): a torso of `torso_mass` at the root, the `arm` links, and massless filler
// joints that carry nothing.
BodyModel small_body(const std::string& name, double torso_mass, const std::vector<ArmLink>& arm,
                     const std::array<GraspFrame, kLimbCount>& grasps) {
  std::string urdf = "<robot name=\"small\">" + testing::root_translations_urdf();
  urdf += fmt::format(
      "<link name=\"torso\"><inertial><origin xyz=\"0 0 0\"/><mass value=\"{}\"/>"
      "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>",
      torso_mass);
  const auto revolute = [&](const std::string& joint, const std::string& parent, const std::string& child,
                            const Eigen::Vector3d& origin, const char* axis) {
    urdf += fmt::format(
        "<joint name=\"{}\" type=\"revolute\"><parent link=\"{}\"/><child link=\"{}\"/>"
        "<origin xyz=\"{} {} {}\" rpy=\"0 0 0\"/><axis xyz=\"{}\"/>"
        "<limit lower=\"-6.3\" upper=\"6.3\" effort=\"1\" velocity=\"1\"/></joint>",
        joint, parent, child, origin.x(), origin.y(), origin.z(), axis);
  };
  for (const ArmLink& link : arm) {
    const std::string child = link.joint + "_link";
    urdf += fmt::format(
        "<link name=\"{}\"><inertial><origin xyz=\"{} {} {}\"/><mass value=\"{}\"/>"
        "<inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial></link>",
        child, link.centre.x(), link.centre.y(), link.centre.z(), link.mass);
    revolute(link.joint, link.parent, child, link.origin, "0 1 0");
  }
  std::string parent = "torso";
  for (int i = static_cast<int>(arm.size()); i < kRevoluteDof; ++i) {
    const std::string child = fmt::format("filler_{}", i);
    urdf += fmt::format("<link name=\"{}\"/>", child);
    revolute(fmt::format("filler_joint_{}", i), parent, child, Eigen::Vector3d(0.0, 0.0, 0.1), "0 0 1");
    parent = child;
  }
  const char* const frames[kLimbCount] = {"right_palm", "left_palm", "right_foot_ball", "left_foot_ball"};
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const GraspFrame& grasp = grasps[limb];
    urdf += fmt::format(
        "<link name=\"{0}\"/><joint name=\"{0}_fixed\" type=\"fixed\"><parent link=\"{1}\"/>"
        "<child link=\"{0}\"/><origin xyz=\"{2} {3} {4}\" rpy=\"0 0 0\"/></joint>",
        frames[limb], grasp.link, grasp.offset.x(), grasp.offset.y(), grasp.offset.z());
  }
  urdf += "</robot>";
  return load_body_model(testing::write_temporary(name, urdf).string());
}

int coordinate_named(const BodyModel& model, const std::string& name) {
  for (int i = 0; i < kConfigurationDof; ++i) {
    if (model.joints[i].name == name) return i;
  }
  throw std::runtime_error("no joint " + name);
}

PointContact contact_at(Limb limb, const Eigen::Vector3d& support, double friction, double limit) {
  PointContact contact;
  contact.limb = limb;
  contact.support_direction = support.normalized();
  contact.friction = friction;
  contact.normal_force_limit = limit;
  check_contact(contact, "test");
  return contact;
}

// Every returned equilibrium re-checked from the model alone, with a fresh workspace: forces
// and moments balance, each force is in its (round) cone and under its limit, each torque
// is -(tau_g + sum J^T f) and within effort x its limit, and the effort is the largest ratio.
void expect_checked(const BodyModel& model, const StrengthProfile& strength, const Posture& g,
                    const std::vector<PointContact>& contacts, const StaticEquilibriumResult& result,
                    const Eigen::Vector3d& gravity = kStandardGravity) {
  ASSERT_TRUE(result.balanced);
  BodyData data(model);
  const GeneralisedForce tau_g = gravity_forces(model, data, g, gravity);
  operational_jacobians(model, data);
  const Eigen::Vector3d com = centre_of_mass(model, data);
  Eigen::Vector3d force = model.total_mass * gravity, moment = com.cross(model.total_mass * gravity);
  GeneralisedForce torques = -tau_g;
  double scale = model.total_mass * kG;
  for (const PointContact& contact : contacts) {
    const int point = operational_point(contact.limb);
    const Eigen::Vector3d& f = result.contact_forces[static_cast<int>(contact.limb)];
    force += f;
    moment += data.points[point].cross(f);
    torques -= data.jacobians[point].transpose() * f;
    EXPECT_TRUE(inside_friction_cone(contact, f, 1e-6)) << enum_name(contact.limb) << " " << f.transpose();
    EXPECT_LE(f.dot(contact.support_direction), contact.normal_force_limit + 1e-6);
  }
  EXPECT_LT(force.norm(), 1e-6 * scale) << force.transpose();
  EXPECT_LT(moment.norm(), 1e-6 * scale) << moment.transpose();
  double largest = 0.0;
  for (int j = kRootDof; j < kConfigurationDof; ++j) {
    EXPECT_NEAR(result.joint_torques[j], torques[j], 1e-6 * scale) << model.joints[j].name;
    const JointStrength& limit = strength.joints[j];
    const double ratio = torques[j] >= 0 ? torques[j] / limit.positive : -torques[j] / limit.negative;
    EXPECT_LE(ratio, result.effort + 1e-6) << model.joints[j].name;
    largest = std::max(largest, ratio);
  }
  EXPECT_NEAR(result.effort, largest, 1e-6);
  EXPECT_EQ(result.feasible, result.effort <= 1.0);
}

// A box of mass M on two ledges of a table, a to its right and b to its left of the centre
// of mass: the moment about x fixes the normal forces at M g b / (a + b) and M g a / (a + b).
// No joint carries anything, so the effort is 0. With the left ledge's limit at its share the
// box is held with that ledge at its limit; 1 % under it, no force in the cones balances:
// infeasible, since the normal forces are forced.
TEST(StaticEquilibrium, RigidBodyOnTwoLedgesSharesItsWeightByTheLever) {
  constexpr double M = 50.0, a = 0.2, b = 0.3, h = 0.4;
  const BodyModel model =
      small_body("two_ledges.urdf", M, {},
                 {GraspFrame{"torso", {0.0, -a, -h}}, GraspFrame{"torso", {0.0, b, -h}}, GraspFrame{}, GraspFrame{}});
  const StrengthProfile strength;  // nothing bounded
  StaticEquilibrium equilibrium(model, strength);
  BodyData data(model);
  Posture g = Posture::Zero();
  g.head<kRootDof>() = Eigen::Vector3d(-0.3, 0.1, 1.0);
  const double right_share = M * kG * b / (a + b), left_share = M * kG * a / (a + b);
  std::vector<PointContact> contacts = {contact_at(Limb::RightHand, Eigen::Vector3d::UnitZ(), 0.5, 1000.0),
                                        contact_at(Limb::LeftHand, Eigen::Vector3d::UnitZ(), 0.5, 1000.0)};
  const StaticEquilibriumResult& result = equilibrium.solve(data, g, contacts);
  ASSERT_TRUE(result.feasible);
  EXPECT_NEAR(result.contact_forces[0].z(), right_share, 1e-6);
  EXPECT_NEAR(result.contact_forces[1].z(), left_share, 1e-6);
  EXPECT_DOUBLE_EQ(result.effort, 0.0);
  EXPECT_EQ(result.binding, EquilibriumBinding::None);
  expect_checked(model, strength, g, contacts, result);

  contacts[1].normal_force_limit = 1.01 * left_share;
  EXPECT_TRUE(equilibrium.solve(data, g, contacts).feasible);
  EXPECT_FALSE(equilibrium.solve(data, g, contacts).at_force_limit[1]);
  contacts[1].normal_force_limit = left_share;  // exactly its forced share: held, at its limit
  const StaticEquilibriumResult& at_limit = equilibrium.solve(data, g, contacts);
  EXPECT_TRUE(at_limit.feasible);
  EXPECT_TRUE(at_limit.at_force_limit[1]);
  EXPECT_FALSE(at_limit.at_force_limit[0]);
  contacts[1].normal_force_limit = 0.99 * left_share;
  const StaticEquilibriumResult& gripless = equilibrium.solve(data, g, contacts);
  EXPECT_FALSE(gripless.balanced);
  EXPECT_FALSE(gripless.feasible);
  EXPECT_EQ(gripless.binding, EquilibriumBinding::Contacts);
  EXPECT_TRUE(std::isinf(gripless.effort));
}

// A body pinched between two vertical faces at (-w, 0, 0) and (w, 0, 0) from its centre of
// mass, pushing +x and -x: the moment about y gives each face half the weight, M g / 2,
// vertically; the x balance gives both the same normal force N <= limit; Coulomb needs
// M g / 2 <= mu N. The pyramid's first edge points straight up, so it grants exactly mu N:
// feasible when mu x limit is 5 % over M g / 2, infeasible (proven by these three lines)
// when 5 % under, whatever the tangential forces.
TEST(StaticEquilibrium, PinchHoldsExactlyWhenFrictionTimesGripCarriesHalfTheWeight) {
  constexpr double M = 40.0, w = 0.15, mu = 0.4;
  const BodyModel model =
      small_body("pinch.urdf", M, {},
                 {GraspFrame{}, GraspFrame{}, GraspFrame{"torso", {-w, 0.0, 0.0}}, GraspFrame{"torso", {w, 0.0, 0.0}}});
  const StrengthProfile strength;
  StaticEquilibrium equilibrium(model, strength);
  BodyData data(model);
  const Posture g = standing_posture(Eigen::Vector3d(-0.5, 0.0, 1.2));
  const double needed = M * kG / 2.0 / mu;
  for (const double margin : {1.05, 0.95}) {
    const std::vector<PointContact> contacts = {
        contact_at(Limb::RightFoot, Eigen::Vector3d::UnitX(), mu, margin * needed),
        contact_at(Limb::LeftFoot, -Eigen::Vector3d::UnitX(), mu, margin * needed)};
    const StaticEquilibriumResult& result = equilibrium.solve(data, g, contacts);
    EXPECT_EQ(result.balanced, margin > 1.0) << margin;
    if (!result.balanced) continue;
    EXPECT_NEAR(result.contact_forces[2].z(), M * kG / 2.0, 1e-6);
    EXPECT_NEAR(result.contact_forces[3].z(), M * kG / 2.0, 1e-6);
    expect_checked(model, strength, g, contacts, result);
  }
}

// A torso of mass M0 hanging by one hand from a jug through a massless two-link arm in the
// x-z plane: shoulder at (sx, 0, sz) from the root, upper arm L1, forearm L2, both about y
// (a link along -z turned by theta ends at L (-sin theta, 0, -cos theta)). One point
// contact has no moment, so the hand must be straight above the centre of mass (the root):
// sx = L1 sin t1 + L2 sin(t1 + t2), and the hold pushes (0, 0, M0 g). Each joint then
// exerts tau_j = -(J_j^T f) = (p - o_j)_x M0 g: shoulder -sx M0 g, elbow
// -L2 sin(t1 + t2) M0 g; the effort is the larger ratio to its limit in that direction.
TEST(StaticEquilibrium, HangingTwoLinkArmHasTheClosedFormTorquesAndEffort) {
  constexpr double M0 = 60.0, sx = 0.1, sz = 0.4, L1 = 0.3, L2 = 0.25;
  const BodyModel model =
      small_body("hanging_arm.urdf", M0,
                 {{"shoulder", "torso", {sx, 0.0, sz}, 0.0, Eigen::Vector3d::Zero()},
                  {"elbow", "shoulder_link", {0.0, 0.0, -L1}, 0.0, Eigen::Vector3d::Zero()}},
                 {GraspFrame{"elbow_link", {0.0, 0.0, -L2}}, GraspFrame{}, GraspFrame{}, GraspFrame{}});
  const int shoulder = coordinate_named(model, "shoulder"), elbow = coordinate_named(model, "elbow");
  StrengthProfile strength;
  strength.joints[shoulder] = {100.0, 80.0};
  strength.joints[elbow] = {50.0, 70.0};
  StaticEquilibrium equilibrium(model, strength);
  BodyData data(model);
  const std::vector<PointContact> jug = {contact_at(Limb::RightHand, Eigen::Vector3d::UnitZ(), 0.5, 2000.0)};
  for (const double t1 : {M_PI - 0.6, M_PI - 0.2, M_PI + 0.3}) {
    const double forearm = M_PI + std::asin((L1 * std::sin(t1) - sx) / L2);  // t1 + t2, forearm up
    Posture g = Posture::Zero();
    g.head<kRootDof>() = Eigen::Vector3d(-0.4, 0.2, 1.1);
    g[shoulder] = t1;
    g[elbow] = forearm - t1;
    const double tau_shoulder = -sx * M0 * kG, tau_elbow = -L2 * std::sin(forearm) * M0 * kG;
    const auto ratio = [](double tau, const JointStrength& limit) {
      return tau >= 0 ? tau / limit.positive : -tau / limit.negative;
    };
    const double shoulder_ratio = ratio(tau_shoulder, strength.joints[shoulder]);
    const double elbow_ratio = ratio(tau_elbow, strength.joints[elbow]);
    const StaticEquilibriumResult& result = equilibrium.solve(data, g, jug);
    ASSERT_TRUE(result.balanced) << t1;
    EXPECT_NEAR(result.contact_forces[0].z(), M0 * kG, 1e-6);
    EXPECT_NEAR(result.joint_torques[shoulder], tau_shoulder, 1e-6);
    EXPECT_NEAR(result.joint_torques[elbow], tau_elbow, 1e-6);
    EXPECT_NEAR(result.effort, std::max(shoulder_ratio, elbow_ratio), 1e-9);
    EXPECT_EQ(result.binding_joint, shoulder_ratio > elbow_ratio ? shoulder : elbow);
    EXPECT_EQ(result.binding, result.joint_torques[result.binding_joint] > 0 ? EquilibriumBinding::JointPositive
                                                                             : EquilibriumBinding::JointNegative);
    EXPECT_EQ(result.feasible, result.effort <= 1.0);
    expect_checked(model, strength, g, jug, result);
  }
  // The hand 5 cm in front of the centre of mass: the weight's moment about the hand,
  // 0.05 m x M0 g, has no contact moment to balance it, whatever the friction or grip.
  Posture off_centre = Posture::Zero();
  off_centre[shoulder] = M_PI;
  off_centre[elbow] = 0.0;  // the hand straight above the shoulder, sx = 0.1 m in front of the root
  const StaticEquilibriumResult& result = equilibrium.solve(data, off_centre, jug);
  EXPECT_FALSE(result.balanced);
  EXPECT_EQ(result.binding, EquilibriumBinding::Contacts);
}

TEST(StaticEquilibrium, TwoContactsOfOneLimbAreAProgrammingError) {
  const BodyModel& model = testing::human_model();
  StaticEquilibrium equilibrium(model, published_strength_profile(model, 68.0, 1.70));
  BodyData data(model);
  const PointContact hand = contact_at(Limb::RightHand, Eigen::Vector3d::UnitZ(), 1.0, 500.0);
  const std::vector<PointContact> twice = {hand, hand};
  EXPECT_THROW(equilibrium.solve(data, standing_posture(Eigen::Vector3d(-0.3, 0.0, 1.0)), twice),
               std::invalid_argument);
}

std::vector<PointContact> climbing_contacts() {
  std::vector<PointContact> four;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const bool hand = limb < 2;
    four.push_back(
        contact_at(static_cast<Limb>(limb), Eigen::Vector3d(hand ? 1.0 : -1.0, 0.0, 1.0), 1.0, hand ? 500.0 : 1000.0));
  }
  return four;
}

// The human on the start stances of the repository's walls, solved by IK kept out of the
// wall: on its four holds every stance balances at a finite effort; on any three its effort
// is at least as large (fewer forces to choose from), and hanging by one hand, far from the
// centre of mass, it cannot balance at all. Test inputs, not data: incut jugs for the hands
// (the hold pushes up and into the wall, (1, 0, 1) / sqrt 2, so the hands can pull the body
// in), ledges for the feet (up and out of it, (-1, 0, 1) / sqrt 2); friction 1; grip 500 N a
// hand, push 1000 N a foot.
TEST(StaticEquilibrium, HumanStartStancesBalanceAndLosingHoldsNeverHelps) {
  const BodyModel& model = testing::human_model();
  const StrengthProfile strength = published_strength_profile(model, 68.0, 1.70);
  StaticEquilibrium equilibrium(model, strength);
  BodyData data(model);
  IkParameters ik;
  ik.wall = WallRule::Avoid;
  int solved = 0;
  for (const char* wall_name : {"home_12.json", "board_140.json", "tall_400.json"}) {
    const Wall wall = load_wall(std::string(CRUX_SOURCE_DIR) + "/walls/" + wall_name);
    ReachTarget target;
    for (int limb = 0; limb < kLimbCount; ++limb) target.hold_centres[limb] = wall.holds[wall.start[limb]].position;
    target.root = root_target(model, target.hold_centres);
    const IkResult reached = solve_ik(model, data, standing_posture(target.root), target, ik);
    if (!reached.reached) continue;
    ++solved;
    const std::vector<PointContact> four = climbing_contacts();
    const StaticEquilibriumResult on_four = equilibrium.solve(data, reached.posture, four);
    ASSERT_TRUE(on_four.balanced) << wall_name;
    EXPECT_TRUE(std::isfinite(on_four.effort)) << wall_name;
    expect_checked(model, strength, reached.posture, four, on_four);
    for (int free_limb = 0; free_limb < kLimbCount; ++free_limb) {
      std::vector<PointContact> three;
      for (const PointContact& contact : four) {
        if (static_cast<int>(contact.limb) != free_limb) three.push_back(contact);
      }
      const StaticEquilibriumResult& on_three = equilibrium.solve(data, reached.posture, three);
      EXPECT_GE(on_three.effort, on_four.effort - 1e-7) << wall_name << " without " << free_limb;
      if (on_three.balanced) expect_checked(model, strength, reached.posture, three, on_three);
    }
    const std::vector<PointContact> one_hand = {four[0]};
    const StaticEquilibriumResult& hanging = equilibrium.solve(data, reached.posture, one_hand);
    EXPECT_FALSE(hanging.balanced) << wall_name;
    EXPECT_GT(hanging.effort, on_four.effort) << wall_name;
  }
  EXPECT_GT(solved, 0) << "no start stance reached";
}

// The same stances solved by a fresh program each time and by one reused (warm-started)
// program agree, in either order.
TEST(StaticEquilibrium, WarmStartsGiveTheColdSolvesEffort) {
  const BodyModel& model = testing::human_model();
  const StrengthProfile strength = published_strength_profile(model, 68.0, 1.70);
  StaticEquilibrium reused(model, strength);
  BodyData data(model);
  Random random(2026);
  const std::vector<PointContact> four = climbing_contacts();
  int balanced = 0;
  for (int sample = 0; sample < 200; ++sample) {
    const Posture g = testing::random_posture(model, random);
    const StaticEquilibriumResult warm = reused.solve(data, g, four);
    StaticEquilibrium fresh(model, strength);
    const StaticEquilibriumResult& cold = fresh.solve(data, g, four);
    ASSERT_EQ(warm.balanced, cold.balanced) << "sample " << sample;
    if (!warm.balanced) continue;
    ++balanced;
    EXPECT_NEAR(warm.effort, cold.effort, 1e-6 * std::max(1.0, cold.effort)) << "sample " << sample;
    expect_checked(model, strength, g, four, warm);
  }
  EXPECT_GT(balanced, 0);
}

// After forget_basis a solve is the cold one, bit for bit, torques included: a warm start
// may end on another optimal vertex of a degenerate program, with the same effort.
TEST(StaticEquilibrium, AForgottenBasisSolvesAsTheFirstSolveDid) {
  const BodyModel& model = testing::human_model();
  const StrengthProfile strength = published_strength_profile(model, 68.0, 1.70);
  StaticEquilibrium equilibrium(model, strength);
  BodyData data(model);
  const unsigned seed = 2027;
  Random random(seed);
  const std::vector<PointContact> four = climbing_contacts();
  const Posture first = testing::random_posture(model, random);
  const StaticEquilibriumResult cold = equilibrium.solve(data, first, four);
  for (int sample = 0; sample < 20; ++sample) equilibrium.solve(data, testing::random_posture(model, random), four);
  equilibrium.forget_basis();
  const StaticEquilibriumResult& again = equilibrium.solve(data, first, four);
  EXPECT_EQ(again.balanced, cold.balanced) << "seed " << seed;
  EXPECT_EQ(again.effort, cold.effort) << "seed " << seed;
  EXPECT_EQ(again.joint_torques, cold.joint_torques) << "seed " << seed;
}

}  // namespace
}  // namespace crux
