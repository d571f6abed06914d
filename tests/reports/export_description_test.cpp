#include "reports/export_description.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

TEST(ExportDescription, NamesTheFileTheBodyAndTheWall) {
  Wall wall = generate_random_wall(1);
  wall.incline_deg = 20.0;
  const MjcfExport written = describe_mjcf_export("climber.xml", testing::human_model(), wall);
  EXPECT_EQ(mjcf_export_text(written), "wrote climber.xml: crux_human (68.0 kg, 32 motors, free root) on " + wall.name +
                                           " (" + std::to_string(wall.hold_count()) + " holds, 20 degrees)\n");
  const nlohmann::ordered_json json = mjcf_export_json(written);
  EXPECT_EQ(json["file"], "climber.xml");
  EXPECT_EQ(json["format"], "mjcf");
  EXPECT_EQ(json["motors"], 32);
  EXPECT_EQ(json["root"], "free");
  EXPECT_EQ(json["holds"], wall.hold_count());
  EXPECT_EQ(json["incline_deg"], 20.0);
  EXPECT_NEAR(json["mass_kg"].get<double>(), 68.0, 1e-9);
}

}  // namespace
}  // namespace crux
