#include "views/wall_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "views/axis_ticks.hpp"
#include "views/legend.hpp"
#include "views/palette.hpp"
#include "views/svg_document.hpp"

namespace crux {
namespace {

constexpr const char* kHoldColour = "#222222";
constexpr const char* kGreyedColour = "#bbbbbb";  // holds outside the moving grid
constexpr const char* kGridColour = "#7f93b0";
constexpr const char* kTileColour = "#6a3d9a";  // a hold's tile and each tile's hold
constexpr const char* kAnchorTileFill = "#e5f5e9";

constexpr double kTitleFontSize = 15;
constexpr double kSubtitleFontSize = 10.5;
constexpr double kLabelFontSize = 11;  // axes and legend
constexpr double kHoldFontSize = 9;    // hold ids and tile labels
constexpr double kTileNumberFontSize = 8;

// Page layout, in pixels.
constexpr double kPageMargin = 12;
constexpr double kPlotLeft = 62;     // room for the z tick labels and axis title
constexpr double kPlotPadding = 32;  // around the content, room for the hold labels
constexpr double kBelowPlot = 52;    // y tick labels and axis title
constexpr double kLegendGap = 56;    // room for the finish label, right of the plot
constexpr double kWallLegendSwatchWidth = 26;
// A column right of the plot: swatches 26 pixels wide, 6 from their text.
constexpr LegendLayout kWallLegendLayout{kLabelFontSize, kWallLegendSwatchWidth + 6, 18, true};
constexpr double kWallLegendDiscRadius = 4.5;
constexpr double kMinimumHoldRadius = 2;  // small holds stay visible
constexpr double kMaxPlotPixels = 20000;  // the larger side of the plot, at most

// Rings around a hold, in pixels outside its circle: one per limb starting on it, then
// the grid -> wall ring outside them. Its id goes above the rings, its tile below.
constexpr double kStartRingGap = 2.5;
constexpr double kStartRingStep = 3;
constexpr double kChosenRingGap = 5.5;
constexpr double kLabelGap = 3;

double start_ring_gap(std::size_t limb_rank) { return kStartRingGap + kStartRingStep * static_cast<double>(limb_rank); }

// A rectangle of the wall plane, in metres.
struct Extent {
  double y_min = std::numeric_limits<double>::infinity();
  double y_max = -std::numeric_limits<double>::infinity();
  double z_min = std::numeric_limits<double>::infinity();
  double z_max = -std::numeric_limits<double>::infinity();

  void include(double y, double z) {
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
  }
  bool empty() const { return !(y_min <= y_max); }
};

// The front view maps the wall plane to the screen as the climber, facing the wall, sees
// it. y grows to the climber's left, so it grows leftwards on screen (screen x = -y,
// mirrored from the usual plot); z grows up (screen y = -z).
struct FrontView {
  double y_max = 0, z_max = 0;  // the wall point drawn at the plot's top-left corner
  double left = 0, top = 0;     // that corner on screen
  double scale = 1;             // pixels per metre

  double screen_x(double y) const { return left + (y_max - y) * scale; }
  double screen_y(double z) const { return top + (z_max - z) * scale; }
};

class WallFigure {
 public:
  WallFigure(const Wall& wall, const WallSvgOptions& options) : wall_(wall), options_(options) {
    if (options.grid) {
      hold_tiles_.reserve(wall.holds.size());
      for (const Hold& hold : wall.holds) hold_tiles_.push_back(options.grid->tile_of(hold.position));
    }
    if (options.mark_start) {
      for (int limb = 0; limb < kLimbCount; ++limb) {
        const int index = wall.start[limb];
        if (index >= 0 && index < wall.hold_count()) start_limbs_[index].push_back(limb);
      }
    }
    lay_out();
  }

  std::string render() {
    out_.reserve(512 + 400 * wall_.holds.size());
    write_header();
    write_plot_frame();
    if (options_.grid) write_grid();
    write_finish_line();
    write_holds();
    if (options_.grid) write_tile_projection();
    if (!start_limbs_.empty()) write_start_rings();
    if (anchor_tile_ != kOutsideGrid) write_anchor();
    if (options_.number_holds) write_hold_ids();
    if (options_.grid) write_hold_tiles();
    if (!start_limbs_.empty()) write_start_codes();  // last: the most important labels
    write_axis_titles();
    draw_legend_column(out_, legend_left_, view_.top, legend_, kWallLegendLayout);
    return svg_document(page_width_, page_height_, wall_.name, out_, XlinkNamespace::Declared);
  }

