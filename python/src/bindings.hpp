#pragma once
// The parts of the module crux._crux, one per area of the library.

#include <pybind11/pybind11.h>

namespace crux::python {

void bind_body(pybind11::module_& module);
void bind_ik(pybind11::module_& module);
void bind_wall(pybind11::module_& module);
void bind_climb_env(pybind11::module_& module);
void bind_vector_climb_env(pybind11::module_& module);
void bind_learning(pybind11::module_& module);
void bind_experiment(pybind11::module_& module);

}  // namespace crux::python
