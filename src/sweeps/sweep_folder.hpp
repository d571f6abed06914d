#pragma once
// A sweep's output folder (docs/OUTPUTS.md): sweep.toml, walls/, runs/, results.csv and
// summary.json. Starting a sweep again in its folder resumes it: the folder must hold
// the same sweep.toml (the same parameters and the same crux build), every finished
// task folder is kept, and only the others run.

#include <filesystem>
#include <string>
#include <vector>

#include "common/folder_lock.hpp"
#include "sweeps/sweep_plan.hpp"

namespace crux {

// Locks `folder` (folder_lock.hpp) and checks it before any work (InputError naming
// it): not written by another sweep, empty or missing, or holding a sweep with the same
// `sweep_toml` (a resume); with `overwrite`, another sweep's or another crux command's
// outputs are removed first. Then writes sweep.toml, clears .partial/ and the
// temporaries a SIGKILL leaves, and marks the folder INCOMPLETE. `inputs` may not lie
// inside the folder. The returned lock keeps other sweeps out until it is destroyed:
// hold it while the sweep writes the folder.
FolderLock prepare_sweep_folder(const std::filesystem::path& folder, const std::string& sweep_toml,
                                const std::vector<std::string>& inputs, bool overwrite);

// One flag per task of `plan`: whether its folder is in place.
std::vector<bool> finished_tasks(const SweepPlan& plan, const std::filesystem::path& folder);

// Removes .partial/ and the INCOMPLETE marker once results.csv and summary.json are
// written.
void mark_sweep_complete(const std::filesystem::path& folder);

}  // namespace crux
