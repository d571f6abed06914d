#include "sweeps/sweep_folder.hpp"

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "outputs/output_folder.hpp"
#include "sweeps/sweep_task.hpp"

namespace crux {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSweepOutputs[] = {"sweep.toml",   "walls",        "runs",           "results.csv",
                                         "summary.json", kPartialFolder, kIncompleteMarker};

}  // namespace

FolderLock prepare_sweep_folder(const fs::path& folder, const std::string& sweep_toml,
                                const std::vector<std::string>& inputs, bool overwrite) {
  if (folder.empty()) throw InputError("--output", "the output folder name is empty");
  FolderLock lock(folder, "crux sweep");
  const fs::path recorded = folder / "sweep.toml";
  std::error_code error;
  // What a SIGKILL may have left half-written: temporaries of the sweep's own files.
  remove_temporaries(folder, kSweepOutputs);
  const bool recorded_exists = fs::is_regular_file(recorded, error);
  const bool resume = recorded_exists && read_input_file(recorded.string(), "sweep file") == sweep_toml;
  if (recorded_exists && !resume && !overwrite) {
    throw InputError(folder.string(),
                     "holds another sweep (its sweep.toml differs: other parameters, or another crux "
                     "build); choose another folder, or pass --overwrite to replace it");
  }
  check_output_folder(folder, inputs, overwrite || resume);
  make_output_directory(folder);
  if (!resume) {
    remove_crux_outputs(folder);
    remove_outputs(folder, kSweepOutputs);
    // sweep.toml first: a folder killed from then on resumes.
    write_file_atomically(recorded, sweep_toml);
  }
  fs::remove_all(folder / kPartialFolder, error);
  if (error)
    throw InputError((folder / kPartialFolder).string(), "cannot remove the half-written tasks: " + error.message());
  write_file_atomically(folder / kIncompleteMarker,
                        "crux is running the sweep of this folder; start the same command again to resume it.\n");
  return lock;
}

std::vector<bool> finished_tasks(const SweepPlan& plan, const fs::path& folder) {
  std::vector<bool> finished(plan.tasks.size());
  std::error_code error;
  for (std::size_t t = 0; t < plan.tasks.size(); ++t)
    finished[t] = fs::is_directory(folder / plan.tasks[t].folder, error);
  return finished;
}

void mark_sweep_complete(const fs::path& folder) {
  std::error_code error;
  fs::remove_all(folder / kPartialFolder, error);
  mark_complete(folder);
}

}  // namespace crux
