#include "outputs/output_folder.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <iterator>

#include "common/input_error.hpp"
#include "outputs/summary.hpp"
#include "support/output_text.hpp"
#include "support/test_models.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

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
  EXPECT_EQ(testing::read_output_text(folder / "config.toml"), "# config\n");
  EXPECT_EQ(load_wall((folder / "wall.json").string()).holds.back().position, wall.holds.back().position);
  const auto summary = nlohmann::json::parse(testing::read_output_text(folder / "summary.json"));
  EXPECT_EQ(summary["run_facts"]["training"][0]["learning_seed"], 8);
  std::size_t leftovers = 0;
  for (const auto& entry : fs::directory_iterator(folder))
    leftovers += entry.path().string().find(".tmp.") != std::string::npos;
  EXPECT_EQ(leftovers, 0u) << "no temporary file left behind";
}

// The problem check_output_file finds, or "" when it accepts the file.
std::string output_file_problem(const fs::path& file, const std::vector<std::string>& inputs) {
  try {
    check_output_file(file, inputs);
    return "";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "--output");
    return e.problem();
  }
}

// crux report RUN -o RUN/summary.json, wall show --wall-file w.json -o ./w.json, -o
// naming the --config file: the input is named however the output names it.
TEST(OutputFolder, AnOutputFileThatIsAnInputOrLiesInAnInputFolderIsRefused) {
  const fs::path folder = testing::temporary_path("output_file_inputs");
  fs::create_directories(folder / "run");
  std::ofstream(folder / "run" / "summary.json") << "{}";
  std::ofstream(folder / "w.json") << "{}";
  const std::vector<std::string> inputs{(folder / "run").string(), (folder / "w.json").string(), ""};
  for (const fs::path& named : {folder / "run" / "summary.json", folder / "run" / "report.html",
                                folder / "run/../run/./summary.json", folder / "./w.json"}) {
    EXPECT_NE(output_file_problem(named, inputs).find("an input of this command"), std::string::npos) << named;
  }
  const std::string problem = output_file_problem(folder / "w.json", inputs);
  EXPECT_EQ(problem, (folder / "w.json").string() + " would overwrite " + inputs[1] +
                         ", an input of this command; write to another file");
  fs::create_symlink(folder / "w.json", folder / "link.json");
  fs::create_hard_link(folder / "w.json", folder / "hard.json");
  EXPECT_NE(output_file_problem(folder / "link.json", inputs), "");
  EXPECT_NE(output_file_problem(folder / "hard.json", inputs), "") << "a hard link is the same file";
  EXPECT_EQ(output_file_problem(folder / "report.html", inputs), "");
  EXPECT_EQ(output_file_problem(folder / "run.html", inputs), "") << "a sibling whose name starts alike";
  EXPECT_EQ(output_file_problem("", inputs), "the output file name is empty");
}

TEST(OutputFolder, AnOutputFileThatIsAFolderIsRefusedAndAFifoAccepted) {
  const fs::path folder = testing::temporary_path("output_file_nodes");
  fs::create_directories(folder);
  EXPECT_EQ(output_file_problem(folder, {}), folder.string() + " is a folder; name a file to write");
  ASSERT_EQ(::mkfifo((folder / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(output_file_problem(folder / "fifo", {(folder / "fifo").string()}), "")
      << "written through, a FIFO overwrites nothing";
}

}  // namespace
}  // namespace crux
