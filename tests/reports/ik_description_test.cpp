#include "reports/ik_description.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "ik/reach_queries.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

// The start layout solved from standing: the JSON places the body at the returned
// posture, the text says what was reached.
TEST(IkDescription, AResultIsDescribedAtItsPosture) {
  const BodyModel& model = testing::human_model();
  ReachTarget target;
  target.hold_centres = start_layout_holds();
  target.root = root_target(model, target.hold_centres);
  BodyData data(model);
  const IkParameters settings;
  const IkResult result = solve_ik(model, data, standing_posture(target.root), target, settings);
  ASSERT_TRUE(result.reached);
  const auto json = ik_result_json(model, IkSolverKind::Fast, target, result);
  EXPECT_EQ(json["solver"], "fast");
  EXPECT_EQ(json["reached"], true);
  EXPECT_EQ(json["iterations"], result.iterations);
  forward_kinematics(model, data, result.posture);
  for (int limb = 0; limb < kLimbCount; ++limb) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_DOUBLE_EQ(json["grasp_points"][limb][c].get<double>(), data.points[operational_point(limb)][c]);
    }
  }
  EXPECT_EQ(json["posture"].size(), static_cast<std::size_t>(kConfigurationDof));
  const std::string text = ik_result_text(model, IkSolverKind::Fast, target, result);
  EXPECT_EQ(text.rfind("solver fast: reached after ", 0), 0u) << text;
  EXPECT_EQ(text.find("G_init"), std::string::npos) << "only an unreached query returns G_init";

  IkResult missed = result;
  missed.reached = false;
  EXPECT_NE(ik_result_text(model, IkSolverKind::Paper, target, missed).find("NOT reached"), std::string::npos);
}

// Hand-made counts: 10 queries, 9 agreeing, means per query.
TEST(IkDescription, AgreementIsCountedPerQuery) {
  SolverAgreement a;
  a.queries = 10;
  a.agree = 9;
  a.paper_reached = 4;
  a.fast_reached = 5;
  a.only_fast_reached = 1;
  a.far_queries = 2;
  a.paper_iterations = 1000;
  a.fast_iterations = 150;
  a.paper_seconds = 0.01;
  a.fast_seconds = 0.0005;
  const auto json = solver_agreement_json(a, 7);
  EXPECT_EQ(json["seed"], 7);
  EXPECT_DOUBLE_EQ(json["agreement"].get<double>(), 0.9);
  EXPECT_DOUBLE_EQ(json["paper_mean_iterations"].get<double>(), 100.0);
  EXPECT_DOUBLE_EQ(json["fast_mean_us"].get<double>(), 50.0);
  const std::string text = solver_agreement_text(a, 7);
  EXPECT_NE(text.find("10 climbing-like queries (seed 7, 2 of them clearly unreachable)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("verdicts agree on 9 queries: 90.00 % (only paper reached 0, only fast reached 1)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("paper 100.0 iterations, 1000.0 us; fast 15.0 iterations, 50.0 us"), std::string::npos) << text;
  a.queries = 1;
  a.agree = 1;
  const std::string one = solver_agreement_text(a, 7);
  EXPECT_EQ(one.rfind("1 climbing-like query (seed 7,", 0), 0u) << one;
  EXPECT_NE(one.find("verdicts agree on 1 query: "), std::string::npos) << one;
}

// The demo's ten solves (tests/ik/ik_demo_test.cpp checks the verdicts) as JSON and text.
TEST(IkDemoDescription, PrintsEverySolveAsJsonAndText) {
  const BodyModel& model = testing::human_model();
  const auto solves = run_ik_demo(model);
  const auto json = ik_demo_json(solves);
  ASSERT_EQ(json.size(), 10u);
  EXPECT_EQ(json[1]["solver"], "fast");
  const std::string text = ik_demo_text(model, solves);
  EXPECT_EQ(text.rfind("body '" + model.name + "'", 0), 0u);
  EXPECT_NE(text.find("\nleft hand 3 m up (no body can):\n  paper NOT reached"), std::string::npos) << text;
}

}  // namespace
}  // namespace crux
