#include "reports/report_page.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

// A run folder's page: its summary, Fig. 1 only (no paper figures), and the replay of
// the chosen climb, titled after it.
TEST(ReportPage, ARunFolderPageReplaysTheChosenClimb) {
  const auto& directory = testing::trained_run_folder();
  const ReportedRun reported = locate_reported_run(directory, "training_0", "--run");
  for (const std::string choice : {"greedy", "1"}) {
    RunFolder run = locate_run_folder(reported.run_directory);
    read_run_climb(run, testing::human_model());
    const ExperimentConfig recorded = read_run_config(run);
    const ReportPage page = report_page(directory, reported, run, testing::human_model(), recorded, choice);
    EXPECT_EQ(page.summary.value("kind", ""), "run");
    ASSERT_EQ(page.figures.size(), 1u) << "Fig. 1 only";
    ASSERT_FALSE(page.replay.is_null());
    if (choice == "greedy") {
      EXPECT_EQ(page.replay_climb, "greedy");
      EXPECT_NE(page.replay_title.find("the greedy policy's climb after learning"), std::string::npos);
    } else {
      EXPECT_EQ(page.replay_climb, "episode");
      EXPECT_EQ(page.replay_episode, 1);
      EXPECT_NE(page.replay_title.find("the climb of episode 1"), std::string::npos) << page.replay_title;
    }
  }
}

}  // namespace
}  // namespace crux
