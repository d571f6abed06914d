#include "reports/table_one_text.hpp"

#include <gtest/gtest.h>

#include <string>

#include "reports/paper_reference.hpp"

namespace crux {
namespace {

TEST(TableOneText, PrintsThePapersValuesInBrackets) {
  ExperimentParameters settings;
  settings.wall_pairs = 1;
  const ExperimentResult empty;
  const std::string text = table_one_text(empty, settings);
  const PaperTableOne& paper = paper_table_one();
  // Training, beginning, w-greedy: the paper's 7.3 cm and 100 % success.
  EXPECT_EQ(paper.vertical_cm[0][0][0], 7.3);
  EXPECT_NE(text.find("( 7.3)"), std::string::npos) << text;
  EXPECT_NE(text.find("(100.0)"), std::string::npos) << text;
  EXPECT_NE(text.find("over 1 run per condition; beginning = first 2000 iterations\n"), std::string::npos) << text;
  settings.wall_pairs = 2;
  settings.analysis.beginning = 1;
  EXPECT_NE(table_one_text(empty, settings).find("over 2 runs per condition; beginning = first 1 iteration\n"),
            std::string::npos);
}

RunResult run_of(std::vector<IterationRecord> iterations) {
  RunResult run;
  run.iterations = std::move(iterations);
  return run;
}

// One run per condition, a beginning window of 2 iterations:
//   training: w ok 5 cm, r fail, w ok 15 cm
//   transfer: g ok 2 cm, g fail
//   control:  r ok 4 cm
ExperimentResult one_run_each() {
  ExperimentResult result;
  result.conditions[static_cast<int>(Condition::Training)].runs = {run_of({{0, Regime::WGreedy, 1, true, 0.05, -1.0},
                                                                           {0, Regime::Random, 2, false, 0.0, -1000.0},
                                                                           {0, Regime::WGreedy, 3, true, 0.15, -1.0}})};
  result.conditions[static_cast<int>(Condition::Transfer)].runs = {
      run_of({{0, Regime::GGreedy, 1, true, 0.02, -1.0}, {0, Regime::GGreedy, 2, false, 0.0, -1000.0}})};
  result.conditions[static_cast<int>(Condition::Control)].runs = {run_of({{0, Regime::Random, 1, true, 0.04, -1.0}})};
  return result;
}

bool has_line(const std::string& text, const std::string& line) {
  return text.find('\n' + line + '\n') != std::string::npos;
}

std::string spaces(int n) { return std::string(n, ' '); }

// Rows are "    <regime padded to 22>", then training and transfer as "ours (paper's)"
// right-aligned in 16 columns ("%6.1f (%4.1f)"), then control alone in 10; the
// actions per run are right-aligned in 16. A cell without a value (no successes for a
// displacement, no actions for a rate) is "-".
TEST(TableOneText, OursBesideThePapersByHand) {
  ExperimentParameters settings;
  settings.wall_pairs = 1;
  settings.analysis.beginning = 2;
  const std::string text = table_one_text(one_run_each(), settings);
  EXPECT_NE(text.find("over 1 run per condition; beginning = first 2 iterations"), std::string::npos) << text;
  // Vertical e0, w-greedy: 5 cm in training's first 2 iterations, 10 cm over its run;
  // transfer and control never chose w-greedy.
  EXPECT_TRUE(has_line(text, "    w_greedy" + spaces(20) + "5.0 ( 7.3)" + spaces(8) + "- (12.0)" + spaces(9) + "-"))
      << text;
  EXPECT_TRUE(has_line(text, "    w_greedy" + spaces(19) + "10.0 ( 9.4)" + spaces(8) + "- (10.6)" + spaces(9) + "-"))
      << text;
  // Vertical e0, random, beginning: training's random action failed, so it has no
  // displacement although it has an action; control's rose 4 cm.
  EXPECT_TRUE(has_line(text, "    random" + spaces(24) + "- ( 2.0)" + spaces(8) + "- ( 2.0)" + spaces(7) + "4.0"))
      << text;
  // Success rate, g-greedy, beginning: transfer's one success in two.
  EXPECT_TRUE(has_line(text, "    g_greedy" + spaces(22) + "- (46.0)" + spaces(5) + "50.0 (45.0)" + spaces(9) + "-"))
      << text;
  // Success rate, random: training's failure is a rate of 0, not "-"; control's 100 %
  // has no paper value beside it.
  EXPECT_TRUE(has_line(text, "    random" + spaces(22) + "0.0 (43.0)" + spaces(8) + "- (44.0)" + spaces(5) + "100.0"))
      << text;
  // Actions per run, w-greedy: training's 1 then 2 (overall), transfer's 0. (Control's
  // value is left unchecked: it does not sit under its 10-column heading.)
  EXPECT_NE(text.find("\n    w_greedy" + spaces(29) + "1" + spaces(15) + "0 "), std::string::npos) << text;
  EXPECT_NE(text.find("\n    w_greedy" + spaces(29) + "2" + spaces(15) + "0 "), std::string::npos) << text;
}

}  // namespace
}  // namespace crux
