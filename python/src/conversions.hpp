#pragma once
// Python arguments into crux's types and back, checked: a value of the right kind but a
// wrong shape, range or content is InputError (ValueError in Python) naming the argument.

#include <cstdint>
#include <memory>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "body/body_model.hpp"
#include "configurations/hold_configuration.hpp"
#include "wall/wall.hpp"

namespace crux::python {

namespace py = pybind11;

using BodyModelPtr = std::shared_ptr<BodyModel>;  // never changed once loaded

// The body `model` (a crux.BodyModel), or the default body (loaded once) when None.
BodyModelPtr body_or_default(const py::handle& model);

// The body of a call that takes both a `model` argument and config's experiment.urdf:
// the one given (InputError when both are), else the default body.
BodyModelPtr body_from(const py::handle& model, const std::string& configured_urdf);

// A str or os.PathLike as a path.
std::string path_from(const py::handle& path);

// Whether `value` is a numpy boolean (numpy lets one pass for an integer).
bool is_numpy_bool(const py::handle& value);
// An integer (Python's or numpy's, not a bool) from 0 to 2^64 - 1: a seed, a state code.
std::uint64_t uint64_from(const py::handle& seed, const char* what);
// An integer (not a bool) within [low, high].
long long integer_from(const py::handle& value, long long low, long long high, const char* what);

// A (35,) array as a posture, finite.
Posture posture_from(const py::handle& array, const char* what);
// A (3,) array as a point, finite.
Eigen::Vector3d point_from(const py::handle& array, const char* what);
// An array of numbers as a C-contiguous float64 array; InputError when it is not one.
py::array_t<double> double_array_from(const py::handle& array, const char* what);
// An array of integers (integer dtype, or a list of ints) as int64.
py::array_t<std::int64_t> integer_array_from(const py::handle& array, const char* what);
// 4 hold indices in limb order, kFree (-1) for a free limb, checked against the wall.
HoldConfiguration configuration_from(const py::handle& holds, const Wall& wall, const char* what);
// A limb by index 0-3 or by name (right_hand, rh, ...).
Limb limb_from(const py::handle& limb);

py::array_t<double> to_array(const Eigen::Vector3d& v);
py::array_t<double> to_array(const Posture& g);
py::array_t<int> to_array(const HoldConfiguration& c);

}  // namespace crux::python
