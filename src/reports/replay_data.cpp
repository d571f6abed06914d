#include "reports/replay_data.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "common/input_error.hpp"
#include "configurations/hold_configuration.hpp"
#include "ik/ik_path.hpp"

namespace crux {
namespace {

nlohmann::ordered_json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

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

class FrameWriter {
 public:
  FrameWriter(const ReplayOptions& settings) : settings_(settings) {}

  void add(const Posture& posture) {
    for (int i = 0; i < kConfigurationDof; ++i)
      values_.push_back(std::round(posture[i] * settings_.decimals) / settings_.decimals);
    ++count_;
  }
  int count() const { return count_; }
  Posture frame(int index) const {
    return Eigen::Map<const Posture>(values_.data() + static_cast<std::size_t>(index) * kConfigurationDof);
  }
  const std::vector<double>& values() const { return values_; }

 private:
  const ReplayOptions& settings_;
  std::vector<double> values_;
  int count_ = 0;
};

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

nlohmann::ordered_json replay_wall_json(const Wall& wall) {
  nlohmann::ordered_json holds = nlohmann::ordered_json::array();
  for (const Hold& hold : wall.holds) {
    holds.push_back({{"id", hold.id}, {"position", vector_json(hold.position)}, {"radius", hold.radius}});
  }
  nlohmann::ordered_json out = {{"name", wall.name},
                                {"finish_height", wall.finish_height},
                                {"holds", holds},
                                {"start", configuration_json(wall, start_configuration(wall))}};
  // Only an inclined wall says so, so that a vertical wall's replay keeps its bytes.
  if (wall.incline_deg != 0.0) out["incline"] = wall.incline_deg;
  return out;
}

// What the page's forward kinematics must reproduce, on the rounded posture it reads: the
// grasp points of the middle frame.
nlohmann::ordered_json replay_check_json(const BodyModel& model, BodyData& data, const FrameWriter& frames) {
  const int check = frames.count() / 2;
  forward_kinematics(model, data, frames.frame(check));
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    points.push_back(vector_json(data.points[operational_point(static_cast<Limb>(limb))]));
  }
  return {{"frame", check}, {"grasp_points", points}};
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
                               {"shape", visual_shape_name(visual.shape)},
                               {"size", size},
                               {"rgba", visual.rgba}});
  }
  body["grasp_points"] = nlohmann::ordered_json::array();
  for (const AttachedPoint& point : model.grasp_points) {
    body["grasp_points"].push_back({{"joint", point.joint}, {"offset", vector_json(point.offset)}});
  }
  return body;
}

nlohmann::ordered_json replay_data(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                   const ReachabilityParameters& reach, const std::string& title,
                                   const std::string& source, const ReplayOptions& settings) {
  nlohmann::ordered_json out;
  out["format"] = "crux-replay";
  out["version"] = 1;
  out["title"] = title;
  out["climb"] = climb.kind;
  out["model"] = body_model_json(model);
  out["grasp_radius"] = reach.ik.tolerances.grasp_radius;
  out["wall"] = replay_wall_json(wall);

  IkParameters ik = reach.ik;
  ik.solver = IkSolverKind::Paper;
  BodyData data(model);
  FrameWriter frames(settings);
  nlohmann::ordered_json moves = nlohmann::ordered_json::array();
  if (!climb.postures.empty()) frames.add(climb.postures.front());
  HoldConfiguration configuration = start_configuration(wall).with(Limb::RightHand, kFree);
  std::size_t posture = 0;  // index into the climb of the body's current posture
  std::vector<Posture> path, samples;
  std::optional<StanceCheck> stances;
  if (settings.physics.model == PhysicsModel::Static) {
    stances.emplace(model, wall, settings.physics);
    if (!climb.postures.empty()) {
      out["start_stance"] = stance_json(stances->loads(climb.postures.front(), start_configuration(wall)));
    }
  }
  const std::size_t shown = std::min(climb.steps.size(), static_cast<std::size_t>(std::max(settings.max_moves, 0)));
  for (const RunStep& step : std::span(climb.steps).first(shown)) {
    const Limb free = configuration.free_limb();
    const int hold = wall.index_of(step.hold_id);
    if (hold < 0) {
      throw InputError(source, fmt::format("a move tries hold {}, which the wall does not have", step.hold_id));
    }
    const HoldConfiguration complete = configuration.with(free, hold);
    const int first = frames.count();
    if (step.success) {
      if (posture + 1 >= climb.postures.size()) throw InputError(source, "more reached moves than postures");
      const Posture& from = climb.postures[posture];
      const Posture& to = climb.postures[posture + 1];
      const ReachTarget target = reach_target(model, wall, complete, reach.root);
      ik_path_samples(model, data, from, to, target, ik, settings.frames_per_move, path, samples);
      for (const Posture& sample : samples) frames.add(sample);
      ++posture;
      configuration = complete.with(next_free_limb(free), kFree);
    } else {
      for (int f = 0; f < settings.frames_per_failure; ++f) frames.add(climb.postures[posture]);
    }
    moves.push_back({{"iteration", step.iteration > 0 ? nlohmann::ordered_json(step.iteration) : nullptr},
                     {"regime", regime_name(step.regime)},
                     {"limb", enum_name(free)},
                     {"hold", step.hold_id},
                     {"success", step.success},
                     {"reward", step.reward},
                     {"root_rise_cm", step.root_rise_cm},
                     {"configuration", configuration_json(wall, step.success ? complete : configuration)},
                     {"first_frame", first},
                     {"last_frame", frames.count() - 1}});
    if (step.success && stances)
      moves.back()["stance"] = stance_json(stances->loads(climb.postures[posture], complete));
  }
  out["climb_moves"] = climb.steps.size();
  out["frames"] = {{"count", frames.count()}, {"postures", frames.values()}};
  out["moves"] = std::move(moves);
  if (frames.count() > 0) out["check"] = replay_check_json(model, data, frames);
  return out;
}

}  // namespace crux