 private:
  double hold_radius_pixels(const Hold& hold) const {
    return std::max(kMinimumHoldRadius, hold.radius * options_.pixels_per_metre);
  }
  std::size_t start_limb_count(int index) const {
    const auto found = start_limbs_.find(index);
    return found == start_limbs_.end() ? 0 : found->second.size();
  }
  double chosen_ring_gap(int index) const { return std::max(kChosenRingGap, start_ring_gap(start_limb_count(index))); }
  // The same for every hold, so that labels line up; from the rings a hold may carry.
  double label_gap() const { return (options_.grid ? kChosenRingGap : start_ring_gap(0)) + kLabelGap; }
  bool outside_grid(int index) const { return options_.grid && hold_tiles_[index] == kOutsideGrid; }
  double hold_x(const Hold& hold) const { return view_.screen_x(hold.position.y()); }
  double hold_y(const Hold& hold) const { return view_.screen_y(hold.position.z()); }

  void lay_out() {
    Extent extent;
    for (const Hold& hold : wall_.holds) {
      extent.include(hold.position.y() - hold.radius, hold.position.z() - hold.radius);
      extent.include(hold.position.y() + hold.radius, hold.position.z() + hold.radius);
    }
    if (options_.grid) {
      const GridPlacement& grid = *options_.grid;
      extent.include(grid.origin.x(), grid.origin.y());
      extent.include(grid.origin.x() + grid.columns * grid.tile_width, grid.origin.y() + grid.rows * grid.tile_height);
    }
    if (extent.empty()) {  // nothing to draw but the finish line: one metre of wall
      extent.include(0.0, 0.0);
      extent.include(1.0, 0.0);
    }
    extent.include(extent.y_min, wall_.finish_height);  // the finish line is always in view
    // A wall larger than kMaxPlotPixels at the asked scale is drawn smaller, so that the
    // page, and the number of its metre lines, stay bounded.
    const double span = std::max(extent.y_max - extent.y_min, extent.z_max - extent.z_min);
    const double scale = std::min(options_.pixels_per_metre, kMaxPlotPixels / span);
    const double padding = kPlotPadding / scale;
    extent_ = {extent.y_min - padding, extent.y_max + padding, extent.z_min - padding, extent.z_max + padding};
    plot_width_ = (extent_.y_max - extent_.y_min) * scale;
    plot_height_ = (extent_.z_max - extent_.z_min) * scale;

    subtitles_.push_back("front view, as the climber facing the wall sees it");
    if (options_.grid) {
      std::string grid_line = fmt::format("moving grid of {} x {} tiles", options_.grid->columns, options_.grid->rows);
      if (options_.grid_limb) grid_line += fmt::format(", placed for the {}", limb_style(*options_.grid_limb).name);
      subtitles_.push_back(std::move(grid_line));
    }
    const double plot_top = kPageMargin + 31 + 15 * static_cast<double>(subtitles_.size());
    view_ = {extent_.y_max, extent_.z_max, kPlotLeft, plot_top, scale};

    if (options_.grid && options_.grid_limb) anchor_tile_ = options_.grid->anchor_tile;
    fill_legend();

    y_axis_title_ = "y (m), to the climber's left";
    const double y_axis_title_width = 36 + estimated_text_width(y_axis_title_, kLabelFontSize);
    legend_left_ = kPlotLeft + std::max(plot_width_, y_axis_title_width) + kLegendGap;
    std::vector<std::string> legend_texts;
    for (const LegendItem& item : legend_) legend_texts.push_back(item.text);
    const double legend_width = crux::legend_width(legend_texts, kWallLegendLayout);
    double header_width = estimated_text_width(wall_.name, kTitleFontSize);
    for (const std::string& line : subtitles_) {
      header_width = std::max(header_width, estimated_text_width(line, kSubtitleFontSize));
    }
    page_width_ = std::ceil(std::max(legend_left_ + legend_width, kPageMargin + header_width) + kPageMargin);
    page_height_ = std::ceil(
        std::max(plot_top + plot_height_ + kBelowPlot,
                 plot_top + kWallLegendLayout.row_height * static_cast<double>(legend_.size()) + kPageMargin));

    tick_spacing_ = metre_tick_spacing(scale);
  }

