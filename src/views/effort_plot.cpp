#include "views/effort_plot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "views/palette.hpp"
#include "views/plot_svg.hpp"
#include "views/svg_document.hpp"

namespace crux {

namespace {

constexpr double kEffortMargin = 16, kEffortPanelWidth = 520, kEffortPanelHeight = 240, kEffortHeader = 36;

// Unbalanced stances are drawn as gaps in the line and marked on the top edge.
std::vector<double> finite_or_gap(const std::vector<double>& values) {
  std::vector<double> out(values);
  for (double& v : out) {
    if (!std::isfinite(v)) v = std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

}  // namespace

std::string render_effort_plot(const EffortAlongClimb& efforts) {
  const std::size_t n = efforts.on_four_holds.size();
  if (n == 0 || efforts.on_three_holds.size() != n) {
    throw std::invalid_argument("render_effort_plot: one effort on four and on three holds per stance");
  }
  double highest = 1.2;
  for (const std::vector<double>* series : {&efforts.on_four_holds, &efforts.on_three_holds}) {
    for (const double v : *series) {
      if (std::isfinite(v)) highest = std::max(highest, v * 1.05);
    }
  }
  std::vector<double> stance(n);
  for (std::size_t k = 0; k < n; ++k) stance[k] = static_cast<double>(k);
  Panel panel;
  panel.x = linear_axis(0.0, std::max(1.0, static_cast<double>(n - 1)), "stance of the climb (0: the start)");
  panel.y = linear_axis(0.0, highest, "effort (largest torque over its limit)");
  panel.left = kEffortMargin + y_axis_room(panel.y);
  panel.top = kEffortMargin + kEffortHeader;
  panel.width = kEffortPanelWidth;
  panel.height = kEffortPanelHeight;
  std::string body;
  draw_text(body, kEffortMargin, kEffortMargin + 14, efforts.title, {15, "start", kTitleColour});
  draw_axes(body, panel);
  draw_reference_line(body, panel, Direction::Horizontal, 1.0, {kDarkGrey, 1.2, "6 4"});
  const Stroke four{kOkabeItoBlue, 2, ""}, three{kOkabeItoOrange, 2, "5 3"};
  draw_polyline(body, panel, stance, finite_or_gap(efforts.on_four_holds), four);
  draw_polyline(body, panel, stance, finite_or_gap(efforts.on_three_holds), three);
  for (std::size_t k = 0; k < n; ++k) {
    for (const auto& [value, colour] :
         {std::pair{efforts.on_four_holds[k], kOkabeItoBlue}, std::pair{efforts.on_three_holds[k], kOkabeItoOrange}}) {
      if (std::isfinite(value)) {
        append_format(body, "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3\" fill=\"{}\"/>\n", panel.x_pixel(stance[k]),
                      panel.y_pixel(value), colour);
      } else {  // no balance: a cross on the top edge
        const double x = panel.x_pixel(stance[k]), y = panel.top;
        draw_line(body, x - 4, y - 4, x + 4, y + 4, {colour, 1.5, ""}, "unbalanced");
        draw_line(body, x - 4, y + 4, x + 4, y - 4, {colour, 1.5, ""}, "unbalanced");
      }
    }
  }
  const double legend_top = panel.top + panel.height + kXAxisRoom + 8;
  const std::vector<LegendEntry> legend{
      {LegendMark::Line, kOkabeItoBlue, "", "on its four holds"},
      {LegendMark::Line, kOkabeItoOrange, "5 3", "on the three left when the next limb lets go"},
      {LegendMark::Line, kDarkGrey, "6 4",
       "the limit: above 1 the stance cannot be held (x on the top edge: no balance)"}};
  draw_legend(body, panel.left, legend_top, legend);
  const double width = std::max({panel.left + panel.width, panel.left + legend_width(legend),
                                 kEffortMargin + estimated_text_width(efforts.title, 15)}) +
                       kEffortMargin;
  const double height = legend_top + legend_height(legend) + kEffortMargin;
  return svg_document(width, height, efforts.title, body);
}

}  // namespace crux
