#include "sweeps/sweep_schedule.hpp"

#include <stdexcept>

namespace crux {

SweepSchedule::SweepSchedule(const std::vector<SweepTask>& tasks, const std::vector<bool>& finished)
    : finished_(finished), dependents_(tasks.size()) {
  if (finished.size() != tasks.size()) throw std::invalid_argument("SweepSchedule: one finished flag per task");
  for (std::size_t t = 0; t < tasks.size(); ++t) {
    finished_count_ += finished_[t] ? 1 : 0;
    const int dependency = tasks[t].depends_on;
    if (dependency >= 0 && !finished_[dependency]) {
      dependents_[dependency].push_back(t);
    } else if (!finished_[t]) {
      ready_.insert(t);
    }
  }
}

std::optional<std::size_t> SweepSchedule::next() {
  if (ready_.empty()) return std::nullopt;
  const std::size_t task = *ready_.begin();
  ready_.erase(ready_.begin());
  return task;
}

void SweepSchedule::finish(std::size_t task) {
  if (finished_.at(task)) throw std::logic_error("SweepSchedule: a task finished twice");
  finished_[task] = true;
  ++finished_count_;
  for (const std::size_t dependent : dependents_[task]) {
    if (!finished_[dependent]) ready_.insert(dependent);
  }
}

}  // namespace crux
