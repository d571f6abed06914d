#include "body/urdf_loader.hpp"
#include "body/body_model.hpp"

#include <algorithm>

#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

using testing::human_model;
using testing::human_urdf_text;
using testing::replaced;
using testing::write_temporary;

TEST(BodyModel, HumanHasTranslatingRootAnd32RevoluteJoints) {
  const BodyModel& model = human_model();
  ASSERT_EQ(model.joints.size(), static_cast<std::size_t>(kConfigurationDof));
  for (int i = 0; i < kRootDof; ++i) EXPECT_TRUE(model.joints[i].prismatic) << model.joints[i].name;
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    EXPECT_FALSE(model.joints[i].prismatic) << model.joints[i].name;
    EXPECT_LT(model.joints[i].lower, model.joints[i].upper);
    EXPECT_LE(model.joints[i].lower, 0.0) << "the standing posture must be within limits";
    EXPECT_GE(model.joints[i].upper, 0.0);
  }
  EXPECT_NEAR(model.stature, 1.70, 0.005);
  EXPECT_NEAR(model.total_mass, 68.0, 1e-9);
  EXPECT_GT(model.root_height_above_soles, 0.9);
  EXPECT_LT(model.root_height_above_soles, 1.1);
}

TEST(BodyModel, ParentsComeBeforeChildren) {
  const BodyModel& model = human_model();
  for (std::size_t i = 0; i < model.joints.size(); ++i) EXPECT_LT(model.joints[i].parent, static_cast<int>(i));
}

TEST(BodyModel, ChainsEndAtTheirOperationalPoints) {
  const BodyModel& model = human_model();
  EXPECT_EQ(model.chains[0], (std::vector<int>{0, 1, 2}));
  for (int limb = 0; limb < kLimbCount; ++limb) {
    EXPECT_EQ(model.chains[operational_point(limb)].back(), model.grasp_points[limb].joint);
    EXPECT_EQ(model.chains[operational_point(limb)].front(), 0);
  }
}

// Each bad model must give one InputError that names the file and the problem.
struct BadModelCase {
  const char* name;
  std::string (*edit)(const std::string& urdf);
  const char* expected_problem;
};

std::string turn_neck_rotation_fixed(const std::string& u) {
  return replaced(u, "<joint name=\"neck_rotation\" type=\"revolute\">",
                  "<joint name=\"neck_rotation\" type=\"fixed\">");
}
std::string add_toe_joint(const std::string& u) {
  return replaced(u, "</robot>",
                  "<link name=\"toe\"/><joint name=\"toe_flexion\" type=\"revolute\"><parent link=\"right_foot\"/>"
                  "<child link=\"toe\"/><axis xyz=\"0 1 0\"/>"
                  "<limit lower=\"-0.5\" upper=\"0.5\" effort=\"1\" velocity=\"1\"/></joint></robot>");
}
std::string drop_neck_limits(const std::string& u) {
  return replaced(u, "<limit lower=\"-1.047198\" upper=\"1.047198\" effort=\"50\" velocity=\"3\"/>", "");
}
std::string make_neck_continuous(const std::string& u) {
  return replaced(u, "<joint name=\"neck_rotation\" type=\"revolute\">",
                  "<joint name=\"neck_rotation\" type=\"continuous\">");
}
std::string make_neck_prismatic(const std::string& u) {
  return replaced(u, "<joint name=\"neck_rotation\" type=\"revolute\">",
                  "<joint name=\"neck_rotation\" type=\"prismatic\">");
}
std::string rename_right_palm(const std::string& u) {
  return replaced(replaced(u, "<link name=\"right_palm\"", "<link name=\"right_paw\""), "<child link=\"right_palm\"",
                  "<child link=\"right_paw\"");
}
std::string break_xml(const std::string& u) { return u.substr(0, u.size() / 2); }
std::string not_urdf(const std::string&) { return "<html><body>hello</body></html>"; }
std::string empty(const std::string&) { return ""; }
std::string rotate_root(const std::string& u) { return replaced(u, "<axis xyz=\"0 1 0\"/>", "<axis xyz=\"0 0 1\"/>"); }
std::string inverted_limits(const std::string& u) {
  return replaced(u, "lower=\"-1.047198\" upper=\"1.047198\"", "lower=\"1.047198\" upper=\"-1.047198\"");
}

