#include "reports/view_description.hpp"

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "common/counted.hpp"

namespace crux {

ViewCaption run_view_caption(const RunFolder& folder, const RecordedClimb& climb, int step, const std::string& svg) {
  return {svg, fmt::format("{} on '{}'", folder.name, folder.wall.name),
          fmt::format("step {} of {} ({}, the start is step 0)", step, climb_description(climb),
                      counted(climb.postures.size(), "posture"))};
}

ViewCaption wall_view_caption(const Wall& wall, const std::string& svg) {
  return {svg, fmt::format("'{}'", wall.name), "the start posture, solved by IK from standing"};
}

nlohmann::ordered_json view_json(const BodyModel& model, const Posture& posture, const ViewCaption& caption) {
  BodyData data(model);
  forward_kinematics(model, data, posture);
  const Eigen::Vector3d& com = centre_of_mass(model, data);
  nlohmann::ordered_json out;
  out["svg"] = caption.svg;
  out["title"] = caption.title;
  out["subtitle"] = caption.subtitle;
  out["root"] = {posture[0], posture[1], posture[2]};
  out["centre_of_mass"] = {com.x(), com.y(), com.z()};
  nlohmann::ordered_json grasp;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const Eigen::Vector3d& p = data.points[operational_point(static_cast<Limb>(limb))];
    grasp[limb_name(static_cast<Limb>(limb))] = {p.x(), p.y(), p.z()};
  }
  out["grasp_points"] = grasp;
  return out;
}

std::string view_text(const ViewCaption& caption) {
  return fmt::format("wrote {}: {}, {}\n", caption.svg, caption.title, caption.subtitle);
}

}  // namespace crux
