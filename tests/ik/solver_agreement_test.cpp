#include "ik/solver_agreement.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"

namespace crux {
namespace {

// The acceptance figure: over 2000 climbing-like queries the two solvers'
// reachability verdicts agree on at least 97 %.
TEST(SolverAgreement, AtLeast97PercentOver2000ClimbingQueries) {
  const BodyModel& model = testing::human_model();
  const IkParameters settings;
  IkParameters walk = settings;
  walk.solver = IkSolverKind::Paper;  // as crux ik-compare does by default
  constexpr std::uint64_t seed = 1;
  const auto queries = climbing_reach_queries(model, walk, 2000, seed);
  const SolverAgreement a = compare_solvers(model, queries, settings);
  EXPECT_EQ(a.queries, 2000);
  EXPECT_GE(a.agreement(), 0.97) << "seed " << seed << ": only paper " << a.only_paper_reached << ", only fast "
                                 << a.only_fast_reached;
  EXPECT_GT(a.far_queries, 0);
  EXPECT_GT(a.fast_reached, 0);
}

}  // namespace
}  // namespace crux