  static const LimbStyle& limb_style(Limb limb) { return kLimbStyles[static_cast<int>(limb)]; }

  // Each legend item's swatch is centred in the swatch column.
  template <typename Draw>
  void add_legend_item(std::string text, Draw draw) {
    legend_.push_back({std::move(text), [draw](std::string& svg, double left, double y) {
                         draw(svg, left + kWallLegendSwatchWidth / 2, y);
                       }});
  }

  void fill_legend() {
    const auto disc = [](std::string& svg, double x, double y, const char* colour) {
      append_format(svg, "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{}\" fill=\"{}\"/>\n", x, y, kWallLegendDiscRadius,
                    colour);
    };
    const auto ring = [](std::string& svg, double x, double y, double ring_radius, const char* colour, double width) {
      append_format(svg,
                    "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"/>\n",
                    x, y, ring_radius, colour, width);
    };
    add_legend_item(options_.number_holds ? "hold, with its id" : "hold",
                    [disc](std::string& svg, double x, double y) { disc(svg, x, y, kHoldColour); });
    for (int limb = 0; limb < kLimbCount; ++limb) {
      if (!start_limbs_.contains(wall_.start[limb])) continue;  // not marked, or no such hold
      const LimbStyle& style = kLimbStyles[limb];
      add_legend_item(fmt::format("{}: {} start hold", style.code, style.name),
                      [disc, ring, &style](std::string& svg, double x, double y) {
                        disc(svg, x, y, kHoldColour);
                        ring(svg, x, y, kWallLegendDiscRadius + kStartRingGap, style.colour, 2);
                      });
    }
    add_legend_item(fmt::format("finish height, {:.2f} m", wall_.finish_height),
                    [](std::string& svg, double x, double y) { draw_line(svg, x - 12, y, x + 12, y, kFinishStroke); });
    if (!options_.grid) return;
    add_legend_item("grid tile, with its number", [](std::string& svg, double x, double y) {
      append_format(svg,
                    "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"22\" height=\"14\" fill=\"none\" stroke=\"{}\" "
                    "stroke-width=\"0.8\"/>\n",
                    x - 11, y - 7, kGridColour);
      append_format(svg, "<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{}\" fill=\"{}\">12</text>\n", x - 9, y + 1,
                    kTileNumberFontSize, kGridColour);
    });
    add_legend_item("tile a hold lies in", [](std::string& svg, double x, double y) {
      append_format(svg,
                    "<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{}\" fill=\"{}\" text-anchor=\"middle\">t12</text>\n",
                    x, y + 3, kHoldFontSize, kTileColour);
    });
    add_legend_item("hold its tile maps to (nearest centre)", [disc, ring](std::string& svg, double x, double y) {
      disc(svg, x, y, kHoldColour);
      ring(svg, x, y, kWallLegendDiscRadius + 3.5, kTileColour, 1);
    });
    add_legend_item("hold outside the grid",
                    [disc](std::string& svg, double x, double y) { disc(svg, x, y, kGreyedColour); });
    if (anchor_tile_ != kOutsideGrid) {
      add_legend_item(fmt::format("anchor P of the {}", limb_style(*options_.grid_limb).name),
                      [](std::string& svg, double x, double y) {
                        append_format(svg, "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"22\" height=\"14\" fill=\"{}\"/>\n",
                                      x - 11, y - 7, kAnchorTileFill);
                        append_format(svg,
                                      "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3.5\" fill=\"{}\" stroke=\"white\" "
                                      "stroke-width=\"1\"/>\n",
                                      x, y, kAnchorColour);
                      });
    }
  }

  void write_header() {
    append_format(out_, "<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{}\" font-weight=\"bold\" fill=\"{}\">{}</text>\n",
                  kPageMargin, kPageMargin + 14, kTitleFontSize, kTitleColour, xml_escaped(wall_.name));
    for (std::size_t i = 0; i < subtitles_.size(); ++i) {
      append_format(out_, "<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{}\" fill=\"{}\">{}</text>\n", kPageMargin,
                    kPageMargin + 32 + 15 * static_cast<double>(i), kSubtitleFontSize, kSubtitleColour,
                    xml_escaped(subtitles_[i]));
    }
  }

