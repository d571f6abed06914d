#include "views/paper_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>

#include "common/counted.hpp"
#include "experiments/statistics.hpp"
#include "views/palette.hpp"
#include "views/plot_svg.hpp"

namespace crux {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// --- Statistics over walls -------------------------------------------------------------

// The mean over walls of each wall's mean of `values` (run i on wall wall_of[i]).
MeanInterval over_walls(const std::vector<double>& values, const std::vector<std::size_t>& wall_of) {
  return mean_interval(cluster_means(values, wall_of));
}

void append(WallBandSeries& series, double x, const MeanInterval& m) {
  series.x.push_back(x);
  series.mean.push_back(m.mean);
  series.low.push_back(m.n >= 2 ? m.mean - m.half_width : kNaN);
  series.high.push_back(m.n >= 2 ? m.mean + m.half_width : kNaN);
  series.walls.push_back(m.n);
}

int wall_count(const PaperConditionData& condition) {
  std::set<int> walls;
  for (const PaperRunData& run : condition.runs) walls.insert(run.wall_pair);
  return static_cast<int>(walls.size());
}

// One sampled iteration in about 400 keeps Fig. 3's file small and its lines smooth.
int fig3_step(int iterations) { return std::max(1, (iterations + 399) / 400); }

// --- Page layout -----------------------------------------------------------------------

constexpr double kFigureMargin = 16;

const char* condition_colour(Condition condition) {
  switch (condition) {
    case Condition::Training:
      return kOkabeItoBlue;
    case Condition::Transfer:
      return kOkabeItoVermillion;
    case Condition::Control:
      return kOkabeItoBluishGreen;
  }
  return kTextColour;
}

struct RegimeStyle {
  const char* label;
  const char* colour;
  const char* dash;  // told apart in grey print too
};
constexpr std::array<RegimeStyle, kRegimeCount> kRegimeStyles{{
    {"w-greedy", kOkabeItoBlue, ""},
    {"g-greedy", kOkabeItoOrange, "8 4"},
    {"random", kTextColour, "2 3"},
}};

struct Header {
  std::string title;
  std::vector<std::string> subtitles;

  double height() const { return 30 + 16 * static_cast<double>(subtitles.size()) + 12; }
  double width() const {
    double widest = estimated_text_width(title, kPlotTitleFontSize);
    for (const std::string& line : subtitles) {
      widest = std::max(widest, estimated_text_width(line, kPlotSubtitleFontSize));
    }
    return widest;
  }
  void draw(std::string& svg) const {
    draw_text(svg, kFigureMargin, kFigureMargin + 14, title,
              {.size = kPlotTitleFontSize, .colour = kTitleColour, .bold = true});
    for (std::size_t i = 0; i < subtitles.size(); ++i) {
      draw_text(svg, kFigureMargin, kFigureMargin + 34 + 16 * static_cast<double>(i), subtitles[i],
                {.size = kPlotSubtitleFontSize, .colour = kSubtitleColour});
    }
  }
};

std::string runs_phrase(int runs, int walls) {
  return fmt::format("{} on {}", counted(runs, "run"), counted(walls, "wall"));
}

std::string band_phrase(const PaperFigureData& data) {
  int walls = 0;
  for (const PaperConditionData& c : data.conditions) walls = std::max(walls, wall_count(c));
  const std::string per_wall =
      data.seeds_per_wall == 1
          ? std::string("mean over walls (one run per wall)")
          : fmt::format("mean over walls of each wall's mean over its {} runs", data.seeds_per_wall);
  if (walls < 2) return per_wall + "; one wall, so no interval";
  return per_wall + "; band: Student-t 95 % interval over walls";
}

std::string limb_title(Limb limb) {
  std::string name = enum_name(limb);
  std::replace(name.begin(), name.end(), '_', ' ');
  return name + " free";
}

std::string format_length(double value) { return fmt::format("{:.1f}", value); }

}  // namespace

