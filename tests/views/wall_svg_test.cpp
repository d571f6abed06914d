#include "views/wall_svg.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/svg_check.hpp"
#include "support/test_walls.hpp"

#include "wall/random_wall.hpp"

namespace crux {
namespace {

using testing::attribute;
using testing::check_well_formed;
using testing::count_of;
using testing::element_with;
using testing::group_texts;
using testing::number_attribute;

// A wall of columns x rows holds on a lattice, ids 1.. row by row from the smallest y
// and z; hands start on the third row, feet on the first.
Wall lattice_wall(int columns, int rows, double spacing_y, double spacing_z) {
  Wall wall;
  wall.name = fmt::format("lattice {} x {}", columns, rows);
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      Hold hold;
      hold.id = row * columns + column + 1;
      hold.position = {0.0, column * spacing_y, row * spacing_z};
      wall.holds.push_back(hold);
    }
  }
  wall.start = {2 * columns, 2 * columns + 1, 0, 1};
  return wall;
}

std::set<std::string> hold_ids_of(const Wall& wall) {
  std::set<std::string> ids;
  for (const Hold& hold : wall.holds) ids.insert(std::to_string(hold.id));
  return ids;
}

std::set<std::string> as_set(const std::vector<std::string>& texts) { return {texts.begin(), texts.end()}; }

