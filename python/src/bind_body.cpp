// The body: loading, joints and limits, forward kinematics (one posture or a batch).

#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "common/input_error.hpp"
#include "conversions.hpp"

namespace crux::python {

namespace {

// Fills one posture's rows of the outputs: points (5, 3), centre of mass (3), and when
// asked the joints' origins (J, 3) and the Jacobians (5, 3, 35).
void kinematics_of(const BodyModel& model, BodyData& data, const Posture& g, double* points, double* com,
                   double* joint_origins, double* jacobians) {
  forward_kinematics(model, data, g);
  centre_of_mass(model, data);
  for (int k = 0; k < kOperationalPointCount; ++k) {
    for (int c = 0; c < 3; ++c) points[3 * k + c] = data.points[k][c];
  }
  for (int c = 0; c < 3; ++c) com[c] = data.centre_of_mass[c];
  if (joint_origins != nullptr) {
    for (std::size_t j = 0; j < data.placements.size(); ++j) {
      for (int c = 0; c < 3; ++c) joint_origins[3 * j + c] = data.placements[j].origin[c];
    }
  }
  if (jacobians == nullptr) return;
  operational_jacobians(model, data);
  for (int k = 0; k < kOperationalPointCount; ++k) {
    for (int r = 0; r < 3; ++r) {
      for (int j = 0; j < kConfigurationDof; ++j) {
        jacobians[(k * 3 + r) * kConfigurationDof + j] = data.jacobians[k](r, j);
      }
    }
  }
}

py::dict forward_kinematics_py(const BodyModelPtr& model, const py::handle& postures, bool with_jacobians,
                               bool with_joints) {
  const auto a = double_array_from(postures, "postures");
  if ((a.ndim() != 1 && a.ndim() != 2) || a.shape(a.ndim() - 1) != kConfigurationDof) {
    throw InputError("postures", fmt::format("must be an array of shape ({0},) or (N, {0})", kConfigurationDof));
  }
  const bool batch = a.ndim() == 2;
  const py::ssize_t n = batch ? a.shape(0) : 1;
  std::vector<Posture> gs(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    for (int j = 0; j < kConfigurationDof; ++j) gs[i][j] = a.data()[i * kConfigurationDof + j];
    if (!gs[i].allFinite()) throw InputError("postures", "must hold finite numbers");
  }
  const auto shape = [&](std::vector<py::ssize_t> tail) {
    if (batch) tail.insert(tail.begin(), n);
    return tail;
  };
  py::array_t<double> points(shape({kOperationalPointCount, 3}));
  py::array_t<double> com(shape({3}));
  py::array_t<double> jacobians, joint_origins;
  if (with_jacobians) jacobians = py::array_t<double>(shape({kOperationalPointCount, 3, kConfigurationDof}));
  const auto joint_count = static_cast<py::ssize_t>(model->joints.size());
  if (with_joints) joint_origins = py::array_t<double>(shape({joint_count, 3}));
  double* p = points.mutable_data();
  double* c = com.mutable_data();
  double* jac = with_jacobians ? jacobians.mutable_data() : nullptr;
  double* origins = with_joints ? joint_origins.mutable_data() : nullptr;
  {
    py::gil_scoped_release release;
    BodyData data(*model);
    for (py::ssize_t i = 0; i < n; ++i) {
      kinematics_of(*model, data, gs[i], p + 3 * kOperationalPointCount * i, c + 3 * i,
                    origins == nullptr ? nullptr : origins + 3 * joint_count * i,
                    jac == nullptr ? nullptr : jac + 3 * kOperationalPointCount * kConfigurationDof * i);
    }
  }
  py::dict out;
  out["points"] = points;
  out["centre_of_mass"] = com;
  if (with_jacobians) out["jacobians"] = jacobians;
  if (with_joints) out["joint_origins"] = joint_origins;
  return out;
}

}  // namespace

void bind_body(py::module_& m) {
  m.attr("CONFIGURATION_DOF") = kConfigurationDof;
  m.attr("ROOT_DOF") = kRootDof;
  py::tuple limbs(kLimbCount);
  for (int limb = 0; limb < kLimbCount; ++limb) limbs[limb] = enum_name(static_cast<Limb>(limb));
  m.attr("LIMB_NAMES") = limbs;

  py::class_<BodyModel, std::shared_ptr<BodyModel>>(m, "BodyModel",
                                                    "The immutable body: a translating root and 32 revolute joints")
      .def_static(
          "load",
          [](const py::handle& path) -> BodyModelPtr {
            if (path.is_none()) return body_or_default(path);
            return std::make_shared<BodyModel>(load_body_model(path_from(path)));
          },
          py::arg("path") = py::none(), "Loads a URDF file; the default 1.70 m human when path is None")
      .def_readonly("source", &BodyModel::source)
      .def_readonly("name", &BodyModel::name)
      .def_readonly("total_mass", &BodyModel::total_mass, "kg")
      .def_readonly("stature", &BodyModel::stature, "m, top of the head above the soles")
      .def_property_readonly("joint_names",
                             [](const BodyModel& model) {
                               py::list names;
                               for (const BodyJoint& joint : model.joints) names.append(joint.name);
                               return names;
                             })
      .def_property_readonly(
          "joint_parents",
          [](const BodyModel& model) {
            py::array_t<int> out(static_cast<py::ssize_t>(model.joints.size()));
            for (std::size_t j = 0; j < model.joints.size(); ++j) out.mutable_at(j) = model.joints[j].parent;
            return out;
          },
          "each joint's parent joint (index), -1 for the world: the skeleton forward_kinematics' joint origins draw")
      .def_property_readonly("lower_limits", [](const BodyModel& model) { return to_array(model.lower_limits); })
      .def_property_readonly("upper_limits", [](const BodyModel& model) { return to_array(model.upper_limits); })
      .def_property_readonly("grasp_frame_names",
                             [](const BodyModel& model) {
                               py::list names;
                               for (const std::string& name : model.grasp_frame_names) names.append(name);
                               return names;
                             })
      .def(
          "standing_posture",
          [](const BodyModel&, const py::handle& root) { return to_array(standing_posture(point_from(root, "root"))); },
          py::arg("root"), "All joint angles 0, the root at `root`")
      .def(
          "within_limits",
          [](const BodyModel& model, const py::handle& posture) {
            return within_limits(model, posture_from(posture, "posture"));
          },
          py::arg("posture"))
      .def("__repr__", [](const BodyModel& model) {
        return fmt::format("<crux.BodyModel '{}' from {}, {:.1f} kg>", model.name, model.source, model.total_mass);
      });

  m.def(
      "forward_kinematics",
      [](const py::handle& model, const py::handle& postures, bool jacobians, bool joints) {
        return forward_kinematics_py(body_or_default(model), postures, jacobians, joints);
      },
      py::arg("model"), py::arg("postures"), py::arg("jacobians") = false, py::arg("joints") = false,
      "Operational points e0..e4 (root, then the limbs), the centre of mass and, if asked, the Jacobians "
      "d e_i / d G and the joints' origins, for a posture (35,) or a batch (N, 35): a dict of arrays (5, 3), (3,), "
      "(5, 3, 35), (35, 3), with a leading N for a batch");
}

}  // namespace crux::python
