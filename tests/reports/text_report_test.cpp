#include "reports/text_report.hpp"

#include <gtest/gtest.h>

#include "reports/summary.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(TextReport, ARunIsOneLineNamingItsWallAndFolder) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(3);
  LearningParameters learning;
  learning.iterations = 40;
  const ExperimentResult result =
      single_run_result(run_learning(model, wall, learning, 2), wall, 3, 2, Condition::Transfer, 0.0);
  const std::string line = run_text(result, 40, "out/x");
  EXPECT_EQ(line.rfind("transfer on '" + wall.name + "'", 0), 0u) << line;
  EXPECT_NE(line.find("wrote out/x"), std::string::npos);
  EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1);
}

}  // namespace
}  // namespace crux
