#include "body/gravity_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "support/allocation_counter.hpp"
#include "support/mujoco_reference.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kGravitySeed = 20261125;
constexpr double kGravityMagnitude = 9.81;

// The human's gravity forces against MuJoCo's bias at rest, which is their negative. The
// tolerance, 1e-9 N or N m, holds although MuJoCo's model carries the nanogram bounds of
// the massless links (at most 25 x 1e-12 kg x 9.81 m/s^2 = 2.5e-10 N on the root).
void expect_gravity_as_mujoco(const std::string& urdf_path, const BodyModel& model, std::uint64_t seed) {
  testing::MujocoReference mujoco(urdf_path, model);
  BodyData data(model);
  Random random(seed);
  for (int sample = 0; sample < 1000; ++sample) {
    const Posture g = testing::random_posture(model, random);
    const GeneralisedForce forces = gravity_forces(model, data, g);
    mujoco.set_posture(g);
    const Posture holding = mujoco.bias_forces();
    for (int i = 0; i < kConfigurationDof; ++i) {
      ASSERT_NEAR(forces[i], -holding[i], 1e-9)
          << "seed " << seed << " sample " << sample << " coordinate " << model.joints[i].name;
    }
  }
}

TEST(GravityForces, HumanAgreesWithMujocoOver1000RandomPostures) {
  expect_gravity_as_mujoco(default_body_model_path(), testing::human_model(), kGravitySeed);
}

TEST(GravityForces, SyntheticTreeAgreesWithMujocoOver1000RandomPostures) {
  const auto path =
      testing::write_temporary("synthetic_gravity.urdf", testing::synthetic_tree_urdf_for_mujoco(kGravitySeed));
  expect_gravity_as_mujoco(path.string(), load_body_model(path.string()), kGravitySeed + 1);
}

// A link of a hanging chain: a revolute joint about y at `origin` in the previous link (the
// torso for the first), carrying `mass` at distance `centre` below the joint.
struct HangingLink {
  std::string joint;
  Eigen::Vector3d origin;
  double mass, centre;
};

