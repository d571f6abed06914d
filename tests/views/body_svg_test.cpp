#include "views/body_svg.hpp"

#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <cmath>

#include <numbers>

#include "body/kinematics.hpp"
#include "support/svg_check.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"

namespace crux {
namespace {

using testing::check_well_formed;
using testing::count_of;

// The text of the group of this class in the n-th panel.
std::string panel_group(const std::string& svg, int panel, const std::string& group_class) {
  std::size_t at = 0;
  for (int k = 0; k <= panel; ++k) at = svg.find("<g class=\"panel\">", at + 1);
  const std::size_t group = svg.find("<g class=\"" + group_class + "\"", at);
  return svg.substr(group, svg.find("</g>", group) - group);
}

std::vector<double> circle_centres(const std::string& group, const char* coordinate) {
  std::vector<double> values;
  const std::regex pattern(std::string(" ") + coordinate + "=\"([-0-9.]+)\"");
  for (auto it = std::sregex_iterator(group.begin(), group.end(), pattern); it != std::sregex_iterator(); ++it) {
    values.push_back(std::stod((*it)[1]));
  }
  return values;
}

const Wall& four_hold_wall() {
  static const Wall wall = testing::wall_with_holds({{0.3, 0.2}, {0.9, 0.2}, {0.35, 1.7}, {0.85, 1.7}});
  return wall;
}

TEST(BodySvg, IsAWellFormedDocumentWithBothViewsAndEveryPrimitive) {
  const BodyModel& model = testing::human_model();
  const std::string svg = render_body_svg(model, standing_posture({-0.35, 0.6, 1.0}), four_hold_wall(),
                                          {.title = "standing & waiting", .subtitle = "step 0"});
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_NE(svg.find("standing &amp; waiting"), std::string::npos);
  EXPECT_EQ(count_of(svg, "<g class=\"panel\">"), 2);
  int polygons = 0, spheres = 0;
  for (const BodyVisual& v : model.visuals) (v.shape == VisualShape::Sphere ? spheres : polygons) += 1;
  for (int panel = 0; panel < 2; ++panel) {
    const std::string body = panel_group(svg, panel, "body");
    EXPECT_EQ(count_of(body, "<polygon"), polygons) << "panel " << panel;
    EXPECT_EQ(count_of(body, "<circle"), spheres) << "panel " << panel;
    EXPECT_EQ(count_of(panel_group(svg, panel, "grasp-spheres"), "<circle"), kLimbCount);
    EXPECT_EQ(count_of(panel_group(svg, panel, "holds"), "<circle"), 4);
  }
}

// Front view from behind the climber: the left hand (+y) is drawn left of the right hand,
// the hands above the feet. Side view: the wall on the left, the body out of the wall.
// Front: from behind the climber, its left limbs on the left. Side: from the climber's
// left, the wall on the left and the climber (at x < 0) to its right.
TEST(BodySvg, ViewsAreOrientedAsSeenFromBehindAndFromTheLeft) {
  const BodyModel& model = testing::human_model();
  const std::string svg = render_body_svg(model, standing_posture({-0.35, 0.6, 1.0}), four_hold_wall());
  const std::string front = panel_group(svg, 0, "grasp-spheres");
  const std::vector<double> x = circle_centres(front, "cx"), y = circle_centres(front, "cy");
  ASSERT_EQ(x.size(), 4u);
  EXPECT_LT(x[1], x[0]) << "left hand left of the right hand";
  EXPECT_LT(x[3], x[2]) << "left foot left of the right foot";
  EXPECT_LT(y[0], y[2]) << "hands above the feet";
  const std::string side = panel_group(svg, 1, "grasp-spheres");
  const std::regex wall_line("class=\"wall\" x1=\"([-0-9.]+)\"");
  std::smatch wall;
  ASSERT_TRUE(std::regex_search(svg, wall, wall_line));
  for (const double cx : circle_centres(side, "cx")) EXPECT_GT(cx, std::stod(wall[1])) << "the body is at x < 0";
}

// Issue 26: an inclined wall is drawn as it stands. In the side view (from the climber's
// left, the climber to the right of the wall) a 30-degree overhang leans its top towards
// the climber, by tan 30 per metre of height; a vertical wall is a vertical line.
TEST(BodySvg, AnOverhangLeansTowardsTheClimberInTheSideView) {
  const BodyModel& model = testing::human_model();
  const std::regex wall_line(
      R"re(<line class="wall" x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)")re");
  Wall wall = four_hold_wall();
  std::smatch line;
  const std::string vertical = render_body_svg(model, standing_posture({-0.35, 0.6, 1.0}), wall);
  ASSERT_TRUE(std::regex_search(vertical, line, wall_line));
  EXPECT_EQ(line[1], line[3]);
  wall.incline_deg = 30.0;
  const std::string overhang = render_body_svg(model, standing_posture({-0.35, 0.6, 1.0}), wall);
  ASSERT_TRUE(std::regex_search(overhang, line, wall_line));
  const double top_x = std::stod(line[1]), top_y = std::stod(line[2]), foot_x = std::stod(line[3]),
               foot_y = std::stod(line[4]);
  EXPECT_NEAR((top_x - foot_x) / (foot_y - top_y), std::tan(30.0 * std::numbers::pi / 180.0), 1e-3);
  EXPECT_NE(overhang.find("inclined 30 degrees"), std::string::npos);
  EXPECT_NE(overhang.find("m along the wall"), std::string::npos);
}

TEST(BodySvg, SamePostureGivesIdenticalBytesAndAnotherPostureOtherBytes) {
  const BodyModel& model = testing::human_model();
  Posture bent = standing_posture({-0.35, 0.6, 1.0});
  const std::string first = render_body_svg(model, bent, four_hold_wall());
  EXPECT_EQ(first, render_body_svg(model, bent, four_hold_wall()));
  bent[kRootDof + 10] = 0.8;
  EXPECT_NE(first, render_body_svg(model, bent, four_hold_wall()));
}

// The static model's loads: one arrow per held limb from its grasp point, 0.1 m per
// 100 N (a force straight up of 200 N is 0.2 m up the page, in pixels at the view's
// scale; one straight into the wall, +x, points left in the side view), none for a free
// limb or an unbalanced stance; one dot per bounded joint in its ratio's colour.
TEST(BodySvg, LoadsAreArrowsAtTheGraspPointsAndColouredJoints) {
  const BodyModel& model = testing::human_model();
  const Posture posture = standing_posture({-0.35, 0.6, 1.0});
  StanceLoads loads;
  loads.balanced = true;
  loads.effort = 0.4;
  loads.held = {true, true, true, false};
  loads.forces = {Eigen::Vector3d(0, 0, 200), Eigen::Vector3d(300, 0, 0), Eigen::Vector3d(0, 0, 100),
                  Eigen::Vector3d(0, 0, 999)};
  loads.joint_ratios = {{5, 0.0}, {6, 0.4}, {7, 1.7}};
  BodySvgOptions options;
  options.loads = &loads;
  const std::string svg = render_body_svg(model, posture, four_hold_wall(), options);
  check_well_formed(svg);
  const std::string front = panel_group(svg, 0, "contact-forces"), side = panel_group(svg, 1, "contact-forces");
  EXPECT_EQ(count_of(front, "<line"), 3) << "the free left foot has no arrow";
  const std::regex line(
      "<line data-limb=\"([A-Z]+)\" data-newtons=\"([0-9.]+)\" x1=\"([-0-9.]+)\" y1=\"([-0-9.]+)\" "
      "x2=\"([-0-9.]+)\" y2=\"([-0-9.]+)\"");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(front, m, line));
  EXPECT_EQ(m[1], "RH");
  EXPECT_EQ(m[2], "200.0");
  EXPECT_DOUBLE_EQ(std::stod(m[3]), std::stod(m[5])) << "straight up";
  EXPECT_NEAR(std::stod(m[4]) - std::stod(m[6]), 0.2 * 160, 0.02) << "0.2 m at 160 pixels a metre";
  const std::string left_hand = side.substr(side.find("<line data-limb=\"LH\""));
  ASSERT_TRUE(std::regex_search(left_hand, m, line));
  EXPECT_NEAR(std::stod(m[3]) - std::stod(m[5]), 0.3 * 160, 0.02) << "into the wall: to the left, towards it";
  const std::string joints = panel_group(svg, 0, "joint-torques");
  EXPECT_EQ(count_of(joints, "<circle"), 3);
  EXPECT_NE(joints.find("data-ratio=\"1.700\""), std::string::npos);
  EXPECT_NE(joints.find("fill=\"" + torque_ratio_colour(1.7) + "\""), std::string::npos);
  EXPECT_NE(svg.find("contact force, 0.1 m per 100 N"), std::string::npos);

