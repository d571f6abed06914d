#pragma once
// A run's output folder read back (docs/OUTPUTS.md): the folder of `crux train` or
// `crux transfer`, or runs/<condition>_<i> of a `crux paper` folder. What the views need
// to draw the run: its wall, the body model it was written with, the postures of its
// last completed climb and the iterations of that climb's episode.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "body/body_model.hpp"
#include "experiments/iterations_file.hpp"
#include "wall/wall.hpp"

namespace crux {

// A climb the run recorded, with the moves between its postures.
struct RecordedClimb {
  std::string kind;      // "last": the last completed episode; "greedy": the learnt policy's climb
  int episode = -1;      // its index from 0, as in iterations.csv; -1 for the greedy climb, or when no episode ended
  bool finished = true;  // false for a replayed episode that the run's iterations cut off
  std::vector<RunStep> steps;     // every move; a greedy move has iteration 0
  std::vector<Posture> postures;  // the start, then one per reached move
};

struct RunFolder {
  std::filesystem::path directory;
  std::string name;                   // "training_3" in an experiment, else the folder's name
  std::filesystem::path config_file;  // the config.toml the run was written with
  std::filesystem::path wall_file;
  Wall wall;
  std::filesystem::path summary_file;
  nlohmann::json summary;      // its contents: the run's, or its experiment's
  int iterations = 0;          // the summary's: the rows iterations.csv must hold
  std::string urdf;            // the body model recorded in the summary's provenance ("" if none)
  std::vector<RunStep> steps;  // every row of iterations.csv
  RecordedClimb last;          // climb.csv and its episode's rows of iterations.csv
  RecordedClimb greedy;        // greedy_climb.csv; empty when the greedy policy does not finish
};

// Where the folder's wall and summary are, and the body model it recorded; InputError
// naming the folder (or the file) when it is not a run folder.
RunFolder locate_run_folder(const std::filesystem::path& directory);

// A report or view of `folder`: the folder itself for a run folder, or runs/`run_name`
// of a crux paper folder (`experiment` is set). InputError naming the folder or `flag`;
// for a run the paper folder does not hold, the error lists the runs it holds.
struct ReportedRun {
  bool experiment = false;
  std::filesystem::path run_directory;
};
ReportedRun locate_reported_run(const std::filesystem::path& folder, const std::string& run_name,
                                const std::string& flag);

// episodes.csv's lengths, each checked (numbered in order, positive); InputError naming
// the file and the problem.
std::vector<int> read_episode_lengths(const std::filesystem::path& directory);

// Reads climb.csv and greedy_climb.csv (whose columns must be `model`'s joints) and
// iterations.csv (which must hold folder.iterations rows) into `folder`; InputError naming
// the file and the problem.
void read_run_climb(RunFolder& folder, const BodyModel& model);

// "the greedy policy's climb after learning" or "the climb of episode N" (N from 1, as
// the paper's Fig. 4 counts episodes; with "unfinished" when the run ended during it).
std::string climb_description(const RecordedClimb& climb);

// The climb to show: "greedy" is the greedy climb when it finishes, else the last
// episode's; "last" the last episode's.
const RecordedClimb& chosen_climb(const RunFolder& folder, std::string_view kind);

}  // namespace crux
