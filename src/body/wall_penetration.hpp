#pragma once
// How far a posture's body passes through the wall (docs/MODEL.md, choice C23). The
// wall is the plane x = 0 and the climber stands at x < 0, so a point of the body with
// x > 0 is inside the wall. Each visual primitive of the URDF (box, cylinder, sphere) is
// measured by its exact support point along +x, its deepest point. The hands and feet
// are left out: a limb that grasps a hold touches the wall there.

#include "body/body_data.hpp"
#include "body/body_model.hpp"

namespace crux {

// A point more than this behind the plane counts as passing through the wall: the
// skin and clothing give way by about this much against a wall.
inline constexpr double kWallSkinMargin = 0.01;

struct WallPenetration {
  double depth_m = 0.0;  // x of the deepest point of the counted primitives (> 0: inside the wall)
  int visual = -1;       // that primitive, an index into BodyModel::visuals; -1 when none is counted

  bool passes_through() const { return visual >= 0 && depth_m > kWallSkinMargin; }
};

// The deepest point along +x of `visual` carried by `carrier`.
Eigen::Vector3d deepest_point(const BodyVisual& visual, const JointPlacement& carrier);

// Whether body/wall_penetration counts primitive `visual`: not a hand's or a foot's
// (carried by a grasp point's joint).
bool counts_for_the_wall(const BodyModel& model, const BodyVisual& visual);

// Over every counted primitive, at the posture of the last forward_kinematics of `data`.
WallPenetration wall_penetration(const BodyModel& model, const BodyData& data);

// d x / d G of the deepest point of model.visuals[visual] at the posture of the last
// forward_kinematics, moving with its carrier (the deepest point of a box or cylinder
// jumps between corners or rim points, but its x is the support function, whose
// gradient is that of the point held fixed).
void deepest_x_gradient(const BodyModel& model, const BodyData& data, int visual, Posture& gradient);

}  // namespace crux