  loads.balanced = false;
  loads.joint_ratios.clear();
  const std::string unbalanced = render_body_svg(model, posture, four_hold_wall(), options);
  EXPECT_EQ(count_of(panel_group(unbalanced, 0, "contact-forces"), "<line"), 0);
  const std::string plain = render_body_svg(model, posture, four_hold_wall());
  EXPECT_EQ(plain.find("contact-forces"), std::string::npos) << "no loads, nothing drawn";
  EXPECT_EQ(plain.find("contact force"), std::string::npos);
}

// A posture simulated in MuJoCo: the body turned about its root (a half turn about z puts
// the right hand where the standing body's right hand mirrors through the root, so the
// front view's right hand moves to the other side), and the forces from the holds as
// arrows, none for a zero force; an unturned body keeps its bytes.
TEST(BodySvg, ASimulatedPostureTurnsAboutItsRootAndDrawsItsHoldForces) {
  const BodyModel& model = testing::human_model();
  const Posture posture = standing_posture({-0.35, 0.6, 1.0});
  const std::string plain = render_body_svg(model, posture, four_hold_wall());
  BodySvgOptions options;
  EXPECT_EQ(render_body_svg(model, posture, four_hold_wall(), options), plain);
  const std::array<Eigen::Vector3d, kLimbCount> forces{Eigen::Vector3d(0, 0, 200), Eigen::Vector3d::Zero(),
                                                       Eigen::Vector3d(0, 0, 100), Eigen::Vector3d(0, 0, 100)};
  options.hold_forces = &forces;
  const std::string with_forces = render_body_svg(model, posture, four_hold_wall(), options);
  EXPECT_EQ(count_of(panel_group(with_forces, 0, "hold-forces"), "<line"), 3) << "no arrow for a zero force";
  EXPECT_NE(with_forces.find("force from the hold in MuJoCo, 0.1 m per 100 N"), std::string::npos);
  // The right hand's x in the front view, from the first hold's (the panel's extent may change).
  const auto right_hand_x = [](const std::string& svg) {
    const std::string front = panel_group(svg, 0, "grasp-spheres");
    std::smatch m;
    EXPECT_TRUE(std::regex_search(front, m, std::regex("<circle data-limb=\"RH\" cx=\"([-0-9.]+)\"")));
    return std::stod(m[1]) - circle_centres(panel_group(svg, 0, "holds"), "cx").front();
  };
  options.hold_forces = nullptr;
  options.root_rotation = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitZ()));
  const std::string turned = render_body_svg(model, posture, four_hold_wall(), options);
  check_well_formed(turned);
  BodyData data(model);
  forward_kinematics(model, data, posture);
  const double right_hand_y = data.points[operational_point(Limb::RightHand)].y();
  // The front view draws -y left to right: the hand at y moves to 2 * 0.6 - y.
  EXPECT_NEAR(right_hand_x(turned) - right_hand_x(plain), 160 * (right_hand_y - (2 * 0.6 - right_hand_y)), 0.02);
}

// Green at 0, yellow at 0.5, red from 1 on (ColorBrewer's RdYlGn ends and middle).
TEST(BodySvg, TorqueRatioColoursRunFromGreenThroughYellowToRed) {
  EXPECT_EQ(torque_ratio_colour(0.0), "#1a9850");
  EXPECT_EQ(torque_ratio_colour(0.5), "#fee08b");
  EXPECT_EQ(torque_ratio_colour(1.0), "#d73027");
  EXPECT_EQ(torque_ratio_colour(3.0), "#d73027");
  EXPECT_EQ(torque_ratio_colour(0.25), "#8cbc6e");  // halfway: (26+254)/2, (152+224)/2, (80+139)/2 rounded
}

TEST(BodySvg, RejectsANonPositiveScale) {
  EXPECT_THROW(render_body_svg(testing::human_model(), standing_posture({-0.35, 0.6, 1.0}), four_hold_wall(),
                               {.pixels_per_metre = 0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace crux