std::string cycle_back_to_torso(const std::string& u) {
  return replaced(u, "</robot>",
                  "<joint name=\"palm_to_torso\" type=\"fixed\"><parent link=\"right_palm\"/>"
                  "<child link=\"torso\"/></joint></robot>");
}
// 2000 fixed joints in a row below the right palm.
std::string very_long_chain(const std::string& u) {
  std::string chain;
  std::string parent = "right_palm";
  for (int i = 0; i < 2000; ++i) {
    const std::string link = "chain_" + std::to_string(i);
    chain += "<link name=\"" + link + "\"/><joint name=\"" + link + "_fixed\" type=\"fixed\"><parent link=\"" + parent +
             "\"/><child link=\"" + link + "\"/></joint>";
    parent = link;
  }
  return replaced(u, "</robot>", chain + "</robot>");
}
// TinyXML would read past the end of the text from this last byte, a UTF-8 lead byte
// (found by the URDF fuzzer).
std::string ends_inside_utf8_character(const std::string&) { return "<?xml version=\"1.0\"?><robot a=\"\xd5"; }
std::string nul_byte(const std::string& u) {
  return replaced(u, "</robot>", std::string("<!--") + '\0' + "--></robot>");
}
std::string negative_mass(const std::string& u) {
  return replaced(u, "<mass value=\"24.14\"/>", "<mass value=\"-24.14\"/>");
}
std::string nan_mass(const std::string& u) { return replaced(u, "<mass value=\"24.14\"/>", "<mass value=\"nan\"/>"); }
std::string negative_moment(const std::string& u) {
  return replaced(u, "<inertia ixx=\"0.569023\"", "<inertia ixx=\"-0.569023\"");
}

class BadModel : public ::testing::TestWithParam<BadModelCase> {};

