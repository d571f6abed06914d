#include "body/wall_penetration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "body/kinematics.hpp"
#include "common/random.hpp"
#include "support/sample_count.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

JointPlacement turned(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& origin) {
  return {rotation, origin, Eigen::Vector3d::UnitZ()};
}

// The deepest point of each shape, computed by hand: a box and a cylinder turned by known
// angles, a sphere.
TEST(WallPenetration, TheDeepestPointOfEachShapeIsItsSupportAlongPlusX) {
  const double angle = std::numbers::pi / 6;  // 30 degrees about z, then the box's half sizes 0.1, 0.2, 0.3
  const Eigen::Matrix3d about_z = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  BodyVisual box;
  box.shape = VisualShape::Box;
  box.size = {0.2, 0.4, 0.6};
  const Eigen::Vector3d origin(-0.5, 1.0, 2.0);
  EXPECT_NEAR(deepest_point(box, turned(about_z, origin)).x(), -0.5 + 0.1 * std::cos(angle) + 0.2 * std::sin(angle),
              1e-15);

  // A cylinder of radius 0.05 and length 0.4 tilted 30 degrees about y: its axis leans
  // towards +x by sin 30, so the deepest point is the upper end's rim.
  BodyVisual cylinder;
  cylinder.shape = VisualShape::Cylinder;
  cylinder.size = {0.05, 0.4, 0.0};
  const Eigen::Matrix3d about_y = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_NEAR(deepest_point(cylinder, turned(about_y, origin)).x(),
              -0.5 + 0.2 * std::sin(angle) + 0.05 * std::cos(angle), 1e-15);
  // Upright, its rim: radius in +x.
  EXPECT_NEAR(deepest_point(cylinder, turned(Eigen::Matrix3d::Identity(), origin)).x(), -0.45, 1e-15);

  BodyVisual sphere;
  sphere.shape = VisualShape::Sphere;
  sphere.size = {0.07, 0.0, 0.0};
  sphere.translation = {0.0, 0.0, 0.1};
  EXPECT_EQ(deepest_point(sphere, turned(about_y, Eigen::Vector3d::Zero())),
            about_y * Eigen::Vector3d(0, 0, 0.1) + Eigen::Vector3d(0.07, 0, 0));
}

// No point of a primitive's surface lies deeper: 2000 points sampled on each shape,
// turned at random, never pass the deepest point's x, and the deepest point is one of
// the shape's own (a box's best corner; a cylinder's best of 20,000 rim points, within
// a micrometre).
TEST(WallPenetration, NoSurfacePointLiesDeeperThanTheDeepestPoint) {
  constexpr std::uint64_t kSeed = 2311;
  Random random(kSeed);
  for (const VisualShape shape : {VisualShape::Box, VisualShape::Cylinder}) {
    for (int trial = 0; trial < 20; ++trial) {
      BodyVisual visual;
      visual.shape = shape;
      visual.size =
          shape == VisualShape::Box
              ? Eigen::Vector3d(random.uniform(0.05, 0.5), random.uniform(0.05, 0.5), random.uniform(0.05, 0.5))
              : Eigen::Vector3d(random.uniform(0.02, 0.1), random.uniform(0.1, 0.5), 0.0);
      const Eigen::Quaterniond q =
          Eigen::Quaterniond(random.normal(), random.normal(), random.normal(), random.normal()).normalized();
      const JointPlacement carrier = turned(q.toRotationMatrix(), Eigen::Vector3d(random.uniform(-1, 1), 0, 0));
      const double deepest = deepest_point(visual, carrier).x();
      const auto world_x = [&](const Eigen::Vector3d& local) {
        return (carrier.origin + carrier.rotation * local).x();
      };
      for (int s = 0; s < 2000; ++s) {
        Eigen::Vector3d local;
        if (shape == VisualShape::Box) {
          local = Eigen::Vector3d(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5))
                      .cwiseProduct(visual.size);
          const int face = static_cast<int>(random.below(3));
          local[face] = (random.uniform() < 0.5 ? -0.5 : 0.5) * visual.size[face];
        } else {
          const double around = random.uniform(0, 2 * std::numbers::pi);
          local = Eigen::Vector3d(visual.size.x() * std::cos(around), visual.size.x() * std::sin(around),
                                  random.uniform(-0.5, 0.5) * visual.size.y());
        }
        ASSERT_LE(world_x(local), deepest + 1e-12) << "seed " << kSeed << " trial " << trial;
      }
      double best = -1e9;
      if (shape == VisualShape::Box) {
        for (int corner = 0; corner < 8; ++corner) {
          best = std::max(best, world_x(Eigen::Vector3d((corner & 1 ? 0.5 : -0.5) * visual.size.x(),
                                                        (corner & 2 ? 0.5 : -0.5) * visual.size.y(),
                                                        (corner & 4 ? 0.5 : -0.5) * visual.size.z())));
        }
        EXPECT_NEAR(best, deepest, 1e-12) << "seed " << kSeed << " trial " << trial;
      } else {
        for (int k = 0; k < 10000; ++k) {
          const double around = 2 * std::numbers::pi * k / 10000;
          for (const double end : {-0.5, 0.5}) {
            best = std::max(best, world_x(Eigen::Vector3d(visual.size.x() * std::cos(around),
                                                          visual.size.x() * std::sin(around), end * visual.size.y())));
          }
        }
        EXPECT_NEAR(best, deepest, 1e-6) << "seed " << kSeed << " trial " << trial;
      }
    }
  }
}

