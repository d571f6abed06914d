#include "outputs/summary_file.hpp"

#include "outputs/paper_figure_data.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// A two-run training condition on a 2 x 1 grid, and two transfer metrics listed out of
// alphabetical order.
const OrderedJson kSummaryDocument = OrderedJson::parse(R"({
  "format": "crux-summary", "version": 4, "kind": "experiment", "iterations": 4, "seeds_per_wall": 2,
  "episode_lengths": {"training": [[3, 1], [2]]},
  "run_facts": {"training": [{"wall_pair": 0, "plan_length": 5}, {"wall_pair": 0, "plan_length": -1}]},
  "qgrid_maps": {"training": {"right_hand": [1, 2.5], "left_hand": [0, 0], "right_foot": [0, 0], "left_foot": [0, 0]}},
  "transfer_vs_control": {
    "zeta": {"description": "z", "higher_is_better": false, "control": {"mean": 1},
             "transfer_minus_control": {"mean": 0.5, "ci95_t_over_walls": [-1, 2], "p_value": 0.25, "walls": 2}},
    "alpha": {"description": "a", "higher_is_better": true, "control": {"mean": 0},
              "transfer_minus_control": {"mean": 1, "ci95_t_over_walls": null, "p_value": 1, "walls": 1}}},
  "provenance": {"urdf": "/models/human.urdf"}
})");

// A folder holding `text` as its summary.json.
fs::path summary_folder_of(const std::string& name, const std::string& text) {
  const fs::path folder = testing::temporary_path(name);
  fs::create_directories(folder);
  std::ofstream(folder / "summary.json") << text;
  return folder;
}

PaperFigureData read_test_paper_summary(const fs::path& folder) {
  PaperFigureData data;
  data.grid.columns = 2;
  data.grid.rows = 1;
  read_paper_summary(folder, data);
  return data;
}

using SummaryReader = std::function<void(const fs::path&)>;
using SummaryEdit = std::function<void(OrderedJson&)>;

void read_paper_summary_of(const fs::path& folder) { read_test_paper_summary(folder); }

// The problem of the InputError that `read` raises on a folder holding `summary`, which
// must name its summary.json.
std::string summary_problem(const std::string& name, const std::string& summary, const SummaryReader& read) {
  const fs::path folder = summary_folder_of(name, summary);
  try {
    read(folder);
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), (folder / "summary.json").string());
    return e.problem();
  }
  ADD_FAILURE() << "read " << name << " without an error";
  return "";
}

// The same for kSummaryDocument with `edit` applied.
std::string summary_edit_problem(const std::string& name, const SummaryEdit& edit,
                                 const SummaryReader& read = read_paper_summary_of) {
  OrderedJson summary = kSummaryDocument;
  edit(summary);
  return summary_problem(name, summary.dump(), read);
}

TEST(SummaryFile, ReadsTheDocumentAndItsSharedKeys) {
  const fs::path folder = summary_folder_of("summary_good", kSummaryDocument.dump());
  const OrderedJson summary = read_summary(folder);
  const std::string file = (folder / "summary.json").string();
  EXPECT_EQ(summary_seeds_per_wall(summary, file), 2);
  EXPECT_EQ(summary_kind(summary, file), "experiment");
  EXPECT_EQ(summary_urdf(summary), "/models/human.urdf");
  EXPECT_EQ(summary_urdf(OrderedJson::object()), "") << "a summary may record no body model";
}

