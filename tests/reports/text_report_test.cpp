#include "reports/text_report.hpp"

#include <gtest/gtest.h>

#include "reports/paper_reference.hpp"
#include "reports/summary.hpp"
#include "reports/table_one_text.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(TextReport, TableOnePrintsThePapersValuesInBrackets) {
  ExperimentSettings settings;
  settings.wall_pairs = 1;
  const ExperimentResult empty;
  const std::string text = table_one_text(empty, settings);
  const PaperTableOne& paper = paper_table_one();
  // Training, beginning, w-greedy: the paper's 7.3 cm and 100 % success.
  EXPECT_EQ(paper.vertical_cm[0][0][0], 7.3);
  EXPECT_NE(text.find("( 7.3)"), std::string::npos) << text;
  EXPECT_NE(text.find("(100.0)"), std::string::npos) << text;
  EXPECT_NE(text.find("beginning = first 2000 iterations"), std::string::npos);
}

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