  // The plot's frame, light lines every tick_spacing_ metres and their labels.
  void write_plot_frame() {
    const double left = view_.left, top = view_.top, right = left + plot_width_, bottom = top + plot_height_;
    const std::vector<double> y_ticks = metre_ticks(extent_.y_min, extent_.y_max, tick_spacing_);
    const std::vector<double> z_ticks = metre_ticks(extent_.z_min, extent_.z_max, tick_spacing_);
    append_format(out_, "<g class=\"metre-lines\" stroke=\"{}\" stroke-width=\"1\">\n", kWallMetreLineColour);
    for (const double y : y_ticks) draw_vertical_line(out_, view_.screen_x(y), top, bottom);
    for (const double z : z_ticks) draw_horizontal_line(out_, left, right, view_.screen_y(z));
    out_ += "</g>\n";
    append_format(out_,
                  "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke=\"{}\" "
                  "stroke-width=\"1\"/>\n",
                  left, top, plot_width_, plot_height_, kViewFrameColour);

    append_format(out_, "<g class=\"tick-labels\" font-size=\"{}\" fill=\"{}\">\n", kLabelFontSize - 1,
                  kSubtitleColour);
    for (const double y : y_ticks) draw_plain_text(out_, view_.screen_x(y), bottom + 14, metre_tick_label(y), "middle");
    for (const double z : z_ticks) draw_plain_text(out_, left - 5, view_.screen_y(z) + 3.5, metre_tick_label(z), "end");
    out_ += "</g>\n";
  }

  // The tiles, with the anchor tile tinted and each tile's number in its top corner.
  void write_grid() {
    const GridPlacement& grid = *options_.grid;
    const double y0 = grid.origin.x(), z0 = grid.origin.y();
    const double y1 = y0 + grid.columns * grid.tile_width, z1 = z0 + grid.rows * grid.tile_height;
    if (anchor_tile_ != kOutsideGrid) {
      const int column = anchor_tile_ % grid.columns, row = anchor_tile_ / grid.columns;
      append_format(
          out_,
          "<rect class=\"anchor-tile\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"/>\n",
          view_.screen_x(y0 + (column + 1) * grid.tile_width), view_.screen_y(z0 + (row + 1) * grid.tile_height),
          grid.tile_width * view_.scale, grid.tile_height * view_.scale, kAnchorTileFill);
    }
    append_format(out_, "<g class=\"moving-grid\" stroke=\"{}\" stroke-width=\"0.8\">\n", kGridColour);
    for (int column = 1; column < grid.columns; ++column) {
      draw_vertical_line(out_, view_.screen_x(y0 + column * grid.tile_width), view_.screen_y(z1), view_.screen_y(z0));
    }
    for (int row = 1; row < grid.rows; ++row) {
      draw_horizontal_line(out_, view_.screen_x(y1), view_.screen_x(y0), view_.screen_y(z0 + row * grid.tile_height));
    }
    append_format(
        out_,
        "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke-width=\"1.5\"/>\n",
        view_.screen_x(y1), view_.screen_y(z1), (y1 - y0) * view_.scale, (z1 - z0) * view_.scale);
    out_ += "</g>\n";

    append_format(out_, "<g class=\"tile-numbers\" font-size=\"{}\" fill=\"{}\">\n", kTileNumberFontSize, kGridColour);
    for (int tile = 0; tile < grid.columns * grid.rows; ++tile) {
      const int column = tile % grid.columns, row = tile / grid.columns;
      // The tile's top corner on the screen's left is its corner of larger y and z.
      append_format(out_, "<text x=\"{:.2f}\" y=\"{:.2f}\">{}</text>\n",
                    view_.screen_x(y0 + (column + 1) * grid.tile_width) + 3,
                    view_.screen_y(z0 + (row + 1) * grid.tile_height) + kTileNumberFontSize + 1, tile);
    }
    out_ += "</g>\n";
  }

