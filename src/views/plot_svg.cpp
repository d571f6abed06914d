#include "views/plot_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "views/legend.hpp"

namespace crux {
namespace {

constexpr double kTickLength = 4;
constexpr double kLegendSwatchWidth = 30;
// The plots' legend: 30 pixels of swatch and 8 of gap before the text.
constexpr LegendLayout kPlotLegendLayout{kPlotLabelFontSize, kLegendSwatchWidth + 8, 20, false};

std::string dash_attribute(std::string_view dash) {
  return dash.empty() ? std::string() : fmt::format(" stroke-dasharray=\"{}\"", dash);
}

// Where a value lies along an axis, 0 at low to 1 at high, clamped to the axis.
double axis_fraction(const Axis& axis, double value) {
  double fraction = 0;
  if (axis.scale == AxisScale::Log10) {
    if (!(value > 0)) return 0;
    fraction = (std::log10(value) - std::log10(axis.low)) / (std::log10(axis.high) - std::log10(axis.low));
  } else {
    fraction = (value - axis.low) / (axis.high - axis.low);
  }
  return std::clamp(fraction, 0.0, 1.0);
}

bool all_finite(double a, double b, double c) { return std::isfinite(a) && std::isfinite(b) && std::isfinite(c); }

// The runs of consecutive indices i in [0, n) where keep(i) holds, as [begin, end).
template <typename Keep>
std::vector<std::pair<std::size_t, std::size_t>> finite_runs(std::size_t n, Keep keep) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t i = 0; i < n;) {
    if (!keep(i)) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < n && keep(end)) ++end;
    runs.emplace_back(i, end);
    i = end;
  }
  return runs;
}

// ColorBrewer's RdBu, blue for negative values: told apart by colour-blind readers, and
// near-white at 0 so that tiles never tried (value 0) stay blank.
constexpr std::array<std::array<int, 3>, 7> kDivergingStops{{
    {0x21, 0x66, 0xac},
    {0x67, 0xa9, 0xcf},
    {0xd1, 0xe5, 0xf0},
    {0xf7, 0xf7, 0xf7},
    {0xfd, 0xdb, 0xc7},
    {0xef, 0x8a, 0x62},
    {0xb2, 0x18, 0x2b},
}};

std::string colour_at(double position) {
  const double scaled = std::clamp(position, 0.0, 1.0) * static_cast<double>(kDivergingStops.size() - 1);
  const auto below = std::min(static_cast<std::size_t>(scaled), kDivergingStops.size() - 2);
  const double t = scaled - static_cast<double>(below);
  std::array<int, 3> rgb{};
  for (int c = 0; c < 3; ++c) {
    const double value = (1 - t) * kDivergingStops[below][c] + t * kDivergingStops[below + 1][c];
    rgb[c] = static_cast<int>(std::lround(value));
  }
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

// An estimate of where a label centred at x spans, to keep labels from overlapping.
struct LabelSpan {
  double x = 0, half_width = 0;
  bool overlaps(const LabelSpan& other, double gap) const {
    return std::abs(x - other.x) < half_width + other.half_width + gap;
  }
};

}  // namespace

Axis linear_axis(double min, double max, std::string title, int target_ticks) {
  const Ticks ticks = nice_ticks(min, max, target_ticks);
  Axis axis{AxisScale::Linear, ticks.low, ticks.high, ticks.values, {}, std::move(title)};
  const double magnitude = std::max(std::abs(ticks.low), std::abs(ticks.high));
  for (const double value : ticks.values) axis.tick_labels.push_back(tick_label(value, ticks.step, magnitude));
  return axis;
}

Axis log10_axis(double min, double max, std::string title) {
  if (!(min > 0) || !std::isfinite(min) || !std::isfinite(max)) {
    throw std::invalid_argument(fmt::format("log10_axis: the range [{}, {}] must be positive and finite", min, max));
  }
  max = std::max(min, max);
  const int low = static_cast<int>(std::floor(std::log10(min) + 1e-9));
  int high = static_cast<int>(std::ceil(std::log10(max) - 1e-9));
  if (high == low) ++high;
  Axis axis{AxisScale::Log10, std::pow(10.0, low), std::pow(10.0, high), {}, {}, std::move(title)};
  const bool fine = high - low <= 2;
  for (int e = low; e <= high; ++e) {
    const double decade = std::pow(10.0, e);
    const int decimals = std::max(0, -e);
    for (const double multiple : {1.0, 2.0, 5.0}) {
      if (multiple != 1.0 && (!fine || e == high)) continue;
      axis.ticks.push_back(multiple * decade);
      axis.tick_labels.push_back(fmt::format("{:.{}f}", multiple * decade, decimals));
    }
  }
  return axis;
}