// A body that loads as crux's bodies do (3 root translations, 32 revolute joints, the four
// grasp frames), all of whose mass hangs on `links` from a massless torso: the remaining
// revolute joints are a massless chain, on which gravity exerts nothing.
BodyModel hanging_chain_model(const std::string& name, const std::vector<HangingLink>& links) {
  std::string urdf = "<robot name=\"hanging\">" + testing::root_translations_urdf() + "<link name=\"torso\"/>";
  const auto revolute = [&](const std::string& joint, const std::string& parent, const std::string& child,
                            const Eigen::Vector3d& origin, const char* axis) {
    urdf += fmt::format(
        "<joint name=\"{}\" type=\"revolute\"><parent link=\"{}\"/><child link=\"{}\"/>"
        "<origin xyz=\"{} {} {}\" rpy=\"0 0 0\"/><axis xyz=\"{}\"/>"
        "<limit lower=\"-3.1\" upper=\"3.1\" effort=\"1\" velocity=\"1\"/></joint>",
        joint, parent, child, origin.x(), origin.y(), origin.z(), axis);
  };
  std::string parent = "torso";
  for (const HangingLink& link : links) {
    const std::string child = link.joint + "_link";
    urdf += fmt::format(
        "<link name=\"{}\"><inertial><origin xyz=\"0 0 {}\"/><mass value=\"{}\"/>"
        "<inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial></link>",
        child, -link.centre, link.mass);
    revolute(link.joint, parent, child, link.origin, "0 1 0");
    parent = child;
  }
  parent = "torso";
  for (int i = static_cast<int>(links.size()); i < kRevoluteDof; ++i) {
    const std::string child = fmt::format("massless_{}", i);
    urdf += fmt::format("<link name=\"{}\"/>", child);
    revolute(fmt::format("massless_joint_{}", i), parent, child, Eigen::Vector3d(0.0, 0.05, 0.1), "0 0 1");
    parent = child;
  }
  for (const char* frame : {"right_palm", "left_palm", "right_foot_ball", "left_foot_ball"}) {
    urdf += fmt::format(
        "<link name=\"{0}\"/><joint name=\"{0}_fixed\" type=\"fixed\"><parent link=\"{1}\"/>"
        "<child link=\"{0}\"/></joint>",
        frame, parent);
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

// Every coordinate: the root translations carry all the mass, the named joints have their
// closed forms, and the massless chain feels nothing.
void expect_hanging_forces(const BodyModel& model, const Posture& g, const Eigen::Vector3d& gravity, double total_mass,
                           const std::vector<std::pair<std::string, double>>& closed_forms) {
  BodyData data(model);
  const GeneralisedForce forces = gravity_forces(model, data, g, gravity);
  GeneralisedForce expected = GeneralisedForce::Zero();
  expected.head<kRootDof>() = total_mass * gravity;
  for (const auto& [joint, force] : closed_forms) expected[coordinate_named(model, joint)] = force;
  for (int i = 0; i < kConfigurationDof; ++i) {
    EXPECT_NEAR(forces[i], expected[i], 1e-12) << model.joints[i].name << " at " << g.transpose();
  }
}

// A bob of mass m at l below a pivot about y, swung by theta: it sits at l (-sin theta, 0,
// -cos theta) from the pivot, so gravity (gx, 0, gz) exerts m l (gz sin theta - gx cos theta).
TEST(GravityForces, SinglePendulumHasTheClosedForm) {
  constexpr double m = 3.0, l = 0.4;
  const BodyModel model = hanging_chain_model("pendulum.urdf", {{"swing", {0.1, 0.2, 0.3}, m, l}});
  const int swing = coordinate_named(model, "swing");
  for (const double theta : {0.0, 0.3, -1.1, M_PI / 2, 2.5}) {
    Posture g = Posture::Zero();
    g.head<kRootDof>() = Eigen::Vector3d(0.3, -0.2, 1.1);
    g[swing] = theta;
    expect_hanging_forces(model, g, kStandardGravity, m, {{"swing", -m * kGravityMagnitude * l * std::sin(theta)}});
    // Gravity tilted by 40 degrees towards +x, as on an inclined wall.
    const double tilt = 40.0 * M_PI / 180.0;
    const Eigen::Vector3d tilted(kGravityMagnitude * std::sin(tilt), 0.0, -kGravityMagnitude * std::cos(tilt));
    expect_hanging_forces(model, g, tilted, m,
                          {{"swing", m * l * (tilted.z() * std::sin(theta) - tilted.x() * std::cos(theta))}});
  }
}

// An upper arm (m1, centre a1 below the shoulder, length L1) and a forearm (m2, centre a2
// below the elbow), both about y: the potential energy is -g (m1 a1 cos t1 + m2 (L1 cos t1
// + a2 cos(t1 + t2))), whose negative gradient is
//   shoulder: -g ((m1 a1 + m2 L1) sin t1 + m2 a2 sin(t1 + t2)),  elbow: -g m2 a2 sin(t1 + t2).
TEST(GravityForces, HangingTwoLinkArmHasTheClosedForm) {
  constexpr double m1 = 2.0, a1 = 0.15, L1 = 0.3, m2 = 1.2, a2 = 0.12;
  const BodyModel model = hanging_chain_model(
      "two_link_arm.urdf", {{"shoulder", {0.0, -0.2, 0.4}, m1, a1}, {"elbow", {0.0, 0.0, -L1}, m2, a2}});
  const int shoulder = coordinate_named(model, "shoulder"), elbow = coordinate_named(model, "elbow");
  const std::pair<double, double> angles[] = {{0.0, 0.0}, {0.5, 0.0}, {0.0, 1.0}, {-0.7, 1.9}, {2.0, -2.4}};
  for (const auto& [t1, t2] : angles) {
    Posture g = Posture::Zero();
    g.head<kRootDof>() = Eigen::Vector3d(-0.3, 0.1, 1.2);
    g[shoulder] = t1;
    g[elbow] = t2;
    const double s1 = std::sin(t1), s12 = std::sin(t1 + t2);
    expect_hanging_forces(model, g, kStandardGravity, m1 + m2,
                          {{"shoulder", -kGravityMagnitude * ((m1 * a1 + m2 * L1) * s1 + m2 * a2 * s12)},
                           {"elbow", -kGravityMagnitude * m2 * a2 * s12}});
  }
}

// tau_g = -dV/dG with V = -M gravity . c(G), c the centre of mass, by central differences.
void expect_minus_potential_gradient(const BodyModel& model, const Eigen::Vector3d& gravity, std::uint64_t seed) {
  BodyData data(model), probe(model);
  Random random(seed);
  const auto potential = [&](const Posture& g) {
    forward_kinematics(model, probe, g);
    return -model.total_mass * gravity.dot(centre_of_mass(model, probe));
  };
  constexpr double h = 1e-5;
  for (int sample = 0; sample < 100; ++sample) {
    const Posture g = testing::random_posture(model, random);
    const GeneralisedForce forces = gravity_forces(model, data, g, gravity);
    for (int i = 0; i < kConfigurationDof; ++i) {
      Posture plus = g, minus = g;
      plus[i] += h;
      minus[i] -= h;
      ASSERT_NEAR(forces[i], -(potential(plus) - potential(minus)) / (2 * h), 1e-6)
          << "seed " << seed << " sample " << sample << " coordinate " << model.joints[i].name;
    }
  }
}

TEST(GravityForces, AreMinusTheGradientOfThePotentialEnergy) {
  expect_minus_potential_gradient(testing::human_model(), kStandardGravity, kGravitySeed + 2);
  expect_minus_potential_gradient(testing::human_model(), Eigen::Vector3d(3.0, -1.0, -9.2), kGravitySeed + 3);
  const auto synthetic =
      testing::write_temporary("synthetic_potential.urdf", testing::synthetic_tree_urdf(kGravitySeed));
  expect_minus_potential_gradient(load_body_model(synthetic.string()), kStandardGravity, kGravitySeed + 4);
}

TEST(GravityForces, DoNotAllocate) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  Random random(kGravitySeed);
  const Posture g = testing::random_posture(model, random);
  const long before = testing::allocation_count();
  double sum = 0.0;
  for (int n = 0; n < 10; ++n) sum += gravity_forces(model, data, g).sum();
  EXPECT_EQ(testing::allocation_count(), before);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace crux