std::array<WallBandSeries, kRegimeCount> regime_series(const PaperConditionData& condition, int iterations, int step) {
  step = std::max(1, step);
  std::vector<int> samples;  // iterations, from 1
  for (int i = 1; i <= iterations; ++i) {
    if (i == 1 || i % step == 0 || i == iterations) samples.push_back(i);
  }
  // counts[run][sample][regime]: the run's actions of each regime up to that iteration.
  std::vector<std::vector<std::array<double, kRegimeCount>>> counts;
  std::vector<std::size_t> wall_of;
  for (const PaperRunData& run : condition.runs) {
    std::array<double, kRegimeCount> count{};
    std::vector<std::array<double, kRegimeCount>> at_samples;
    std::size_t next = 0;
    for (int i = 1; i <= iterations; ++i) {
      if (i <= static_cast<int>(run.regimes.size())) count[static_cast<int>(run.regimes[i - 1])] += 1;
      if (next < samples.size() && samples[next] == i) {
        at_samples.push_back(count);
        ++next;
      }
    }
    counts.push_back(std::move(at_samples));
    wall_of.push_back(static_cast<std::size_t>(run.wall_pair));
  }
  std::array<WallBandSeries, kRegimeCount> series;
  std::vector<double> values(condition.runs.size());
  for (std::size_t s = 0; s < samples.size(); ++s) {
    for (int r = 0; r < kRegimeCount; ++r) {
      for (std::size_t k = 0; k < counts.size(); ++k) values[k] = counts[k][s][r];
      append(series[r], samples[s], over_walls(values, wall_of));
    }
  }
  return series;
}

WallBandSeries episode_length_series(const PaperConditionData& condition) {
  std::size_t episodes = 0;
  for (const PaperRunData& run : condition.runs) episodes = std::max(episodes, run.episode_lengths.size());
  WallBandSeries series;
  for (std::size_t e = 0; e < episodes; ++e) {
    std::vector<double> values;
    std::vector<std::size_t> wall_of;
    for (const PaperRunData& run : condition.runs) {
      if (e >= run.episode_lengths.size()) continue;  // this run never completed episode e
      values.push_back(run.episode_lengths[e]);
      wall_of.push_back(static_cast<std::size_t>(run.wall_pair));
    }
    append(series, static_cast<double>(e + 1), over_walls(values, wall_of));
  }
  return series;
}

namespace {

// Where Fig. 2b's maps go: each fits a 130 x 240 pixel box, its tiles keeping their
// proportions, in one slot per free limb wide enough for the limb's heading.
struct Fig2bLayout {
  double cell_width = 0, cell_height = 0, map_width = 0, map_height = 0, slot = 0;
  double maps_left = kFigureMargin + 56;  // room for the row numbers and the row title
  // Numbers at most every 14 pixels, so that they never touch.
  int column_every = 1, row_every = 1;

