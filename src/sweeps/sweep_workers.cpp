#include "sweeps/sweep_workers.hpp"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace crux {

namespace {

// How long a process that also talks to others waits for its threads before polling.
constexpr auto kPollInterval = std::chrono::milliseconds(2);

// Threads that take tasks from an inbox and put them, done, into an outbox.
class LocalSlots {
 public:
  LocalSlots(int threads, const TaskRunner& run) {
    for (int t = 0; t < threads; ++t) {
      threads_.emplace_back([this, &run] {
        for (;;) {
          std::optional<std::size_t> task;
          {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return !inbox_.empty(); });
            task = inbox_.front();
            inbox_.pop_front();
          }
          if (!task) return;
          std::exception_ptr failure;
          try {
            run(*task);
          } catch (...) {
            failure = std::current_exception();
          }
          const std::lock_guard lock(mutex_);
          outbox_.push_back({*task, failure});
          done_.notify_all();
        }
      });
    }
  }
  ~LocalSlots() {
    {
      const std::lock_guard lock(mutex_);
      for (std::size_t t = 0; t < threads_.size(); ++t) inbox_.push_back(std::nullopt);
    }
    wake_.notify_all();
    for (std::thread& thread : threads_) thread.join();
  }

  void assign(std::size_t task) {
    {
      const std::lock_guard lock(mutex_);
      inbox_.push_back(task);
    }
    wake_.notify_one();
  }

  struct Finished {
    std::size_t task;
    std::exception_ptr failure;
  };
  // The tasks finished since the last call, waiting up to `wait` (forever if null) for one.
  std::vector<Finished> finished(std::optional<std::chrono::milliseconds> wait) {
    std::unique_lock lock(mutex_);
    const auto any = [&] { return !outbox_.empty(); };
    if (wait) {
      done_.wait_for(lock, *wait, any);
    } else {
      done_.wait(lock, any);
    }
    std::vector<Finished> out(outbox_.begin(), outbox_.end());
    outbox_.clear();
    return out;
  }

 private:
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::deque<std::optional<std::size_t>> inbox_;  // nullopt: stop one thread
  std::deque<Finished> outbox_;
  std::vector<std::thread> threads_;
};

}  // namespace

void coordinate_sweep(SweepSchedule& schedule, int threads, const TaskRunner& run, CoordinatorLink* others,
                      const std::function<void(std::size_t)>& progress) {
  std::exception_ptr failure;
  std::deque<int> waiting_workers;  // other processes' slots that asked
  std::size_t stopped_slots = 0;
  {
    LocalSlots local(threads, run);
    int idle_threads = threads;
    std::size_t in_flight = 0;
    std::vector<CoordinatorLink::Request> requests;
    const auto finished = [&](std::size_t task) {
      --in_flight;
      schedule.finish(task);
      if (progress) progress(schedule.finished_count());
    };
    for (;;) {
      while (!failure && (idle_threads > 0 || !waiting_workers.empty())) {
        const std::optional<std::size_t> task = schedule.next();
        if (!task) break;
        ++in_flight;
        if (idle_threads > 0) {
          --idle_threads;
          local.assign(*task);
        } else {
          others->assign(waiting_workers.front(), *task);
          waiting_workers.pop_front();
        }
      }
      if (in_flight == 0 && (schedule.done() || failure)) break;
      const auto wait = others != nullptr ? std::optional(kPollInterval) : std::nullopt;
      for (const LocalSlots::Finished& f : local.finished(wait)) {
        ++idle_threads;
        if (f.failure) {
          --in_flight;
          if (!failure) failure = f.failure;
          continue;
        }
        finished(f.task);
      }
      if (others != nullptr) {
        requests.clear();
        others->poll(requests);
        for (const CoordinatorLink::Request& r : requests) {
          if (r.finished >= 0) finished(static_cast<std::size_t>(r.finished));
          waiting_workers.push_back(r.worker);
        }
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
  // Every slot of the other processes is stopped once it asks again.
  if (others != nullptr) {
    std::vector<CoordinatorLink::Request> requests;
    for (;;) {
      while (!waiting_workers.empty()) {
        others->stop(waiting_workers.front());
        waiting_workers.pop_front();
        ++stopped_slots;
      }
      if (stopped_slots >= others->slots()) break;
      std::this_thread::sleep_for(kPollInterval);
      requests.clear();
      others->poll(requests);
      for (const CoordinatorLink::Request& r : requests) waiting_workers.push_back(r.worker);
    }
  }
}

void serve_sweep(int threads, const TaskRunner& run, WorkerLink& coordinator) {
  LocalSlots local(threads, run);
  for (int t = 0; t < threads; ++t) coordinator.request(-1);
  int stopped = 0;
  std::vector<long long> orders;
  while (stopped < threads) {
    orders.clear();
    coordinator.poll(orders);
    for (const long long order : orders) {
      if (order < 0) {
        ++stopped;
      } else {
        local.assign(static_cast<std::size_t>(order));
      }
    }
    for (const LocalSlots::Finished& f : local.finished(kPollInterval)) {
      if (f.failure) std::rethrow_exception(f.failure);
      coordinator.request(static_cast<long long>(f.task));
    }
  }
}

}  // namespace crux
