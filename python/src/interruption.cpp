#include "interruption.hpp"

#include <atomic>

#include <pybind11/pybind11.h>

namespace crux::python {

namespace {

// Set by the handler of the one active guard (only the main thread installs one, and
// its calls do not nest).
std::atomic<bool> interrupt_requested{false};

extern "C" void raise_interrupt_flag(int) { interrupt_requested.store(true); }

}  // namespace

InterruptGuard::InterruptGuard() {
  namespace py = pybind11;
  const py::module_ threading = py::module_::import("threading");
  if (!threading.attr("current_thread")().is(threading.attr("main_thread")())) return;
  const py::module_ signal = py::module_::import("signal");
  if (!signal.attr("getsignal")(signal.attr("SIGINT")).is(signal.attr("default_int_handler"))) return;
  interrupt_requested.store(false);
  struct sigaction action {};
  action.sa_handler = raise_interrupt_flag;
  sigemptyset(&action.sa_mask);
  active_ = sigaction(SIGINT, &action, &previous_) == 0;
}

InterruptGuard::~InterruptGuard() {
  if (!active_) return;
  sigaction(SIGINT, &previous_, nullptr);
  // A Ctrl-C no poll saw (the call was past its last one) is Python's to act on.
  if (interrupt_requested.exchange(false) && !std::uncaught_exceptions()) PyErr_SetInterrupt();
}

void InterruptGuard::poll() const {
  if (active_ && interrupt_requested.load(std::memory_order_relaxed)) throw Interrupted();
}

}  // namespace crux::python