  double map_left(int limb) const { return maps_left + slot * limb + (slot - 32 - map_width) / 2; }
  double maps_right() const { return maps_left + slot * kLimbCount - 32; }
};

Fig2bLayout fig2b_layout(const GridParameters& grid) {
  const double scale = std::min(130.0 / (grid.columns * grid.tile_width), 240.0 / (grid.rows * grid.tile_height));
  Fig2bLayout layout;
  layout.cell_width = grid.tile_width * scale;
  layout.cell_height = grid.tile_height * scale;
  layout.map_width = layout.cell_width * grid.columns;
  layout.map_height = layout.cell_height * grid.rows;
  double heading_width = 0;
  for (int l = 0; l < kLimbCount; ++l) {
    heading_width = std::max(heading_width, estimated_text_width(limb_title(static_cast<Limb>(l)), kPlotLabelFontSize));
  }
  layout.slot = std::max(layout.map_width, heading_width) + 32;
  layout.column_every = static_cast<int>(std::ceil(14 / layout.cell_width));
  layout.row_every = static_cast<int>(std::ceil(14 / layout.cell_height));
  return layout;
}

// One colour scale for all maps, from 0 to the lowest and the highest value of any.
DivergingScale fig2b_colour_scale(const PaperFigureData& data) {
  DivergingScale colours{0, 0};
  for (const PaperConditionData& c : data.conditions) {
    for (const auto& map : c.q_grid_maps) {
      if (map.size() != static_cast<std::size_t>(data.grid.tile_count())) {
        throw std::invalid_argument(
            fmt::format("fig2b_svg: a map of {} values for a grid of {} tiles", map.size(), data.grid.tile_count()));
      }
      for (const double v : map) {
        colours.low = std::min(colours.low, v);
        colours.high = std::max(colours.high, v);
      }
    }
  }
  return colours;
}

// One condition's row of maps, its top at y, with the row numbers on its left.
void draw_fig2b_condition_maps(std::string& svg, const GridParameters& grid, const Fig2bLayout& layout,
                               const PaperConditionData& c, const DivergingScale& colours, double y) {
  for (int l = 0; l < kLimbCount; ++l) {
    // The climber's view: column 0 (the climber's right) on the right, row 0 at the bottom.
    const auto cell_x = [&](int column) {
      return layout.map_left(l) + (grid.columns - 1 - column) * layout.cell_width;
    };
    const auto cell_y = [&](int row) { return y + (grid.rows - 1 - row) * layout.cell_height; };
    std::vector<Cell> cells;
    for (int tile = 0; tile < grid.tile_count(); ++tile) {
      const int column = tile % grid.columns, row = tile / grid.columns;
      cells.push_back({cell_x(column), cell_y(row), layout.cell_width, layout.cell_height, c.q_grid_maps[l][tile]});
    }
    draw_cells(svg, cells, colours);
    svg += fmt::format(
        "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke=\"{}\" "
        "stroke-width=\"1\"/>\n",
        layout.map_left(l), y, layout.map_width, layout.map_height, kPlotFrameColour);
    if (grid.space != AgentSpaceKind::Grid) continue;  // the reach agent space has no anchors
    const auto [anchor_column, anchor_row] = grid.anchors[l];
    svg += fmt::format(
        "<circle class=\"anchor\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"4.5\" fill=\"{}\" stroke=\"white\" "
        "stroke-width=\"1.5\"/>\n",
        cell_x(anchor_column) + layout.cell_width / 2, cell_y(anchor_row) + layout.cell_height / 2, kAnchorColour);
  }
  for (int row = 0; row < grid.rows; row += layout.row_every) {
    draw_text(svg, layout.maps_left - 8, y + (grid.rows - 0.5 - row) * layout.cell_height + 4, std::to_string(row),
              {.size = kPlotTickFontSize, .anchor = "end", .colour = kDarkGrey});
  }
}

}  // namespace

