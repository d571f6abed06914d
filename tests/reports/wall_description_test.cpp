#include "reports/wall_description.hpp"

#include <gtest/gtest.h>

#include "wall/random_wall.hpp"

namespace crux {
namespace {

IkResult reached_start() {
  IkResult start;
  start.reached = true;
  start.iterations = 12;
  return start;
}

TEST(WallDescription, AGeneratedWallNamesItsFileSeedAndStart) {
  const Wall wall = generate_random_wall(4);
  const auto json = generated_wall_json("w.json", wall, 4, reached_start(), "fast");
  EXPECT_EQ(json["seed"], 4);
  EXPECT_EQ(json["holds"], wall.hold_count());
  EXPECT_EQ(json["start"]["left_foot"], wall.holds[wall.start[3]].id);
  EXPECT_EQ(json["start_iterations"], 12);
  const std::string text = generated_wall_text("w.json", wall, reached_start(), "fast");
  EXPECT_EQ(text.rfind("wrote w.json: '" + wall.name + "'", 0), 0u) << text;
  EXPECT_NE(text.find("reachable (fast solver, 12 iterations)\n"), std::string::npos) << text;
  EXPECT_NE(generated_wall_text("w.json", wall, IkResult{}, "fast").find("NOT reachable\n"), std::string::npos);
  IkResult at_once = reached_start();
  at_once.iterations = 1;
  EXPECT_NE(generated_wall_text("w.json", wall, at_once, "fast").find("reachable (fast solver, 1 iteration)\n"),
            std::string::npos);
}

// A two-hold wall: its extent, and the grid placed so that each hold falls in a known tile.
TEST(WallDescription, ASummaryGivesTheExtentAndTheGridsTiles) {
  Wall wall;
  wall.name = "two";
  wall.finish_height = 3;
  wall.holds = {{1, {0, 0.2, 0.5}, 0.04}, {2, {0, 0.8, 1.5}, 0.04}};
  wall.start = {0, 0, 0, 0};
  const std::string text = wall_summary_text("two.json", wall, reached_start(), std::nullopt);
  EXPECT_EQ(text,
            "'two' (two.json): 2 holds, y from 0.20 to 0.80 m, z from 0.50 to 1.50 m\n"
            "finish height 3 m; start configuration: right hand 1, left hand 1, right foot 1, left foot 1 "
            "(reachable)\n");
  GridParameters parameters;
  const PlacedGrid grid{Limb::RightHand, place_grid(parameters, Limb::RightHand, wall.holds[0].position), parameters};
  const auto json = wall_summary_json("two.json", wall, reached_start(), grid);
  ASSERT_EQ(json["grid"]["hold_tiles"].size(), 2u);
  const int tile = json["grid"]["hold_tiles"][0]["tile"];
  EXPECT_EQ(tile, grid.placement.tile_of(wall.holds[0].position));
  EXPECT_EQ(json["grid"]["tile_holds"].size(), static_cast<std::size_t>(parameters.tile_count()));
  EXPECT_EQ(json["grid"]["tile_holds"][tile]["id"], 1);
  EXPECT_NE(wall_summary_text("two.json", wall, reached_start(), grid).find(" " + std::to_string(tile) + ":1"),
            std::string::npos);
}

}  // namespace
}  // namespace crux
