#pragma once
// Who runs a sweep's tasks. One coordinator owns the schedule and hands out one task at
// a time to each free slot that asks: its own threads, and the slots of other processes
// (MPI ranks, mpi_cluster.hpp) through a CoordinatorLink. A worker process serves its
// threads through a WorkerLink. Slots that finish early ask again sooner, which balances
// runs of unequal length. Where a task runs never changes what it writes.

#include <cstddef>
#include <functional>
#include <vector>

#include "sweeps/sweep_schedule.hpp"

namespace crux {

// The coordinator's side of the other processes' slots.
class CoordinatorLink {
 public:
  virtual ~CoordinatorLink() = default;
  struct Request {
    int worker = 0;           // the process that asks
    long long finished = -1;  // the task its slot just finished (-1: its first request)
  };
  virtual std::size_t slots() const = 0;  // slots of all the other processes
  // The requests that arrived, without waiting.
  virtual void poll(std::vector<Request>& requests) = 0;
  virtual void assign(int worker, std::size_t task) = 0;
  virtual void stop(int worker) = 0;  // one slot of `worker` is done
};

// A worker process's side.
class WorkerLink {
 public:
  virtual ~WorkerLink() = default;
  virtual void request(long long finished) = 0;  // a slot asks, having finished that task (-1: none)
  // The orders that arrived, without waiting: a task, or -1 to stop one slot.
  virtual void poll(std::vector<long long>& orders) = 0;
};

using TaskRunner = std::function<void(std::size_t task)>;

// Runs every task `schedule` still holds on `threads` threads and `others`' slots (may
// be null), calling `progress` with the number of finished tasks after each. The first
// task that throws stops the hand-out; its exception is rethrown once the threads
// have stopped.
void coordinate_sweep(SweepSchedule& schedule, int threads, const TaskRunner& run, CoordinatorLink* others,
                      const std::function<void(std::size_t finished)>& progress);

// A worker process: asks for a task per thread and runs what it is sent until every
// slot is stopped. A task that throws is rethrown (the caller ends the whole job).
void serve_sweep(int threads, const TaskRunner& run, WorkerLink& coordinator);

}  // namespace crux