// Paper, Fig. 2b: one map per free limb of the summed Q_grid value of each tile, with the
// limb's P_i point. Rows here are conditions, so that transfer's maps sit under
// training's.
std::string fig2b_svg(const PaperFigureData& data) {
  const GridParameters& grid = data.grid;
  const Header header{
      "Fig. 2b: Q_grid maps per free limb",
      {"each tile: Q_grid(s, tile) summed over the agent-space states s with that free limb, mean over a condition's "
       "runs",
       fmt::format("{} x {} grid of {} x {} m tiles, drawn as the climber facing the wall sees it (its right on the "
                   "right)",
                   grid.columns, grid.rows, grid.tile_width, grid.tile_height),
       "one colour scale for all maps: white at 0; blue to the lowest value, red to the highest"}};
  const Fig2bLayout layout = fig2b_layout(grid);
  const DivergingScale colours = fig2b_colour_scale(data);

  std::string svg;
  header.draw(svg);
  double y = kFigureMargin + header.height();
  for (int l = 0; l < kLimbCount; ++l) {
    draw_text(svg, layout.map_left(l) + layout.map_width / 2, y + 12, limb_title(static_cast<Limb>(l)),
              {.anchor = "middle", .bold = true});
  }
  y += 22;
  const double rows_top = y;
  for (const PaperConditionData& c : data.conditions) {
    draw_text(svg, layout.maps_left - 30, y + 13,
              fmt::format("{} (mean over {})", enum_name(c.condition),
                          runs_phrase(static_cast<int>(c.runs.size()), wall_count(c))),
              {.colour = condition_colour(c.condition), .bold = true});
    y += 22;
    draw_fig2b_condition_maps(svg, grid, layout, c, colours, y);
    y += layout.map_height + 14;
  }
  for (int l = 0; l < kLimbCount; ++l) {
    for (int column = 0; column < grid.columns; column += layout.column_every) {
      draw_text(svg, layout.map_left(l) + (grid.columns - 0.5 - column) * layout.cell_width, y + 2,
                std::to_string(column), {.size = kPlotTickFontSize, .anchor = "middle", .colour = kDarkGrey});
    }
  }
  const double maps_left = layout.maps_left, maps_right = layout.maps_right();
  draw_text(svg, (maps_left + maps_right) / 2, y + 22, "grid column (0 = the climber's right)", {.anchor = "middle"});
  draw_text(svg, kFigureMargin + 12, (rows_top + y - 14) / 2, "grid row (0 = bottom)",
            {.anchor = "middle", .rotation = -90});
  y += 42;

  const double bar_width = std::min(360.0, maps_right - maps_left);
  draw_colour_bar(svg, maps_left, y, bar_width, colours, "summed Q_grid (reward units)");
  const std::vector<LegendEntry> legend{
      {LegendMark::Point, kAnchorColour, "", "P_i: centre of the free limb's anchor tile"}};
  const double legend_left = maps_left + bar_width + 32;
  draw_legend(svg, legend_left, y - 3, legend);

  const double width =
      std::max({maps_right, legend_left + legend_width(legend), kFigureMargin + header.width()}) + kFigureMargin;
  return svg_document(width, y + kColourBarRoom + kFigureMargin, header.title, svg);
}

// Paper, Fig. 3: how many actions each selection regime has taken by each iteration, one
// panel per condition on a shared y axis.
std::string fig3_svg(const PaperFigureData& data) {
  const int step = fig3_step(data.iterations);
  const Header header{"Fig. 3: cumulative actions per selection regime",
                      {band_phrase(data), fmt::format("sampled at iteration 1, every {}{} iteration and the last", step,
                                                      step == 1 ? "" : "th")}};
  constexpr double kPanelWidth = 300, kPanelHeight = 240, kPanelGap = 24;
  const Axis x = linear_axis(0, std::max(1, data.iterations), "iteration (real actions)");
  const Axis y = linear_axis(0, std::max(1, data.iterations), "cumulative actions (count)");
  Axis y_untitled = y;
  y_untitled.title.clear();

  std::string svg;
  header.draw(svg);
  const double top = kFigureMargin + header.height() + 22;  // room for the panel titles
  double left = kFigureMargin + y_axis_room(y);
  bool any_band = false;
  for (const PaperConditionData& c : data.conditions) {
    // Only the first panel carries the y axis title; all panels share the axis.
    const Panel panel{left, top, kPanelWidth, kPanelHeight, x, &c == &data.conditions.front() ? y : y_untitled};
    draw_axes(svg, panel);
    const auto series = regime_series(c, data.iterations, step);
    for (int r = 0; r < kRegimeCount; ++r) {
      draw_band(svg, panel, series[r].x, series[r].low, series[r].high, kRegimeStyles[r].colour);
      any_band = any_band ||
                 std::any_of(series[r].low.begin(), series[r].low.end(), [](double v) { return std::isfinite(v); });
    }
    for (int r = 0; r < kRegimeCount; ++r) {
      draw_polyline(svg, panel, series[r].x, series[r].mean, {kRegimeStyles[r].colour, 2, kRegimeStyles[r].dash});
    }
    draw_text(
        svg, left, top - 8,
        fmt::format("{} ({})", enum_name(c.condition), runs_phrase(static_cast<int>(c.runs.size()), wall_count(c))),
        {.colour = condition_colour(c.condition), .bold = true});
    left += kPanelWidth + kPanelGap + y_axis_room(y_untitled);
  }
  std::vector<LegendEntry> legend;
  for (const RegimeStyle& style : kRegimeStyles) {
    legend.push_back({any_band ? LegendMark::LineWithBand : LegendMark::Line, style.colour, style.dash, style.label});
  }
  const double legend_left = left - y_axis_room(y_untitled) - kPanelGap + 24;
  draw_legend(svg, legend_left, top, legend);
  const double width = std::max(legend_left + legend_width(legend), kFigureMargin + header.width()) + kFigureMargin;
  return svg_document(width, top + kPanelHeight + kXAxisRoom + kFigureMargin, header.title, svg);
}

