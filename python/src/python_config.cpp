#include "python_config.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "common/input_error.hpp"

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
  const bool is_bool = py::isinstance<py::bool_>(value);
  const bool is_int = !is_bool && py::isinstance<py::int_>(value);
  std::visit(
      [&](auto* target) {
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, double>) {
          if (is_bool || !(is_int || py::isinstance<py::float_>(value))) fail("a finite number");
          const double v = value.cast<double>();
          if (!std::isfinite(v)) fail("a finite number");
          *target = v;
        } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) {
          if (!is_int) fail("an integer");
          const long long v = value.cast<py::int_>().cast<long long>();
          if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
            fail("an integer from -2147483648 to 2147483647");
          }
          *target = static_cast<int>(v);
        } else if constexpr (std::is_same_v<T, std::uint64_t> || std::is_same_v<T, std::optional<std::uint64_t>>) {
          if (!is_int || value.cast<py::int_>() < py::int_(0) ||
              value.cast<py::int_>() > py::int_(std::numeric_limits<std::uint64_t>::max())) {
            fail("an integer from 0 to 18446744073709551615");
          }
          *target = value.cast<std::uint64_t>();
        } else if constexpr (std::is_same_v<T, bool>) {
          if (!is_bool) fail("true or false");
          *target = value.cast<bool>();
        } else {
          if (py::isinstance<py::str>(value)) {
            *target = value.cast<std::string>();
          } else if (py::isinstance(value, py::module_::import("os").attr("PathLike"))) {
            *target = py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>();
          } else {
            fail("a string");
          }
        }
      },
      field.target);
}

}  // namespace

ExperimentConfig config_from_python(const py::handle& config, const ParameterSet& accepted,
                                    const std::string& caller) {
  ExperimentConfig out;
  if (config.is_none()) {
    // the defaults
  } else if (py::isinstance<py::str>(config) || py::isinstance(config, py::module_::import("os").attr("PathLike"))) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(config)).cast<std::string>();
    apply_config_file(path, out, accepted, caller);
  } else if (py::isinstance<py::dict>(config)) {
    std::vector<std::pair<std::string, py::handle>> entries;
    flatten(config.cast<py::dict>(), "", entries);
    const std::vector<ConfigField> fields = config_fields(out);
    for (const auto& [key, value] : entries) {
      const auto field = std::find_if(fields.begin(), fields.end(), [&](const ConfigField& f) { return f.key == key; });
      if (field == fields.end()) throw InputError(kSource, fmt::format("unknown key {}", key));
      if (!accepted.accepts(key)) throw InputError(kSource, fmt::format("crux.{} does not take {}", caller, key));
      assign(*field, value);
    }
  } else {
    throw InputError(kSource, "must be None, a dict of config keys, or the path of a config.toml");
  }
  finalize_config(out);
  return out;
}

}  // namespace crux::python
