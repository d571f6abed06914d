// IK with either solver, returning a result object (and the path when asked).

#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "body/body_data.hpp"
#include "common/input_error.hpp"
#include "conversions.hpp"
#include "ik/ik_solver.hpp"
#include "ik/root_target.hpp"
#include "jobs/command_keys.hpp"
#include "python_config.hpp"

namespace crux::python {

namespace {

struct PythonIkResult {
  IkResult result;
  Eigen::Vector3d root_target;
  std::optional<std::vector<Posture>> path;
};

std::array<Eigen::Vector3d, kLimbCount> holds_from(const py::handle& holds) {
  const auto a = double_array_from(holds, "holds");
  if (a.ndim() != 2 || a.shape(0) != kLimbCount || a.shape(1) != 3) {
    throw InputError("holds", "must be an array of shape (4, 3): the hold centres in limb order");
  }
  std::array<Eigen::Vector3d, kLimbCount> out;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    out[limb] = {a.at(limb, 0), a.at(limb, 1), a.at(limb, 2)};
    if (!out[limb].allFinite()) throw InputError("holds", "must hold finite numbers");
  }
  return out;
}

}  // namespace

void bind_ik(py::module_& m) {
  py::class_<PythonIkResult>(m, "IkResult", "What an IK solve returns (Algorithm 1, or crux's fast solver)")
      .def_property_readonly("reached", [](const PythonIkResult& r) { return r.result.reached; })
      .def_property_readonly("iterations", [](const PythonIkResult& r) { return r.result.iterations; })
      .def_property_readonly("simulated_time_s", [](const PythonIkResult& r) { return r.result.simulated_time_s; })
      .def_property_readonly(
          "residual_m", [](const PythonIkResult& r) { return r.result.residual_m; },
          "largest grasp-point-to-hold distance at the last iterate")
      .def_property_readonly(
          "posture", [](const PythonIkResult& r) { return to_array(r.result.posture); },
          "the reached posture, or the start posture when not reached")
      .def_property_readonly("root_target", [](const PythonIkResult& r) { return to_array(r.root_target); })
      .def_property_readonly(
          "path",
          [](const PythonIkResult& r) -> py::object {
            if (!r.path) return py::none();
            py::array_t<double> out({static_cast<py::ssize_t>(r.path->size()), py::ssize_t{kConfigurationDof}});
            for (std::size_t i = 0; i < r.path->size(); ++i) {
              std::copy((*r.path)[i].data(), (*r.path)[i].data() + kConfigurationDof,
                        out.mutable_data() + i * kConfigurationDof);
            }
            return out;
          },
          "(K, 35) postures along the solve when path_every > 0, else None")
      .def("__repr__", [](const PythonIkResult& r) {
        return fmt::format("<crux.IkResult reached={} iterations={} residual_m={:.4g}>",
                           r.result.reached ? "True" : "False", r.result.iterations, r.result.residual_m);
      });

  m.def(
      "root_target",
      [](const py::handle& model, const py::handle& holds, const py::handle& config) {
        const ExperimentConfig c = config_from_python(config, kIkKeys, "root_target");
        return to_array(
            root_target(*body_or_default(model), holds_from(holds), c.settings.learning.climbing.reachability.root));
      },
      py::arg("model"), py::arg("holds"), py::arg("config") = py::none(),
      "The root target H(C4) of four hold centres (4, 3) in limb order");

  m.def(
      "solve_ik",
      [](const py::handle& model_handle, const py::handle& holds, const py::handle& start, const py::handle& radii,
         const py::handle& config, int path_every) {
        const BodyModelPtr model = body_or_default(model_handle);
        const ExperimentConfig c = config_from_python(config, kIkKeys, "solve_ik");
        const ReachabilityParameters& reachability = c.settings.learning.climbing.reachability;
        if (path_every < 0) throw InputError("path_every", "must be 0 (no path) or positive");
        ReachTarget target;
        target.hold_centres = holds_from(holds);
        if (!radii.is_none()) {
          const auto r = double_array_from(radii, "radii");
          if (r.ndim() != 1 || r.shape(0) != kLimbCount) throw InputError("radii", "must have shape (4,)");
          for (int limb = 0; limb < kLimbCount; ++limb) {
            if (!(r.at(limb) > 0.0) || !std::isfinite(r.at(limb))) throw InputError("radii", "must be positive");
            target.hold_radii[limb] = r.at(limb);
          }
        }
        target.root = root_target(*model, target.hold_centres, reachability.root);
        const Posture g_init = start.is_none() ? standing_posture(target.root) : posture_from(start, "start");
        PythonIkResult out;
        out.root_target = target.root;
        std::vector<Posture> path;
        {
          py::gil_scoped_release release;
          BodyData data(*model);
          out.result = solve_ik(*model, data, g_init, target, reachability.ik,
                                PathRecorder{path_every > 0 ? &path : nullptr, path_every});
        }
        if (path_every > 0) out.path = std::move(path);
        return out;
      },
      py::arg("model"), py::arg("holds"), py::arg("start") = py::none(), py::arg("radii") = py::none(),
      py::arg("config") = py::none(), py::arg("path_every") = 0,
      "Reaches four holds (4, 3), limb order, from `start` (default: standing at the root target H(C4)). "
      "config takes the ik.* keys (ik.solver = 'fast' or 'paper'); path_every > 0 records every k-th iterate.");
}

}  // namespace crux::python