namespace {

// Fig. 4's dashed lines: conditions whose walls give the same mean shortest climb share one
// (transfer and control run on the same walls).
struct Fig4ShortestClimbs {
  std::map<std::string, std::vector<Condition>> conditions;  // the mean, formatted -> its conditions
  std::map<std::string, double> values;                      // the mean, formatted -> the mean
  // Over every condition's mean, so that the axis holds them all.
  double lowest = std::numeric_limits<double>::infinity(), highest = -std::numeric_limits<double>::infinity();
};

Fig4ShortestClimbs fig4_shortest_climbs(const PaperFigureData& data) {
  Fig4ShortestClimbs climbs;
  for (const PaperConditionData& c : data.conditions) {
    std::map<int, int> plan_of_wall;
    for (const PaperRunData& run : c.runs) {
      if (run.plan_length >= 0) plan_of_wall[run.wall_pair] = run.plan_length;
    }
    if (plan_of_wall.empty()) continue;
    double sum = 0;
    for (const auto& [wall, length] : plan_of_wall) sum += length;
    const double mean = sum / static_cast<double>(plan_of_wall.size());
    climbs.conditions[format_length(mean)].push_back(c.condition);
    climbs.values[format_length(mean)] = mean;
    climbs.lowest = std::min(climbs.lowest, mean);
    climbs.highest = std::max(climbs.highest, mean);
  }
  return climbs;
}

// Each condition's band, then each one's mean line over all the bands.
void draw_fig4_conditions(std::string& svg, const Panel& panel, const PaperFigureData& data,
                          const std::vector<WallBandSeries>& series, std::vector<LegendEntry>& legend) {
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PaperConditionData& c = data.conditions[k];
    const bool band =
        std::any_of(series[k].low.begin(), series[k].low.end(), [](double v) { return std::isfinite(v); });
    // Fainter than Fig. 3's: three conditions' bands overlap here.
    draw_band(svg, panel, series[k].x, series[k].low, series[k].high, condition_colour(c.condition), 0.15);
    legend.push_back(
        {band ? LegendMark::LineWithBand : LegendMark::Line, condition_colour(c.condition), "",
         fmt::format("{} ({})", enum_name(c.condition), runs_phrase(static_cast<int>(c.runs.size()), wall_count(c)))});
  }
  for (std::size_t k = 0; k < series.size(); ++k) {
    draw_polyline(svg, panel, series[k].x, series[k].mean, {condition_colour(data.conditions[k].condition), 1.6, ""});
  }
}

