// Q-tables to and from numpy, and Q-table files (the format of q_grid.bin).

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "agent_space/moving_grid.hpp"
#include "bindings.hpp"
#include "common/input_error.hpp"
#include "conversions.hpp"
#include "learning/q_table.hpp"
#include "learning/q_table_file.hpp"
#include "python_config.hpp"

namespace crux::python {

namespace {

// The action counts a QTable takes from Python, by its constructor and by from_numpy alike.
constexpr long long kMaxActionCount = 1 << 20;

int action_count_from(const py::handle& count, const char* what) {
  return static_cast<int>(integer_from(count, 1, kMaxActionCount, what));
}

py::tuple table_to_numpy(const QTable& table) {
  const auto rows = static_cast<py::ssize_t>(table.state_count());
  const py::ssize_t actions = table.action_count();
  py::array_t<std::uint64_t> states(rows);
  py::array_t<double> values({rows, actions});
  py::array_t<std::uint32_t> visits({rows, actions});
  py::ssize_t row = 0;
  table.for_each_row([&](StateCode s, std::span<const double> v, std::span<const std::uint32_t> n) {
    states.mutable_at(row) = s;
    std::copy(v.begin(), v.end(), values.mutable_data() + row * actions);
    std::copy(n.begin(), n.end(), visits.mutable_data() + row * actions);
    ++row;
  });
  return py::make_tuple(states, values, visits);
}

QTable table_from_numpy(const py::handle& states_handle, const py::handle& values_handle,
                        const py::handle& visits_handle) {
  const auto states = integer_array_from(states_handle, "states");
  const auto values = double_array_from(values_handle, "values");
  if (states.ndim() != 1) throw InputError("states", "must be a 1-D array of state codes");
  if (values.ndim() != 2 || values.shape(0) != states.shape(0) || values.shape(1) < 1) {
    throw InputError("values", "must have shape (len(states), actions)");
  }
  std::optional<py::array_t<std::int64_t>> visits;
  if (!visits_handle.is_none()) {
    visits = integer_array_from(visits_handle, "visits");
    if (visits->ndim() != 2 || visits->shape(0) != values.shape(0) || visits->shape(1) != values.shape(1)) {
      throw InputError("visits", "must have the shape of values");
    }
  }
  // A (0, n) array holds no values for any n; n must still be an action count, never wrapped.
  const int actions = action_count_from(py::int_(values.shape(1)), "values' columns (the action count)");
  QTable table(actions);
  for (py::ssize_t r = 0; r < states.shape(0); ++r) {
    if (states.at(r) < 0) throw InputError("states", "must be state codes, 0 or more");
    const auto s = static_cast<StateCode>(states.at(r));
    for (int a = 0; a < actions; ++a) {
      const double v = values.at(r, a);
      if (!std::isfinite(v)) throw InputError("values", "must hold finite numbers");
      table.set_value(s, a, v);
      if (!visits) continue;
      const std::int64_t n = visits->at(r, a);
      if (n < 0 || n > std::numeric_limits<std::uint32_t>::max()) {
        throw InputError("visits", "must be counts from 0 to 4294967295");
      }
      table.set_visits(s, a, static_cast<std::uint32_t>(n));
    }
    if (table.state_count() != static_cast<std::size_t>(r + 1)) {
      throw InputError("states", fmt::format("state {} is listed twice", s));
    }
  }
  return table;
}

ActionCode action_from(const QTable& table, const py::handle& action) {
  return static_cast<ActionCode>(integer_from(action, 0, table.action_count() - 1, "action"));
}

}  // namespace

void bind_learning(py::module_& m) {
  py::class_<QTable>(m, "QTable", "A Q-table over integer states and actions, sparse in states; unwritten values are 0")
      .def(py::init(
               [](const py::handle& action_count) { return QTable(action_count_from(action_count, "action_count")); }),
           py::arg("action_count"))
      .def_property_readonly("action_count", &QTable::action_count)
      .def_property_readonly("state_count", &QTable::state_count)
      .def(
          "value",
          [](const QTable& t, const py::handle& s, const py::handle& a) {
            return t.value(uint64_from(s, "state"), action_from(t, a));
          },
          py::arg("state"), py::arg("action"))
      .def(
          "visits",
          [](const QTable& t, const py::handle& s, const py::handle& a) {
            return t.visits(uint64_from(s, "state"), action_from(t, a));
          },
          py::arg("state"), py::arg("action"))
      .def(
          "set_value",
          [](QTable& t, const py::handle& s, const py::handle& a, double value) {
            if (!std::isfinite(value)) throw InputError("value", "must be a finite number");
            t.set_value(uint64_from(s, "state"), action_from(t, a), value);
          },
          py::arg("state"), py::arg("action"), py::arg("value"))
      .def("to_numpy", &table_to_numpy,
           "(states (R,) uint64, values (R, A) float64, visits (R, A) uint32), states ascending")
      .def_static("from_numpy", &table_from_numpy, py::arg("states"), py::arg("values"), py::arg("visits") = py::none())
      .def_static(
          "load",
          [](const py::handle& path, int action_count, const std::string& state_space) {
            return load_q_table(path_from(path), action_count, state_space);
          },
          py::arg("path"), py::arg("action_count"), py::arg("state_space"),
          "Reads a crux Q-table file whose action count and state space are those given")
      .def(
          "save",
          [](const QTable& table, const py::handle& path, const std::string& state_space) {
            save_q_table(path_from(path), table, state_space);
          },
          py::arg("path"), py::arg("state_space"));

  m.def(
      "grid_state_space",
      [](const py::handle& config) {
        return describe_grid(config_from_python(config, kGridKeys, "grid_state_space").settings.learning.climbing.grid);
      },
      py::arg("config") = py::none(), "The state space a Q_grid file records for the configured moving grid");
}

}  // namespace crux::python
