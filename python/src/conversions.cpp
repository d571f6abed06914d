#include "conversions.hpp"

#include <limits>
#include <mutex>
#include <optional>

#include <fmt/format.h>

#include "body/urdf_loader.hpp"
#include "common/input_error.hpp"
#include "common/printable.hpp"

namespace crux::python {

BodyModelPtr body_or_default(const py::handle& model) {
  if (!model.is_none()) {
    if (!py::isinstance<BodyModel>(model)) throw InputError("model", "must be a crux.BodyModel or None");
    return model.cast<BodyModelPtr>();
  }
  static std::mutex mutex;
  static BodyModelPtr body;
  const std::lock_guard lock(mutex);
  if (!body) body = std::make_shared<BodyModel>(load_body_model(default_body_model_path()));
  return body;
}

BodyModelPtr body_from(const py::handle& model, const std::string& configured_urdf) {
  if (configured_urdf.empty()) return body_or_default(model);
  if (!model.is_none()) throw InputError("model", "give the body as model or as config's experiment.urdf, not both");
  return std::make_shared<BodyModel>(load_body_model(configured_urdf));
}

std::string path_from(const py::handle& path) {
  const py::module_ os = py::module_::import("os");
  if (!py::isinstance<py::str>(path) && !py::isinstance(path, os.attr("PathLike"))) {
    throw py::type_error("a path is a str or an os.PathLike");
  }
  return py::str(os.attr("fspath")(path)).cast<std::string>();
}

// numpy.bool_, looked up once (env.step converts an action at every step); the
// reference is kept for the life of the process, as the module's.
bool is_numpy_bool(const py::handle& value) {
  static PyObject* const numpy_bool = py::object(py::module_::import("numpy").attr("bool_")).release().ptr();
  return PyObject_IsInstance(value.ptr(), numpy_bool) == 1;
}

namespace {

// The integer value of `value` (Python's int or numpy's integers; bools refused), or
// nothing.
std::optional<py::int_> as_integer(const py::handle& value) {
  if (PyBool_Check(value.ptr()) != 0 || is_numpy_bool(value)) return std::nullopt;
  PyObject* index = PyNumber_Index(value.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    return std::nullopt;
  }
  return py::reinterpret_steal<py::int_>(index);
}

}  // namespace

std::uint64_t uint64_from(const py::handle& seed, const char* what) {
  const auto integer = as_integer(seed);
  if (!integer || *integer < py::int_(0) || *integer > py::int_(std::numeric_limits<std::uint64_t>::max())) {
    throw InputError(what, "must be an integer from 0 to 18446744073709551615");
  }
  return integer->cast<std::uint64_t>();
}

long long integer_from(const py::handle& value, long long low, long long high, const char* what) {
  const auto integer = as_integer(value);
  if (!integer || *integer < py::int_(low) || *integer > py::int_(high)) {
    throw InputError(what, fmt::format("must be an integer from {} to {}", low, high));
  }
  return integer->cast<long long>();
}

py::array_t<double> double_array_from(const py::handle& array, const char* what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a) {
    PyErr_Clear();
    throw InputError(what, "must be an array of numbers");
  }
  return a;
}

py::array_t<std::int64_t> integer_array_from(const py::handle& array, const char* what) {
  const py::array any = py::array::ensure(array);
  if (!any) PyErr_Clear();
  if (!any || (any.dtype().kind() != 'i' && any.dtype().kind() != 'u')) {
    throw InputError(what, "must be an array of integers");
  }
  if (any.dtype().kind() == 'u' && any.dtype().itemsize() == 8) {
    const auto unsigned_values = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(any);
    for (py::ssize_t i = 0; i < unsigned_values.size(); ++i) {
      if (unsigned_values.data()[i] > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        throw InputError(what, "holds a value too large");
      }
    }
  }
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(any);
}

Posture posture_from(const py::handle& array, const char* what) {
  const auto a = double_array_from(array, what);
  if (a.ndim() != 1 || a.shape(0) != kConfigurationDof) {
    throw InputError(what, fmt::format("must be an array of shape ({},)", kConfigurationDof));
  }
  Posture g;
  for (int i = 0; i < kConfigurationDof; ++i) g[i] = a.at(i);
  if (!g.allFinite()) throw InputError(what, "must hold finite numbers");
  return g;
}

Eigen::Vector3d point_from(const py::handle& array, const char* what) {
  const auto a = double_array_from(array, what);
  if (a.ndim() != 1 || a.shape(0) != 3) throw InputError(what, "must be an array of shape (3,)");
  const Eigen::Vector3d v(a.at(0), a.at(1), a.at(2));
  if (!v.allFinite()) throw InputError(what, "must hold finite numbers");
  return v;
}

HoldConfiguration configuration_from(const py::handle& holds, const Wall& wall, const char* what) {
  const auto a = integer_array_from(holds, what);
  if (a.ndim() != 1 || a.shape(0) != kLimbCount) {
    throw InputError(what, "must be 4 hold indices in limb order (-1 for a free limb)");
  }
  HoldConfiguration c;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const std::int64_t hold = a.at(limb);
    if (hold < kFree || hold >= wall.hold_count()) {
      throw InputError(what, fmt::format("hold index {} is not -1 (free) or a hold of the wall (0 to {})", hold,
                                         wall.hold_count() - 1));
    }
    c.holds[limb] = static_cast<int>(hold);
  }
  return c;
}

Limb limb_from(const py::handle& limb) {
  if (py::isinstance<py::str>(limb)) {
    const std::string name = limb.cast<std::string>();
    if (const auto parsed = parse_enum<Limb>(name)) return *parsed;
    throw InputError("limb",
                     fmt::format("unknown limb '{}' (right_hand, left_hand, right_foot, left_foot)", printable(name)));
  }
  if (const auto index = as_integer(limb); index && *index >= py::int_(0) && *index < py::int_(kLimbCount)) {
    return static_cast<Limb>(index->cast<int>());
  }
  throw InputError("limb", "must be 0-3 or a limb's name (right_hand, left_hand, right_foot, left_foot)");
}

py::array_t<double> to_array(const Eigen::Vector3d& v) {
  py::array_t<double> out(3);
  std::copy(v.data(), v.data() + 3, out.mutable_data());
  return out;
}

py::array_t<double> to_array(const Posture& g) {
  py::array_t<double> out(kConfigurationDof);
  std::copy(g.data(), g.data() + kConfigurationDof, out.mutable_data());
  return out;
}

py::array_t<int> to_array(const HoldConfiguration& c) {
  py::array_t<int> out(kLimbCount);
  std::copy(c.holds.begin(), c.holds.end(), out.mutable_data());
  return out;
}

}  // namespace crux::python
