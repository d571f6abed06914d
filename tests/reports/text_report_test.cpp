#include "reports/text_report.hpp"

#include <regex>

#include <gtest/gtest.h>

#include "experiments/experiment_analysis.hpp"
#include "outputs/summary.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(TextReport, ARunIsOneLineNamingItsWallAndFolder) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(3);
  LearningParameters learning;
  learning.iterations = 40;
  const ExperimentResult result =
      single_run_result(run_learning(model, wall, learning, 2), wall, 3, 2, Condition::Transfer);
  const std::string line = run_text(result, 40, "out/x");
  EXPECT_EQ(line.rfind("transfer on '" + wall.name + "'", 0), 0u) << line;
  EXPECT_NE(line.find("wrote out/x"), std::string::npos);
  EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1);
}

TEST(TextReport, ARunOfOneIterationIsSingular) {
  const Wall wall = generate_random_wall(3);
  LearningParameters learning;
  learning.iterations = 1;
  const ExperimentResult result =
      single_run_result(run_learning(testing::human_model(), wall, learning, 2), wall, 3, 2, Condition::Training);
  EXPECT_NE(run_text(result, 1, "out/x").find(": 0 episodes in 1 iteration; greedy climb: "), std::string::npos);
}

// An experiment of 1 wall pair x 1 seed: a count of 1 takes the singular, and where a
// number cannot be given (walls for 80 % power, a correlation) the text says why.
ExperimentParameters one_wall_settings(int wall_pairs) {
  ExperimentParameters settings;
  settings.wall_pairs = wall_pairs;
  settings.learning.iterations = 30;
  settings.analysis.beginning = 1;
  settings.analysis.threshold_length = 1;
  settings.analysis.bootstrap_resamples = 20;
  settings.plan = false;
  settings.threads = 1;
  return settings;
}

TEST(TextReport, OneWallAndOneSeedAreSingularAndTheMissingPowerSaysWhy) {
  const ExperimentParameters settings = one_wall_settings(1);
  const ExperimentResult result = run_paper_experiment(testing::human_model(), settings);
  const std::string text = experiment_text(result, analyse_experiment(result, settings), settings);
  EXPECT_NE(text.find("over 1 run per condition; beginning = first 1 iteration\n"), std::string::npos) << text;
  EXPECT_NE(text.find("greedy climb finishes in 0 of 1 run\n"), std::string::npos) << text;
  EXPECT_NE(text.find("paired by wall and seed (1 wall x 1 seed)"), std::string::npos) << text;
  EXPECT_NE(text.find("walls for 80 % power: not estimable (needs at least 2 walls: with one, the difference has no "
                      "spread to plan from)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("paired r = undefined (needs 2 pairs or more"), std::string::npos) << text;
  EXPECT_NE(text.find("Take-off (first episode of at most 1 iteration, "), std::string::npos) << text;
  EXPECT_NE(text.find("  training  0 of 1 run take off\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Transfer's choices in its first 1 iteration "), std::string::npos) << text;
  EXPECT_EQ(text.find(": -"), std::string::npos) << "no bare dash for a missing number";
  // No count of 1 with a plural noun (a decimal such as 0.1 is no count).
  const std::regex plural_after_one(R"((^|[^.\d])1 (runs|walls|seeds|iterations|episodes|actions)\b)");
  EXPECT_FALSE(std::regex_search(text, plural_after_one)) << text;
}

// With transfer's runs standing in for control's, every difference is 0: no number of
// walls detects it.
TEST(TextReport, NoDifferenceHasNoPowerAndSaysSo) {
  const ExperimentParameters settings = one_wall_settings(2);
  ExperimentResult result = run_paper_experiment(testing::human_model(), settings);
  result.conditions[static_cast<int>(Condition::Control)] = result.conditions[static_cast<int>(Condition::Transfer)];
  const std::string text = experiment_text(result, analyse_experiment(result, settings), settings);
  EXPECT_NE(text.find("walls for 80 % power: not estimable (the mean difference is 0: no effect to detect)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("(2 walls x 1 seed)"), std::string::npos) << text;
  // rliable's view agrees: an IQM difference of 0 and every pair a tie, P = 1/2, with one
  // seed per wall nothing to resample.
  EXPECT_NE(text.find("\n  jumpstart              IQM transfer "), std::string::npos) << text;
  EXPECT_NE(text.find("  No intervals: one seed per wall leaves the stratified bootstrap nothing to resample.\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("difference +0; P(improvement) 0.50\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("[+0, +0]"), std::string::npos) << "no interval of zero width";
  EXPECT_NE(text.find("(2000 replicates; the walls are kept"), std::string::npos) << text;
}

}  // namespace
}  // namespace crux
