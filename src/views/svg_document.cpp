#include "views/svg_document.hpp"

#include <algorithm>
#include <cmath>

namespace crux {

double estimated_text_width(std::string_view text, double font_size) {
  const auto code_points = std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // not a UTF-8 continuation byte
  });
  return 0.6 * font_size * static_cast<double>(code_points);
}

std::string svg_document(double width, double height, std::string_view title, std::string_view body,
                         XlinkNamespace xlink) {
  std::string svg;
  svg.reserve(body.size() + 512);
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
  append_format(svg,
                "<svg xmlns=\"http://www.w3.org/2000/svg\"{} version=\"1.1\" width=\"{:.0f}\" height=\"{:.0f}\" "
                "viewBox=\"0 0 {:.0f} {:.0f}\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n",
                xlink == XlinkNamespace::Declared ? " xmlns:xlink=\"http://www.w3.org/1999/xlink\"" : "",
                std::ceil(width), std::ceil(height), std::ceil(width), std::ceil(height));
  append_format(svg, "<title>{}</title>\n", xml_escaped(title));
  append_format(svg, "<rect width=\"{:.0f}\" height=\"{:.0f}\" fill=\"white\"/>\n", std::ceil(width),
                std::ceil(height));
  svg += body;
  svg += "</svg>\n";
  return svg;
}

void draw_vertical_line(std::string& svg, double x, double y1, double y2) {
  append_format(svg, "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\"/>\n", x, y1, y2);
}

void draw_horizontal_line(std::string& svg, double x1, double x2, double y) {
  append_format(svg, "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\"/>\n", x1, y, x2);
}

void draw_line(std::string& svg, double x1, double y1, double x2, double y2, const Stroke& stroke,
               std::string_view css_class) {
  svg += "<line";
  if (!css_class.empty()) append_format(svg, " class=\"{}\"", css_class);
  append_format(svg, " x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"{}\" stroke-width=\"{}\"", x1,
                y1, x2, y2, stroke.colour, stroke.width);
  if (!stroke.dash.empty()) append_format(svg, " stroke-dasharray=\"{}\"", stroke.dash);
  svg += "/>\n";
}

void draw_text(std::string& svg, double x, double y, std::string_view text, const TextStyle& style) {
  append_format(svg, "<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{}\" fill=\"{}\"", x, y, style.size, style.colour);
  if (style.anchor != "start") append_format(svg, " text-anchor=\"{}\"", style.anchor);
  if (style.bold) svg += " font-weight=\"bold\"";
  if (style.italic) svg += " font-style=\"italic\"";
  if (style.rotation != 0) append_format(svg, " transform=\"rotate({:.1f} {:.2f} {:.2f})\"", style.rotation, x, y);
  append_format(svg, ">{}</text>\n", xml_escaped(text));
}

void draw_plain_text(std::string& svg, double x, double y, std::string_view text, std::string_view anchor) {
  append_format(svg, "<text x=\"{:.2f}\" y=\"{:.2f}\"", x, y);
  if (anchor != "start") append_format(svg, " text-anchor=\"{}\"", anchor);
  append_format(svg, ">{}</text>\n", xml_escaped(text));
}

}  // namespace crux
