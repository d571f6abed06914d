// crux sweep: crux paper's experiment over every combination of listed parameter values,
// on threads or across MPI processes (mpirun -n N crux sweep ...), resumable.

#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/progress_bar.hpp"
#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "common/sha256.hpp"
#include "experiments/run_inputs.hpp"
#include "reports/sweep_description.hpp"
#include "sweeps/mpi_cluster.hpp"
#include "sweeps/sweep_definition.hpp"
#include "sweeps/sweep_run.hpp"

namespace crux::cli {

namespace {

// Writes `failure` as main would, and returns its exit code.
int report(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const InputError& e) {
    std::fprintf(stderr, "crux: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crux: internal error: %s\n", e.what());
    return 1;
  }
}

// The first 64 bits of the sweep file's SHA-256: processes that hold different sweeps
// (config files, flags or crux builds) are told apart.
std::uint64_t job_digest(const std::string& sweep_toml) {
  return std::stoull(sha256_hex(sweep_toml).substr(0, 16), nullptr, 16);
}

struct SweepCommand {
  ParameterBinding binding{"sweep", with_progress(kSweepKeys)};
  ProgressDisplay progress_display = ProgressDisplay::Bar;
  std::string output = "out/sweep";
  bool json = false;
  bool overwrite = false;

  void run() {
    std::optional<MpiCluster> cluster;
    if (launched_by_mpi()) cluster.emplace(nullptr, nullptr);
    const bool coordinator = !cluster || cluster->rank() == 0;
    std::optional<SweepJob> job;
    std::optional<BodyModel> model;
    std::exception_ptr failure;
    try {
      std::tie(job, model) = prepare();
    } catch (...) {
      failure = std::current_exception();
    }
    if (cluster) {
      const SweepCluster::Agreement agreed = cluster->agree(!failure, failure ? 0 : job_digest(job->sweep_toml));
      if (!agreed.every_ok || !agreed.same_job) {
        // Every process meets the same bad input: process 0 alone reports it, or the
        // processes that failed where it did not. All wait until it is written: mpirun
        // ends the job at the first process that exits with an error.
        int code = 2;
        if (failure && (coordinator || agreed.coordinator_ok)) {
          code = report(failure);
        } else if (!failure && coordinator) {
          report(std::make_exception_ptr(
              InputError("mpirun",
                         "another process of this sweep failed to read it, or was given another sweep (its "
                         "config file, flags or crux build differ)")));
        }
        cluster->barrier();
        throw CLI::RuntimeError(code);
      }
    } else if (failure) {
      std::rethrow_exception(failure);
    }
    run_job(*job, *model, cluster ? &*cluster : nullptr, coordinator);
  }

  std::pair<SweepJob, BodyModel> prepare() {
    const SweepGrid grid{binding.listed_keys(), binding.config_path()};
    SweepDefinition definition = define_sweep(grid, [&](const ListChoice& choice) { return binding.resolve(choice); });
    const ExperimentConfig& first = definition.plan.cells.front().config;
    if (!binding.config_path().empty()) {
      check_recorded_provenance(first, definition.provenance, binding.config_path());
    }
    BodyModel model = load_configured_body(first);
    progress_display = first.progress;
    SweepJob job{std::move(definition.plan),
                 output.empty() ? std::filesystem::path() : std::filesystem::absolute(output).lexically_normal(),
                 std::move(definition.sweep_toml),
                 {first.urdf, binding.config_path()},
                 provenance_json(definition.provenance),
                 overwrite,
                 first.settings.threads};
    if (job.threads == 0) {
      job.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / local_processes());
    }
    return {std::move(job), std::move(model)};
  }

  void run_job(const SweepJob& job, const BodyModel& model, MpiCluster* cluster, bool coordinator) {
    std::optional<ProgressBar> progress;
    if (coordinator) {
      progress.emplace(
          fmt::format("sweep: {}, {}", counted(job.plan.cells.size(), "cell"), counted(job.plan.tasks.size(), "task")),
          static_cast<long>(job.plan.tasks.size()), progress_display, true);
    }
    bool started = false;
    const SweepOutcome outcome = run_sweep(job, model, cluster, [&](std::size_t done, std::size_t) {
      if (!started) progress->start_at(static_cast<long>(done));
      started = true;
      progress->update(static_cast<long>(done));
    });
    if (!outcome.coordinator) return;
    progress->finish();
    std::cout << (json ? outcome.summary.dump(2) + "\n"
                       : sweep_text(nlohmann::json(outcome.summary), output, outcome.tasks, outcome.already_finished,
                                    outcome.seconds));
  }
};

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto sweep = std::make_shared<SweepCommand>();
  auto* s = app.add_subcommand(
      "sweep",
      "Run crux paper's experiment for every combination of the values listed in --config (key = [a, b]); "
      "resumable, and across processes under mpirun");
  s->add_option("-o,--output", sweep->output, "Output folder; the same command started again there resumes the sweep")
      ->capture_default_str();
  s->add_flag("--json", sweep->json, "Print summary.json's contents instead of text");
  s->add_flag("--overwrite", sweep->overwrite,
              "Replace another sweep's, or another crux command's, outputs in the output folder");
  sweep->binding.bind(s, false);
  sweep->binding.option("experiment.runs")
      ->excludes(sweep->binding.option("experiment.walls"))
      ->excludes(sweep->binding.option("experiment.seeds_per_wall"));
  s->callback([sweep] { sweep->run(); });
}

}  // namespace crux::cli
