#include "views/legend.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "views/svg_document.hpp"

namespace crux {

double legend_width(const std::vector<std::string>& texts, const LegendLayout& layout) {
  double widest = 0;
  for (const std::string& text : texts) widest = std::max(widest, estimated_text_width(text, layout.font_size));
  return layout.mark_width + widest;
}

std::vector<LegendPlace> flowing_legend_places(const std::vector<LegendItem>& items, const LegendLayout& layout,
                                               double gap, double margin, double& page_width) {
  std::vector<LegendPlace> places;
  double x = margin;
  int row = 0;
  for (const LegendItem& item : items) {
    const double width = layout.mark_width + estimated_text_width(item.text, layout.font_size) + gap;
    if (x > margin && x + width > page_width - margin) {
      x = margin;
      ++row;
    }
    page_width = std::max(page_width, std::ceil(x + width + margin));
    places.push_back({x, row});
    x += width;
  }
  return places;
}

void draw_legend_at(std::string& svg, double top, const std::vector<LegendItem>& items,
                    const std::vector<LegendPlace>& places, const LegendLayout& layout) {
  if (places.size() != items.size()) {
    throw std::invalid_argument(fmt::format("draw_legend_at: {} places for {} items", places.size(), items.size()));
  }
  if (layout.font_on_group) {
    append_format(svg, "<g class=\"legend\" font-size=\"{}\" fill=\"{}\">\n", layout.font_size, kTextColour);
  } else {
    svg += "<g class=\"legend\">\n";
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    const double x = places[i].left, y = top + layout.row_height * (static_cast<double>(places[i].row) + 0.5);
    if (items[i].draw_mark) items[i].draw_mark(svg, x, y);
    if (layout.font_on_group) {
      draw_plain_text(svg, x + layout.mark_width, y + 4, items[i].text);
    } else {
      draw_text(svg, x + layout.mark_width, y + 4, items[i].text, {.size = layout.font_size});
    }
  }
  svg += "</g>\n";
}

void draw_legend_column(std::string& svg, double left, double top, const std::vector<LegendItem>& items,
                        const LegendLayout& layout) {
  std::vector<LegendPlace> places;
  for (std::size_t i = 0; i < items.size(); ++i) places.push_back({left, static_cast<int>(i)});
  draw_legend_at(svg, top, items, places, layout);
}

}  // namespace crux