  void write_finish_line() {
    const double y = view_.screen_y(wall_.finish_height), right = view_.left + plot_width_;
    draw_line(out_, view_.left, y, right, y, kFinishStroke, "finish");
    // Outside the plot, where no hold label can cover it.
    append_format(out_,
                  "<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{}\" font-style=\"italic\" fill=\"{}\">finish</text>\n",
                  right + 4, y + 3.5, kLabelFontSize - 1, kFinishStroke.colour);
  }

  void write_holds() {
    out_ += "<g class=\"holds\">\n";
    for (int i = 0; i < wall_.hold_count(); ++i) {
      const Hold& hold = wall_.holds[i];
      append_format(out_, "<circle id=\"hold-{}\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"{}\"/>\n", hold.id,
                    hold_x(hold), hold_y(hold), hold_radius_pixels(hold),
                    outside_grid(i) ? kGreyedColour : kHoldColour);
    }
    out_ += "</g>\n";
  }

  // Grid -> wall: a ring around the hold each tile projects onto.
  void write_tile_projection() {
    const GridPlacement& grid = *options_.grid;
    append_format(out_, "<g class=\"tile-holds\" fill=\"none\" stroke=\"{}\" stroke-width=\"1\">\n", kTileColour);
    for (int tile = 0; tile < grid.columns * grid.rows; ++tile) {
      const int index = hold_in_tile(wall_, grid, tile);
      if (index < 0) continue;
      const Hold& hold = wall_.holds[index];
      append_format(out_, "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\"/>\n", hold_x(hold), hold_y(hold),
                    hold_radius_pixels(hold) + chosen_ring_gap(index));
    }
    out_ += "</g>\n";
  }

  // Labels go over a white halo, to stay legible where they cross lines or each other:
  // the group is defined once and drawn twice, stroked white and then plain.
  template <typename... Args>
  void begin_haloed_labels(std::string_view group_class, fmt::format_string<Args...> attributes, Args&&... args) {
    append_format(out_, "<defs>\n<g class=\"{0}\" id=\"{0}\" ", group_class);
    append_format(out_, attributes, std::forward<Args>(args)...);
    out_ += ">\n";
  }
  void end_haloed_labels(std::string_view group_class) {
    append_format(
        out_,
        "</g>\n</defs>\n<use xlink:href=\"#{0}\" stroke=\"white\" stroke-width=\"3\" stroke-linejoin=\"round\"/>\n"
        "<use xlink:href=\"#{0}\"/>\n",
        group_class);
  }

  // One coloured ring per limb on its start hold.
  void write_start_rings() {
    out_ += "<g class=\"start-rings\" fill=\"none\" stroke-width=\"2\">\n";
    for (const auto& [index, limbs] : start_limbs_) {
      const Hold& hold = wall_.holds[index];
      for (std::size_t k = 0; k < limbs.size(); ++k) {
        const LimbStyle& style = kLimbStyles[limbs[k]];
        append_format(out_, "<circle id=\"start-{}\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" stroke=\"{}\"/>\n",
                      style.code, hold_x(hold), hold_y(hold), hold_radius_pixels(hold) + start_ring_gap(k),
                      style.colour);
      }
    }
    out_ += "</g>\n";
  }

  // The limbs' codes on the left of their start hold.
  void write_start_codes() {
    begin_haloed_labels("start-marks", "font-size=\"{}\" font-weight=\"bold\" text-anchor=\"end\"", kHoldFontSize + 1);
    for (const auto& [index, limbs] : start_limbs_) {
      const Hold& hold = wall_.holds[index];
      append_format(out_, "<text x=\"{:.2f}\" y=\"{:.2f}\">",
                    hold_x(hold) - hold_radius_pixels(hold) - chosen_ring_gap(index) - kLabelGap, hold_y(hold) + 3.5);
      for (std::size_t k = 0; k < limbs.size(); ++k) {
        const LimbStyle& style = kLimbStyles[limbs[k]];
        append_format(out_, "{}<tspan fill=\"{}\">{}</tspan>", k == 0 ? "" : "/", style.colour, style.code);
      }
      out_ += "</text>\n";
    }
    end_haloed_labels("start-marks");
  }

