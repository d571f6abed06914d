#include "learning/prioritized_sweeping.hpp"

#include <algorithm>
#include <cassert>

#include "common/checkpoint_stream.hpp"

namespace crux {

void PriorityQueue::push(std::size_t entry, double priority) {
  if (entry >= priority_of_.size()) priority_of_.resize(entry + 1, -1.0);
  if (priority_of_[entry] < priority) insert(entry, priority);
}

void PriorityQueue::set(std::size_t entry, double priority) {
  if (entry >= priority_of_.size()) priority_of_.resize(entry + 1, -1.0);
  if (priority_of_[entry] != priority) insert(entry, priority);
}

void PriorityQueue::remove(std::size_t entry) {
  if (entry < priority_of_.size() && priority_of_[entry] >= 0.0) {
    priority_of_[entry] = -1.0;
    --queued_;
  }
}

void PriorityQueue::insert(std::size_t entry, double priority) {
  if (priority_of_[entry] < 0.0) ++queued_;
  priority_of_[entry] = priority;
  heap_.push_back({priority, entry});
  std::push_heap(heap_.begin(), heap_.end(), lower);
  // Stale items are skipped when popped, but low ones may never be: rebuild from the
  // live priorities before they outnumber them. The pop order depends only on
  // (priority, entry), so a rebuild changes nothing that is popped.
  if (heap_.size() > 4 * queued_ + 64) {
    heap_.clear();
    for (std::size_t e = 0; e < priority_of_.size(); ++e) {
      if (priority_of_[e] >= 0.0) heap_.push_back({priority_of_[e], e});
    }
    std::make_heap(heap_.begin(), heap_.end(), lower);
  }
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

void PriorityQueue::save_state(CheckpointWriter& out) const {
  out.vector(heap_);
  out.vector(priority_of_);
  out.value<std::uint64_t>(queued_);
}

void PriorityQueue::load_state(CheckpointReader& in, std::size_t entries) {
  heap_ = in.vector<Item>();
  priority_of_ = in.vector<double>();
  queued_ = in.value<std::uint64_t>();
  if (priority_of_.size() > entries) in.fail();
  for (const Item& item : heap_) {
    if (item.entry >= priority_of_.size()) in.fail();
  }
  const auto live = static_cast<std::size_t>(
      std::count_if(priority_of_.begin(), priority_of_.end(), [](double p) { return p >= 0.0; }));
  if (live != queued_) in.fail();
  // Every live priority must be in the heap, or pop() would run past its end.
  std::vector<bool> in_heap(priority_of_.size(), false);
  for (const Item& item : heap_) {
    if (item.priority == priority_of_[item.entry]) in_heap[item.entry] = true;
  }
  for (std::size_t e = 0; e < priority_of_.size(); ++e) {
    if (priority_of_[e] >= 0.0 && !in_heap[e]) in.fail();
  }
  if (!std::is_heap(heap_.begin(), heap_.end(), lower)) in.fail();
}

}  // namespace crux
