#pragma once
// The virtual human on the wall at one posture, as the paper's Fig. 1 shows it: a front
// view (from behind the climber, facing the wall) and a side view (from the climber's
// right), the body drawn from the URDF's primitive visuals, with the holds, the grasp
// spheres and the finishing height.

#include <array>
#include <string>

#include <Eigen/Geometry>

#include "body/body_model.hpp"
#include "climbing/stance_check.hpp"
#include "wall/wall.hpp"

namespace crux {

struct BodySvgOptions {
  double pixels_per_metre = 160;
  double grasp_radius = 0.04;  // the grasp spheres drawn at the four grasp points
  std::string title{};
  std::string subtitle{};
  // The static model's loads at this posture: each held limb's contact force, an arrow
  // from its grasp point (kMetresPerNewton), and each bounded joint's torque-to-limit
  // ratio, a dot at the joint coloured from green (0) through yellow to red (1 and over).
  // Null: neither is drawn.
  const StanceLoads* loads = nullptr;
  // A posture simulated in MuJoCo: the root's rotation from its orientation on the wall
  // (the body turns about its root's frame), and each limb's force from its hold, an
  // arrow as the static model's (zero: none). Null: none drawn.
  Eigen::Quaterniond root_rotation = Eigen::Quaterniond::Identity();
  const std::array<Eigen::Vector3d, kLimbCount>* hold_forces = nullptr;
};

// The contact force arrows' scale: 100 N is drawn 0.1 m long.
inline constexpr double kMetresPerNewton = 0.001;

// The colour of a torque-to-limit ratio: green at 0, yellow at 0.5, red from 1 on.
std::string torque_ratio_colour(double ratio);

// A standalone SVG 1.1 document; deterministic. Throws std::invalid_argument for a
// non-positive scale.
std::string render_body_svg(const BodyModel& model, const Posture& posture, const Wall& wall,
                            const BodySvgOptions& options = {});

}  // namespace crux
