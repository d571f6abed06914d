#pragma once
// The one writer of crux's SVG documents and of the elements every view shares: the
// standalone page (XML declaration, <svg> root with its size and viewBox, title, white
// background), text made safe for XML, text and axis-parallel lines, and a width
// estimate for laying out text (SVG cannot measure it). The HTML reports use its
// escaping too. Numbers are written with a fixed format, so the same input gives the
// same bytes.

#include <iterator>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "common/xml_escaped.hpp"
#include "views/palette.hpp"

namespace crux {

// Appends the formatted text to `out`: how the SVG and HTML writers build their documents.
template <typename... Args>
void append_format(std::string& out, fmt::format_string<Args...> format, Args&&... args) {
  fmt::format_to(std::back_inserter(out), format, std::forward<Args>(args)...);
}

// Width of `text` in a sans-serif font of `font_size` pixels, from a generous average.
double estimated_text_width(std::string_view text, double font_size);

// Whether the root declares the xlink namespace, which <use xlink:href> needs.
enum class XlinkNamespace { Absent, Declared };

// The standalone document: XML declaration, <svg> root with xmlns, version, width,
// height and viewBox (sizes rounded up to whole pixels), <title>, a white page, the body.
std::string svg_document(double width, double height, std::string_view title, std::string_view body,
                         XlinkNamespace xlink = XlinkNamespace::Absent);

// Lines that take their stroke from the group around them: grids, ticks, metre lines.
void draw_vertical_line(std::string& svg, double x, double y1, double y2);
void draw_horizontal_line(std::string& svg, double x1, double x2, double y);

// A line of its own stroke: width and dash written as given ("1.2", "6 4"), a class
// ("finish") when css_class is not empty.
void draw_line(std::string& svg, double x1, double y1, double x2, double y2, const Stroke& stroke,
               std::string_view css_class = "");

inline constexpr double kDefaultFontSize = 12;

struct TextStyle {
  double size = kDefaultFontSize;
  std::string anchor = "start";  // start, middle or end
  std::string colour = kTextColour;
  bool bold = false;
  bool italic = false;
  double rotation = 0;  // degrees, about (x, y)
};
// A <text> with its own font size and colour.
void draw_text(std::string& svg, double x, double y, std::string_view text, const TextStyle& style = {});
// A <text> that takes its font and colour from the group around it: tick and legend labels.
void draw_plain_text(std::string& svg, double x, double y, std::string_view text, std::string_view anchor = "start");

}  // namespace crux
