#include "learning/prioritized_sweeping.hpp"

#include <algorithm>
#include <cassert>

namespace crux {

void PriorityQueue::push(std::size_t entry, double priority) {
  if (entry >= priority_of_.size()) priority_of_.resize(entry + 1, -1.0);
  double& current = priority_of_[entry];
  if (current >= priority) return;
  if (current < 0.0) ++queued_;
  current = priority;
  heap_.push_back({priority, entry});
  std::push_heap(heap_.begin(), heap_.end(), lower);
}

std::size_t PriorityQueue::pop() {
  assert(!empty());
  while (true) {
    std::pop_heap(heap_.begin(), heap_.end(), lower);
    const Item top = heap_.back();
    heap_.pop_back();
    if (priority_of_[top.entry] != top.priority) continue;  // superseded by a raise
    priority_of_[top.entry] = -1.0;
    --queued_;
    return top.entry;
  }
}

}  // namespace crux
