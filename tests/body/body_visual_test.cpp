#include "body/body_visual.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(BodyVisual, ShapesAreNamedAsInUrdf) {
  EXPECT_STREQ(enum_name(VisualShape::Box), "box");
  EXPECT_STREQ(enum_name(VisualShape::Cylinder), "cylinder");
  EXPECT_STREQ(enum_name(VisualShape::Sphere), "sphere");
}

TEST(BodyVisual, AnUncolouredVisualIsUrdfsDefaultGrey) {
  const BodyVisual visual;
  EXPECT_EQ(visual.rgba, (std::array<double, 4>{0.7, 0.7, 0.7, 1.0}));
  EXPECT_TRUE(visual.rotation.isIdentity());
  EXPECT_EQ(visual.joint, -1);
}

}  // namespace
}  // namespace crux
