// crux._crux: the C++ library as a Python module; the package crux (crux/__init__.py)
// re-exports it.

#include "bindings.hpp"
#include "python_errors.hpp"

#include "common/build_info.hpp"

PYBIND11_MODULE(_crux, module) {
  module.doc() = "crux: a virtual human that learns to climb walls of holds (C++ core)";
  module.attr("__version__") = crux::crux_version();
  crux::python::register_error_translation(module);
  crux::python::bind_body(module);
  crux::python::bind_ik(module);
  crux::python::bind_wall(module);
  crux::python::bind_climb_env(module);
  crux::python::bind_vector_climb_env(module);
  crux::python::bind_learning(module);
  crux::python::bind_experiment(module);
}
