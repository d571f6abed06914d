#include "reports/replay_data.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "common/json_field.hpp"
#include "configurations/hold_configuration.hpp"
#include "reports/perform_description.hpp"

namespace crux {
namespace {

nlohmann::ordered_json quaternion_json(const Eigen::Matrix3d& rotation) {
  const Eigen::Quaterniond q(rotation);
  return {q.x(), q.y(), q.z(), q.w()};
}

nlohmann::ordered_json configuration_json(const Wall& wall, const HoldConfiguration& configuration) {
  nlohmann::ordered_json out;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const int hold = configuration.holds[limb];
    out[enum_name(static_cast<Limb>(limb))] = hold == kFree ? 0 : wall.holds[hold].id;
  }
  return out;
}

// What holds a stance, as the replay draws it: the effort (null when no forces balance
// it), each limb's contact force (null when free), and the bounded joints' torque ratios
// as [joint, ratio] pairs, to a thousandth.
nlohmann::ordered_json stance_json(const StanceLoads& loads) {
  nlohmann::ordered_json forces = nlohmann::ordered_json::array();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    forces.push_back(loads.held[limb] && loads.balanced ? vector_json(loads.forces[limb]) : nlohmann::ordered_json());
  }
  nlohmann::ordered_json ratios = nlohmann::ordered_json::array();
  for (const auto& [joint, ratio] : loads.joint_ratios) ratios.push_back({joint, std::round(ratio * 1000) / 1000});
  return {{"effort", loads.balanced ? nlohmann::ordered_json(loads.effort) : nlohmann::ordered_json()},
          {"forces", forces},
          {"joint_ratios", ratios}};
}

}  // namespace

nlohmann::ordered_json body_model_json(const BodyModel& model) {
  nlohmann::ordered_json body;
  body["joints"] = nlohmann::ordered_json::array();
  for (const BodyJoint& joint : model.joints) {
    body["joints"].push_back({{"name", joint.name},
                              {"parent", joint.parent},
                              {"origin_xyz", vector_json(joint.origin_translation)},
                              {"origin_quat", quaternion_json(joint.origin_rotation)},
                              {"axis", vector_json(joint.axis)},
                              {"prismatic", joint.prismatic}});
  }
  body["visuals"] = nlohmann::ordered_json::array();
  for (const BodyVisual& visual : model.visuals) {
    nlohmann::ordered_json size;
    switch (visual.shape) {
      case VisualShape::Box:
        size = vector_json(visual.size);
        break;
      case VisualShape::Cylinder:
        size = {visual.size.x(), visual.size.y()};
        break;
      case VisualShape::Sphere:
        size = {visual.size.x()};
        break;
    }
    body["visuals"].push_back({{"link", visual.link},
                               {"joint", visual.joint},
                               {"xyz", vector_json(visual.translation)},
                               {"quat", quaternion_json(visual.rotation)},
                               {"shape", enum_name(visual.shape)},
                               {"size", size},
                               {"rgba", visual.rgba}});
  }
  body["grasp_points"] = nlohmann::ordered_json::array();
  for (const AttachedPoint& point : model.grasp_points) {
    body["grasp_points"].push_back({{"joint", point.joint}, {"offset", vector_json(point.offset)}});
  }
  return body;
}

