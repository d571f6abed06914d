#include "views/paper_figures.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/svg_check.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

using testing::check_well_formed;

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Student's t 97.5 % quantile with 1 degree of freedom, tan(0.475 pi): two walls.
constexpr double kT975With1Dof = 12.706204736174706;

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// A 3 x 2 grid; the right hand's anchor is tile (column 2, row 0).
constexpr const char* kConfig = R"([experiment]
walls = 2
seeds_per_wall = 2

[grid]
columns = 3
rows = 2
tile_width = 0.3
tile_height = 0.5
right_hand_anchor_column = 2
right_hand_anchor_row = 0
left_hand_anchor_column = 0
left_hand_anchor_row = 1
right_foot_anchor_column = 1
right_foot_anchor_row = 0
left_foot_anchor_column = 0
left_foot_anchor_row = 0
)";

// Four runs per condition, two on each of two walls (run i on wall i / 2), four
// iterations each. Cumulative w-greedy actions at iteration 4: 1 and 3 on wall 0, 4 and
// 2 on wall 1.
const std::vector<std::vector<std::string>> kRegimes{
    {"w_greedy", "random", "random", "random"},
    {"w_greedy", "w_greedy", "w_greedy", "g_greedy"},
    {"w_greedy", "w_greedy", "w_greedy", "w_greedy"},
    {"g_greedy", "w_greedy", "random", "w_greedy"},
};
const std::vector<std::vector<int>> kEpisodeLengths{{10, 4}, {20}, {30, 6, 2}, {40, 8}};

std::string iterations_csv(const std::vector<std::string>& regimes) {
  std::string csv = "iteration,episode,regime,hold,success,root_rise_cm,reward\n";
  for (std::size_t i = 0; i < regimes.size(); ++i) {
    csv += fmt::format("{},0,{},3,1,0.5,-1\n", i + 1, regimes[i]);
  }
  return csv;
}

Json summary_json() {
  Json summary;
  summary["format"] = "crux-summary";
  summary["version"] = 3;
  summary["kind"] = "experiment";
  summary["seeds_per_wall"] = 2;
  summary["iterations"] = 4;
  // Listed out of alphabetical order: the figure keeps the file's order.
  summary["transfer_vs_control"]["zeta_metric"] = {
      {"description", "episodes completed early"},
      {"higher_is_better", true},
      {"control", {{"mean", 2.0}, {"ci95_over_walls", nullptr}}},
      {"transfer_minus_control",
       {{"mean", 0.5}, {"ci95_t_over_walls", {-0.25, 1.25}}, {"p_value", 0.4341}, {"walls", 2}}}};
  summary["transfer_vs_control"]["alpha_metric"] = {
      {"description", "a metric whose control mean is 0"},
      {"higher_is_better", false},
      {"control", {{"mean", 0.0}}},
      {"transfer_minus_control", {{"mean", 1.0}, {"ci95_t_over_walls", nullptr}, {"p_value", 1.0}, {"walls", 2}}}};
  for (const char* condition : {"training", "transfer", "control"}) {
    summary["episode_lengths"][condition] = kEpisodeLengths;
    for (int i = 0; i < 4; ++i) {
      summary["run_facts"][condition].push_back({{"wall_pair", i / 2}, {"plan_length", i < 2 ? 8 : 11}});
    }
    for (const char* limb : {"right_hand", "left_hand", "right_foot", "left_foot"}) {
      summary["qgrid_maps"][condition][limb] = std::vector<double>(6, 0.0);
    }
  }
  // The only extremes: -5 on tile 1 (column 1, row 0) and 100 on tile 2 (column 2, row 0).
  summary["qgrid_maps"]["training"]["right_hand"] = {0.0, -5.0, 100.0, 0.0, 0.0, 0.0};
  return summary;
}

fs::path write_folder(const std::string& name, const Json& summary = summary_json()) {
  const fs::path folder = testing::temporary_path(name);
  write_file(folder / "config.toml", kConfig);
  write_file(folder / "summary.json", summary.dump(1));
  for (const char* condition : {"training", "transfer", "control"}) {
    for (int i = 0; i < 4; ++i) {
      write_file(folder / "runs" / fmt::format("{}_{}", condition, i) / "iterations.csv", iterations_csv(kRegimes[i]));
    }
  }
  return folder;
}

