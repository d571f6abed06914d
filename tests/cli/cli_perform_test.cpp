// crux perform, and crux plan under the dynamic model, end to end.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/jug_ladder.hpp"
#include "support/output_text.hpp"
#include "support/repository_docs.hpp"
#include "support/run_crux.hpp"
#include "support/trained_run.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;
using testing::run_crux;

fs::path perform_scratch(const std::string& name) {
  const fs::path dir = testing::test_folder() / "perform-cli";
  fs::create_directories(dir);
  return dir / name;
}

// The jug ladder, climbed by the right hand's one move, as a wall file.
std::string ladder_file() {
  static const fs::path file = [] {
    testing::JugLadder ladder;
    ladder.finish_after_one_move();
    const fs::path path = perform_scratch("jug_ladder.json");
    save_wall(path.string(), ladder.wall);
    return path;
  }();
  return file.string();
}

// The folder holds the climb, --json prints the documented keys, and the folder's
// config.toml performs the same climb to the same bytes.
TEST(CliPerform, TheClimbsFolderReplaysToTheSameBytesFromItsConfig) {
  const fs::path first = perform_scratch("first");
  const auto outcome = run_crux("perform --wall-file " + ladder_file() + " --json -o " + first.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::ordered_json::parse(outcome.out);
  std::vector<std::string> printed;
  for (const auto& [key, value] : json.items()) printed.push_back(key);
  EXPECT_EQ(printed, testing::documented_keys(testing::repository_file("docs/OUTPUTS.md"), "## `crux perform`"));
  EXPECT_TRUE(json["reached_top"]) << outcome.out;
  EXPECT_EQ(json["physics_model"], "static");
  EXPECT_EQ(json["moves_performed"], 1);
  EXPECT_TRUE(json["cause"].is_null());
  EXPECT_GT(json["wall_s"].get<double>(), 0.0);
  const fs::path second = perform_scratch("second");
  const auto replay = run_crux("perform --config " + (first / "config.toml").string() + " -o " + second.string());
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  for (const char* file : {"config.toml", "wall.json", "perform.json", "trajectory.csv", "climber.xml"}) {
    EXPECT_EQ(testing::read_output_text(first / file), testing::read_output_text(second / file)) << file;
  }
}

TEST(CliPerform, PlanUnderTheDynamicModelAnswersWithAClimbPerformed) {
  const auto outcome = run_crux("plan --physics-model dynamic --json --wall-file " + ladder_file());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::ordered_json::parse(outcome.out);
  EXPECT_EQ(json["physics_model"], "dynamic");
  EXPECT_EQ(json["length"], 1);
  EXPECT_EQ(json["replans"], 0);
  EXPECT_EQ(json["moves_simulated"], 1);
  EXPECT_TRUE(json["reached_top"]);
  EXPECT_TRUE(json.contains("wall_s"));
}

TEST(CliPerform, BadInputIsOneLineAndExitCode2AndWritesNoFolder) {
  const fs::path folder = perform_scratch("refused");
  const std::string out = " -o " + folder.string();
  const std::string wall = " --wall-file " + ladder_file() + out;
  for (const std::string& arguments : {
           "perform" + wall + " --perform-joint-speed nan",
           "perform" + wall + " --perform-settle-time -1",
           "perform" + wall + " --physics-grip 1",  // the start does not hold
           "perform" + wall + " --physics-model quantum",
           "perform" + wall + " --plan-max-replans 5",  // the static model plans once
           "plan" + wall + " --perform-joint-speed 1",  // the static model performs nothing
           "perform" + out,                             // no wall
           "perform --wall-file /nonexistent/wall.json" + out,
           "train" + wall + " --perform-lift 0.2",  // the static model performs nothing
           "paper --walls 1 --iterations 5 --plan false --physics-model dynamic" + out,
       }) {
    const auto outcome = run_crux(arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments << "\n" << outcome.err;
    EXPECT_EQ(testing::count_lines(outcome.err), 1) << arguments << "\n" << outcome.err;
    EXPECT_FALSE(fs::exists(folder)) << arguments;
  }
  const auto dynamic = run_crux("paper --walls 1 --iterations 5 --plan false --physics-model dynamic" + out);
  EXPECT_NE(dynamic.err.find("dynamic is not taken by crux paper"), std::string::npos) << dynamic.err;
}

// A learnt run's greedy climb, performed from its start on the run's wall under the run's
// (kinematic) parameters; its folder replays from its config.toml.
TEST(CliPerform, ARunsClimbIsPerformedUnderTheRunsParameters) {
  const std::string run = testing::trained_run_folder().string();
  const fs::path first = perform_scratch("run-first");
  const auto outcome = run_crux("perform --run " + run + " --climb greedy --json -o " + first.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::ordered_json::parse(outcome.out);
  EXPECT_EQ(json["physics_model"], "kinematic") << "the run's";
  EXPECT_EQ(json["climb"], "the greedy policy's climb after learning");
  EXPECT_GE(json["length"].get<int>(), 1);
  // Every move until the first that failed; none when the start did not hold still.
  const auto& failed = json["first_failed_move"];
  const std::size_t attempted = !json["start"]["performed"] ? 0
                                : failed.is_null()          ? json["length"].get<std::size_t>()
                                                            : failed.get<std::size_t>() + 1;
  EXPECT_EQ(json["moves"].size(), attempted) << outcome.out;
  const fs::path second = perform_scratch("run-second");
  ASSERT_EQ(run_crux("perform --config " + (first / "config.toml").string() + " -o " + second.string()).exit_code, 0);
  EXPECT_EQ(testing::read_output_text(first / "perform.json"), testing::read_output_text(second / "perform.json"));
  EXPECT_EQ(testing::read_output_text(first / "trajectory.csv"), testing::read_output_text(second / "trajectory.csv"));
}

TEST(CliPerform, ABadRunOrClimbIsOneLineAndExitCode2AndWritesNoFolder) {
  const std::string run = testing::trained_run_folder().string();
  const fs::path short_run = perform_scratch("short-run");
  ASSERT_EQ(run_crux("train --wall-seed 3 --iterations 3 -o " + short_run.string()).exit_code, 0);
  const fs::path folder = perform_scratch("refused-run");
  const std::string other_body = perform_scratch("other_body.urdf").string();
  fs::copy_file(std::string(CRUX_SOURCE_DIR) + "/models/crux_human.urdf", other_body,
                fs::copy_options::overwrite_existing);
  const std::string out = " -o " + folder.string();
  for (const std::string& arguments : {"perform --run " + run + " --climb bogus" + out,
                                       "perform --run " + run + " --climb 100000" + out,  // no such episode
                                       "perform --run " + run + " --wall-seed 3" + out,
                                       "perform --run " + run + " --wall-incline 20" + out,       // the run's wall
                                       "perform --run " + run + " --urdf " + other_body + out,    // the run's body
                                       "perform --run " + run + " --physics-model static" + out,  // not the run's
                                       "perform --run " + short_run.string() + out,  // a run without a climb
                                       "perform --run " + perform_scratch("nothing").string() + out,
                                       "perform --wall-file " + ladder_file() + " --climb last" + out}) {
    const auto outcome = run_crux(arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments << "\n" << outcome.err;
    EXPECT_EQ(testing::count_lines(outcome.err), 1) << arguments << "\n" << outcome.err;
    EXPECT_FALSE(fs::exists(folder)) << arguments;
  }
}

// crux report on a crux perform folder: a page of its own that plays the simulated climb;
// beside a run's replay with --performed. crux view draws its steps as simulated. Bad
// combinations are one line, exit 2, no file.
TEST(CliPerform, TheReportAndTheViewShowAPerformedClimb) {
  const fs::path performed = perform_scratch("reported");
  ASSERT_EQ(run_crux("perform --wall-file " + ladder_file() + " -o " + performed.string()).exit_code, 0);
  const fs::path page = perform_scratch("performed.html");
  const auto alone = run_crux("report " + performed.string() + " --json -o " + page.string());
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  const auto json = nlohmann::ordered_json::parse(alone.out);
  EXPECT_EQ(json["performed"]["moves"], 1);
  EXPECT_GT(json["performed"]["frames"].get<int>(), 10);
  EXPECT_EQ(json["performed"]["outcome"].get<std::string>().rfind("All 1 move performed, to the top", 0), 0u)
      << alone.out;
  const std::string html = testing::read_output_text(page);
  EXPECT_NE(html.find("id=\"crux-performed-data\""), std::string::npos);
  EXPECT_EQ(html.find("id=\"crux-replay-data\""), std::string::npos);

  const std::string run = testing::trained_run_folder().string();
  const fs::path beside = perform_scratch("beside.html");
  const auto both = run_crux("report " + run + " --performed " + performed.string() + " -o " + beside.string());
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_NE(both.out.find("performed in MuJoCo (" + performed.string() + "): All 1 move performed"), std::string::npos)
      << both.out;
  const std::string two = testing::read_output_text(beside);
  EXPECT_NE(two.find("id=\"crux-replay-data\""), std::string::npos);
  EXPECT_NE(two.find("id=\"crux-performed-data\""), std::string::npos);

  const fs::path svg = perform_scratch("performed.svg");
  const auto view = run_crux("view --run " + performed.string() + " --step 1 --json -o " + svg.string());
  ASSERT_EQ(view.exit_code, 0) << view.err;
  const auto drawn = nlohmann::ordered_json::parse(view.out);
  EXPECT_NE(drawn["subtitle"].get<std::string>().find("step 1 of 1: move 1, right_hand to hold 5, performed"),
            std::string::npos)
      << view.out;
  EXPECT_EQ(drawn["root_rotation"].size(), 4u);
  EXPECT_EQ(drawn["hold_forces_n"].size(), 4u) << "all four limbs on their holds at the end";
  EXPECT_NE(testing::read_output_text(svg).find("class=\"hold-forces\""), std::string::npos);

  const fs::path refused = perform_scratch("refused.html");
  for (const std::string& arguments :
       {"view --run " + performed.string() + " --step 2 -o " + refused.string(),
        "view --run " + performed.string() + " --climb last -o " + refused.string(),
        "report " + performed.string() + " --run training_1 -o " + refused.string(),
        "report " + performed.string() + " --performed " + performed.string() + " -o " + refused.string(),
        "report " + run + " --performed " + run + " -o " + refused.string()}) {
    const auto outcome = run_crux(arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments << "\n" << outcome.err;
    EXPECT_EQ(testing::count_lines(outcome.err), 1) << arguments << "\n" << outcome.err;
    EXPECT_FALSE(fs::exists(refused)) << arguments;
  }
}

// crux train under the dynamic model: its moves performed in MuJoCo are counted, its falls
// recorded in iterations.csv as a static run's are, and its folder reported.
TEST(CliPerform, ALearningRunUnderTheDynamicModelRecordsItsFallsAndItsMoves) {
  const fs::path run = perform_scratch("dynamic-run");
  const auto trained = run_crux("train --wall-file " + ladder_file() +
                                " --physics-model dynamic --iterations 6 --json -o " + run.string());
  ASSERT_EQ(trained.exit_code, 0) << trained.err;
  const auto summary = nlohmann::ordered_json::parse(trained.out);
  EXPECT_GE(summary["run_facts"]["training"][0]["moves_simulated"].get<int>(), 1) << trained.out;
  const std::string iterations = testing::read_output_text(run / "iterations.csv");
  EXPECT_EQ(iterations.substr(0, iterations.find('\n')).rfind(",fell"), iterations.find('\n') - 5)
      << "the header ends with fell";
  const auto reported = run_crux("report " + run.string() + " -o " + perform_scratch("dynamic-run.html").string());
  EXPECT_EQ(reported.exit_code, 0) << reported.err;
}

}  // namespace
}  // namespace crux
