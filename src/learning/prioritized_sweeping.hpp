#pragma once
// The queue of prioritized sweeping (Moore and Atkeson 1993; Sutton and Barto 2018,
// section 8.4): (state, action) pairs of the learnt model, each queued once at the
// largest priority it was given, popped highest first. Equal priorities pop the pair
// the model learnt first, so planning needs no random numbers.

#include <cstddef>
#include <vector>

namespace crux {

class CheckpointWriter;
class CheckpointReader;

class PriorityQueue {
 public:
  // Queues model entry `entry`, or raises its priority if it is queued lower.
  void push(std::size_t entry, double priority);
  // Queues `entry` at exactly this priority (its error is known afresh), lower or not.
  void set(std::size_t entry, double priority);
  void remove(std::size_t entry);
  bool empty() const { return queued_ == 0; }
  std::size_t size() const { return queued_; }
  // The entry of highest priority, removed from the queue. Precondition: !empty().
  std::size_t pop();

  // The heap as it is (stale items included, since they decide later rebuilds), for a
  // run's checkpoint; load_state replaces this queue.
  void save_state(CheckpointWriter& out) const;
  // Entries must be below `entries` (the model's size), or the reader fails.
  void load_state(CheckpointReader& in, std::size_t entries);

 private:
  struct Item {
    double priority;
    std::size_t entry;
  };
  static bool lower(const Item& a, const Item& b) {
    return a.priority < b.priority || (a.priority == b.priority && a.entry > b.entry);
  }

  void insert(std::size_t entry, double priority);

  std::vector<Item> heap_;           // may hold stale items, superseded by a later priority
  std::vector<double> priority_of_;  // per entry: its queued priority, or -1 when not queued
  std::size_t queued_ = 0;
};

}  // namespace crux