TEST(SummaryFile, ReadsAPaperExperimentInTheFilesOrder) {
  const PaperFigureData data = read_test_paper_summary(summary_folder_of("summary_paper", kSummaryDocument.dump()));
  EXPECT_EQ(data.iterations, 4);
  EXPECT_EQ(data.seeds_per_wall, 2);
  ASSERT_EQ(data.conditions.size(), 1u);
  ASSERT_EQ(data.conditions[0].runs.size(), 2u);
  EXPECT_EQ(data.conditions[0].runs[0].episode_lengths, (std::vector<int>{3, 1}));
  EXPECT_EQ(data.conditions[0].runs[0].plan_length, 5);
  EXPECT_EQ(data.conditions[0].runs[1].plan_length, -1);
  EXPECT_TRUE(data.conditions[0].runs[1].regimes.empty()) << "iterations.csv's, not the summary's";
  EXPECT_EQ(data.conditions[0].q_grid_maps[0], (std::vector<double>{1, 2.5}));
  ASSERT_EQ(data.transfer_metrics.size(), 2u);
  EXPECT_EQ(data.transfer_metrics[0].name, "zeta");
  EXPECT_FALSE(data.transfer_metrics[0].higher_is_better);
  EXPECT_EQ(data.transfer_metrics[0].difference_ci95, (std::array<double, 2>{-1, 2}));
  EXPECT_DOUBLE_EQ(data.transfer_metrics[0].p_value, 0.25);
  EXPECT_EQ(data.transfer_metrics[1].name, "alpha");
  EXPECT_FALSE(data.transfer_metrics[1].difference_ci95.has_value());
}

TEST(SummaryFile, RefusesAFileThatIsNotACruxSummary) {
  const auto document = [](const fs::path& folder) { read_summary(folder); };
  EXPECT_TRUE(summary_problem("summary_not_json", "{\"format\": ", document).starts_with("not JSON: ")) << "syntax";
  EXPECT_EQ(summary_problem("summary_array", "[1]", document), "the top level must be an object, got array");
  EXPECT_EQ(summary_problem("summary_no_format", "{}", document),
            "not a crux summary: format is missing, not \"crux-summary\"");
  EXPECT_EQ(summary_edit_problem(
                "summary_format", [](OrderedJson& s) { s["format"] = "crux-wall"; }, document),
            "not a crux summary: format is \"crux-wall\", not \"crux-summary\"");
  EXPECT_EQ(summary_edit_problem(
                "summary_version", [](OrderedJson& s) { s["version"] = 2; }, document),
            "version 2 is not one of the versions 3 to 4 this crux reads; write the folder again");
  EXPECT_EQ(summary_edit_problem(
                "summary_version_5", [](OrderedJson& s) { s["version"] = 5; }, document),
            "version 5 is not one of the versions 3 to 4 this crux reads; write the folder again");
  // Version 3 (with the run time it recorded) is read as version 4.
  OrderedJson version_3 = kSummaryDocument;
  version_3["version"] = 3;
  version_3["seconds"] = 1.5;
  EXPECT_NO_THROW(read_summary(summary_folder_of("summary_version_3", version_3.dump())));
  EXPECT_EQ(summary_edit_problem(
                "summary_version_text", [](OrderedJson& s) { s["version"] = "3"; }, document),
            "version must be an integer from -2147483648 to 2147483647, got string");
  EXPECT_EQ(summary_edit_problem(
                "summary_no_version", [](OrderedJson& s) { s.erase("version"); }, document),
            "version is missing");
  const fs::path nowhere = testing::temporary_path("summary_nowhere");
  EXPECT_THROW(read_summary(nowhere), InputError);
}

TEST(SummaryFile, SharedKeysHaveOneRule) {
  const auto seeds = [](const fs::path& folder) {
    summary_seeds_per_wall(read_summary(folder), (folder / "summary.json").string());
  };
  EXPECT_EQ(summary_edit_problem(
                "summary_seeds_zero", [](OrderedJson& s) { s["seeds_per_wall"] = 0; }, seeds),
            "seeds_per_wall must be an integer from 1 to 1000000, got 0");
  EXPECT_EQ(summary_edit_problem(
                "summary_seeds_large", [](OrderedJson& s) { s["seeds_per_wall"] = 1000001; }, seeds),
            "seeds_per_wall must be an integer from 1 to 1000000, got 1000001");
  EXPECT_EQ(summary_edit_problem(
                "summary_seeds_text", [](OrderedJson& s) { s["seeds_per_wall"] = "2"; }, seeds),
            "seeds_per_wall must be an integer from 1 to 1000000, got string");
  EXPECT_EQ(summary_edit_problem(
                "summary_seeds_missing", [](OrderedJson& s) { s.erase("seeds_per_wall"); }, seeds),
            "seeds_per_wall is missing");
  const auto kind = [](const fs::path& folder) {
    summary_kind(read_summary(folder), (folder / "summary.json").string());
  };
  EXPECT_EQ(summary_edit_problem(
                "summary_kind", [](OrderedJson& s) { s["kind"] = "sweep"; }, kind),
            "kind is \"sweep\", not \"experiment\" or \"run\"");
  EXPECT_EQ(summary_edit_problem(
                "summary_no_kind", [](OrderedJson& s) { s.erase("kind"); }, kind),
            "kind is missing");
}

