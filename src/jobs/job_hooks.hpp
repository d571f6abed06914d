#pragma once
// What a caller gives a long job besides its inputs: who it is (recorded in the
// provenance), where to report progress, and where the job may be interrupted.

#include <functional>
#include <string>

namespace crux {

struct JobHooks {
  std::string caller;                          // "crux train", "crux.run_learning", ...
  std::function<void(int done)> progress;      // learning iterations (or runs) done so far
  std::function<void()> interruption_point;    // may throw to stop the job
  std::function<void(int iteration)> resumed;  // a checkpoint was found: learning resumes after it
};

}  // namespace crux
