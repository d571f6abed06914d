// crux model: what the body is.

#include <cmath>
#include <iostream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "experiments/run_inputs.hpp"

namespace crux::cli {

namespace {

struct SegmentLength {
  std::string name;
  double length_m;
};

// Distance between consecutive distinct joint origins along the body, at the standing
// posture: the segment lengths actually used by the kinematics.
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

void run_model(const ExperimentConfig& config, bool json) {
  const BodyModel model = load_configured_body(config);
  const auto segments = segment_lengths(model);
  if (json) {
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
    for (const auto& s : segments) out["segments"].push_back({{"between", s.name}, {"length_m", s.length_m}});
    std::cout << out.dump(2) << '\n';
    return;
  }
  std::cout << fmt::format("body '{}' from {}\n", model.name, model.source)
            << fmt::format("degrees of freedom: {} root translations + {} revolute = {}\n", kRootDof, kRevoluteDof,
                           kConfigurationDof)
            << fmt::format("height {:.3f} m, mass {:.2f} kg, root {:.3f} m above the soles when standing\n",
                           model.stature, model.total_mass, model.root_height_above_soles)
            << fmt::format("grasp frames: {}, {}, {}, {}\n", model.grasp_frame_names[0], model.grasp_frame_names[1],
                           model.grasp_frame_names[2], model.grasp_frame_names[3])
            << "joints (limits in degrees):\n";
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    const BodyJoint& j = model.joints[i];
    std::cout << fmt::format("  {:2d} {:<26} [{:7.1f}, {:6.1f}]\n", i, j.name, j.lower * 180 / M_PI,
                             j.upper * 180 / M_PI);
  }
  std::cout << "segment lengths:\n";
  for (const auto& s : segments) std::cout << fmt::format("  {:<52} {:.3f} m\n", s.name, s.length_m);
}

}  // namespace

void add_model_command(CLI::App& app) {
  auto* command = app.add_subcommand("model", "Describe the virtual human: degrees of freedom, size, mass, joints");
  auto binding = std::make_shared<ParameterBinding>("model", ParameterSet{{"experiment.urdf"}, {}});
  auto json = std::make_shared<bool>(false);
  binding->bind(command);
  command->add_flag("--json", *json, "Print JSON instead of text");
  command->callback([binding, json] { run_model(binding->resolve(), *json); });
}

}  // namespace crux::cli
