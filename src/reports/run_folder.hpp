#pragma once
// A run's output folder read back (docs/OUTPUTS.md): the folder of `crux train` or
// `crux transfer`, or runs/<condition>_<i> of a `crux paper` folder. What the views need
// to draw the run: its wall, the body model it was written with, the postures of its
// last completed climb and the iterations of that climb's episode.

#include <filesystem>
#include <string>
#include <vector>

#include "body/body_model.hpp"
#include "learning/action_selection.hpp"
#include "wall/wall.hpp"

namespace crux {

// A row of iterations.csv.
struct RunStep {
  int iteration = 0;  // from 1
  int episode = 0;
  Regime regime = Regime::Random;
  int hold_id = 0;
  bool success = false;
  double root_rise_cm = 0.0;
  double reward = 0.0;
};

struct RunFolder {
  std::filesystem::path directory;
  std::string name;  // "training_3" in an experiment, else the folder's name
  std::filesystem::path wall_file;
  Wall wall;
  std::filesystem::path summary_file;
  std::string urdf;  // the body model recorded in the summary's provenance ("" if none)
  // The last completed episode (-1 if none) and its iterations; climb.csv's postures:
  // the start, then one per reached iteration of that episode.
  int climb_episode = -1;
  std::vector<RunStep> climb_steps;
  std::vector<Posture> climb;
};

// Where the folder's wall and summary are, and the body model it recorded; InputError
// naming the folder (or the file) when it is not a run folder.
RunFolder locate_run_folder(const std::filesystem::path& directory);

// Reads the wall, climb.csv (whose columns must be `model`'s joints) and iterations.csv
// into `folder`; InputError naming the file and the problem.
void read_run_climb(RunFolder& folder, const BodyModel& model);

}  // namespace crux
