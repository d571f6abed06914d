#pragma once
// A whole sweep (crux sweep), in one process or across the processes of a SweepCluster
// (MPI: mpi_cluster.hpp). Process 0 locks and prepares the folder, coordinates and, at the end,
// writes results.csv and summary.json from the task folders; every other process only
// runs the tasks it is sent. Every process must be given the same job.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "body/body_model.hpp"
#include "sweeps/sweep_plan.hpp"
#include "sweeps/sweep_workers.hpp"

namespace crux {

// The processes that share a sweep. Every call is collective: all processes make it.
class SweepCluster {
 public:
  virtual ~SweepCluster() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Whether every process read its sweep (`ok`) and holds the same one (`job`, a digest
  // of its sweep.toml), and whether process 0 did.
  struct Agreement {
    bool every_ok = true, coordinator_ok = true, same_job = true;
  };
  virtual Agreement agree(bool ok, std::uint64_t job) = 0;
  // Process 0's `ready`, on every process.
  virtual bool share_readiness(bool ready) = 0;
  // Returns once every process has called it.
  virtual void barrier() = 0;
  // Ends every process of the job once one has failed after the work started (the
  // others would wait for it forever), reporting `failure` on stderr.
  [[noreturn]] virtual void fail(const std::exception& failure) = 0;
  // Process 0's link to the others' `threads` slots; theirs to it.
  virtual std::unique_ptr<CoordinatorLink> coordinator_link() = 0;
  virtual std::unique_ptr<WorkerLink> worker_link(int threads) = 0;
};

struct SweepJob {
  SweepPlan plan;
  std::filesystem::path folder;     // absolute: every process resolves transfer inputs in it
  std::string sweep_toml;           // the effective sweep file, written to the folder
  std::vector<std::string> inputs;  // files the sweep reads: not inside the folder
  nlohmann::ordered_json provenance;
  bool overwrite = false;
  int threads = 1;  // worker threads of this process
};

struct SweepOutcome {
  bool coordinator = false;                     // this process wrote the results
  std::size_t tasks = 0, already_finished = 0;  // of the plan; kept from an earlier start
  double seconds = 0.0;
  nlohmann::ordered_json summary;  // summary.json's contents (the coordinator's)
};

// Progress: finished tasks out of all of them (process 0 only).
using SweepProgress = std::function<void(std::size_t finished, std::size_t total)>;

// `cluster` null: this process alone. On a process other than 0, returns when the
// coordinator stops it; when process 0 failed to prepare the folder, returns at once
// (process 0 throws the error). A failure once the work has started ends every
// process (SweepCluster::fail).
SweepOutcome run_sweep(const SweepJob& job, const BodyModel& model, SweepCluster* cluster,
                       const SweepProgress& progress = {});

}  // namespace crux