// Labels under the right end of their line, where no mean can be (no episode is shorter
// than the shortest climb), on a white ground over the bands, pushed down so that close
// lines' labels do not overlap; the highest line first.
void draw_fig4_shortest_climbs(std::string& svg, const Panel& panel, const Fig4ShortestClimbs& climbs,
                               std::vector<LegendEntry>& legend) {
  double label_floor = -std::numeric_limits<double>::infinity();
  for (auto it = climbs.conditions.rbegin(); it != climbs.conditions.rend(); ++it) {
    const auto& [text, conditions] = *it;
    const char* colour = conditions.size() == 1 ? condition_colour(conditions.front()) : kDarkGrey;
    std::string names;
    for (const Condition c : conditions) names += fmt::format("{}{}", names.empty() ? "" : ", ", enum_name(c));
    const double value = climbs.values.at(text);
    draw_reference_line(svg, panel, Direction::Horizontal, value, {colour, 1.6, "7 4"});
    double label_y = std::max(panel.y_pixel(value) + 15, label_floor + 15);
    if (label_y > panel.top + panel.height - 4) label_y = panel.y_pixel(value) - 5;  // a line on the axis
    label_floor = label_y;
    const std::string label = fmt::format("shortest climb {} ({})", text, names);
    const double label_width = estimated_text_width(label, kPlotTickFontSize);
    svg += fmt::format(
        "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"15\" fill=\"white\" fill-opacity=\"0.85\"/>\n",
        panel.left + panel.width - 8 - label_width, label_y - 11.5, label_width + 4);
    draw_text(svg, panel.left + panel.width - 6, label_y, label,
              {.size = kPlotTickFontSize, .anchor = "end", .colour = colour});
    legend.push_back({LegendMark::Line, colour, "7 4", fmt::format("shortest climb {} (walls of {})", text, names)});
  }
}

}  // namespace

// Paper, Fig. 4: episode length against episode, on a log scale, with the walls' shortest
// climb for reference (the paper quotes about 10 actions for the optimal policy).
std::string fig4_svg(const PaperFigureData& data, std::string_view title) {
  std::vector<WallBandSeries> series;
  double low = std::numeric_limits<double>::infinity(), high = 0, episodes = 1;
  for (const PaperConditionData& c : data.conditions) {
    series.push_back(episode_length_series(c));
    for (std::size_t i = 0; i < series.back().x.size(); ++i) {
      low = std::min(low, series.back().mean[i]);
      high = std::max(high, series.back().mean[i]);
      if (std::isfinite(series.back().high[i])) high = std::max(high, series.back().high[i]);
    }
    episodes = std::max(episodes, static_cast<double>(series.back().x.size()));
  }
  const Fig4ShortestClimbs climbs = fig4_shortest_climbs(data);
  low = std::min(low, climbs.lowest);
  high = std::max(high, climbs.highest);
  if (!std::isfinite(low)) low = high = 1;  // no episode at all
  low = std::max(low, 1.0);
  Header header{std::string(title),
                {band_phrase(data) + " (cut at the axis)",
                 "episode n counts only the runs that completed it, so later episodes rest on fewer runs"}};
  if (!climbs.conditions.empty()) {
    header.subtitles.push_back(
        "dashed: the shortest climb of the condition's walls (exact plan), mean over the walls where it is known");
  }
  const Axis x = linear_axis(0, episodes, "episode (from 1)");
  const Axis y = log10_axis(low, std::max(high, low), "episode length (actions, log scale)");
  const Panel panel{kFigureMargin + y_axis_room(y), kFigureMargin + header.height() + 6, 640, 360, x, y};

  std::string svg;
  header.draw(svg);
  draw_axes(svg, panel);
  std::vector<LegendEntry> legend;
  draw_fig4_conditions(svg, panel, data, series, legend);
  draw_fig4_shortest_climbs(svg, panel, climbs, legend);
  const double legend_left = panel.left + panel.width + 20;
  draw_legend(svg, legend_left, panel.top, legend);
  const double width = std::max(legend_left + legend_width(legend), kFigureMargin + header.width()) + kFigureMargin;
  return svg_document(width, panel.top + panel.height + kXAxisRoom + kFigureMargin, header.title, svg);
}