double Panel::x_pixel(double value) const { return left + axis_fraction(x, value) * width; }
double Panel::y_pixel(double value) const { return top + height - axis_fraction(y, value) * height; }

double y_axis_room(const Axis& y) {
  double widest = 0;
  for (const std::string& label : y.tick_labels)
    widest = std::max(widest, estimated_text_width(label, kPlotTickFontSize));
  return widest + kTickLength + 6 + (y.title.empty() ? 0 : 24);
}

void draw_axes(std::string& svg, const Panel& panel) {
  const double right = panel.left + panel.width, bottom = panel.top + panel.height;
  append_format(svg, "<g class=\"grid-lines\" stroke=\"{}\" stroke-width=\"1\">\n", kPlotGridLineColour);
  for (const double tick : panel.x.ticks) draw_vertical_line(svg, panel.x_pixel(tick), panel.top, bottom);
  for (const double tick : panel.y.ticks) draw_horizontal_line(svg, panel.left, right, panel.y_pixel(tick));
  svg += "</g>\n";
  append_format(svg,
                "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke=\"{}\" "
                "stroke-width=\"1\"/>\n",
                panel.left, panel.top, panel.width, panel.height, kPlotFrameColour);

  append_format(svg, "<g class=\"ticks\" stroke=\"{}\" stroke-width=\"1\">\n", kPlotFrameColour);
  for (const double tick : panel.x.ticks) draw_vertical_line(svg, panel.x_pixel(tick), bottom, bottom + kTickLength);
  for (const double tick : panel.y.ticks)
    draw_horizontal_line(svg, panel.left - kTickLength, panel.left, panel.y_pixel(tick));
  svg += "</g>\n";

  append_format(svg, "<g class=\"tick-labels\" font-size=\"{}\" fill=\"{}\">\n", kPlotTickFontSize, kDarkGrey);
  for (std::size_t i = 0; i < panel.x.ticks.size(); ++i) {
    draw_plain_text(svg, panel.x_pixel(panel.x.ticks[i]), bottom + kTickLength + 12, panel.x.tick_labels[i], "middle");
  }
  for (std::size_t i = 0; i < panel.y.ticks.size(); ++i) {
    draw_plain_text(svg, panel.left - kTickLength - 3, panel.y_pixel(panel.y.ticks[i]) + 4, panel.y.tick_labels[i],
                    "end");
  }
  svg += "</g>\n";

  if (!panel.x.title.empty()) {
    draw_text(svg, panel.left + panel.width / 2, bottom + 36, panel.x.title, {.anchor = "middle"});
  }
  if (!panel.y.title.empty()) {
    const double x = panel.left - y_axis_room(panel.y) + 14;
    draw_text(svg, x, panel.top + panel.height / 2, panel.y.title, {.anchor = "middle", .rotation = -90});
  }
}

void draw_polyline(std::string& svg, const Panel& panel, const std::vector<double>& x, const std::vector<double>& y,
                   const Stroke& stroke) {
  if (x.size() != y.size()) {
    throw std::invalid_argument(fmt::format("draw_polyline: {} x values but {} y values", x.size(), y.size()));
  }
  const auto runs = finite_runs(x.size(), [&](std::size_t i) { return std::isfinite(x[i]) && std::isfinite(y[i]); });
  for (const auto& [begin, end] : runs) {
    if (end - begin == 1) {  // a lone point would draw nothing as a line
      append_format(svg, "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"{}\"/>\n", panel.x_pixel(x[begin]),
                    panel.y_pixel(y[begin]), stroke.width, stroke.colour);
      continue;
    }
    svg += "<polyline points=\"";
    for (std::size_t i = begin; i < end; ++i) {
      append_format(svg, "{}{:.2f},{:.2f}", i == begin ? "" : " ", panel.x_pixel(x[i]), panel.y_pixel(y[i]));
    }
    append_format(svg, "\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.2f}\" stroke-linejoin=\"round\"{}/>\n",
                  stroke.colour, stroke.width, dash_attribute(stroke.dash));
  }
}

