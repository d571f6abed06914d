#pragma once
// The virtual human on the wall at one posture, as the paper's Fig. 1 shows it: a front
// view (from behind the climber, facing the wall) and a side view (from the climber's
// right), the body drawn from the URDF's primitive visuals, with the holds, the grasp
// spheres and the finishing height.

#include <string>

#include "body/body_model.hpp"
#include "wall/wall.hpp"

namespace crux {

struct BodySvgOptions {
  double pixels_per_metre = 160;
  double grasp_radius = 0.04;  // the grasp spheres drawn at the four grasp points
  std::string title;
  std::string subtitle;
};

// A standalone SVG 1.1 document; deterministic. Throws std::invalid_argument for a
// non-positive scale.
std::string render_body_svg(const BodyModel& model, const Posture& posture, const Wall& wall,
                            const BodySvgOptions& options = {});

}  // namespace crux
