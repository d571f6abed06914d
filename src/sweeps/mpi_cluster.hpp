#pragma once
// A sweep across processes and machines under MPI (Open MPI: mpirun -n N crux sweep ...).
// Rank 0 coordinates; the others ask it for tasks, one message per free thread, and it
// answers each with a task or a stop. Messages are polled (with short sleeps), so a
// waiting rank does not spin a core that its threads need.

#include "sweeps/sweep_run.hpp"

namespace crux {

// Whether this process was started by an MPI launcher (mpirun sets these variables).
bool launched_by_mpi();

// Processes on this machine under the launcher (1 when not launched).
int local_processes();

class MpiCluster final : public SweepCluster {
 public:
  MpiCluster(int* argc, char*** argv);  // MPI_Init_thread (funneled)
  ~MpiCluster() override;               // MPI_Finalize
  MpiCluster(const MpiCluster&) = delete;
  MpiCluster& operator=(const MpiCluster&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  Agreement agree(bool ok, std::uint64_t job) override;
  bool share_readiness(bool ready) override;
  void barrier() override;
  [[noreturn]] void fail(const std::exception& failure) override;
  std::unique_ptr<CoordinatorLink> coordinator_link() override;
  std::unique_ptr<WorkerLink> worker_link(int threads) override;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace crux