void draw_band(std::string& svg, const Panel& panel, const std::vector<double>& x, const std::vector<double>& low,
               const std::vector<double>& high, std::string_view colour, double opacity) {
  if (x.size() != low.size() || x.size() != high.size()) {
    throw std::invalid_argument(
        fmt::format("draw_band: {} x values, {} low and {} high values", x.size(), low.size(), high.size()));
  }
  const auto runs = finite_runs(x.size(), [&](std::size_t i) { return all_finite(x[i], low[i], high[i]); });
  for (const auto& [begin, end] : runs) {
    if (end - begin < 2) continue;  // no area
    svg += "<polygon points=\"";
    for (std::size_t i = begin; i < end; ++i) {
      append_format(svg, "{}{:.2f},{:.2f}", i == begin ? "" : " ", panel.x_pixel(x[i]), panel.y_pixel(high[i]));
    }
    for (std::size_t i = end; i-- > begin;)
      append_format(svg, " {:.2f},{:.2f}", panel.x_pixel(x[i]), panel.y_pixel(low[i]));
    append_format(svg, "\" fill=\"{}\" fill-opacity=\"{:.2f}\" stroke=\"none\"/>\n", colour, opacity);
  }
}

void draw_reference_line(std::string& svg, const Panel& panel, Direction direction, double value,
                         const Stroke& stroke) {
  double x1 = panel.left, x2 = panel.left + panel.width, y1 = panel.top, y2 = panel.top + panel.height;
  if (direction == Direction::Horizontal) {
    y1 = y2 = panel.y_pixel(value);
  } else {
    x1 = x2 = panel.x_pixel(value);
  }
  append_format(
      svg, "<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"{}\" stroke-width=\"{:.2f}\"{}/>\n",
      x1, y1, x2, y2, stroke.colour, stroke.width, dash_attribute(stroke.dash));
}

void draw_point_with_error_bar(std::string& svg, const Panel& panel, double x, double x_low, double x_high, double y,
                               std::string_view colour) {
  constexpr double kCap = 5;
  const double py = panel.y_pixel(y), low = panel.x_pixel(x_low), high = panel.x_pixel(x_high);
  append_format(svg, "<g class=\"error-bar\" stroke=\"{}\" stroke-width=\"1.8\">\n", colour);
  draw_horizontal_line(svg, low, high, py);
  for (const double end : {low, high}) {
    draw_vertical_line(svg, end, py - kCap, py + kCap);
  }
  svg += "</g>\n";
  append_format(svg,
                "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"5\" fill=\"{}\" stroke=\"white\" stroke-width=\"1.2\"/>\n",
                panel.x_pixel(x), py, colour);
}

double legend_width(const std::vector<LegendEntry>& entries) {
  std::vector<std::string> texts;
  for (const LegendEntry& entry : entries) texts.push_back(entry.text);
  return crux::legend_width(texts, kPlotLegendLayout);
}

double legend_height(const std::vector<LegendEntry>& entries) {
  return kPlotLegendLayout.row_height * static_cast<double>(entries.size());
}

void draw_legend(std::string& svg, double left, double top, const std::vector<LegendEntry>& entries) {
  std::vector<LegendItem> items;
  for (const LegendEntry& entry : entries) {
    items.push_back({entry.text, [&entry](std::string& out, double x, double y) {
                       const double x1 = x + 2, x2 = x + kLegendSwatchWidth - 2, middle = x + kLegendSwatchWidth / 2;
                       switch (entry.mark) {
                         case LegendMark::LineWithBand:
                           append_format(out,
                                         "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"12\" fill=\"{}\" "
                                         "fill-opacity=\"0.22\"/>\n",
                                         x1, y - 6, x2 - x1, entry.colour);
                           [[fallthrough]];
                         case LegendMark::Line:
                           draw_line(out, x1, y, x2, y, {entry.colour, 2, entry.dash});
                           break;
                         case LegendMark::PointWithBar:
                           draw_line(out, x1, y, x2, y, {entry.colour, 1.8, ""});
                           [[fallthrough]];
                         case LegendMark::Point:
                           append_format(out,
                                         "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"5\" fill=\"{}\" stroke=\"white\" "
                                         "stroke-width=\"1.2\"/>\n",
                                         middle, y, entry.colour);
                           break;
                       }
                     }});
  }
  draw_legend_column(svg, left, top, items, kPlotLegendLayout);
}

