#pragma once
// A `crux perform` folder read back (docs/OUTPUTS.md, "crux perform"): what the report and
// the view show of a climb performed in MuJoCo. Its writer is write_perform_folder
// (outputs/output_folder).

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/performed_replay.hpp"

namespace crux {

struct PerformFolder {
  std::filesystem::path directory;
  Wall wall;
  std::string climb;    // what was performed: "the wall's exact plan", a run's climb
  std::string physics;  // the physics model it was planned under (perform.json's physics_model)
  bool found = false;   // a plan was found (else nothing was performed)
  int planned_moves = 0;
  bool start_held = false;  // the start stance held still (false also when nothing was performed)
  MoveFailure start_cause = MoveFailure::None;
  std::vector<AttemptedMove> moves;  // every move attempted, performed but perhaps the last
  bool reached_top = false;
  double max_torque_ratio = 0.0;
  double simulated_s = 0.0;
  std::vector<TrajectorySample> trajectory;  // trajectory.csv

  // The sample step `step` ends on: the start come to rest (0), or the end of move `step`
  // (from 1 to the moves attempted); the last sample before it when the move has none.
  const TrajectorySample& step_sample(int step) const;
};

// Whether `directory` is a `crux perform` folder (it holds perform.json).
bool is_perform_folder(const std::filesystem::path& directory);

// Reads the folder's wall.json, perform.json and trajectory.csv (whose joints must be
// `model`'s): InputError naming the file and the problem.
PerformFolder read_perform_folder(const std::filesystem::path& directory, const BodyModel& model);

}  // namespace crux
