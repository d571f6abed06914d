#include "ik/wall_clearance.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "body/wall_penetration.hpp"
#include "ik/reach_queries.hpp"
#include "support/sample_count.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

// The head (a sphere of radius 0.1105 m above the root) is the deepest part of a body
// standing 0.05 m off the wall: one row, its excess past the 0.01 m skin margin.
TEST(WallClearance, OneRowPerPrimitivePastTheSkinMargin) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  WallClearance clearance;
  forward_kinematics(model, data, standing_posture({-0.30, 0.6, 1.0}));
  wall_clearance(model, data, clearance);
  EXPECT_TRUE(clearance.clear());
  EXPECT_EQ(clearance.cost(), 0.0);
  forward_kinematics(model, data, standing_posture({-0.05, 0.6, 1.0}));
  wall_clearance(model, data, clearance);
  ASSERT_GE(clearance.rows, 1);
  double deepest = 0.0, sum = 0.0;
  for (int r = 0; r < clearance.rows; ++r) {
    EXPECT_GT(clearance.excess[r], 0.0);
    deepest = std::max(deepest, clearance.excess[r]);
    sum += clearance.excess[r] * clearance.excess[r];
    EXPECT_DOUBLE_EQ(clearance.gradient[r][0], 1.0) << "the root's x moves every point along x";
  }
  EXPECT_NEAR(deepest, -0.05 + 0.1105 - kWallSkinMargin, 1e-12);
  EXPECT_DOUBLE_EQ(clearance.cost(), 0.5 * sum);
}

// ik.wall = reject is ignore's verdict and posture, refused when the posture passes
// through the wall; ik.wall = avoid reaches only postures clear of it, and reaches some
// whose ignore solution passes through. 300 climbing-like queries (a tenth under the
// sanitizers: support/sample_count.hpp), both solvers.
TEST(WallClearance, RejectRefusesWhatPassesThroughAndAvoidReachesOnlyPosturesClearOfTheWall) {
  const BodyModel& model = testing::human_model();
  constexpr std::uint64_t kSeed = 24;
  const auto queries = climbing_reach_queries(model, IkParameters{}, testing::sample_count(300), kSeed);
  BodyData data(model);
  for (const IkSolverKind solver : {IkSolverKind::Fast, IkSolverKind::Paper}) {
    IkParameters ignore;
    ignore.solver = solver;
    IkParameters reject = ignore, avoid = ignore;
    reject.wall = WallRule::Reject;
    avoid.wall = WallRule::Avoid;
    int rescued = 0, avoided = 0;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      const ReachQuery& query = queries[q];
      const IkResult free = solve_ik(model, data, query.start, query.target, ignore);
      const bool through = wall_penetration(model, data).passes_through();
      const IkResult refused = solve_ik(model, data, query.start, query.target, reject);
      ASSERT_EQ(refused.reached, free.reached && !through)
          << "seed " << kSeed << " query " << q << " solver " << enum_name(solver);
      const IkResult kept_out = solve_ik(model, data, query.start, query.target, avoid);
      if (!kept_out.reached) continue;
      ++avoided;
      EXPECT_FALSE(wall_penetration(model, data).passes_through())
          << "seed " << kSeed << " query " << q << " solver " << enum_name(solver);
      EXPECT_TRUE(target_reached(data.points, query.target, avoid.tolerances));
      if (free.reached && through) ++rescued;
    }
    EXPECT_GT(avoided, 0) << enum_name(solver);
    EXPECT_GT(rescued, 0) << enum_name(solver) << ": no query that ignore reaches through the wall";
  }
}

}  // namespace
}  // namespace crux
