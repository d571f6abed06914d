// crux wall and crux filter-stats end to end.

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/repository_docs.hpp"
#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

using testing::run_crux;

std::filesystem::path wall_scratch(const std::string& name) {
  const auto dir = testing::test_folder() / "wall-cli";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(CliWall, GenerateChecksTheStartAndShowReadsItBack) {
  const auto file = wall_scratch("wall.json");
  const auto generated = run_crux("wall generate --wall-seed 4 -o " + file.string());
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  EXPECT_NE(generated.out.find("reachable"), std::string::npos);
  const auto shown = run_crux("wall show --wall-file " + file.string() + " --json");
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  const auto json = nlohmann::json::parse(shown.out);
  EXPECT_EQ(json["holds"], 45);
  EXPECT_TRUE(json["start_reachable"].get<bool>());
  EXPECT_EQ(json["start"]["right_hand"], 17);
  EXPECT_EQ(json["start"]["left_foot"], 4);
}

TEST(CliWall, UnreachableStartIsReportedWithExitCode3) {
  const auto file = wall_scratch("far.json");
  // Rows of 1.5 m: the hands' start row is 4.5 m above the feet.
  const auto outcome = run_crux("wall generate --wall-seed 4 --wall-tile-height 1.5 -o " + file.string());
  EXPECT_EQ(outcome.exit_code, 3);
  EXPECT_NE(outcome.err.find("not reachable"), std::string::npos);
  EXPECT_EQ(testing::count_lines(outcome.err), 1);
}

TEST(CliWall, ShowDrawsTheGridAsSvg) {
  const auto file = wall_scratch("grid.json");
  ASSERT_EQ(run_crux("wall generate --wall-seed 2 -o " + file.string()).exit_code, 0);
  const auto svg = wall_scratch("grid.svg");
  const auto outcome =
      run_crux("wall show --wall-file " + file.string() + " --limb right_hand --at 0.3,1.5 --json -o " + svg.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::json::parse(outcome.out);
  EXPECT_EQ(json["grid"]["limb"], "right_hand");
  EXPECT_EQ(json["grid"]["tile_holds"].size(), 35u);
  std::ifstream in(svg);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
}

TEST(CliWall, BadWallFileIsOneLineAndExitCode2) {
  const auto file =
      testing::write_temporary("cli_bad_wall.json", "{\"format\": \"crux-wall\", \"version\": 1,\n  \"holds\": [}");
  for (const std::string& command :
       {"wall show --wall-file " + file.string(), std::string("wall show --wall-file /nonexistent/wall.json"),
        "wall show --wall-file " + file.string() + " --limb elbow"}) {
    const auto outcome = run_crux(command);
    EXPECT_EQ(outcome.exit_code, 2) << command;
    EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  }
}

TEST(CliFilterStats, ReportsPassSharesBesideThePapers) {
  const auto outcome = run_crux("filter-stats --wall-count 2 --wall-seed 3 --json");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::json::parse(outcome.out);
  EXPECT_EQ(json["configurations4"], 2u * 45 * 44 * 43 * 42);
  EXPECT_EQ(json["configurations3"], 2u * 4 * 45 * 44 * 43);
  EXPECT_GT(json["pass3"].get<double>(), json["pass4"].get<double>());
  EXPECT_EQ(json["readings"].size(), 4u);
  EXPECT_DOUBLE_EQ(json["paper_pass3"].get<double>(), 0.073);
}

TEST(CliFilterStats, JsonKeysAreThoseDocsOutputsMdLists) {
  const auto outcome = run_crux("filter-stats --wall-count 1 --wall-seed 3 --json");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::vector<std::string> printed;
  const auto json = nlohmann::ordered_json::parse(outcome.out);
  for (const auto& [key, value] : json.items()) printed.push_back(key);
  const auto documented =
      testing::documented_keys(testing::repository_file("docs/OUTPUTS.md"), "## `crux filter-stats --json`");
  EXPECT_EQ(printed, documented) << "docs/OUTPUTS.md lists the keys in the order crux prints them";
}

TEST(CliWall, GenerateAndShowCheckTheStartWithTheLearningsIkSettings) {
  const auto file = wall_scratch("strict.json");
  // A grasp sphere of 1 mm: the fast solver stops on its stall rule before reaching it.
  const auto strict = run_crux(
      "wall generate --wall-seed 4 --ik-grasp-radius 0.001 --ik-fast-max-iterations 3 --json -o " + file.string());
  EXPECT_EQ(strict.exit_code, 3) << strict.err;
  const auto json = nlohmann::json::parse(strict.out);
  EXPECT_FALSE(json["start_reachable"].get<bool>());
  const auto shown = run_crux("wall show --wall-file " + file.string() + " --json");
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_TRUE(nlohmann::json::parse(shown.out)["start_reachable"].get<bool>()) << "the default settings reach it";
}

}  // namespace
}  // namespace crux
