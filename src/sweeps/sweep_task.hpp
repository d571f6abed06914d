#pragma once
// One task of a sweep (sweep_plan.hpp), run by whichever worker the schedule gave it to.
// Its folder is written under <sweep>/.partial/ and renamed into place once whole, so a
// sweep killed at any moment leaves only finished task folders (and a .partial/ that
// the next start clears).

#include <cstddef>
#include <filesystem>

#include "body/body_model.hpp"
#include "sweeps/sweep_plan.hpp"

namespace crux {

inline constexpr const char* kPartialFolder = ".partial";

// Runs task `task` of `plan` and writes its folder under `sweep_folder`. A transfer run
// reads its training run's q_grid.bin, which must be there.
void run_sweep_task(const SweepPlan& plan, std::size_t task, const BodyModel& model,
                    const std::filesystem::path& sweep_folder);

// A training task with K > 1 training walls: the file of the Q_grid its K - 1 preceding
// runs left, which its last run starts from, beside the task's folder
// (runs/c<C>/training_<r>.preceding_q_grid.bin), relative to the sweep folder.
std::filesystem::path preceding_q_grid_file(const SweepTask& task);

}  // namespace crux
