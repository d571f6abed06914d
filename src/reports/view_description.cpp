#include "reports/view_description.hpp"

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "common/counted.hpp"
#include "common/json_field.hpp"
#include "common/printable.hpp"
#include "reports/perform_description.hpp"

namespace crux {

ViewCaption run_view_caption(const RunFolder& folder, const RecordedClimb& climb, int step, const std::string& svg) {
  return {svg, fmt::format("{} on '{}'", folder.name, folder.wall.name),
          fmt::format("step {} of {} ({}, the start is step 0)", step, climb_description(climb),
                      counted(climb.postures.size(), "posture"))};
}

ViewCaption performed_view_caption(const PerformFolder& folder, int step, const std::string& svg) {
  const std::string title = fmt::format("{} on '{}', performed in MuJoCo", folder.climb, printable(folder.wall.name));
  const double time = folder.step_sample(step).time;
  const std::size_t steps = folder.moves.size();
  if (step == 0) return {svg, title, fmt::format("step 0 of {}: the start at rest, t = {:.2f} s", steps, time)};
  const AttemptedMove& move = folder.moves[step - 1];
  return {svg, title,
          fmt::format("step {} of {}: move {}, {} to hold {}, {}, t = {:.2f} s", step, steps, step,
                      enum_name(move.limb), folder.wall.holds[move.hold].id,
                      move.performed ? "performed" : "failed: " + failure_words(move.cause), time)};
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

namespace {

// Where the body placed in `data` (at `posture`) is.
nlohmann::ordered_json placed_body_json(const BodyModel& model, BodyData& data, const Posture& posture,
                                        const ViewCaption& caption) {
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
  return out;
}

}  // namespace

nlohmann::ordered_json view_json(const BodyModel& model, const Posture& posture, const ViewCaption& caption,
                                 const StanceLoads* loads) {
  BodyData data(model);
  forward_kinematics(model, data, posture);
  nlohmann::ordered_json out = placed_body_json(model, data, posture, caption);
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

nlohmann::ordered_json performed_view_json(const BodyModel& model, const TrajectorySample& sample,
                                           const ViewCaption& caption) {
  BodyData data(model);
  forward_kinematics(model, data, sample.posture);
  turn_about_root(data, sample.root_orientation);
  nlohmann::ordered_json out = placed_body_json(model, data, sample.posture, caption);
  const Eigen::Quaterniond& q = sample.root_orientation;
  out["root_rotation"] = {q.w(), q.x(), q.y(), q.z()};
  out["time_s"] = sample.time;
  nlohmann::ordered_json forces = nlohmann::ordered_json::object();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (!sample.hold_forces[limb].isZero())
      forces[enum_name(static_cast<Limb>(limb))] = vector_json(sample.hold_forces[limb]);
  }
  out["hold_forces_n"] = forces;
  return out;
}

std::string view_text(const ViewCaption& caption) {
  return fmt::format("wrote {}: {}, {}\n", caption.svg, caption.title, caption.subtitle);
}

}  // namespace crux