namespace {

nlohmann::ordered_json replay_head(const BodyModel& model, const Wall& wall, double grasp_radius,
                                   const std::string& title, const std::string& climb) {
  nlohmann::ordered_json out;
  out["format"] = "crux-replay";
  out["version"] = 1;
  out["title"] = title;
  out["climb"] = climb;
  out["model"] = body_model_json(model);
  out["grasp_radius"] = grasp_radius;
  nlohmann::ordered_json holds = nlohmann::ordered_json::array();
  for (const Hold& hold : wall.holds) {
    holds.push_back({{"id", hold.id}, {"position", vector_json(hold.position)}, {"radius", hold.radius}});
  }
  out["wall"] = {{"name", wall.name},
                 {"finish_height", wall.finish_height},
                 {"holds", holds},
                 {"start", configuration_json(wall, start_configuration(wall))}};
  // Only an inclined wall says so, so that a vertical wall's replay keeps its bytes.
  if (wall.incline_deg != 0.0) out["wall"]["incline"] = wall.incline_deg;
  return out;
}

nlohmann::ordered_json check_json(int frame, const std::array<Eigen::Vector3d, kLimbCount>& grasp_points) {
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const Eigen::Vector3d& point : grasp_points) points.push_back(vector_json(point));
  return {{"frame", frame}, {"grasp_points", points}};
}

}  // namespace

nlohmann::ordered_json replay_data(const BodyModel& model, const Wall& wall, const ClimbReplay& replay,
                                   const ClimbStances* stances, const std::string& title) {
  nlohmann::ordered_json out = replay_head(model, wall, replay.grasp_radius, title, replay.climb_kind);
  if (stances && !stances->loads.empty()) out["start_stance"] = stance_json(stances->loads.front());
  nlohmann::ordered_json moves = nlohmann::ordered_json::array();
  for (const ReplayMove& move : replay.moves) {
    const RunStep& step = move.step;
    moves.push_back({{"iteration", step.iteration > 0 ? nlohmann::ordered_json(step.iteration) : nullptr},
                     {"regime", enum_name(step.regime)},
                     {"limb", enum_name(move.limb)},
                     {"hold", step.hold_id},
                     {"success", step.success},
                     {"reward", step.reward},
                     {"root_rise_cm", step.root_rise_cm},
                     {"configuration", configuration_json(wall, move.configuration)},
                     {"first_frame", move.first_frame},
                     {"last_frame", move.last_frame}});
    if (move.posture >= 0 && stances) moves.back()["stance"] = stance_json(stances->loads[move.posture]);
  }
  out["climb_moves"] = replay.climb_moves;
  out["frames"] = {{"count", replay.frame_count}, {"postures", replay.frames}};
  out["moves"] = std::move(moves);
  if (replay.check_frame >= 0) out["check"] = check_json(replay.check_frame, replay.check_grasp_points);
  return out;
}

nlohmann::ordered_json performed_replay_data(const BodyModel& model, const Wall& wall, const PerformedReplay& replay,
                                             int planned_moves, double grasp_radius, const std::string& title) {
  nlohmann::ordered_json out = replay_head(model, wall, grasp_radius, title, "performed");
  out["performed"] = true;
  nlohmann::ordered_json moves = nlohmann::ordered_json::array();
  for (const PerformedReplayMove& move : replay.moves) {
    const AttemptedMove& attempted = move.move;
    moves.push_back(
        {{"limb", enum_name(attempted.limb)},
         {"hold", wall.holds[attempted.hold].id},
         {"success", attempted.performed},
         {"cause", attempted.performed ? nlohmann::ordered_json() : nlohmann::ordered_json(enum_name(attempted.cause))},
         {"cause_text",
          attempted.performed ? nlohmann::ordered_json() : nlohmann::ordered_json(failure_words(attempted.cause))},
         {"max_torque_ratio", std::round(attempted.max_torque_ratio * 1000) / 1000},
         {"configuration", configuration_json(wall, move.configuration)},
         {"first_frame", move.first_frame},
         {"last_frame", move.last_frame}});
  }
  out["climb_moves"] = planned_moves;
  out["frames"] = {{"count", replay.frame_count},
                   {"postures", replay.postures},
                   {"root_rotations", replay.root_rotations},
                   {"hold_forces", replay.hold_forces},
                   {"times", replay.times}};
  out["moves"] = std::move(moves);
  if (replay.check_frame >= 0) out["check"] = check_json(replay.check_frame, replay.check_grasp_points);
  return out;
}

}  // namespace crux
