#pragma once
// A small SVG plotting layer (Debian packages no C++ plotting library): axes with "nice"
// linear or log10 ticks, lines, shaded bands, dashed reference lines, points with
// horizontal error bars, legends of those marks, and colour-mapped cells with a colour
// bar. Each draw_* function appends SVG elements to a string; svg_document wraps them
// into a standalone SVG 1.1 page. Numbers are written with a fixed format, so the same
// input gives the same bytes.

#include <string>
#include <string_view>
#include <vector>

#include "views/axis_ticks.hpp"
#include "views/palette.hpp"
#include "views/svg_document.hpp"

namespace crux {

inline constexpr double kPlotTitleFontSize = 16;
inline constexpr double kPlotSubtitleFontSize = 12;
inline constexpr double kPlotLabelFontSize = kDefaultFontSize;  // axis titles, legend, panel titles
inline constexpr double kPlotTickFontSize = 11;

enum class AxisScale { Linear, Log10 };

struct Axis {
  AxisScale scale = AxisScale::Linear;
  double low = 0, high = 1;  // the data range shown; positive on a log10 axis
  std::vector<double> ticks;
  std::vector<std::string> tick_labels;
  std::string title;  // with its unit
};

// An axis over the nice ticks that cover [min, max].
Axis linear_axis(double min, double max, std::string title, int target_ticks = 5);
// An axis from the power of ten at or below min to the one above max (0 < min <= max),
// ticked at each power of ten, and at its 2 and 5 multiples when it spans at most two
// decades. Throws std::invalid_argument for a non-positive or non-finite min.
Axis log10_axis(double min, double max, std::string title);

// A plot area on the page and the axes that map data into it.
struct Panel {
  double left = 0, top = 0, width = 1, height = 1;  // pixels
  Axis x, y;

  // Data to pixels. A value outside its axis is drawn on the axis's edge, so a band
  // reaching below a log10 axis (or to 0 or below) stops at the axis.
  double x_pixel(double value) const;
  double y_pixel(double value) const;
};

// The horizontal room the y axis's tick labels and title need left of the panel.
double y_axis_room(const Axis& y);
inline constexpr double kXAxisRoom = 44;  // below the panel: tick labels and title

// Light grid lines at the ticks, the frame, tick marks and labels, and the axis titles
// (the y title turned a quarter, left of the tick labels; either title may be empty).
void draw_axes(std::string& svg, const Panel& panel);

// A line through the points (x[i], y[i]), broken wherever a value is not finite.
// Throws std::invalid_argument when the sizes differ.
void draw_polyline(std::string& svg, const Panel& panel, const std::vector<double>& x, const std::vector<double>& y,
                   const Stroke& stroke);

// The area between low[i] and high[i] over x[i], broken wherever a value is not finite.
// Throws std::invalid_argument when the sizes differ.
void draw_band(std::string& svg, const Panel& panel, const std::vector<double>& x, const std::vector<double>& low,
               const std::vector<double>& high, std::string_view colour, double opacity = 0.22);

enum class Direction { Horizontal, Vertical };
// A line across the whole panel at `value` of the y axis (horizontal) or x axis (vertical).
void draw_reference_line(std::string& svg, const Panel& panel, Direction direction, double value, const Stroke& stroke);

// A disc at (x, y) with a horizontal bar from x_low to x_high, capped at both ends.
void draw_point_with_error_bar(std::string& svg, const Panel& panel, double x, double x_low, double x_high, double y,
                               std::string_view colour);

enum class LegendMark {
  Line,          // a stroke (dashed when the entry has a dash)
  LineWithBand,  // a stroke over a shaded band
  Point,         // a disc
  PointWithBar,  // a disc on a horizontal error bar
};
struct LegendEntry {
  LegendMark mark = LegendMark::Line;
  std::string colour;
  std::string dash;
  std::string text;
};
// One row per entry, from (left, top), through the views' legend writer; the size it takes.
double legend_width(const std::vector<LegendEntry>& entries);
double legend_height(const std::vector<LegendEntry>& entries);
void draw_legend(std::string& svg, double left, double top, const std::vector<LegendEntry>& entries);

// A colour scale diverging from white at 0, blue below and red above, each side spread
// over its own range (low <= 0 <= high), so that small negative values stay visible
// beside large positive ones.
struct DivergingScale {
  double low = -1, high = 1;
};
// Where a value lies on the scale, 0 (low) to 1 (high), 0.5 at 0 when both sides exist.
double diverging_position(const DivergingScale& scale, double value);
std::string diverging_colour(const DivergingScale& scale, double value);  // "#rrggbb"

struct Cell {
  double x = 0, y = 0, width = 0, height = 0;  // pixels
  double value = 0;
};
void draw_cells(std::string& svg, const std::vector<Cell>& cells, const DivergingScale& scale);

// A horizontal colour bar with its ticks (0 and nice ticks on each side) and title below.
inline constexpr double kColourBarHeight = 14;
inline constexpr double kColourBarRoom = 52;  // the bar, its tick labels and its title
void draw_colour_bar(std::string& svg, double left, double top, double width, const DivergingScale& scale,
                     std::string_view title);

}  // namespace crux
