#include "outputs/sweep_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/input_error.hpp"
#include "support/output_text.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) {
  const fs::path folder = testing::temporary_path(name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

TEST(SweepFiles, WallFactsReadBackAsWrittenUnderTheirFormat) {
  const fs::path folder = fresh_folder("sweep-files-facts");
  nlohmann::ordered_json facts;
  facts["name"] = "random wall 7";
  facts["seed"] = 7;
  facts["plan"] = nullptr;
  write_sweep_wall_facts(folder, facts);
  const std::string text = testing::read_output_text(folder / kWallFactsFile);
  EXPECT_EQ(text.rfind("{\n  \"format\": \"crux-sweep-wall\",\n  \"version\": 1,\n  \"name\"", 0), 0u) << text;
  const nlohmann::json read = read_sweep_wall_facts(folder);
  EXPECT_EQ(read.at("name"), "random wall 7");
  EXPECT_EQ(read.at("seed"), 7);
  EXPECT_TRUE(read.at("plan").is_null());
}

TEST(SweepFiles, WallFactsOfAnotherKindAreOneLineErrors) {
  const fs::path folder = fresh_folder("sweep-files-bad-facts");
  const std::string file = (folder / kWallFactsFile).string();
  const auto problem = [&](const std::string& text) {
    std::ofstream(file) << text;
    try {
      read_sweep_wall_facts(folder);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(problem("{\"format\": ").find(file + ": not valid JSON"), std::string::npos);
  const std::string refused = file + ": not a crux sweep's wall facts (format crux-sweep-wall, version 1)";
  EXPECT_EQ(problem("[1, 2]"), refused);
  EXPECT_EQ(problem("{\"format\": 3, \"version\": 1}"), refused);
  EXPECT_EQ(problem("{\"format\": \"crux-sweep-wall\", \"version\": 2}"), refused);
  EXPECT_EQ(problem("{\"format\": \"crux-summary\", \"version\": 1}"), refused);
  fs::remove(file);
  try {
    read_sweep_wall_facts(folder);
    ADD_FAILURE() << "a missing facts file was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file + ": ", 0), 0u) << e.what();
  }
}

TEST(SweepFiles, ResultsAndReportAreWrittenWhereOutputsSays) {
  const fs::path folder = fresh_folder("sweep-files-results");
  const nlohmann::ordered_json summary =
      write_sweep_results_files(folder, "cell,run\n0,0\n", {{"crux", "test"}}, {"learning.alpha"},
                                nlohmann::ordered_json::array({{{"cell", 0}}}));
  EXPECT_EQ(testing::read_output_text(folder / "results.csv"), "cell,run\n0,0\n");
  EXPECT_EQ(testing::read_output_text(folder / "summary.json"), summary.dump(2) + "\n");
  EXPECT_EQ(summary.at("format"), "crux-sweep-summary");
  EXPECT_EQ(summary.at("version"), 1);
  EXPECT_EQ(summary.at("listed_keys").at(0), "learning.alpha");
  EXPECT_EQ(summary.begin().key(), "format");

  const auto written = write_sweep_report_files(folder, {"<svg>0</svg>", "<svg>1</svg>"}, "<html></html>");
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(written[1], folder / "figures" / "c1_episode_lengths.svg");
  EXPECT_EQ(testing::read_output_text(written[1]), "<svg>1</svg>");
  EXPECT_EQ(written[2], folder / "report.html");
  EXPECT_EQ(testing::read_output_text(written[2]), "<html></html>");
}

}  // namespace
}  // namespace crux
