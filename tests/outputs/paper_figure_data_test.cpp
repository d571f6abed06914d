#include "outputs/paper_figure_data.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// A 2 x 1 grid.
constexpr const char* kFigureConfig = R"([grid]
columns = 2
rows = 1
tile_width = 0.3
tile_height = 0.5
right_hand_anchor_column = 1
right_hand_anchor_row = 0
left_hand_anchor_column = 0
left_hand_anchor_row = 0
right_foot_anchor_column = 1
right_foot_anchor_row = 0
left_foot_anchor_column = 0
left_foot_anchor_row = 0
)";

// Two training runs of three iterations, no metrics.
constexpr const char* kFigureSummary = R"({
  "format": "crux-summary", "version": 3, "kind": "experiment", "iterations": 3, "seeds_per_wall": 1,
  "episode_lengths": {"training": [[2], [3]]},
  "run_facts": {"training": [{"wall_pair": 0, "plan_length": 2}, {"wall_pair": 1, "plan_length": -1}]},
  "qgrid_maps": {"training": {"right_hand": [1, 2], "left_hand": [0, 0], "right_foot": [0, 0], "left_foot": [0, 0]}},
  "transfer_vs_control": {}
})";

constexpr const char* kFigureIterations = R"(iteration,episode,regime,hold,success,root_rise_cm,reward
1,0,w_greedy,3,1,0.5,-1
2,0,random,4,1,0.5,100
3,1,g_greedy,3,0,0,-10
)";

void write_figure_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

fs::path write_figure_folder(const std::string& name) {
  const fs::path folder = testing::temporary_path(name);
  write_figure_file(folder / "config.toml", kFigureConfig);
  write_figure_file(folder / "summary.json", kFigureSummary);
  write_figure_file(folder / "runs" / "training_0" / "iterations.csv", kFigureIterations);
  write_figure_file(folder / "runs" / "training_1" / "iterations.csv", kFigureIterations);
  return folder;
}

// The InputError that reading the folder raises.
InputError figure_data_error(const fs::path& folder) {
  try {
    read_paper_figure_data(folder);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << folder;
  return InputError("", "");
}

TEST(PaperFigureData, ReadsTheGridTheSummaryAndEachRunsRegimes) {
  const PaperFigureData data = read_paper_figure_data(write_figure_folder("figure_data_read"));
  EXPECT_EQ(data.grid.columns, 2);
  EXPECT_EQ(data.grid.rows, 1);
  EXPECT_DOUBLE_EQ(data.grid.tile_height, 0.5);
  EXPECT_EQ(data.grid.anchors[0], (std::array<int, 2>{1, 0}));
  EXPECT_EQ(data.iterations, 3);
  ASSERT_EQ(data.conditions.size(), 1u);
  ASSERT_EQ(data.conditions[0].runs.size(), 2u);
  const PaperRunData& run = data.conditions[0].runs[1];
  EXPECT_EQ(run.wall_pair, 1);
  EXPECT_EQ(run.episode_lengths, (std::vector<int>{3}));
  EXPECT_EQ(run.regimes, (std::vector<Regime>{Regime::WGreedy, Regime::Random, Regime::GGreedy}));
  EXPECT_EQ(data.conditions[0].q_grid_maps[0], (std::vector<double>{1, 2}));
  EXPECT_TRUE(data.transfer_metrics.empty());
}

// Each file is refused by its own reader, and the error names that file.
TEST(PaperFigureData, EachErrorNamesItsFile) {
  const fs::path no_rows = write_figure_folder("figure_data_no_rows");
  std::string config = kFigureConfig;
  config.erase(config.find("rows = 1\n"), 9);
  write_figure_file(no_rows / "config.toml", config);
  InputError e = figure_data_error(no_rows);
  EXPECT_EQ(e.source(), (no_rows / "config.toml").string());
  EXPECT_EQ(e.problem(), "grid.rows is missing (crux writes every grid key)");

  const fs::path no_summary = write_figure_folder("figure_data_no_summary");
  fs::remove(no_summary / "summary.json");
  e = figure_data_error(no_summary);
  EXPECT_EQ(e.source(), (no_summary / "summary.json").string());
  EXPECT_EQ(e.problem(), "no such file");

  const fs::path bad_row = write_figure_folder("figure_data_bad_row");
  const fs::path csv = bad_row / "runs" / "training_1" / "iterations.csv";
  std::string text = kFigureIterations;
  text.replace(text.find(",1,0.5,100"), 10, ",2,0.5,100");
  write_figure_file(csv, text);
  e = figure_data_error(bad_row);
  EXPECT_EQ(e.source(), csv.string());
  EXPECT_EQ(e.problem(), "line 3: success must be 0 or 1") << "the figures now refuse what the reports refused";

  const fs::path missing = write_figure_folder("figure_data_missing_csv");
  fs::remove(missing / "runs" / "training_0" / "iterations.csv");
  e = figure_data_error(missing);
  EXPECT_EQ(e.source(), (missing / "runs" / "training_0" / "iterations.csv").string());
  EXPECT_EQ(e.problem(), "no such file");
}

TEST(PaperFigureData, EveryRunHasTheSummarysIterations) {
  const fs::path short_run = write_figure_folder("figure_data_short_run");
  std::string text = kFigureIterations;
  text.erase(text.rfind("3,1,"));
  write_figure_file(short_run / "runs" / "training_1" / "iterations.csv", text);
  const InputError e = figure_data_error(short_run);
  EXPECT_EQ(e.source(), (short_run / "runs" / "training_1" / "iterations.csv").string());
  EXPECT_EQ(e.problem(),
            "has 2 iterations, but summary.json records 3: the file was cut short or belongs to another run");
}

}  // namespace
}  // namespace crux