TEST(SummaryFile, APaperSummaryNamesTheKeyAtFault) {
  EXPECT_EQ(summary_edit_problem("summary_no_iterations", [](OrderedJson& s) { s.erase("iterations"); }),
            "iterations is missing");
  EXPECT_EQ(summary_edit_problem("summary_no_wall_pair",
                                 [](OrderedJson& s) { s["run_facts"]["training"][1].erase("wall_pair"); }),
            "run_facts.training[1].wall_pair is missing");
  EXPECT_EQ(summary_edit_problem("summary_length_text",
                                 [](OrderedJson& s) { s["episode_lengths"]["training"][0][1] = "one"; }),
            "episode_lengths.training[0][1] must be an integer from 1 to 2147483647, got string");
  EXPECT_EQ(summary_edit_problem("summary_description",
                                 [](OrderedJson& s) { s["transfer_vs_control"]["zeta"]["description"] = 4; }),
            "transfer_vs_control.zeta.description must be a string, got 4");
  EXPECT_EQ(summary_edit_problem("summary_lengths_array",
                                 [](OrderedJson& s) { s["episode_lengths"] = OrderedJson::array(); }),
            "episode_lengths must be an object, got array");
}

TEST(SummaryFile, APaperSummaryRefusesValuesOutOfRange) {
  EXPECT_EQ(
      summary_edit_problem("summary_length_zero", [](OrderedJson& s) { s["episode_lengths"]["training"][1][0] = 0; }),
      "episode_lengths.training[1][0] must be an integer from 1 to 2147483647, got 0");
  EXPECT_EQ(summary_edit_problem("summary_wall_pair",
                                 [](OrderedJson& s) { s["run_facts"]["training"][0]["wall_pair"] = -1; }),
            "run_facts.training[0].wall_pair must be an integer from 0 to 2147483647, got -1");
  EXPECT_EQ(summary_edit_problem("summary_iterations", [](OrderedJson& s) { s["iterations"] = -4; }),
            "iterations must be an integer from 0 to 2147483647, got -4");
  EXPECT_EQ(summary_edit_problem("summary_short_map",
                                 [](OrderedJson& s) { s["qgrid_maps"]["training"]["left_hand"] = {1.0}; }),
            "qgrid_maps.training.left_hand has 1 values, not 2");
  EXPECT_EQ(summary_edit_problem("summary_facts", [](OrderedJson& s) { s["run_facts"]["training"].erase(1); }),
            "run_facts.training has 1 values, not 2");
  EXPECT_EQ(
      summary_edit_problem("summary_interval",
                           [](OrderedJson& s) {
                             s["transfer_vs_control"]["zeta"]["transfer_minus_control"]["ci95_t_over_walls"] = {1.0};
                           }),
      "transfer_vs_control.zeta.transfer_minus_control.ci95_t_over_walls has 1 values, not 2");
  EXPECT_EQ(summary_edit_problem("summary_no_condition",
                                 [](OrderedJson& s) { s["episode_lengths"] = OrderedJson::object(); }),
            "episode_lengths holds none of training, transfer, control");
}

}  // namespace
}  // namespace crux
