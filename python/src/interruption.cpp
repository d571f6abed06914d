#include "interruption.hpp"

#include <atomic>

#include <pybind11/pybind11.h>

namespace crux::python {

namespace {

std::atomic<bool> interrupt_requested{false};

extern "C" void raise_interrupt_flag(int) { interrupt_requested.store(true); }

}  // namespace

InterruptGuard::InterruptGuard() {
  // Python delivers signals to its main thread only; a call made from another thread
  // leaves SIGINT to Python, as Python code would.
  const pybind11::module_ threading = pybind11::module_::import("threading");
  if (!threading.attr("current_thread")().is(threading.attr("main_thread")())) return;
  interrupt_requested.store(false);
  struct sigaction action {};
  action.sa_handler = raise_interrupt_flag;
  sigemptyset(&action.sa_mask);
  installed_ = sigaction(SIGINT, &action, &previous_) == 0;
}

InterruptGuard::~InterruptGuard() {
  if (installed_) sigaction(SIGINT, &previous_, nullptr);
}

void InterruptGuard::poll() {
  if (interrupt_requested.load(std::memory_order_relaxed)) throw Interrupted();
}

}  // namespace crux::python