// The gradient of each counted primitive's deepest x against central differences, on
// 100 random postures (a tenth under the sanitizers: support/sample_count.hpp).
TEST(WallPenetration, TheDeepestXGradientMatchesCentralDifferences) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  constexpr std::uint64_t kSeed = 2612;
  Random random(kSeed);
  const double h = 1e-6;
  Posture gradient;
  for (int sample = 0; sample < testing::sample_count(100); ++sample) {
    const Posture g = testing::random_posture(model, random, {-0.3, 0.6, 1.0});
    for (int v = 0; v < static_cast<int>(model.visuals.size()); ++v) {
      const BodyVisual& visual = model.visuals[v];
      if (!counts_for_the_wall(model, visual)) continue;
      forward_kinematics(model, data, g);
      deepest_x_gradient(model, data, v, gradient);
      for (int i = 0; i < kConfigurationDof; ++i) {
        Posture plus = g, minus = g;
        plus[i] += h;
        minus[i] -= h;
        forward_kinematics(model, data, plus);
        const double up = deepest_point(visual, data.placements[visual.joint]).x();
        forward_kinematics(model, data, minus);
        const double down = deepest_point(visual, data.placements[visual.joint]).x();
        ASSERT_NEAR(gradient[i], (up - down) / (2 * h), 1e-6)
            << "seed " << kSeed << " sample " << sample << " " << visual.link << " coordinate " << i;
      }
    }
  }
}

// The human standing 0.30 m off the wall is clear of it; 0.05 m off, its head (a sphere
// of radius 0.1105 m above the root, the body's deepest part forward) is 0.0605 m
// inside. The feet, whose toes reach past the plane first, are not counted.
TEST(WallPenetration, ABodyTooCloseToTheWallPassesThroughItAndTheFeetAreNotCounted) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  forward_kinematics(model, data, standing_posture({-0.30, 0.6, 1.0}));
  const WallPenetration clear = wall_penetration(model, data);
  EXPECT_FALSE(clear.passes_through());
  EXPECT_NEAR(clear.depth_m, -0.30 + 0.1105, 1e-12) << "the head's front";
  forward_kinematics(model, data, standing_posture({-0.15, 0.6, 1.0}));
  EXPECT_GT(data.points[operational_point(Limb::RightFoot)].x(), -0.15 + 0.1) << "the toes reach past -0.05";
  EXPECT_LT(wall_penetration(model, data).depth_m, 0.0) << "toes inside the wall, but feet are not counted";
  forward_kinematics(model, data, standing_posture({-0.05, 0.6, 1.0}));
  const WallPenetration inside = wall_penetration(model, data);
  EXPECT_TRUE(inside.passes_through());
  EXPECT_NEAR(inside.depth_m, -0.05 + 0.1105, 1e-12);
  EXPECT_EQ(model.visuals[inside.visual].link, "head");
}

}  // namespace
}  // namespace crux
