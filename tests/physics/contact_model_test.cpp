#include "physics/contact_model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include "common/input_error.hpp"
#include "common/random.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kContactSeed = 20261129;

PointContact contact_with(const Eigen::Vector3d& support, double friction) {
  PointContact contact;
  contact.limb = Limb::LeftFoot;
  contact.support_direction = support.normalized();
  contact.friction = friction;
  contact.normal_force_limit = 800.0;
  return contact;
}

// Every edge has normal component 1 and lies on the round cone's surface; the first points
// up the contact plane, and the edges turn by 2 pi / faces about the support direction.
TEST(ContactModel, GeneratorsAreTheInscribedPyramidsEdgesStartingUpTheContactPlane) {
  for (const Eigen::Vector3d& support :
       {Eigen::Vector3d(-1.0, 0.0, 1.0), Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(-1.0, 0.3, -0.2)}) {
    const PointContact contact = contact_with(support, 0.6);
    const FrictionConeGenerators edges = friction_cone_generators(contact);
    const Eigen::Vector3d& n = contact.support_direction;
    for (int k = 0; k < kFrictionConeFaces; ++k) {
      EXPECT_NEAR(edges[k].dot(n), 1.0, 1e-12);
      EXPECT_NEAR((edges[k] - n).norm(), 0.6, 1e-12);
      EXPECT_TRUE(inside_friction_cone(contact, edges[k], 1e-12));
      const Eigen::Vector3d next = edges[(k + 1) % kFrictionConeFaces] - n, here = edges[k] - n;
      EXPECT_NEAR(here.cross(next).dot(n) / (0.6 * 0.6), std::sin(2 * M_PI / kFrictionConeFaces), 1e-12);
    }
    const Eigen::Vector3d up_the_plane = (Eigen::Vector3d::UnitZ() - n.z() * n);
    if (up_the_plane.norm() > 1e-9) {
      EXPECT_NEAR((edges[0] - n).normalized().dot(up_the_plane.normalized()), 1.0, 1e-12);
    }
  }
}

TEST(ContactModel, InsideTheConeIsCoulombsInequality) {
  const PointContact contact = contact_with(Eigen::Vector3d::UnitZ(), 0.5);
  EXPECT_TRUE(inside_friction_cone(contact, Eigen::Vector3d(30.0, 40.0, 100.0), 1e-9));  // 50 <= 0.5 x 100
  EXPECT_FALSE(inside_friction_cone(contact, Eigen::Vector3d(30.0, 40.1, 100.0), 1e-9));
  EXPECT_FALSE(inside_friction_cone(contact, Eigen::Vector3d(0.0, 0.0, -1.0), 1e-9));  // a hold cannot pull
}

// Hand-computed on a jug's top (n = +z, so the edges' axes are x and y), mu = 0.5: the
// pyramid admits |f_x| + |f_y| <= 0.5 f_z, inside the round cone, and every combination
// of its edges with weights >= 0.
TEST(ContactModel, InsideThePyramidIsWhatItsEdgesSpan) {
  PointContact top;
  top.support_direction = Eigen::Vector3d::UnitZ();
  top.friction = 0.5;
  EXPECT_TRUE(inside_friction_pyramid(top, {0.2, -0.3, 1.0}, 1e-12));
  EXPECT_FALSE(inside_friction_pyramid(top, {0.3, 0.3, 1.0}, 1e-12)) << "0.6 > 0.5";
  EXPECT_TRUE(inside_friction_cone(top, {0.3, 0.3, 1.0}, 1e-12)) << "0.42 < 0.5: the round cone admits it";
  EXPECT_FALSE(inside_friction_pyramid(top, {0.0, 0.0, -1.0}, 1e-12)) << "a hold cannot pull";
  PointContact lip;
  lip.support_direction = Eigen::Vector3d(std::sqrt(0.5), 0.0, std::sqrt(0.5));
  lip.friction = 0.8;
  Random random(kContactSeed);
  const FrictionConeGenerators edges = friction_cone_generators(lip);
  for (int sample = 0; sample < 1000; ++sample) {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& edge : edges) force += random.uniform(0.0, 100.0) * edge;
    ASSERT_TRUE(inside_friction_pyramid(lip, force, 1e-9)) << "seed " << kContactSeed << " sample " << sample;
    // Past an edge by a newton along the tangent that edge points to.
    const Eigen::Vector3d outward = (edges[sample % 4] - lip.support_direction).normalized();
    const Eigen::Vector3d beyond = 100.0 * edges[sample % 4] + outward;
    ASSERT_FALSE(inside_friction_pyramid(lip, beyond, 1e-9)) << "seed " << kContactSeed << " sample " << sample;
  }
}

TEST(ContactModel, BadContactsAreRefusedWithOneLineNamingTheLimb) {
  const PointContact good = contact_with(Eigen::Vector3d::UnitZ(), 0.5);
  EXPECT_NO_THROW(check_contact(good, "stance"));
  PointContact unbounded = good;
  unbounded.normal_force_limit = std::numeric_limits<double>::infinity();
  EXPECT_NO_THROW(check_contact(unbounded, "stance"));
  PointContact bad = good;
  bad.friction = -0.1;
  EXPECT_THROW(check_contact(bad, "stance"), InputError);
  bad = good;
  bad.normal_force_limit = -1.0;
  EXPECT_THROW(check_contact(bad, "stance"), InputError);
  bad = good;
  bad.support_direction = Eigen::Vector3d(0.0, 0.0, 2.0);
  try {
    check_contact(bad, "stance");
    FAIL() << "a support direction of length 2 was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "stance: the support direction of the left_foot must be a unit vector, not of length 2");
  }
}

}  // namespace
}  // namespace crux
