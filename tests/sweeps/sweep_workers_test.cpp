#include "sweeps/sweep_workers.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace crux {
namespace {

std::vector<SweepTask> independent_tasks(std::size_t n, int transfer_every = 0) {
  std::vector<SweepTask> tasks(n);
  // Every `transfer_every`-th task waits for the one before it, as transfer runs do.
  for (std::size_t t = 1; transfer_every > 0 && t < n; t += transfer_every)
    tasks[t].depends_on = static_cast<int>(t - 1);
  return tasks;
}

TEST(SweepWorkers, ThreadsRunEveryTaskOnceAfterItsDependency) {
  const auto tasks = independent_tasks(40, 3);
  SweepSchedule schedule(tasks, std::vector<bool>(tasks.size(), false));
  std::vector<std::atomic<int>> runs(tasks.size());
  std::vector<std::atomic<bool>> done(tasks.size());
  std::atomic<bool> order_kept{true};
  std::size_t last_progress = 0;
  coordinate_sweep(
      schedule, 3,
      [&](std::size_t t) {
        if (tasks[t].depends_on >= 0 && !done[tasks[t].depends_on]) order_kept = false;
        ++runs[t];
        done[t] = true;
      },
      nullptr, [&](std::size_t finished) { last_progress = finished; });
  for (std::size_t t = 0; t < tasks.size(); ++t) EXPECT_EQ(runs[t], 1) << "task " << t;
  EXPECT_TRUE(order_kept);
  EXPECT_TRUE(schedule.done());
  EXPECT_EQ(last_progress, tasks.size());
}

TEST(SweepWorkers, AFailingTaskStopsTheHandOutAndIsRethrown) {
  // One thread, so that "after the failure is seen" does not depend on timing: with two,
  // the other thread may run every remaining task before the failing one returns.
  for (const int threads : {1, 2}) {
    const auto tasks = independent_tasks(50);
    SweepSchedule schedule(tasks, std::vector<bool>(tasks.size(), false));
    std::atomic<int> started{0};
    std::atomic<long> last_started{-1};
    EXPECT_THROW(coordinate_sweep(schedule, threads,
                                  [&](std::size_t t) {
                                    ++started;
                                    last_started = static_cast<long>(t);
                                    if (t == 3) throw std::runtime_error("disk full");
                                  },
                                  nullptr, {}),
                 std::runtime_error)
        << threads << " threads";
    EXPECT_FALSE(schedule.done()) << threads << " threads";
    if (threads == 1) {
      EXPECT_EQ(last_started, 3) << "no task is handed out after the failure is seen";
      EXPECT_LT(started, 50);
    }
  }
}

// Two processes in one: a worker "process" on its own thread, linked by queues.
struct Channel {
  std::mutex mutex;
  std::deque<CoordinatorLink::Request> requests;
  std::deque<long long> orders;
};

class FakeCoordinatorLink final : public CoordinatorLink {
 public:
  FakeCoordinatorLink(Channel& channel, std::size_t slots) : channel_(channel), slots_(slots) {}
  std::size_t slots() const override { return slots_; }
  void poll(std::vector<Request>& requests) override {
    const std::lock_guard lock(channel_.mutex);
    requests.insert(requests.end(), channel_.requests.begin(), channel_.requests.end());
    channel_.requests.clear();
  }
  void assign(int worker, std::size_t task) override {
    EXPECT_EQ(worker, 1);
    const std::lock_guard lock(channel_.mutex);
    channel_.orders.push_back(static_cast<long long>(task));
  }
  void stop(int) override {
    const std::lock_guard lock(channel_.mutex);
    channel_.orders.push_back(-1);
  }

 private:
  Channel& channel_;
  std::size_t slots_;
};

class FakeWorkerLink final : public WorkerLink {
 public:
  explicit FakeWorkerLink(Channel& channel) : channel_(channel) {}
  void request(long long finished) override {
    const std::lock_guard lock(channel_.mutex);
    channel_.requests.push_back({1, finished});
  }
  void poll(std::vector<long long>& orders) override {
    const std::lock_guard lock(channel_.mutex);
    orders.insert(orders.end(), channel_.orders.begin(), channel_.orders.end());
    channel_.orders.clear();
  }

 private:
  Channel& channel_;
};

TEST(SweepWorkers, AnotherProcessesSlotsShareTheTasks) {
  const auto tasks = independent_tasks(60, 3);
  SweepSchedule schedule(tasks, std::vector<bool>(tasks.size(), false));
  std::vector<std::atomic<int>> runs(tasks.size());
  std::atomic<int> remote_runs{0};
  Channel channel;
  FakeCoordinatorLink coordinator_side(channel, 2);
  FakeWorkerLink worker_side(channel);
  const auto slow = [] { std::this_thread::sleep_for(std::chrono::milliseconds(1)); };
  std::thread worker([&] {
    serve_sweep(
        2,
        [&](std::size_t t) {
          slow();
          ++runs[t];
          ++remote_runs;
        },
        worker_side);
  });
  coordinate_sweep(schedule, 1,
                   [&](std::size_t t) {
                     slow();
                     ++runs[t];
                   },
                   &coordinator_side, {});
  worker.join();  // returns only once both of its slots were stopped
  for (std::size_t t = 0; t < tasks.size(); ++t) EXPECT_EQ(runs[t], 1) << "task " << t;
  EXPECT_GT(remote_runs, 0);
  EXPECT_LT(remote_runs, 60);
}

}  // namespace
}  // namespace crux
