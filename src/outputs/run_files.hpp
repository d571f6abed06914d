#pragma once
// The files of one learning run (docs/OUTPUTS.md): iterations.csv, episodes.csv,
// q_grid.bin and climb.csv, each written atomically.

#include <filesystem>

#include "experiments/learning_run.hpp"

namespace crux {

void write_run_files(const std::filesystem::path& directory, const RunResult& run, const BodyModel& model,
                     const GridParameters& grid);

}  // namespace crux
