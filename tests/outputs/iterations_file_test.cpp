#include "outputs/iterations_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

const std::string kIterationsCsvHeader = "iteration,episode,regime,hold,success,root_rise_cm,reward\n";

// The problem of the InputError that reading `text` as a run of `recorded` iterations
// raises, which must name the file.
std::string iterations_problem(const std::string& name, const std::string& text, int recorded = 2,
                               PhysicsModel model = PhysicsModel::Kinematic) {
  const auto file = testing::write_temporary(name, text);
  try {
    read_iterations_file(file, recorded, model);
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), file.string());
    return e.problem();
  }
  ADD_FAILURE() << "read " << name << " without an error";
  return "";
}

TEST(IterationsFile, ReadsEveryRow) {
  const auto file = testing::write_temporary(
      "iterations_good.csv",
      kIterationsCsvHeader + "1,0,w_greedy,12,1,4.5,-1\n2,0,random,7,0,0,-10\n3,1,g_greedy,3,1,-2.25,100\n");
  const std::vector<RunStep> steps = read_iterations_file(file, 3, PhysicsModel::Kinematic);
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[0].iteration, 1);
  EXPECT_EQ(steps[0].regime, Regime::WGreedy);
  EXPECT_EQ(steps[0].hold_id, 12);
  EXPECT_TRUE(steps[0].success);
  EXPECT_DOUBLE_EQ(steps[0].root_rise_cm, 4.5);
  EXPECT_DOUBLE_EQ(steps[1].reward, -10);
  EXPECT_FALSE(steps[1].success);
  EXPECT_EQ(steps[2].episode, 1);
  EXPECT_EQ(steps[2].regime, Regime::GGreedy);
  EXPECT_TRUE(read_iterations_file(testing::write_temporary("iterations_none.csv", kIterationsCsvHeader), 0,
                                   PhysicsModel::Kinematic)
                  .empty());
}

// A run of the static model adds `fell`: the failed moves after which the climber fell
// back to the start (docs/MODEL.md, C27).
TEST(IterationsFile, ReadsTheFallsOfAStaticRun) {
  const std::string header = "iteration,episode,regime,hold,success,root_rise_cm,reward,fell\n";
  const auto file = testing::write_temporary(
      "iterations_falls.csv",
      header + "1,0,w_greedy,12,1,4.5,-1,0\n2,0,random,7,0,0,-1000,1\n3,0,random,8,0,0,-1000,0\n");
  const std::vector<RunStep> steps = read_iterations_file(file, 3, PhysicsModel::Static);
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_FALSE(steps[0].fell);
  EXPECT_TRUE(steps[1].fell);
  EXPECT_FALSE(steps[2].fell);
  EXPECT_DOUBLE_EQ(steps[1].reward, -1000);
  EXPECT_EQ(
      iterations_problem("iterations_fell_value.csv", header + "1,0,random,7,0,0,-1000,2\n", 1, PhysicsModel::Static),
      "line 2: fell must be 0 or 1");
  EXPECT_EQ(
      iterations_problem("iterations_fell_reached.csv", header + "1,0,random,7,1,3,-1,1\n", 1, PhysicsModel::Static),
      "line 2: a reached move cannot fall");
  EXPECT_EQ(
      iterations_problem("iterations_fell_fields.csv", header + "1,0,random,7,0,0,-1000\n", 1, PhysicsModel::Static),
      "line 2: 7 fields, not 8");
  // Issue 39: a static run's file without the column was read as a run without falls, and
  // a kinematic run's file with it as one with falls: the run's config says which header.
  EXPECT_EQ(iterations_problem("iterations_static_no_falls.csv", kIterationsCsvHeader + "1,0,random,7,0,0,-1000\n", 1,
                               PhysicsModel::Static)
                .rfind("line 1: the header must be '" + header.substr(0, header.size() - 1) + "', not 'iteration", 0),
            0u);
  EXPECT_NE(iterations_problem("iterations_kinematic_falls.csv", header + "1,0,random,7,0,0,-1000,0\n", 1)
                .find("line 1: the header must be"),
            std::string::npos);
}

TEST(IterationsFile, RefusesAMissingFileAndAnotherHeader) {
  EXPECT_THROW(read_iterations_file(testing::temporary_path("iterations_missing.csv"), 0, PhysicsModel::Kinematic),
               InputError);
  EXPECT_EQ(iterations_problem("iterations_empty.csv", ""),
            "is empty; the header line must be 'iteration,episode,regime,hold,success,root_rise_cm,reward'");
  EXPECT_EQ(iterations_problem("iterations_header.csv", "iteration,episode,mode\n1,0,random\n"),
            "line 1: the header must be 'iteration,episode,regime,hold,success,root_rise_cm,reward', not "
            "'iteration,episode,mode'");
}

TEST(IterationsFile, RefusesABadRowNamingItsLine) {
  const std::string one = kIterationsCsvHeader + "1,0,random,3,1,0.5,-1\n";
  EXPECT_EQ(iterations_problem("iterations_fields.csv", one + "2,0,random\n"), "line 3: 3 fields, not 7");
  EXPECT_EQ(iterations_problem("iterations_blank.csv", one + "\n2,0,random,3,1,0.5,-1\n"), "line 3: 1 field, not 7");
  EXPECT_EQ(iterations_problem("iterations_order.csv", one + "7,0,random,3,1,0.5,-1\n"),
            "line 3: iteration 7 where 2 was due");
  EXPECT_EQ(iterations_problem("iterations_regime.csv", one + "2,0,greedy,3,1,0.5,-1\n"),
            "line 3: unknown regime 'greedy'");
  EXPECT_EQ(iterations_problem("iterations_success.csv", one + "2,0,random,3,yes,0.5,-1\n"),
            "line 3: success must be 0 or 1");
  EXPECT_EQ(iterations_problem("iterations_jump.csv", one + "2,2,random,3,1,0.5,-1\n"),
            "line 3: episode 2 after episode 0");
  EXPECT_EQ(iterations_problem("iterations_negative.csv", kIterationsCsvHeader + "1,-1,random,3,1,0.5,-1\n"),
            "line 2: episodes count from 0");
  EXPECT_EQ(iterations_problem("iterations_hold.csv", one + "2,0,random,h3,1,0.5,-1\n"),
            "line 3: 'h3' is not an integer");
  EXPECT_EQ(iterations_problem("iterations_reward.csv", one + "2,0,random,3,1,0.5,inf\n"),
            "line 3: 'inf' is not finite");
  EXPECT_EQ(iterations_problem("iterations_rise.csv", one + "2,0,random,3,1,,-1\n"), "line 3: '' is not a number");
}

TEST(IterationsFile, RefusesAFileCutShort) {
  const std::string rows = kIterationsCsvHeader + "1,0,random,3,1,0.5,-1\n2,0,random,4,1,2.25,-1\n";
  EXPECT_EQ(iterations_problem("iterations_mid_row.csv", rows.substr(0, rows.size() - 5)),
            "does not end with a newline: it was cut short")
      << "'2,0,random,4,1,2.' parses as a row";
  EXPECT_EQ(iterations_problem("iterations_no_newline.csv", rows.substr(0, rows.size() - 1)),
            "does not end with a newline: it was cut short");
  EXPECT_EQ(iterations_problem("iterations_rows_removed.csv", rows, 3),
            "has 2 iterations, but summary.json records 3: the file was cut short or belongs to another run");
  EXPECT_EQ(iterations_problem("iterations_rows_added.csv", rows, 1),
            "has 2 iterations, but summary.json records 1: the file was cut short or belongs to another run");
}

}  // namespace
}  // namespace crux
