#include "reports/model_description.hpp"

#include <cmath>

#include <fmt/format.h>

#include "body/kinematics.hpp"

namespace crux {

std::vector<SegmentLength> segment_lengths(const BodyModel& model) {
  BodyData data(model);
  forward_kinematics(model, data, standing_posture(Eigen::Vector3d::Zero()));
  std::vector<SegmentLength> out;
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    const int parent = model.joints[i].parent;
    const double length = (data.placements[i].origin - data.placements[parent].origin).norm();
    if (length > 1e-9) out.push_back({model.joints[parent].name + " -> " + model.joints[i].name, length});
  }
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const int carrier = model.grasp_points[limb].joint;
    out.push_back({model.joints[carrier].name + " -> " + model.grasp_frame_names[limb],
                   (data.points[operational_point(limb)] - data.placements[carrier].origin).norm()});
  }
  return out;
}

nlohmann::ordered_json model_json(const BodyModel& model) {
  nlohmann::ordered_json out;
  out["source"] = model.source;
  out["name"] = model.name;
  out["dof_root"] = kRootDof;
  out["dof_revolute"] = kRevoluteDof;
  out["height_m"] = model.stature;
  out["mass_kg"] = model.total_mass;
  out["root_height_above_soles_m"] = model.root_height_above_soles;
  out["grasp_frames"] = model.grasp_frame_names;
  out["joints"] = nlohmann::json::array();
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    const BodyJoint& j = model.joints[i];
    out["joints"].push_back({{"name", j.name}, {"lower", j.lower}, {"upper", j.upper}});
  }
  out["segments"] = nlohmann::json::array();
  for (const auto& s : segment_lengths(model))
    out["segments"].push_back({{"between", s.name}, {"length_m", s.length_m}});
  return out;
}

std::string model_text(const BodyModel& model) {
  std::string out = fmt::format("body '{}' from {}\n", model.name, model.source) +
                    fmt::format("degrees of freedom: {} root translations + {} revolute = {}\n", kRootDof, kRevoluteDof,
                                kConfigurationDof) +
                    fmt::format("height {:.3f} m, mass {:.2f} kg, root {:.3f} m above the soles when standing\n",
                                model.stature, model.total_mass, model.root_height_above_soles) +
                    fmt::format("grasp frames: {}, {}, {}, {}\n", model.grasp_frame_names[0],
                                model.grasp_frame_names[1], model.grasp_frame_names[2], model.grasp_frame_names[3]) +
                    "joints (limits in degrees):\n";
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    const BodyJoint& j = model.joints[i];
    out += fmt::format("  {:2d} {:<26} [{:7.1f}, {:6.1f}]\n", i, j.name, j.lower * 180 / M_PI, j.upper * 180 / M_PI);
  }
  out += "segment lengths:\n";
  for (const auto& s : segment_lengths(model)) out += fmt::format("  {:<52} {:.3f} m\n", s.name, s.length_m);
  return out;
}

}  // namespace crux