namespace {

constexpr const char* kFavoursTransfer = kOkabeItoBlue;
constexpr const char* kFavoursControl = kOkabeItoVermillion;
constexpr const char* kNoDifference = "#777777";
constexpr double kTransferRowHeight = 46;

// One metric's row of the forest plot, in % of |control's mean|.
struct TransferMetricRow {
  const TransferMetricData* metric;
  bool available;
  double value = 0, low = 0, high = 0;
};

std::vector<TransferMetricRow> transfer_metric_rows(const PaperFigureData& data) {
  std::vector<TransferMetricRow> rows;
  for (const TransferMetricData& m : data.transfer_metrics) {
    TransferMetricRow row{&m, m.control_mean != 0};
    if (row.available) {
      const double scale = 100 / std::abs(m.control_mean);
      row.value = m.difference * scale;
      row.low = m.difference_ci95 ? (*m.difference_ci95)[0] * scale : row.value;
      row.high = m.difference_ci95 ? (*m.difference_ci95)[1] * scale : row.value;
      // A control mean so close to 0 that the ratio overflows is no comparison either.
      row.available = std::isfinite(row.value) && std::isfinite(row.low) && std::isfinite(row.high);
    }
    rows.push_back(row);
  }
  return rows;
}

std::string transfer_metric_title(const TransferMetricData& m) {
  return m.name + (m.higher_is_better ? " (higher is better)" : " (lower is better)");
}

// The text right of each row's interval, and the widths the labels and these notes take.
struct TransferMetricNotes {
  std::vector<std::string> notes;
  double label_width = 0, note_width = 0;
};

TransferMetricNotes transfer_metric_notes(const std::vector<TransferMetricRow>& rows) {
  TransferMetricNotes out;
  for (const TransferMetricRow& row : rows) {
    const TransferMetricData& m = *row.metric;
    out.label_width = std::max({out.label_width, estimated_text_width(transfer_metric_title(m), kPlotLabelFontSize),
                                estimated_text_width(m.description, kPlotTickFontSize)});
    std::string note = "n/a";
    if (row.available) {
      note = m.difference_ci95 ? fmt::format("{:+.1f} % [{:+.1f}, {:+.1f}]", row.value, row.low, row.high)
                               : fmt::format("{:+.1f} % (no interval)", row.value);
    }
    out.notes.push_back(note);
    out.note_width = std::max(out.note_width, estimated_text_width(note, kPlotTickFontSize));
  }
  return out;
}

// Row i of `count`: its labels on the left, its note and p-value on the right, and its
// point and interval, coloured by which condition it favours.
void draw_transfer_metric_row(std::string& svg, const Panel& panel, const TransferMetricRow& row,
                              const std::string& note, std::size_t i, std::size_t count) {
  const TransferMetricData& m = *row.metric;
  const double centre = static_cast<double>(count) - 0.5 - static_cast<double>(i);
  const double row_top = panel.top + kTransferRowHeight * static_cast<double>(i);
  draw_text(svg, kFigureMargin + 4, row_top + 19, transfer_metric_title(m), {.bold = true});
  draw_text(svg, kFigureMargin + 4, row_top + 36, m.description,
            {.size = kPlotTickFontSize, .colour = kSubtitleColour});
  const double text_left = panel.left + panel.width + 16;
  draw_text(svg, text_left, row_top + 19, note, {.size = kPlotTickFontSize});
  const std::string p = m.p_value < 0.001 ? "p < 0.001" : fmt::format("p = {:.3f}", m.p_value);
  draw_text(svg, text_left, row_top + 36, fmt::format("{}, {}", p, counted(m.walls, "wall")),
            {.size = kPlotTickFontSize, .colour = kSubtitleColour});
  if (!row.available) {
    draw_text(svg, panel.left + panel.width / 2, panel.y_pixel(centre) + 4, "not available: control's mean is 0",
              {.size = kPlotTickFontSize, .anchor = "middle", .colour = kNoDifference, .italic = true});
    return;
  }
  const char* colour = row.value == 0                          ? kNoDifference
                       : (row.value > 0) == m.higher_is_better ? kFavoursTransfer
                                                               : kFavoursControl;
  draw_point_with_error_bar(svg, panel, row.value, row.low, row.high, centre, colour);
}

}  // namespace

