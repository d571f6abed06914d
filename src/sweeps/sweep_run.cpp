#include "sweeps/sweep_run.hpp"

#include <chrono>
#include <optional>

#include "sweeps/sweep_folder.hpp"
#include "sweeps/sweep_results.hpp"
#include "sweeps/sweep_schedule.hpp"
#include "sweeps/sweep_task.hpp"

namespace crux {

SweepOutcome run_sweep(const SweepJob& job, const BodyModel& model, SweepCluster* cluster,
                       const SweepProgress& progress) {
  const auto started = std::chrono::steady_clock::now();
  SweepOutcome outcome;
  outcome.tasks = job.plan.tasks.size();
  const TaskRunner run = [&](std::size_t task) { run_sweep_task(job.plan, task, model, job.folder); };
  if (cluster != nullptr && cluster->rank() != 0) {
    if (!cluster->share_readiness(false)) return outcome;
    try {
      serve_sweep(job.threads, run, *cluster->worker_link(job.threads));
    } catch (const std::exception& e) {
      cluster->fail(e);
    }
    return outcome;
  }
  outcome.coordinator = true;
  std::vector<bool> finished;
  std::optional<FolderLock> lock;
  try {
    lock.emplace(prepare_sweep_folder(job.folder, job.sweep_toml, job.inputs, job.overwrite));
    finished = finished_tasks(job.plan, job.folder);
  } catch (...) {
    if (cluster != nullptr) cluster->share_readiness(false);
    throw;
  }
  std::unique_ptr<CoordinatorLink> others;
  if (cluster != nullptr) {
    cluster->share_readiness(true);
    others = cluster->coordinator_link();
  }
  SweepSchedule schedule(job.plan.tasks, finished);
  outcome.already_finished = schedule.finished_count();
  if (progress) progress(schedule.finished_count(), outcome.tasks);
  try {
    coordinate_sweep(schedule, job.threads, run, others.get(), [&](std::size_t done) {
      if (progress) progress(done, outcome.tasks);
    });
    outcome.summary = write_sweep_results(job.plan, job.folder, job.provenance);
    write_sweep_report(job.plan, job.folder, outcome.summary);
  } catch (const std::exception& e) {
    if (cluster != nullptr) cluster->fail(e);
    throw;
  }
  mark_sweep_complete(job.folder);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return outcome;
}

}  // namespace crux
