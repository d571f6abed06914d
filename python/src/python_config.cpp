#include "python_config.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/printable.hpp"
#include "conversions.hpp"

namespace py = pybind11;

namespace crux::python {

namespace {

constexpr const char* kSource = "config";

void flatten(const py::dict& table, const std::string& prefix, std::vector<std::pair<std::string, py::handle>>& out) {
  for (const auto& [name, value] : table) {
    if (!py::isinstance<py::str>(name)) throw InputError(kSource, "keys must be strings");
    const std::string key = prefix.empty() ? name.cast<std::string>() : prefix + "." + name.cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
      flatten(value.cast<py::dict>(), key, out);
    } else {
      out.emplace_back(key, value);
    }
  }
}

void assign(const ConfigField& field, const py::handle& value) {
  const auto fail = [&](const char* expected) {
    throw InputError(kSource, fmt::format("{} must be {}", field.key, expected));
  };
  const bool is_bool = py::isinstance<py::bool_>(value) || is_numpy_bool(value);
  const bool is_text = py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value);
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    fail("one value; only crux sweep takes lists");
  }
  std::visit(
      [&](auto target) {
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, ChoiceTarget<false>>) {
          if (!py::isinstance<py::str>(value)) fail(("one of " + target.type->choices()).c_str());
          assign_text(field, value.cast<std::string>());
        } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) {
          // Python's and numpy's numbers, through __float__.
          if (is_bool || is_text) fail("a finite number");
          const double v = PyFloat_AsDouble(value.ptr());
          if (PyErr_Occurred() != nullptr) {
            PyErr_Clear();
            fail("a finite number");
          }
          if (!std::isfinite(v)) fail("a finite number");
          *target = v;
        } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) {
          try {
            *target = static_cast<int>(integer_from(value, std::numeric_limits<int>::min(),
                                                    std::numeric_limits<int>::max(), field.key.c_str()));
          } catch (const InputError&) {
            fail("an integer from -2147483648 to 2147483647");
          }
        } else if constexpr (std::is_same_v<T, std::uint64_t> || std::is_same_v<T, std::optional<std::uint64_t>>) {
          try {
            *target = uint64_from(value, field.key.c_str());
          } catch (const InputError&) {
            fail("an integer from 0 to 18446744073709551615");
          }
        } else if constexpr (std::is_same_v<T, bool>) {
          if (!is_bool) fail("true or false");
          *target = value.cast<bool>();
        } else {
          if (py::isinstance<py::str>(value)) {
            *target = value.cast<std::string>();
          } else if (py::isinstance(value, py::module_::import("os").attr("PathLike"))) {
            *target = path_from(value);
          } else {
            fail("a string");
          }
        }
      },
      field.target);
}

}  // namespace

ExperimentConfig config_from_python(const py::handle& config, const ParameterSet& accepted, const std::string& caller,
                                    const ExperimentConfig& defaults) {
  ExperimentConfig out = defaults;
  if (config.is_none()) {
    // the defaults
  } else if (py::isinstance<py::str>(config) || py::isinstance(config, py::module_::import("os").attr("PathLike"))) {
    apply_config_file(path_from(config), out, accepted, caller);
  } else if (py::isinstance<py::dict>(config)) {
    std::vector<std::pair<std::string, py::handle>> entries;
    flatten(config.cast<py::dict>(), "", entries);
    const std::vector<ConfigField> fields = config_fields(out);
    for (const auto& [key, value] : entries) {
      const auto field = std::find_if(fields.begin(), fields.end(), [&](const ConfigField& f) { return f.key == key; });
      if (field == fields.end()) throw InputError(kSource, fmt::format("unknown key {}", printable(key)));
      if (!accepted.accepts(key))
        throw InputError(kSource, fmt::format("crux.{} does not take {}", caller, printable(key)));
      assign(*field, value);
      out.given.insert(key);
    }
  } else {
    throw InputError(kSource, "must be None, a dict of config keys, or the path of a config.toml");
  }
  finalize_config(out);
  require_physics_model_taken(out, accepted, "crux." + std::string(caller));
  return out;
}

}  // namespace crux::python