TEST(WallSvgTest, IsAWellFormedStandaloneDocument) {
  const std::string svg = render_wall_svg(lattice_wall(3, 4, 0.3, 0.5));
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_TRUE(svg.starts_with("<?xml version=\"1.0\""));
  const std::string root = element_with(svg, "<svg");
  EXPECT_EQ(attribute(root, "xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_EQ(attribute(root, "version"), "1.1");
  EXPECT_NE(svg.find("fill=\"white\""), std::string::npos);
  EXPECT_NE(svg.find(">lattice 3 x 4</text>"), std::string::npos);
  EXPECT_NE(svg.find("class=\"finish\""), std::string::npos);
  EXPECT_NE(svg.find(">finish</text>"), std::string::npos);
  EXPECT_NE(svg.find("y (m), to the climber&apos;s left"), std::string::npos);
}

TEST(WallSvgTest, TheCheckerCatchesMalformedDocuments) {
  EXPECT_EQ(check_well_formed("<svg xmlns=\"x\"><g></g></svg>"), "");
  EXPECT_NE(check_well_formed("<svg xmlns=\"x\"><g></svg>"), "");
  EXPECT_NE(check_well_formed("<svg xmlns=\"x\"><text>a < b</text></svg>"), "");
  EXPECT_NE(check_well_formed("<svg xmlns=\"x\"><text>a & b</text></svg>"), "");
  EXPECT_NE(check_well_formed("<svg xmlns=\"x\"><rect width=3/></svg>"), "");
  EXPECT_NE(check_well_formed("<svg xmlns=\"x\"></svg><svg xmlns=\"x\"></svg>"), "");
}

TEST(WallSvgTest, LabelsEveryHoldWithItsId) {
  const Wall wall = lattice_wall(3, 4, 0.3, 0.5);
  const std::string svg = render_wall_svg(wall);
  const std::vector<std::string> ids = group_texts(svg, "hold-ids");
  EXPECT_EQ(ids.size(), wall.holds.size());
  EXPECT_EQ(as_set(ids), hold_ids_of(wall));
  for (const Hold& hold : wall.holds) EXPECT_NE(svg.find(fmt::format("id=\"hold-{}\"", hold.id)), std::string::npos);
}

TEST(WallSvgTest, EscapesTheWallName) {
  Wall wall = lattice_wall(3, 4, 0.3, 0.5);
  wall.name = "a <b> & \"c\" 'd'";
  const std::string svg = render_wall_svg(wall);
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_EQ(svg.find(wall.name), std::string::npos);
  EXPECT_EQ(count_of(svg, "a &lt;b&gt; &amp; &quot;c&quot; &apos;d&apos;"), 2);  // <title> and the heading
}

TEST(WallSvgTest, MarksEachStartHoldWithItsLimb) {
  const Wall wall = lattice_wall(3, 4, 0.3, 0.5);
  const std::string svg = render_wall_svg(wall);
  const char* codes[kLimbCount] = {"RH", "LH", "RF", "LF"};
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const std::string hold = fmt::format("id=\"hold-{}\"", wall.holds[wall.start[limb]].id);
    const std::string mark = fmt::format("id=\"start-{}\"", codes[limb]);
    EXPECT_EQ(number_attribute(svg, mark, "cx"), number_attribute(svg, hold, "cx")) << codes[limb];
    EXPECT_EQ(number_attribute(svg, mark, "cy"), number_attribute(svg, hold, "cy")) << codes[limb];
    EXPECT_NE(svg.find(fmt::format("{}: ", codes[limb])), std::string::npos) << "legend entry for " << codes[limb];
  }
  EXPECT_EQ(as_set(group_texts(svg, "start-marks")), (std::set<std::string>{"RH", "LH", "RF", "LF"}));
  // Each limb has its own colour.
  std::set<std::string> colours;
  for (const char* code : codes)
    colours.insert(attribute(element_with(svg, fmt::format("id=\"start-{}\"", code)), "stroke"));
  EXPECT_EQ(colours.size(), 4u);
}

TEST(WallSvgTest, NamesEveryLimbOnASharedStartHold) {
  Wall wall = lattice_wall(3, 4, 0.3, 0.5);
  wall.start[3] = wall.start[2];  // both feet on one hold
  const std::string svg = render_wall_svg(wall);
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_EQ(as_set(group_texts(svg, "start-marks")), (std::set<std::string>{"RH", "LH", "RF/LF"}));
  EXPECT_NE(number_attribute(svg, "id=\"start-RF\"", "r"), number_attribute(svg, "id=\"start-LF\"", "r"));
}

TEST(WallSvgTest, OptionsLeaveOutIdsAndStartMarks) {
  WallSvgOptions options;
  options.number_holds = false;
  options.mark_start = false;
  const std::string svg = render_wall_svg(lattice_wall(3, 4, 0.3, 0.5), options);
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_EQ(svg.find("class=\"hold-ids\""), std::string::npos);
  EXPECT_EQ(svg.find("class=\"start-marks\""), std::string::npos);
  EXPECT_EQ(svg.find("start hold"), std::string::npos);
}

TEST(WallSvgTest, DrawsLargerYFurtherLeftAndLargerZHigher) {
  const Wall wall = lattice_wall(2, 2, 0.8, 1.0);  // hold 2 is at larger y than hold 1, hold 3 above hold 1
  const std::string svg = render_wall_svg(wall);
  EXPECT_LT(number_attribute(svg, "id=\"hold-2\"", "cx"), number_attribute(svg, "id=\"hold-1\"", "cx"));
  EXPECT_LT(number_attribute(svg, "id=\"hold-3\"", "cy"), number_attribute(svg, "id=\"hold-1\"", "cy"));
  EXPECT_NEAR(number_attribute(svg, "id=\"hold-1\"", "cx") - number_attribute(svg, "id=\"hold-2\"", "cx"), 0.8 * 150,
              0.02);
}

TEST(WallSvgTest, DrawsHoldsAtTrueRadiusButNeverUnderTwoPixels) {
  Wall wall = lattice_wall(2, 2, 0.8, 1.0);
  wall.holds[0].radius = 0.05;
  wall.holds[1].radius = 0.001;
  const std::string svg = render_wall_svg(wall);
  EXPECT_EQ(attribute(element_with(svg, "id=\"hold-1\""), "r"), "7.50");
  EXPECT_EQ(attribute(element_with(svg, "id=\"hold-2\""), "r"), "2.00");
}

// A 6 x 10 lattice under a grid whose tile centres are the lattice's first 5 x 7 points:
// the hold at lattice (column, row) lies in tile row * 5 + column, the others outside.
TEST(WallSvgTest, DrawsTheMovingGridAndBothProjections) {
  const Wall wall = lattice_wall(6, 10, 0.3, 0.5);
  GridPlacement grid;
  grid.origin = {-0.15, -0.25};
  grid.anchor_tile = 4 * 5 + 1;  // the right hand's anchor, column 1 of row 4
  WallSvgOptions options;
  options.grid = grid;
  options.grid_limb = Limb::RightHand;
  const std::string svg = render_wall_svg(wall, options);
  EXPECT_EQ(check_well_formed(svg), "");

  std::vector<std::string> tile_numbers = group_texts(svg, "tile-numbers");
  std::set<std::string> all_tiles;
  for (int tile = 0; tile < 35; ++tile) all_tiles.insert(std::to_string(tile));
  EXPECT_EQ(tile_numbers.size(), 35u);
  EXPECT_EQ(as_set(tile_numbers), all_tiles);

  std::multiset<std::string> expected_hold_tiles;
  for (int row = 0; row < 7; ++row) {
    for (int column = 0; column < 5; ++column) expected_hold_tiles.insert(fmt::format("t{}", row * 5 + column));
  }
  const std::vector<std::string> hold_tiles = group_texts(svg, "hold-tiles");
  EXPECT_EQ(std::multiset<std::string>(hold_tiles.begin(), hold_tiles.end()), expected_hold_tiles);

  // Inside (lattice (1, 4), id 26) and outside (lattice (5, 0), id 6; (0, 8), id 49).
  const std::string inside_fill = attribute(element_with(svg, "id=\"hold-26\""), "fill");
  EXPECT_NE(attribute(element_with(svg, "id=\"hold-6\""), "fill"), inside_fill);
  EXPECT_NE(attribute(element_with(svg, "id=\"hold-49\""), "fill"), inside_fill);

  // Every tile holds exactly one hold, so each has its ring: grid -> wall.
  const std::size_t rings = svg.find("<g class=\"tile-holds\"");
  ASSERT_NE(rings, std::string::npos);
  EXPECT_EQ(count_of(svg.substr(rings, svg.find("</g>", rings) - rings), "<circle"), 35);

  // The right hand's anchor is tile (1, 4), whose centre is hold 26.
  EXPECT_EQ(number_attribute(svg, "class=\"anchor\"", "cx"), number_attribute(svg, "id=\"hold-26\"", "cx"));
  EXPECT_EQ(number_attribute(svg, "class=\"anchor\"", "cy"), number_attribute(svg, "id=\"hold-26\"", "cy"));
  EXPECT_NE(svg.find("class=\"anchor-tile\""), std::string::npos);
}

TEST(WallSvgTest, DrawsAGridPlacedOnALimbOfARandomWall) {
  const Wall wall = generate_random_wall(1);
  WallSvgOptions options;
  options.grid = place_grid(GridParameters{}, Limb::LeftFoot, wall.holds[wall.start[3]].position);
  options.grid_limb = Limb::LeftFoot;
  const std::string svg = render_wall_svg(wall, options);
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_EQ(number_attribute(svg, "class=\"anchor\"", "cx"),
            number_attribute(svg, fmt::format("id=\"hold-{}\"", wall.holds[wall.start[3]].id), "cx"));
  int inside = 0;
  for (const Hold& hold : wall.holds) inside += options.grid->tile_of(hold.position) != kOutsideGrid;
  EXPECT_EQ(group_texts(svg, "hold-tiles").size(), static_cast<std::size_t>(inside));
}

TEST(WallSvgTest, SameInputGivesIdenticalBytes) {
  const Wall wall = generate_random_wall(7);
  WallSvgOptions options;
  options.grid = place_grid(GridParameters{}, Limb::RightHand, wall.holds[wall.start[0]].position);
  options.grid_limb = Limb::RightHand;
  const Wall copy = wall;
  const WallSvgOptions options_copy = options;
  EXPECT_EQ(render_wall_svg(wall, options), render_wall_svg(copy, options_copy));
  EXPECT_EQ(render_wall_svg(wall), render_wall_svg(wall));
}

TEST(WallSvgTest, RendersSmallAndLargeWalls) {
  for (const Wall& wall : {lattice_wall(3, 4, 0.3, 0.5), lattice_wall(5, 80, 0.3, 0.25)}) {
    SCOPED_TRACE(wall.name);
    const std::string svg = render_wall_svg(wall);
    EXPECT_EQ(check_well_formed(svg), "");
    EXPECT_EQ(as_set(group_texts(svg, "hold-ids")), hold_ids_of(wall));
  }
  const std::string tall = render_wall_svg(lattice_wall(5, 80, 0.3, 0.25));
  EXPECT_GT(number_attribute(tall, "<svg", "height"), 19.75 * 150);
}

TEST(WallSvgTest, RejectsANonPositiveScale) {
  WallSvgOptions options;
  options.pixels_per_metre = 0;
  EXPECT_THROW(render_wall_svg(lattice_wall(3, 4, 0.3, 0.5), options), std::invalid_argument);
}

// One hold ten thousand kilometres up: the drawing shrinks instead of drawing a metre
// line per half metre of that height.
TEST(WallSvg, AFarHoldGivesABoundedDrawing) {
  for (const double far : {1e7, 1e16}) {
    Wall wall = testing::wall_with_holds({{0.3, 1.5}, {0.9, 1.5}, {0.3, 0.0}, {0.9, far}});
    const std::string svg = render_wall_svg(wall, {});
    EXPECT_LT(svg.size(), 200000u) << far;
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
  }
}

}  // namespace
}  // namespace crux
