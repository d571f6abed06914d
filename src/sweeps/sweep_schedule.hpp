#pragma once
// Which sweep task may start next: the lowest-numbered task that is neither finished nor
// handed out and whose dependency has finished. Whoever asks first gets it, so workers
// that finish early take more tasks (dynamic load balancing); the results do not depend
// on who ran what.

#include <cstddef>
#include <optional>
#include <set>
#include <vector>

#include "sweeps/sweep_plan.hpp"

namespace crux {

class SweepSchedule {
 public:
  // `finished`: tasks already done (a resumed sweep), one flag per task.
  SweepSchedule(const std::vector<SweepTask>& tasks, const std::vector<bool>& finished);

  // The next task to start, now marked as handed out; none when every remaining task
  // waits for one that is running.
  std::optional<std::size_t> next();
  void finish(std::size_t task);

  bool done() const { return finished_count_ == finished_.size(); }
  std::size_t finished_count() const { return finished_count_; }

 private:
  std::vector<bool> finished_;
  std::vector<std::vector<std::size_t>> dependents_;
  std::set<std::size_t> ready_;
  std::size_t finished_count_ = 0;
};

}  // namespace crux
