#pragma once
// The one legend writer of crux's figures: rows of a mark and its text, in a column (the
// plots, the wall view) or flowing across the page (the body view). Each view draws its
// own marks; the writer places them, writes the texts and groups the whole.

#include <functional>
#include <string>
#include <vector>

namespace crux {

struct LegendItem {
  std::string text;
  // Draws the item's mark, the item's left edge at x, centred on y.
  std::function<void(std::string& svg, double x, double y)> draw_mark;
};

struct LegendLayout {
  double font_size = 12;
  double mark_width = 38;  // from an item's left edge to its text
  double row_height = 20;
  // The views give the legend's group its font and colour once; the plots give them to
  // each text (as their other texts have them). Both look the same.
  bool font_on_group = false;
};

// Where an item goes: its left edge, and its row (0 at the legend's top).
struct LegendPlace {
  double left = 0;
  int row = 0;
};

// The width a column of these texts takes: the mark and the widest text.
double legend_width(const std::vector<std::string>& texts, const LegendLayout& layout);

// Items left to right from `margin`, each `gap` from the next, on a new row when one would
// end past page_width - margin; an item too wide for a row of its own widens the page
// (to whole pixels). page_width is the page's width, widened as needed.
std::vector<LegendPlace> flowing_legend_places(const std::vector<LegendItem>& items, const LegendLayout& layout,
                                               double gap, double margin, double& page_width);

// The legend, as <g class="legend">, with places[i]'s row centred at
// top + row_height * (row + 0.5).
void draw_legend_at(std::string& svg, double top, const std::vector<LegendItem>& items,
                    const std::vector<LegendPlace>& places, const LegendLayout& layout);
// The items one per row, from (left, top).
void draw_legend_column(std::string& svg, double left, double top, const std::vector<LegendItem>& items,
                        const LegendLayout& layout);

}  // namespace crux
