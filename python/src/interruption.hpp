#pragma once
// Ctrl-C during a long call. The call runs without the GIL, often on worker threads,
// where Python's own SIGINT handler cannot act; so while it runs, SIGINT only raises a
// flag that the call's progress callback polls, and the call unwinds from there with
// Interrupted, which Python sees as KeyboardInterrupt. The previous handler comes back
// when the guard ends.

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

  // Throws Interrupted once SIGINT has arrived; called from any thread.
  static void poll();

 private:
  struct sigaction previous_{};
  bool installed_ = false;
};

}  // namespace crux::python
