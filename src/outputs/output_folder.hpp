#pragma once
// Output folders (docs/OUTPUTS.md): every file written to a temporary name and renamed,
// so that an interrupted run leaves no half-written file.

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/experiment_analysis.hpp"
#include "experiments/experiment_config.hpp"
#include "outputs/provenance.hpp"

namespace crux {

// Checks `directory` before the long work, writing nothing: InputError naming it when it
// holds one of the command's `inputs` (it would be overwritten), or already holds files
// (a lock file alone does not count: folder_lock.hpp) and `overwrite` is false.
void check_output_folder(const std::filesystem::path& directory, const std::vector<std::string>& inputs,
                         bool overwrite);

// Checks the file `-o` names before the work, writing nothing: InputError("--output", ...)
// when the name is empty, when the file is one of the command's `inputs` (a file, or a
// file inside an input folder such as the run folder it reads: the same file however
// named, ./w.json and w.json, a link or a hard link), or when write_file_atomically would
// refuse it (a folder, a socket).
void check_output_file(const std::filesystem::path& file, const std::vector<std::string>& inputs);

// The writers below first remove crux's earlier outputs from the folder (and nothing
// else) and mark it incomplete with this file, which they remove once every output is
// written: a folder that keeps it was interrupted.
inline constexpr const char* kIncompleteMarker = "INCOMPLETE";

// Removes the outputs `names` from `directory`, and their temporaries (a command killed
// by SIGKILL leaves them); InputError naming an output that cannot be removed.
void remove_outputs(const std::filesystem::path& directory, std::span<const char* const> names);
// Only the temporaries of `names`: what a command killed by SIGKILL leaves (other
// signals remove their own).
void remove_temporaries(const std::filesystem::path& directory, std::span<const char* const> names);
// ... every output of every crux command but crux sweep, or only their temporaries.
void remove_crux_outputs(const std::filesystem::path& directory);
void remove_crux_temporaries(const std::filesystem::path& directory);
// Removes the INCOMPLETE marker.
void mark_complete(const std::filesystem::path& directory);

// config.toml's text: the command's parameters, then the [provenance] table.
std::string config_file_text(ExperimentConfig& config, const ParameterSet& accepted, const Provenance& provenance);

// A `crux paper` folder: config.toml, walls/, runs/<condition>_<r>/, figures/ (the CSVs
// of Figs. 2b, 3 and 4) and summary.json.
// `draw_figures` draws the SVG figures into the folder from the files just written (as
// `crux figures` redraws them), before the folder is marked complete: the drawing is the
// reports' and views', above this layer.
void write_experiment_folder(const std::filesystem::path& directory, const ExperimentResult& result,
                             const ExperimentParameters& parameters, const BodyModel& model,
                             const std::string& config_toml, const nlohmann::ordered_json& summary,
                             const std::function<void(const std::filesystem::path&)>& draw_figures);

// Writes a long run's checkpoint file (run_checkpoint.hpp) atomically into `directory`,
// which it marks incomplete until write_run_folder completes it (and removes the file).
void write_checkpoint(const std::filesystem::path& directory, const std::string& bytes);

// A `crux train` or `crux transfer` folder: the run's files, wall.json, config.toml and
// summary.json. `result` holds the one run (single_run_result).
void write_run_folder(const std::filesystem::path& directory, const ExperimentResult& result, const BodyModel& model,
                      const GridParameters& grid, const std::string& config_toml,
                      const nlohmann::ordered_json& summary);

// A `crux perform` folder: config.toml, wall.json, perform.json (the climb performed and
// its moves), trajectory.csv (outputs/trajectory_csv) and climber.xml (the MJCF it was
// performed in; empty when no plan was found, and then not written).
void write_perform_folder(const std::filesystem::path& directory, const std::string& config_toml, const Wall& wall,
                          const nlohmann::ordered_json& record, const std::string& trajectory_csv,
                          const std::string& mjcf);

}  // namespace crux
