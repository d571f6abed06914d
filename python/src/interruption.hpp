#pragma once
// Ctrl-C during a long call. The call runs without the GIL, often on worker threads,
// where Python's own SIGINT handler cannot act. So while a call made from the main
// thread runs, and only when SIGINT is Python's default (KeyboardInterrupt), SIGINT just
// raises this guard's flag; the call's progress callback polls it and unwinds with
// Interrupted, which Python sees as KeyboardInterrupt. A signal that arrives after the
// last poll is handed back to Python when the guard ends. A script that handles or
// ignores SIGINT itself keeps its choice: the guard then stays inactive.

#include <csignal>
#include <stdexcept>

namespace crux::python {

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

class InterruptGuard {
 public:
  InterruptGuard();  // with the GIL held
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Throws Interrupted once SIGINT has arrived while this guard is active; called from
  // any thread.
  void poll() const;

 private:
  struct sigaction previous_ {};
  bool active_ = false;
};

}  // namespace crux::python
