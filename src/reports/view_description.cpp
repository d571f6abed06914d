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

namespace {

WallPenetration penetration_at(const BodyModel& model, const Posture& posture) {
  BodyData data(model);
  forward_kinematics(model, data, posture);
  return wall_penetration(model, data);
}

}  // namespace

std::string wall_penetration_note(const BodyModel& model, const WallPenetration& penetration) {
  if (!penetration.passes_through()) return "";
  return fmt::format("the {} is {:.3f} m inside the wall", model.visuals[penetration.visual].link, penetration.depth_m);
}

ViewCaption with_wall_note(ViewCaption caption, const BodyModel& model, const Posture& posture) {
  const std::string note = wall_penetration_note(model, penetration_at(model, posture));
  if (!note.empty()) caption.subtitle += "; " + note + " (the kinematic model ignores the wall)";
  return caption;
}

ViewCaption with_stance_note(ViewCaption caption, const BodyModel& model, const StanceLoads& loads) {
  if (!loads.balanced) {
    caption.subtitle += "; static model: no forces on these holds balance it";
    return caption;
  }
  int binding = -1;
  double largest = -1.0;
  for (const auto& [joint, ratio] : loads.joint_ratios) {
    if (ratio > largest) {
      largest = ratio;
      binding = joint;
    }
  }
  caption.subtitle += fmt::format("; static model: {} at effort {:.2f}{}", loads.effort <= 1.0 ? "held" : "not held",
                                  loads.effort, binding >= 0 ? fmt::format(" ({})", model.joints[binding].name) : "");
  return caption;
}

nlohmann::ordered_json view_json(const BodyModel& model, const Posture& posture, const ViewCaption& caption,
                                 const StanceLoads* loads) {
  BodyData data(model);
  forward_kinematics(model, data, posture);
  const WallPenetration penetration = wall_penetration(model, data);
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
    grasp[enum_name(static_cast<Limb>(limb))] = {p.x(), p.y(), p.z()};
  }
  out["grasp_points"] = grasp;
  out["wall_penetration"] = {
      {"passes_through", penetration.passes_through()},
      {"depth_m", penetration.depth_m},
      {"link", penetration.visual < 0 ? nlohmann::ordered_json()
                                      : nlohmann::ordered_json(model.visuals[penetration.visual].link)}};
  if (loads == nullptr) return out;
  nlohmann::ordered_json forces = nlohmann::ordered_json::object();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (!loads->held[limb] || !loads->balanced) continue;
    const Eigen::Vector3d& f = loads->forces[limb];
    forces[enum_name(static_cast<Limb>(limb))] = {f.x(), f.y(), f.z()};
  }
  nlohmann::ordered_json ratios = nlohmann::ordered_json::object();
  for (const auto& [joint, ratio] : loads->joint_ratios) ratios[model.joints[joint].name] = ratio;
  out["stance"] = {{"balanced", loads->balanced},
                   {"feasible", loads->balanced && loads->effort <= 1.0},
                   {"effort", loads->balanced ? nlohmann::ordered_json(loads->effort) : nlohmann::ordered_json()},
                   {"contact_forces_n", forces},
                   {"torque_to_limit", ratios}};
  return out;
}

std::string view_text(const ViewCaption& caption) {
  return fmt::format("wrote {}: {}, {}\n", caption.svg, caption.title, caption.subtitle);
}

}  // namespace crux
