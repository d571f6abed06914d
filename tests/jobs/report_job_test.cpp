#include "jobs/report_job.hpp"
#include "reports/written_report.hpp"

#include <unistd.h>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "outputs/run_config_file.hpp"
#include "support/run_crux.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

ReportPage page_of(const std::filesystem::path& directory, const std::string& choice) {
  const ReportedRun reported = locate_reported_run(directory, "training_0", "--run");
  RunFolder run = locate_run_folder(reported.run_directory);
  read_run_climb(run, testing::human_model());
  const ExperimentConfig recorded = read_run_config(run.config_file);
  return report_page(directory, reported, run, testing::human_model(), recorded, choice);
}

// A run folder's page: its summary, Fig. 1 only (no paper figures), and the replay of
// the chosen climb, titled after it and saying why it is the one.
TEST(ReportPage, ARunFolderPageReplaysTheChosenClimb) {
  const auto& directory = testing::trained_run_folder();
  for (const std::string choice : {"greedy", "1"}) {
    const ReportPage page = page_of(directory, choice);
    EXPECT_EQ(page.summary.value("kind", ""), "run");
    ASSERT_EQ(page.figures.size(), 1u) << "Fig. 1 only";
    ASSERT_FALSE(page.replay.is_null());
    if (choice == "greedy") {
      EXPECT_EQ(page.replay_climb, "greedy");
      EXPECT_NE(page.replay_title.find("the greedy policy's climb after learning"), std::string::npos);
      EXPECT_EQ(page.replay_reason.rfind("the greedy policy's climb after learning, which reaches the top in ", 0), 0u)
          << page.replay_reason;
    } else {
      // --climb 1 is the first episode, iterations.csv's episode 0.
      EXPECT_EQ(page.replay_climb, "episode");
      EXPECT_EQ(page.replay_episode, 0);
      EXPECT_NE(page.replay_title.find("the climb of episode 1"), std::string::npos) << page.replay_title;
      EXPECT_EQ(page.replay_reason, "episode 1, as --climb 1 asks");
    }
  }
}

// A run trained briefly (the fixture's wall and seed, 1000 iterations: 1 episode) has a
// greedy policy that does not reach the top: its page replays the last completed episode
// and says so, and why. With 300 iterations no episode ends: no replay, and the page and
// the text say why.
TEST(ReportPage, AGreedyClimbThatDoesNotFinishGivesWayToTheLastEpisodeAndThePageSaysWhy) {
  for (const int iterations : {1000, 300}) {
    const auto folder = testing::temporary_path(fmt::format("report_page_{}_{}", iterations, ::getpid()));
    const auto trained = testing::run_crux(
        fmt::format("train --wall-seed 3 --seed 5 --iterations {} --overwrite -o {}", iterations, folder.string()));
    ASSERT_EQ(trained.exit_code, 0) << trained.err;
    const ReportPage page = page_of(folder, "greedy");
    const std::string unfinished = "the greedy policy did not reach the top within 500 actions (experiment.greedy_cap)";
    const std::string text = written_report_text(page, "train", "r.html", 1000, 0.1);
    if (iterations == 1000) {
      EXPECT_EQ(page.replay_climb, "last");
      EXPECT_EQ(page.replay_episode, 0);
      EXPECT_NE(page.replay_title.find("the climb of episode 1"), std::string::npos) << page.replay_title;
      EXPECT_EQ(page.replay_reason, "the last completed episode (episode 1), since " + unfinished);
      ASSERT_FALSE(page.replay.is_null());
      EXPECT_NE(text.find("\nreplayed: the last completed episode (episode 1), since " + unfinished + "\n"),
                std::string::npos)
          << text;
    } else {
      EXPECT_TRUE(page.replay.is_null());
      EXPECT_EQ(page.replay_reason, unfinished + " and the run completed no episode");
      EXPECT_EQ(text, "wrote r.html (0.0 MB, 1 figure, no replay) in 0.10 s\nno replay: " + page.replay_reason + "\n");
    }
    std::filesystem::remove_all(folder);
  }
}

TEST(ReportPage, WhatIsWrittenIsSummarised) {
  ReportPage page;
  page.figures.resize(5);
  page.replay_climb = "last";
  page.replay_episode = 4;
  page.replay_reason = "the last completed episode (episode 5), since the greedy policy did not reach the top";
  page.replay = {{"frames", {{"count", 977}}}, {"moves", nlohmann::json::array({1, 2, 3})}};
  const auto json = written_report_json(page, "training_0", "r.html", 1150000, 0.25);
  EXPECT_EQ(json["bytes"], 1150000);
  EXPECT_EQ(json["figures"], 5);
  EXPECT_EQ(json["replay_climb"], "last");
  EXPECT_EQ(json["replay_episode"], 5) << "index 4 is episode 5: episodes are shown from 1";
  EXPECT_EQ(json["replay_reason"], page.replay_reason);
  EXPECT_EQ(json["replay_moves"], 3);
  EXPECT_EQ(json["replay_frames"], 977);
  EXPECT_EQ(written_report_text(page, "training_0", "r.html", 1150000, 0.25),
            "wrote r.html (1.1 MB, 5 figures, a replay of training_0 with 3 moves) in 0.25 s\n"
            "replayed: " +
                page.replay_reason + "\n");
  page.figures.resize(1);
  page.replay["moves"] = nlohmann::json::array({1});
  EXPECT_EQ(written_report_text(page, "training_0", "r.html", 1150000, 0.25)
                .rfind("wrote r.html (1.1 MB, 1 figure, a replay of training_0 with 1 move) in 0.25 s\n", 0),
            0u);
  page.replay_episode = -1;
  EXPECT_EQ(written_report_json(page, "training_0", "r.html", 10, 0.1)["replay_episode"], -1) << "the greedy climb";
  page.replay = nullptr;
  EXPECT_TRUE(written_report_json(page, "training_0", "r.html", 10, 0.1)["replay_climb"].is_null());
}

}  // namespace
}  // namespace crux