  void write_hold_ids() {
    begin_haloed_labels("hold-ids", "font-size=\"{}\" fill=\"{}\" text-anchor=\"middle\"", kHoldFontSize, kDarkGrey);
    for (int i = 0; i < wall_.hold_count(); ++i) {
      const Hold& hold = wall_.holds[i];
      const double radius = hold_radius_pixels(hold);
      append_format(out_, "<text x=\"{:.2f}\" y=\"{:.2f}\"{}>{}</text>\n", hold_x(hold),
                    hold_y(hold) - radius - label_gap(),
                    outside_grid(i) ? fmt::format(" fill=\"{}\"", kGreyedColour) : "", hold.id);
    }
    end_haloed_labels("hold-ids");
  }

  // Wall -> grid: the number of the tile each hold lies in, below it.
  void write_hold_tiles() {
    begin_haloed_labels("hold-tiles", "font-size=\"{}\" fill=\"{}\" text-anchor=\"middle\"", kHoldFontSize,
                        kTileColour);
    for (int i = 0; i < wall_.hold_count(); ++i) {
      if (outside_grid(i)) continue;
      const Hold& hold = wall_.holds[i];
      const double radius = hold_radius_pixels(hold);
      // The baseline sits a cap height below the gap.
      append_format(out_, "<text x=\"{:.2f}\" y=\"{:.2f}\">t{}</text>\n", hold_x(hold),
                    hold_y(hold) + radius + label_gap() + 7, hold_tiles_[i]);
    }
    end_haloed_labels("hold-tiles");
  }

  // The P_i point: the anchor tile's centre, placed on the free limb.
  void write_anchor() {
    const Eigen::Vector3d centre = options_.grid->tile_centre(anchor_tile_);
    append_format(out_,
                  "<circle class=\"anchor\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3.5\" fill=\"{}\" stroke=\"white\" "
                  "stroke-width=\"1\"/>\n",
                  view_.screen_x(centre.y()), view_.screen_y(centre.z()), kAnchorColour);
  }

  // y is mirrored (see FrontView), so its title carries an arrow pointing left.
  void write_axis_titles() {
    const double bottom = view_.top + plot_height_;
    const double z_title_x = 18, z_title_y = view_.top + plot_height_ / 2;
    append_format(out_, "<g class=\"axis-titles\" font-size=\"{}\" fill=\"{}\">\n", kLabelFontSize, kTextColour);
    append_format(out_,
                  "<text x=\"{0:.2f}\" y=\"{1:.2f}\" text-anchor=\"middle\" transform=\"rotate(-90 {0:.2f} {1:.2f})\">"
                  "z (m), up</text>\n",
                  z_title_x, z_title_y);
    const double title_width = 36 + estimated_text_width(y_axis_title_, kLabelFontSize);
    const double arrow_x = view_.left + std::max(0.0, (plot_width_ - title_width) / 2), arrow_y = bottom + 36;
    draw_line(out_, arrow_x + 4, arrow_y, arrow_x + 30, arrow_y, {kTextColour, 1.2, ""});
    append_format(out_, "<polygon points=\"{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}\"/>\n", arrow_x, arrow_y,
                  arrow_x + 8, arrow_y - 4, arrow_x + 8, arrow_y + 4);
    draw_plain_text(out_, arrow_x + 36, arrow_y + 4, y_axis_title_);
    out_ += "</g>\n";
  }

  const Wall& wall_;
  const WallSvgOptions& options_;
  std::vector<int> hold_tiles_;                  // per hold, with a grid
  std::map<int, std::vector<int>> start_limbs_;  // hold index -> limbs starting on it
  int anchor_tile_ = kOutsideGrid;
  Extent extent_;  // the plot, in metres
  FrontView view_;
  double plot_width_ = 0, plot_height_ = 0, page_width_ = 0, page_height_ = 0;
  double legend_left_ = 0;
  double tick_spacing_ = 0;
  std::vector<std::string> subtitles_;
  std::string y_axis_title_;
  std::vector<LegendItem> legend_;
  std::string out_;
};

}  // namespace

std::string render_wall_svg(const Wall& wall, const WallSvgOptions& options) {
  if (!(options.pixels_per_metre > 0) || !std::isfinite(options.pixels_per_metre)) {
    throw std::invalid_argument(
        fmt::format("render_wall_svg: pixels_per_metre must be positive, not {}", options.pixels_per_metre));
  }
  return WallFigure(wall, options).render();
}

}  // namespace crux