double diverging_position(const DivergingScale& scale, double value) {
  if (value < 0) return scale.low < 0 ? 0.5 - 0.5 * std::min(1.0, value / scale.low) : 0.5;
  if (value > 0) return scale.high > 0 ? 0.5 + 0.5 * std::min(1.0, value / scale.high) : 0.5;
  return 0.5;  // 0, and NaN
}

std::string diverging_colour(const DivergingScale& scale, double value) {
  return colour_at(diverging_position(scale, value));
}

void draw_cells(std::string& svg, const std::vector<Cell>& cells, const DivergingScale& scale) {
  // A light outline keeps cells of value 0, as white as the page, visible as cells.
  svg += "<g class=\"cells\" stroke=\"#d0d0d0\" stroke-width=\"0.6\">\n";
  for (const Cell& cell : cells) {
    append_format(svg, "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"/>\n", cell.x,
                  cell.y, cell.width, cell.height, diverging_colour(scale, cell.value));
  }
  svg += "</g>\n";
}

void draw_colour_bar(std::string& svg, double left, double top, double width, const DivergingScale& scale,
                     std::string_view title) {
  // Only the sides the scale has are drawn: a scale without negative values starts at 0.
  const double first = scale.low < 0 ? 0.0 : 0.5, last = scale.high > 0 ? 1.0 : 0.5;
  const auto bar_x = [&](double value) {
    return last > first ? left + width * (diverging_position(scale, value) - first) / (last - first) : left;
  };
  constexpr int kSlices = 96;
  svg += "<g class=\"colour-bar\">\n";
  for (int i = 0; i < kSlices; ++i) {
    const double position = first + (last - first) * (i + 0.5) / kSlices;
    // Slices overlap by a fraction of a pixel so that no seam shows between them.
    append_format(svg, "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{}\" fill=\"{}\"/>\n",
                  left + width * i / kSlices, top, width / kSlices + 0.4, kColourBarHeight, colour_at(position));
  }
  append_format(svg,
                "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{}\" fill=\"none\" stroke=\"{}\" "
                "stroke-width=\"0.8\"/>\n",
                left, top, width, kColourBarHeight, kPlotFrameColour);

  // 0 first, then each side's nice ticks from 0 outwards, each kept if its label has room.
  struct Candidate {
    double value;
    std::string label;
  };
  std::vector<Candidate> candidates{{0.0, "0"}};
  const auto add_side = [&](double end) {
    const Ticks ticks = nice_ticks(std::min(0.0, end), std::max(0.0, end), 4);
    std::vector<Candidate> side;
    for (const double value : ticks.values) {
      if (value == 0 || std::abs(value) > std::abs(end) * (1 + 1e-9) || (value < 0) != (end < 0)) continue;
      side.push_back({value, tick_label(value, ticks.step, std::abs(end))});
    }
    std::sort(side.begin(), side.end(),
              [](const auto& a, const auto& b) { return std::abs(a.value) < std::abs(b.value); });
    candidates.insert(candidates.end(), side.begin(), side.end());
  };
  if (scale.low < 0) add_side(scale.low);
  if (scale.high > 0) add_side(scale.high);
  std::vector<LabelSpan> kept;
  append_format(svg, "<g class=\"colour-bar-ticks\" font-size=\"{}\" fill=\"{}\" text-anchor=\"middle\">\n",
                kPlotTickFontSize, kDarkGrey);
  for (const Candidate& candidate : candidates) {
    const LabelSpan span{bar_x(candidate.value), estimated_text_width(candidate.label, kPlotTickFontSize) / 2};
    if (std::any_of(kept.begin(), kept.end(), [&](const LabelSpan& k) { return span.overlaps(k, 6); })) continue;
    kept.push_back(span);
    draw_line(svg, span.x, top + kColourBarHeight, span.x, top + kColourBarHeight + kTickLength,
              {kPlotFrameColour, 1, ""});
    draw_plain_text(svg, span.x, top + kColourBarHeight + kTickLength + 12, candidate.label);
  }
  svg += "</g>\n";
  draw_text(svg, left + width / 2, top + kColourBarHeight + 40, title, {.anchor = "middle"});
  svg += "</g>\n";
}

}  // namespace crux
