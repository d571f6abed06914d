#pragma once
// The parts of the module crux._crux, one per area of the library, and the conversions
// they share between numpy arrays and crux's types.

#include <memory>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "body/body_model.hpp"
#include "configurations/hold_configuration.hpp"
#include "wall/wall.hpp"

namespace crux::python {

namespace py = pybind11;

void bind_body(py::module_& module);
void bind_ik(py::module_& module);
void bind_wall(py::module_& module);
void bind_climb_env(py::module_& module);
void bind_learning(py::module_& module);
void bind_experiment(py::module_& module);

using BodyModelPtr = std::shared_ptr<BodyModel>;  // never changed once loaded

// The body of `model`, or the default body (loaded once) when it is None.
BodyModelPtr body_or_default(const py::handle& model);

// A str or os.PathLike as a path.
std::string path_from(const py::handle& path);

// A (35,) array as a posture; InputError naming `what` for another shape or a NaN.
Posture posture_from(const py::handle& array, const char* what);
// A (3,) array as a point.
Eigen::Vector3d point_from(const py::handle& array, const char* what);
// 4 hold indices in limb order, kFree (-1) for a free limb, checked against the wall.
HoldConfiguration configuration_from(const py::handle& holds, const Wall& wall, const char* what);
// A limb by index 0-3 or by name (right_hand, rh, ...).
Limb limb_from(const py::handle& limb);

py::array_t<double> to_array(const Eigen::Vector3d& v);
py::array_t<double> to_array(const Posture& g);
py::array_t<int> to_array(const HoldConfiguration& c);

}  // namespace crux::python
