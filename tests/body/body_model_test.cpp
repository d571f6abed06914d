#include "body/body_model.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(BodyModel, StandingPostureHasTheRootWhereAskedAndEveryAngleZero) {
  const Posture g = standing_posture({0.3, -0.1, 1.0});
  EXPECT_EQ(g.head<kRootDof>(), Eigen::Vector3d(0.3, -0.1, 1.0));
  EXPECT_TRUE(g.tail<kRevoluteDof>().isZero());
}

TEST(BodyModel, WithinLimitsChecksEveryJointButNotTheFreeRoot) {
  const BodyModel& model = testing::human_model();
  Posture g = standing_posture({100.0, -50.0, 7.0});
  EXPECT_TRUE(within_limits(model, g)) << "the root translates freely";
  g[kRootDof] = model.upper_limits[kRootDof] + 1e-9;
  EXPECT_FALSE(within_limits(model, g));
  g[kRootDof] = model.lower_limits[kRootDof];
  EXPECT_TRUE(within_limits(model, g)) << "a limit itself is inside";
}

}  // namespace
}  // namespace crux
