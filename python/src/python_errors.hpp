#pragma once
// How crux's errors reach Python: bad input (InputError) is a ValueError whose message
// is the CLI's error line without its "crux: " prefix; a long call stopped by Ctrl-C
// (interruption.hpp) is a KeyboardInterrupt.

#include <pybind11/pybind11.h>

namespace crux::python {

void register_error_translation(pybind11::module_& module);

}  // namespace crux::python
