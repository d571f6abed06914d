#include "reports/output_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "reports/summary.hpp"
#include "support/test_models.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(OutputFolder, ConfigTextIsTheCommandsKeysThenTheProvenance) {
  ExperimentConfig config;
  config.wall_seed = 4;
  const ParameterSet wall_only{{"wall"}, {}};
  Provenance provenance;
  provenance.crux_version = "9.9.9";
  const std::string text = config_file_text(config, wall_only, provenance);
  EXPECT_NE(text.find("[wall]\nseed = 4"), std::string::npos) << text;
  EXPECT_EQ(text.find("[experiment]"), std::string::npos) << "only the command's keys";
  EXPECT_GT(text.find("[provenance]"), text.find("[wall]"));
  EXPECT_NE(text.find("crux_version = \"9.9.9\""), std::string::npos);
}

TEST(OutputFolder, ARunFolderHoldsTheRunsFilesItsWallConfigAndSummary) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(3);
  LearningParameters learning;
  learning.iterations = 60;
  const ExperimentResult result =
      single_run_result(run_learning(model, wall, learning, 8), wall, 3, 8, Condition::Training);
  const fs::path folder = testing::temporary_path("run_folder");
  write_run_folder(folder, result, model, GridParameters{}, "# config\n",
                   summary_json(result, nullptr, ExperimentParameters{}, {}));
  for (const char* file :
       {"iterations.csv", "episodes.csv", "q_grid.bin", "climb.csv", "wall.json", "config.toml", "summary.json"}) {
    EXPECT_TRUE(fs::exists(folder / file)) << file;
  }
  EXPECT_EQ(read_text(folder / "config.toml"), "# config\n");
  EXPECT_EQ(load_wall((folder / "wall.json").string()).holds.back().position, wall.holds.back().position);
  const auto summary = nlohmann::json::parse(read_text(folder / "summary.json"));
  EXPECT_EQ(summary["run_facts"]["training"][0]["learning_seed"], 8);
  std::size_t leftovers = 0;
  for (const auto& entry : fs::directory_iterator(folder))
    leftovers += entry.path().string().find(".tmp.") != std::string::npos;
  EXPECT_EQ(leftovers, 0u) << "no temporary file left behind";
}

}  // namespace
}  // namespace crux
