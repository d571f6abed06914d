// The crux binary end to end: JSON keys, one-line errors and exit codes.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {


TEST(Cli, ModelJsonHasTheDocumentedKeys) {
  const testing::Outcome run = testing::run_crux("model --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["dof_root"], 3);
  EXPECT_EQ(json["dof_revolute"], 32);
  EXPECT_NEAR(json["height_m"].get<double>(), 1.70, 0.005);
  EXPECT_GT(json["mass_kg"].get<double>(), 0.0);
  ASSERT_EQ(json["joints"].size(), 32u);
  for (const auto& joint : json["joints"]) {
    EXPECT_TRUE(joint.contains("name"));
    EXPECT_LT(joint["lower"].get<double>(), joint["upper"].get<double>());
  }
}

TEST(Cli, BadModelIsOneLineAndExitCode2) {
  const auto bad = testing::write_temporary("cli_bad.urdf", "<robot name='x'><link name='a'/>");
  for (const std::string& command : std::vector<std::string>{"model --urdf " + bad.string(), "model --urdf /nonexistent.urdf",
                                    "ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --urdf " + bad.string()}) {
    const testing::Outcome run = testing::run_crux(command);
    EXPECT_EQ(run.exit_code, 2) << command;
    EXPECT_EQ(testing::count_lines(run.err), 1) << run.err;
    EXPECT_EQ(run.err.rfind("crux: ", 0), 0u) << run.err;
    EXPECT_TRUE(run.out.empty());
  }
}

TEST(Cli, BadArgumentsExitWithCode2) {
  for (const std::string command : {"ik --rh 0.3 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0", "ik --rh 0.3,1.5",
                                    "ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --ik-solver kdl", "frobnicate"}) {
    const testing::Outcome run = testing::run_crux(command);
    EXPECT_EQ(run.exit_code, 2) << command;
    EXPECT_EQ(testing::count_lines(run.err), 1) << run.err;
  }
  const testing::Outcome too_large = testing::run_crux("plan --wall-seed 3 --plan-max-solves 99999999999");
  EXPECT_EQ(too_large.exit_code, 2);
  EXPECT_EQ(too_large.err.rfind("crux: --plan-max-solves: '99999999999' is out of range", 0), 0u) << too_large.err;
  const testing::Outcome huge_grid =
      testing::run_crux("train --wall-seed 3 --grid-columns 65536 --grid-rows 65536 --iterations 5 -o /tmp/crux-never");
  EXPECT_EQ(huge_grid.exit_code, 2) << huge_grid.err;
  EXPECT_EQ(huge_grid.err.rfind("crux: --grid-columns: ", 0), 0u) << huge_grid.err;
}

TEST(Cli, IkReportsTheIssuesKeysForBothSolvers) {
  for (const std::string solver : {"paper", "fast"}) {
    const testing::Outcome run = testing::run_crux("ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --json --ik-solver " + solver);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["solver"], solver);
    EXPECT_TRUE(json["reached"].get<bool>());
    EXPECT_GT(json["iterations"].get<int>(), 0);
    EXPECT_GT(json["simulated_time_s"].get<double>(), 0.0);
    EXPECT_LE(json["residual_m"].get<double>(), 0.08);
  }
}

TEST(Cli, IkOnUnreachableHoldsSaysSo) {
  const testing::Outcome run = testing::run_crux("ik --rh 0.3,4.5 --lh 0.9,4.5 --rf 0.3,0 --lf 0.9,0 --json --ik-solver fast");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(nlohmann::json::parse(run.out)["reached"].get<bool>());
}

TEST(Cli, IkCompareReportsAgreement) {
  const testing::Outcome run = testing::run_crux("ik-compare --compare-queries 30 --seed 3 --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["queries"], 30);
  const double agreement = json["agreement"].get<double>();
  EXPECT_GE(agreement, 0.0);
  EXPECT_LE(agreement, 1.0);
  EXPECT_LE(json["paper_reached"].get<int>(), 30);
  EXPECT_LE(json["fast_reached"].get<int>(), 30);
}

TEST(Cli, IkPathIsWrittenAsCsv) {
  const auto out = std::filesystem::temp_directory_path() / "crux-tests" / "path.csv";
  std::filesystem::remove(out);
  const testing::Outcome run =
      testing::run_crux("ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --ik-solver paper --path-every 5 -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(std::filesystem::exists(out));
  EXPECT_GT(std::filesystem::file_size(out), 100u);
}

}  // namespace
}  // namespace crux
