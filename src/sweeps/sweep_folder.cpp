#include "sweeps/sweep_folder.hpp"

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "reports/output_folder.hpp"
#include "sweeps/sweep_task.hpp"

namespace crux {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSweepOutputs[] = {"sweep.toml", "walls", "runs", "results.csv", "summary.json", kPartialFolder,
                                         kIncompleteMarker};

void remove_outputs(const fs::path& folder, bool every_output) {
  std::error_code error;
  for (const char* name : kSweepOutputs) {
    if (!every_output && std::string(name) != kPartialFolder) continue;
    fs::remove_all(folder / name, error);
    if (error) throw InputError((folder / name).string(), "cannot remove the earlier output: " + error.message());
  }
}

}  // namespace

void prepare_sweep_folder(const fs::path& folder, const std::string& sweep_toml, const std::vector<std::string>& inputs,
                          bool overwrite) {
  const fs::path recorded = folder / "sweep.toml";
  std::error_code error;
  const bool resume = fs::is_regular_file(recorded, error) &&
                      read_input_file(recorded.string(), "sweep file") == sweep_toml;
  if (!resume) {
    // The checks of every other output folder: not an input's, empty unless --overwrite.
    check_output_folder(folder, inputs, overwrite);
    if (fs::exists(folder, error)) remove_outputs(folder, true);
  } else {
    check_output_folder(folder, inputs, true);
  }
  remove_outputs(folder, false);
  make_output_directory(folder);
  write_file_atomically(folder / kIncompleteMarker,
                        "crux is running the sweep of this folder; start the same command again to resume it.\n");
  if (!resume) write_file_atomically(recorded, sweep_toml);
}

std::vector<bool> finished_tasks(const SweepPlan& plan, const fs::path& folder) {
  std::vector<bool> finished(plan.tasks.size());
  std::error_code error;
  for (std::size_t t = 0; t < plan.tasks.size(); ++t) finished[t] = fs::is_directory(folder / plan.tasks[t].folder, error);
  return finished;
}

void mark_sweep_complete(const fs::path& folder) {
  std::error_code error;
  fs::remove(folder / kIncompleteMarker, error);
}

}  // namespace crux
