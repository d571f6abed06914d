#include "ik/ik_demo.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"

namespace crux {
namespace {

// Five queries with both solvers; the reachable moves are reached by both and the 3 m
// reach by neither.
TEST(IkDemo, BothSolversAnswerEveryQuery) {
  const BodyModel& model = testing::human_model();
  const auto solves = run_ik_demo(model);
  ASSERT_EQ(solves.size(), 10u);
  for (std::size_t i = 0; i < solves.size(); i += 2) {
    EXPECT_EQ(solves[i].query, solves[i + 1].query);
    EXPECT_EQ(solves[i].solver, IkSolverKind::Paper);
    EXPECT_EQ(solves[i + 1].solver, IkSolverKind::Fast);
    const bool impossible = solves[i].query.find("no body can") != std::string::npos;
    EXPECT_EQ(solves[i].result.reached, !impossible) << solves[i].query;
    EXPECT_EQ(solves[i + 1].result.reached, !impossible) << solves[i].query;
  }
}

}  // namespace
}  // namespace crux