// Not in the paper: the transfer metrics as a forest plot, each difference divided by
// |control's mean| so that metrics of different units share one axis.
std::string transfer_metrics_svg(const PaperFigureData& data) {
  int walls = 0;
  for (const TransferMetricData& m : data.transfer_metrics) walls = std::max(walls, m.walls);
  const Header header{
      "Transfer minus control, per metric",
      {"point: mean over walls of each wall's mean paired difference (transfer run minus its control run)",
       fmt::format("bar: Student-t 95 % interval over {}; both in % of |control's mean|, so that metrics of "
                   "different units share one axis",
                   counted(walls, "wall"))}};
  const std::vector<TransferMetricRow> rows = transfer_metric_rows(data);
  double low = 0, high = 0;
  for (const TransferMetricRow& row : rows) {
    if (!row.available) continue;
    low = std::min({low, row.value, row.low});
    high = std::max({high, row.value, row.high});
  }
  const TransferMetricNotes notes = transfer_metric_notes(rows);
  const Axis x = linear_axis(low, high, "transfer minus control (% of |control's mean|)", 6);
  const double plot_left = kFigureMargin + notes.label_width + 20;
  const double plot_height = kTransferRowHeight * static_cast<double>(std::max<std::size_t>(rows.size(), 1));
  const Panel panel{
      plot_left, kFigureMargin + header.height() + 6,
      380,       plot_height,
      x,         Axis{AxisScale::Linear, 0, std::max<double>(1, static_cast<double>(rows.size())), {}, {}, ""}};

  std::string svg;
  header.draw(svg);
  const double right_edge = panel.left + panel.width + 16 + std::max(notes.note_width, 120.0);
  for (std::size_t i = 0; i < rows.size(); i += 2) {  // every other row shaded, to guide the eye
    svg += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"#f4f4f4\"/>\n",
                       kFigureMargin, panel.top + kTransferRowHeight * static_cast<double>(i),
                       right_edge - kFigureMargin, kTransferRowHeight);
  }
  draw_axes(svg, panel);
  draw_reference_line(svg, panel, Direction::Vertical, 0, {kDarkGrey, 1.2, "5 4"});
  if (rows.empty()) {
    draw_text(svg, panel.left + panel.width / 2, panel.top + kTransferRowHeight / 2 + 4, "no metrics in this folder",
              {.anchor = "middle", .colour = kNoDifference, .italic = true});
  }
  for (std::size_t i = 0; i < rows.size(); ++i)
    draw_transfer_metric_row(svg, panel, rows[i], notes.notes[i], i, rows.size());
  const std::vector<LegendEntry> legend{{LegendMark::PointWithBar, kFavoursTransfer, "", "favours transfer"},
                                        {LegendMark::PointWithBar, kFavoursControl, "", "favours control"},
                                        {LegendMark::Line, kDarkGrey, "5 4", "no difference"}};
  const double legend_top = panel.top + panel.height + kXAxisRoom + 6;
  draw_legend(svg, panel.left, legend_top, legend);
  const double width =
      std::max({right_edge, panel.left + legend_width(legend), kFigureMargin + header.width()}) + kFigureMargin;
  return svg_document(width, legend_top + legend_height(legend) + kFigureMargin, header.title, svg);
}

std::vector<std::pair<std::string, std::string>> paper_figures(const PaperFigureData& data) {
  return {{"fig2b_qgrid_maps.svg", fig2b_svg(data)},
          {"fig3_regimes.svg", fig3_svg(data)},
          {"fig4_episode_lengths.svg", fig4_svg(data)},
          {"transfer_minus_control.svg", transfer_metrics_svg(data)}};
}

}  // namespace crux