TEST(PaperFiguresTest, RegimeBandIsAStudentTIntervalOverWallMeans) {
  const PaperFigureData data = read_paper_figure_data(write_folder("paper_figures_regimes"));
  const auto series = regime_series(data.conditions[0], data.iterations, 1);
  const WallBandSeries& w = series[static_cast<int>(Regime::WGreedy)];
  EXPECT_EQ(w.x, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(w.walls, (std::vector<int>{2, 2, 2, 2}));
  // Iteration 4: wall means 2 and 3; sd of the two means sqrt(0.5), half-width t sd / sqrt 2.
  EXPECT_DOUBLE_EQ(w.mean[3], 2.5);
  EXPECT_NEAR(w.high[3] - w.mean[3], kT975With1Dof * 0.5, 1e-9);
  EXPECT_NEAR(w.mean[3] - w.low[3], kT975With1Dof * 0.5, 1e-9);
  // Iteration 1: wall means 1 and 0.5.
  EXPECT_DOUBLE_EQ(w.mean[0], 0.75);
  EXPECT_NEAR(w.high[0] - w.mean[0], kT975With1Dof * 0.25, 1e-9);
  // Random, iteration 4: 3 and 0 on wall 0, 0 and 1 on wall 1.
  EXPECT_DOUBLE_EQ(series[static_cast<int>(Regime::Random)].mean[3], 1.0);

  // Sampling: iteration 1, every step-th and the last.
  EXPECT_EQ(regime_series(data.conditions[0], 4, 3)[0].x, (std::vector<double>{1, 3, 4}));
}

TEST(PaperFiguresTest, EpisodeLengthsCountOnlyTheRunsThatCompletedTheEpisode) {
  const PaperFigureData data = read_paper_figure_data(write_folder("paper_figures_episodes"));
  const WallBandSeries s = episode_length_series(data.conditions[0]);
  EXPECT_EQ(s.x, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(s.walls, (std::vector<int>{2, 2, 1}));
  // Episode 1: wall means 15 and 35.
  EXPECT_DOUBLE_EQ(s.mean[0], 25);
  EXPECT_NEAR(s.high[0] - s.mean[0], kT975With1Dof * 10, 1e-9);
  // Episode 2: wall 0 has only its first run (4), wall 1 both (6 and 8, mean 7).
  EXPECT_DOUBLE_EQ(s.mean[1], 5.5);
  EXPECT_NEAR(s.mean[1] - s.low[1], kT975With1Dof * 1.5, 1e-9);
  // Episode 3: one wall, no interval.
  EXPECT_DOUBLE_EQ(s.mean[2], 2);
  EXPECT_TRUE(std::isnan(s.low[2]));
  EXPECT_TRUE(std::isnan(s.high[2]));
}

TEST(PaperFiguresTest, EveryFigureIsWellFormedAndNamesItsSeries) {
  const PaperFigureData data = read_paper_figure_data(write_folder("paper_figures_svg"));
  const auto figures = paper_figures(data);
  ASSERT_EQ(figures.size(), 4u);
  EXPECT_EQ(figures[0].first, "fig2b_qgrid_maps.svg");
  EXPECT_EQ(figures[1].first, "fig3_regimes.svg");
  EXPECT_EQ(figures[2].first, "fig4_episode_lengths.svg");
  EXPECT_EQ(figures[3].first, "transfer_minus_control.svg");
  for (const auto& [name, svg] : figures) {
    EXPECT_EQ(check_well_formed(svg), "") << name;
    EXPECT_NE(svg.find("viewBox=\"0 0 "), std::string::npos) << name;
    EXPECT_EQ(svg.find("nan"), std::string::npos) << name;
    EXPECT_EQ(svg.find("inf"), std::string::npos) << name;
  }
  const std::string& fig2b = figures[0].second;
  for (const char* text : {">right hand free<", ">left foot free<", "P_i: centre of the free limb",
                           ">training (mean over 4 runs on 2 walls)<", "summed Q_grid"}) {
    EXPECT_NE(fig2b.find(text), std::string::npos) << text;
  }
  const std::string& fig3 = figures[1].second;
  for (const char* text :
       {">w-greedy<", ">g-greedy<", ">random<", ">control (4 runs on 2 walls)<", "cumulative actions (count)",
        "iteration (real actions)", "Student-t 95 % interval over walls"}) {
    EXPECT_NE(fig3.find(text), std::string::npos) << text;
  }
  EXPECT_NE(fig3.find("<polygon"), std::string::npos) << "bands, with two walls";
  const std::string& fig4 = figures[2].second;
  // Both walls' plans: (8 + 11) / 2 for every condition, so one dashed line for all three.
  for (const char* text :
       {">training (4 runs on 2 walls)<", "episode length (actions, log scale)",
        ">shortest climb 9.5 (training, transfer, control)<", "counts only the runs that completed it"}) {
    EXPECT_NE(fig4.find(text), std::string::npos) << text;
  }
  const std::string& forest = figures[3].second;
  for (const char* text : {">zeta_metric (higher is better)<", ">alpha_metric (lower is better)<", "p = 0.434, 2 walls",
                           "+25.0 % [-12.5, +62.5]", "not available: control&apos;s mean is 0", ">favours transfer<"}) {
    EXPECT_NE(forest.find(text), std::string::npos) << text;
  }
  EXPECT_LT(forest.find("zeta_metric"), forest.find("alpha_metric"));
}

// Tile t is (column t % columns, row t / columns), drawn as the climber sees it: column 0
// on the right, row 0 at the bottom; the P_i point at the anchor tile's centre.
TEST(PaperFiguresTest, Fig2bPlacesTilesByRowTimesColumnsPlusColumn) {
  const std::string svg = fig2b_svg(read_paper_figure_data(write_folder("paper_figures_tiles")));
  const auto number = [&](std::size_t at, const std::string& name) {
    const std::size_t value = svg.find(" " + name + "=\"", at) + name.size() + 3;
    return std::stod(svg.substr(value, svg.find('"', value) - value));
  };
  const std::size_t first_map = svg.find("<g class=\"cells\"");
  const std::size_t map_end = svg.find("</g>", first_map);
  double min_x = 1e9, max_y = -1e9;
  for (std::size_t at = svg.find("<rect", first_map); at < map_end; at = svg.find("<rect", at + 1)) {
    min_x = std::min(min_x, number(at, "x"));
    max_y = std::max(max_y, number(at, "y"));
  }
  const std::size_t highest = svg.find("fill=\"#b2182b\"", first_map);
  ASSERT_LT(highest, map_end);
  const std::size_t highest_rect = svg.rfind("<rect", highest);
  EXPECT_DOUBLE_EQ(number(highest_rect, "x"), min_x) << "column 2 of 3 is the leftmost";
  EXPECT_DOUBLE_EQ(number(highest_rect, "y"), max_y) << "row 0 is the bottom";
  const std::size_t lowest = svg.find("fill=\"#2166ac\"", first_map);
  ASSERT_LT(lowest, map_end);
  const double cell_width = number(highest_rect, "width"), cell_height = number(highest_rect, "height");
  EXPECT_NEAR(number(svg.rfind("<rect", lowest), "x"), min_x + cell_width, 0.01) << "column 1: the middle";

  const std::size_t anchor = svg.find("class=\"anchor\"", map_end);
  ASSERT_NE(anchor, std::string::npos);
  EXPECT_NEAR(number(anchor, "cx"), min_x + cell_width / 2, 0.01);
  EXPECT_NEAR(number(anchor, "cy"), max_y + cell_height / 2, 0.01);
}

TEST(PaperFiguresTest, SameFolderGivesSameBytes) {
  const fs::path folder = write_folder("paper_figures_determinism");
  const auto first = paper_figures(read_paper_figure_data(folder));
  const auto second = paper_figures(read_paper_figure_data(folder));
  EXPECT_EQ(first, second);
}

TEST(PaperFiguresTest, OneWallDrawsNoBand) {
  Json summary = summary_json();
  summary["seeds_per_wall"] = 4;
  for (const char* condition : {"training", "transfer", "control"}) {
    for (auto& facts : summary["run_facts"][condition]) facts["wall_pair"] = 0;
  }
  const auto figures = paper_figures(read_paper_figure_data(write_folder("paper_figures_one_wall", summary)));
  EXPECT_EQ(figures[1].second.find("<polygon"), std::string::npos);
  EXPECT_EQ(figures[2].second.find("<polygon"), std::string::npos);
  EXPECT_NE(figures[1].second.find("one wall, so no interval"), std::string::npos);
}

TEST(PaperFiguresTest, Fig4ExplainsTheDashedLineOnlyWhenAPlanIsKnownAndTakesATitle) {
  PaperFigureData data = read_paper_figure_data(write_folder("paper_figures_plans"));
  const std::string with_plans = fig4_svg(data, "cell 2: experiment.transfer = prior");
  EXPECT_NE(with_plans.find("dashed: the shortest climb"), std::string::npos);
  EXPECT_NE(with_plans.find("cell 2: experiment.transfer = prior"), std::string::npos);
  for (PaperConditionData& condition : data.conditions) {
    for (PaperRunData& run : condition.runs) run.plan_length = -1;
  }
  const std::string without = fig4_svg(data);
  EXPECT_EQ(without.find("dashed"), std::string::npos);
  EXPECT_EQ(without.find("shortest climb"), std::string::npos);
  EXPECT_NE(without.find("Fig. 4: episode lengths"), std::string::npos);
}

}  // namespace
}  // namespace crux
