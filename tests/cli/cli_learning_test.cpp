// crux paper, train, transfer and plan end to end.

#include <gtest/gtest.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <fstream>

#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;
using testing::run_crux;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "crux-tests" / ("learning-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

TEST(CliLearning, ShortPaperRunWritesTheOutputFolder) {
  const fs::path out = scratch("paper");
  const auto outcome = run_crux("paper --runs 1 --iterations 300 --plan=false --seed 5 -o " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("Table I"), std::string::npos);
  for (const char* file : {"config.toml", "summary.json", "runs/training_0/iterations.csv", "runs/transfer_0/episodes.csv",
                           "runs/control_0/q_grid.bin", "runs/training_0/climb.csv", "walls/transfer_0.json",
                           "figures/fig3_regimes.csv", "figures/fig4_episode_lengths.csv", "figures/fig2b_qgrid_maps.csv"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_TRUE(summary["table1"]["control"]["overall"]["random"].contains("success_rate"));
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << "no temporary file left";
  }
}

TEST(CliLearning, TrainThenTransferFromItsQGrid) {
  const fs::path train = scratch("train"), transfer = scratch("transfer");
  const auto trained = run_crux("train --wall-seed 3 --iterations 300 -o " + train.string());
  ASSERT_EQ(trained.exit_code, 0) << trained.err;
  const auto transferred = run_crux("transfer --qgrid " + (train / "q_grid.bin").string() +
                                    " --wall-seed 4 --iterations 300 -o " + transfer.string());
  ASSERT_EQ(transferred.exit_code, 0) << transferred.err;
  std::ifstream in(transfer / "summary.json");
  EXPECT_FALSE(nlohmann::json::parse(in)["transferred_q_grid"].is_null());
}

TEST(CliLearning, BadQGridIsOneLineExit2AndWritesNothing) {
  const auto bad = testing::write_temporary("cli_bad_qgrid.bin", "CRUXQTAB\x01");
  const fs::path out = scratch("never");
  const auto outcome = run_crux("transfer --qgrid " + bad.string() + " --wall-seed 4 -o " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliLearning, ConfigFileAndFlagsCombine) {
  const auto config = testing::write_temporary("cli_config.toml", "[experiment]\niterations = 250\nseed = 9\n");
  const fs::path out = scratch("configured");
  const auto outcome = run_crux("train --wall-seed 3 --config " + config.string() + " --seed 11 -o " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::ifstream in(out / "config.toml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("iterations = 250"), std::string::npos) << "from the file";
  EXPECT_NE(text.find("seed = 11"), std::string::npos) << "the flag overrides the file";
}

TEST(CliLearning, PlanReportsItsLength) {
  const auto outcome = run_crux("plan --wall-seed 3 --json");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::json::parse(outcome.out);
  EXPECT_GT(json["length"].get<int>(), 0);
  EXPECT_EQ(json["holds"].size(), json["length"].get<std::size_t>());
}

TEST(CliLearning, MissingWallIsExplained) {
  const auto outcome = run_crux("plan");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.err.find("--wall"), std::string::npos);
}

}  // namespace
}  // namespace crux
