#include "reports/report_page.hpp"

#include <gtest/gtest.h>

#include "experiments/run_config_file.hpp"
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
    const ExperimentConfig recorded = read_run_config(run.config_file);
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

TEST(ReportPage, WhatIsWrittenIsSummarised) {
  ReportPage page;
  page.figures.resize(5);
  page.replay_climb = "last";
  page.replay_episode = 4;
  page.replay = {{"frames", {{"count", 977}}}, {"moves", nlohmann::json::array({1, 2, 3})}};
  const auto json = written_report_json(page, "training_0", "r.html", 1150000, 0.25);
  EXPECT_EQ(json["bytes"], 1150000);
  EXPECT_EQ(json["figures"], 5);
  EXPECT_EQ(json["replay_climb"], "last");
  EXPECT_EQ(json["replay_episode"], 4);
  EXPECT_EQ(json["replay_moves"], 3);
  EXPECT_EQ(json["replay_frames"], 977);
  EXPECT_EQ(written_report_text(page, "training_0", "r.html", 1150000, 0.25),
            "wrote r.html (1.1 MB, 5 figures, a replay of training_0 with 3 moves) in 0.25 s\n");
  page.replay = nullptr;
  EXPECT_TRUE(written_report_json(page, "training_0", "r.html", 10, 0.1)["replay_climb"].is_null());
}

}  // namespace
}  // namespace crux
