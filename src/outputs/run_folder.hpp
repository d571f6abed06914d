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
#include "outputs/iterations_file.hpp"
#include "wall/wall.hpp"

namespace crux {

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

// The climb named by `choice`: "greedy", "last" (chosen_climb) or an episode number N,
// counted from 1 as the paper's Fig. 4 and crux's figures count episodes, replayed from
// the folder's iterations.csv (replay_episode) with the run's own climbing `parameters`.
// InputError naming `flag` for a choice that is none of these or an episode the run does
// not have.
RecordedClimb climb_to_show(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                            const std::string& choice, const std::string& flag);

// Which climb `shown` (climb_to_show's for `choice`) is and why it is the one, for the
// reader of a report: the greedy climb, or the last completed episode because the greedy
// policy did not reach the top within `greedy_cap` actions, or the episode `flag` asked
// for. With no climb to show (no postures), why there is none.
std::string shown_climb_reason(const RunFolder& folder, const RecordedClimb& shown, const std::string& choice,
                               int greedy_cap, const std::string& flag);

}  // namespace crux