TEST_P(BadModel, IsOneClearInputError) {
  const BadModelCase& c = GetParam();
  const auto path = write_temporary(std::string("bad_") + c.name + ".urdf", c.edit(human_urdf_text()));
  try {
    load_body_model(path.string());
    FAIL() << "loaded a bad model: " << c.name;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.source(), path.string());
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected_problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadModel,
    ::testing::Values(
        BadModelCase{"missing_joint", turn_neck_rotation_fixed, "exactly 32 revolute joints, found 31"},
        BadModelCase{"extra_joint", add_toe_joint, "exactly 32 revolute joints, found 33"},
        BadModelCase{"no_limits", drop_neck_limits, "limits"},
        BadModelCase{"continuous", make_neck_continuous, "type continuous"},
        BadModelCase{"stray_prismatic", make_neck_prismatic, "type prismatic"},
        BadModelCase{"missing_grasp_frame", rename_right_palm, "grasp frame 'right_palm'"},
        BadModelCase{"broken_xml", break_xml, "invalid URDF"}, BadModelCase{"not_urdf", not_urdf, "invalid URDF"},
        BadModelCase{"empty", empty, "empty"}, BadModelCase{"rotated_root", rotate_root, "must translate along y"},
        BadModelCase{"inverted_limits", inverted_limits, "neck_rotation"},
        BadModelCase{"cycle", cycle_back_to_torso, "torso"},
        BadModelCase{"very_long_chain", very_long_chain, "deeper than 1000 links"},
        BadModelCase{"negative_mass", negative_mass, "has mass -24.14"}, BadModelCase{"nan_mass", nan_mass, "mass"},
        BadModelCase{"negative_moment", negative_moment, "link 'torso' has an inertia"},
        BadModelCase{"ends_inside_utf8_character", ends_inside_utf8_character, "ends inside a UTF-8 character"},
        BadModelCase{"nul_byte", nul_byte, "a NUL byte at offset"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(BadModelFile, MissingFileAndDirectoryAreInputErrors) {
  EXPECT_THROW(load_body_model("/nonexistent/crux/body.urdf"), InputError);
  EXPECT_THROW(load_body_model(std::filesystem::temp_directory_path().string()), InputError);
}

// Any URDF viewer can draw the body: every segment (a link with mass) has visual
// geometry, made of primitives only, and the frames without mass have none.
TEST(BodyModel, EverySegmentHasPrimitiveVisualsAndNoFrameHasAny) {
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(human_urdf_text());
  ASSERT_TRUE(urdf);
  int segments = 0;
  for (const auto& [name, link] : urdf->links_) {
    const bool segment = link->inertial != nullptr && link->inertial->mass > 0;
    segments += segment ? 1 : 0;
    EXPECT_EQ(!link->visual_array.empty(), segment) << name;
    for (const auto& visual : link->visual_array) {
      ASSERT_TRUE(visual->geometry) << name;
      const auto type = visual->geometry->type;
      EXPECT_TRUE(type == urdf::Geometry::SPHERE || type == urdf::Geometry::BOX || type == urdf::Geometry::CYLINDER)
          << name;
    }
  }
  EXPECT_EQ(segments, 15);  // torso, pelvis, head, and six segments on each side
  for (const auto& entry : urdf->links_) entry.second->child_links.clear();
}

TEST(BodyModel, LoaderKeepsEachPrimitiveVisualOnTheJointThatCarriesIt) {
  const BodyModel& model = human_model();
  ASSERT_EQ(model.visuals.size(), 16u);  // 15 segments; the head has a neck cylinder and a sphere
  BodyData data(model);
  forward_kinematics(model, data, standing_posture({0.3, 0.6, 1.0}));
  const auto world_centre = [&](const BodyVisual& visual) {
    const JointPlacement& carrier = data.placements[visual.joint];
    return Eigen::Vector3d(carrier.origin + carrier.rotation * visual.translation);
  };
  for (const BodyVisual& visual : model.visuals) {
    if (visual.link == "right_hand") {
      // docs/MODEL.md: the hand box is centred on the palm frame, the right-hand grasp point.
      EXPECT_EQ(visual.shape, VisualShape::Box);
      EXPECT_LT((world_centre(visual) - data.points[operational_point(Limb::RightHand)]).norm(), 1e-12);
      EXPECT_EQ(model.joints[visual.joint].name, "right_wrist_deviation");
    }
    if (visual.link == "head" && visual.shape == VisualShape::Sphere) {
      EXPECT_DOUBLE_EQ(visual.size.x(), 0.1105);
      EXPECT_NEAR(world_centre(visual).z() + 0.1105 - (1.0 - model.root_height_above_soles), model.stature, 1e-9);
    }
    if (visual.link == "torso") {
      // crux_skin, defined once at the top of the file and named by the visual.
      EXPECT_NEAR(visual.rgba[0], 0.85, 1e-7);  // urdfdom keeps colours as floats
      EXPECT_EQ(visual.rgba[3], 1.0);
    }
  }
}

TEST(BodyModel, VisualsOfFixedFramesAreCarriedThroughTheFixedJointAndMeshesAreSkipped) {
  const std::string text =
      replaced(human_urdf_text(), "<link name=\"right_palm\"/>",
               "<link name=\"right_palm\"><visual><origin xyz=\"0 0 0.01\"/><geometry><sphere radius=\"0.02\"/>"
               "</geometry></visual><visual><geometry><mesh filename=\"hand.stl\"/></geometry></visual></link>");
  const BodyModel model = load_body_model(write_temporary("palm_visual.urdf", text).string());
  ASSERT_EQ(model.visuals.size(), 17u);
  const auto found = std::find_if(model.visuals.begin(), model.visuals.end(),
                                  [](const BodyVisual& v) { return v.link == "right_palm"; });
  ASSERT_NE(found, model.visuals.end());
  const BodyVisual& palm = *found;
  const AttachedPoint& grasp = model.grasp_points[static_cast<int>(Limb::RightHand)];
  EXPECT_EQ(palm.joint, grasp.joint);
  EXPECT_LT((palm.translation - (grasp.offset + Eigen::Vector3d(0, 0, 0.01))).norm(), 1e-12);
  EXPECT_EQ(palm.rgba, (std::array<double, 4>{0.7, 0.7, 0.7, 1.0}));
}

TEST(BodyModel, GraspFramesCanBeRenamedToMapAnotherHumanoid) {
  const auto path = write_temporary("renamed_palm.urdf", rename_right_palm(human_urdf_text()));
  GraspFrameNames names;
  names.frames[0] = "right_paw";
  const BodyModel model = load_body_model(path.string(), names);
  EXPECT_EQ(model.grasp_frame_names[0], "right_paw");
}

}  // namespace
}  // namespace crux
