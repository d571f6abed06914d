#include "outputs/output_folder.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "common/atomic_file.hpp"
#include "common/folder_lock.hpp"
#include "common/input_error.hpp"
#include "experiments/run_checkpoint.hpp"
#include "outputs/figure_tables.hpp"
#include "outputs/run_files.hpp"
#include "wall/wall_file.hpp"

namespace crux {

namespace fs = std::filesystem;

namespace {

// Everything a crux command writes into an output folder but a long run's checkpoint,
// which stays until the folder is complete: a kill while the folder is written leaves
// it to resume from.
constexpr const char* kOutputNames[] = {"config.toml",    "summary.json",     "runs",           "walls",
                                        "figures",        "iterations.csv",   "episodes.csv",   "q_grid.bin",
                                        "climb.csv",      "greedy_climb.csv", "wall.json",      "perform.json",
                                        "trajectory.csv", "climber.xml",      kIncompleteMarker};
constexpr const char* kCheckpointOnly[] = {kCheckpointFile};

// Complete, then without a checkpoint: a kill between the two resumes from it again.
void finish_output_folder(const fs::path& directory) {
  mark_complete(directory);
  remove_outputs(directory, kCheckpointOnly);
}

void begin_output_folder(const fs::path& directory) {
  remove_outputs(directory, kOutputNames);
  make_output_directory(directory);
  write_file_atomically(directory / kIncompleteMarker,
                        "crux is writing this folder; if this file remains, the command was interrupted and the "
                        "folder's outputs are incomplete.\n");
}

// The absolute path with links, `.` and `..` resolved as far as it exists, without a
// trailing separator: two names of one file compare equal.
fs::path resolved_path(const fs::path& path) {
  std::error_code error;
  fs::path resolved = fs::weakly_canonical(fs::absolute(path), error).lexically_normal();
  if (resolved.filename().empty()) resolved = resolved.parent_path();
  return resolved;
}

// Whether `path` is `folder` or lies inside it.
bool lies_within(const fs::path& path, const fs::path& folder) {
  const auto [end, _] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return end == folder.end();
}

}  // namespace

void remove_outputs(const fs::path& directory, std::span<const char* const> names) {
  std::error_code error;
  for (const char* name : names) {
    fs::remove_all(directory / name, error);
    if (error) throw InputError((directory / name).string(), "cannot remove the earlier output: " + error.message());
  }
  remove_temporaries(directory, names);
}

void remove_temporaries(const fs::path& directory, std::span<const char* const> names) {
  std::error_code error;
  if (fs::is_directory(directory, error)) {
    for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
      const std::string name = entry.path().filename().string();
      const bool temporary = std::any_of(names.begin(), names.end(), [&](const char* output) {
        const std::string prefix = std::string(output) + ".tmp.";
        return name.size() == prefix.size() + kTemporarySuffixDigits && name.rfind(prefix, 0) == 0 &&
               name.find_first_not_of("0123456789abcdef", prefix.size()) == std::string::npos;
      });
      if (temporary) fs::remove(entry.path(), error);
    }
  }
}

void remove_crux_outputs(const fs::path& directory) {
  remove_outputs(directory, kOutputNames);
  remove_outputs(directory, kCheckpointOnly);
}

void remove_crux_temporaries(const fs::path& directory) {
  remove_temporaries(directory, kOutputNames);
  remove_temporaries(directory, kCheckpointOnly);
}

void mark_complete(const fs::path& directory) {
  std::error_code error;
  fs::remove(directory / kIncompleteMarker, error);
}

void check_output_folder(const fs::path& directory, const std::vector<std::string>& inputs, bool overwrite) {
  if (directory.empty()) throw InputError("--output", "the output folder name is empty");
  std::error_code error;
  const fs::path folder = resolved_path(directory);
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    if (lies_within(resolved_path(input), folder)) {
      throw InputError(directory.string(),
                       fmt::format("holds {}, an input of this command; write the outputs to another folder", input));
    }
  }
  if (!fs::exists(directory, error)) return;
  if (!fs::is_directory(directory, error)) throw InputError(directory.string(), "exists and is not a folder");
  const bool holds_files =
      std::any_of(fs::directory_iterator(directory, error), fs::directory_iterator(),
                  [](const fs::directory_entry& entry) { return entry.path().filename() != kFolderLockFile; });
  if (!overwrite && holds_files) {
    throw InputError(directory.string(),
                     "already holds files; choose another output folder, or pass --overwrite to replace crux's "
                     "outputs there");
  }
}

void check_output_file(const fs::path& file, const std::vector<std::string>& inputs) {
  if (file.empty()) throw InputError("--output", "the output file name is empty");
  const OutputNode node = output_node(file);
  if (node.target == OutputTarget::kRefuse) throw InputError("--output", file.string() + " " + node.refusal);
  // A device or a FIFO is written through, never replaced: writing to /dev/null destroys no input.
  if (node.target == OutputTarget::kStream) return;
  const fs::path output = resolved_path(file);
  std::error_code error;
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    // equivalent() also catches a hard link to an input.
    if (lies_within(output, resolved_path(input)) || fs::equivalent(file, input, error)) {
      throw InputError("--output", fmt::format("{} would overwrite {}, an input of this command; write to another file",
                                               file.string(), input));
    }
  }
}

std::string config_file_text(ExperimentConfig& config, const ParameterSet& accepted, const Provenance& provenance) {
  return config_to_toml(config, accepted) + provenance_toml(provenance);
}

void write_experiment_folder(const fs::path& directory, const ExperimentResult& result,
                             const ExperimentParameters& parameters, const BodyModel& model,
                             const std::string& config_toml, const nlohmann::ordered_json& summary,
                             const std::function<void(const fs::path&)>& draw_figures) {
  begin_output_folder(directory);
  write_file_atomically(directory / "config.toml", config_toml);
  make_output_directory(directory / "walls");
  for (std::size_t w = 0; w < result.walls.size(); ++w) {
    const bool training = static_cast<int>(w) < parameters.wall_pairs;
    save_wall(
        (directory / "walls" / fmt::format("{}_{}.json", training ? "training" : "transfer", w % parameters.wall_pairs))
            .string(),
        result.walls[w].wall);
  }
  for (const Condition condition : kConditions) {
    const ConditionResult& c = result.conditions[static_cast<int>(condition)];
    for (std::size_t i = 0; i < c.runs.size(); ++i) {
      write_run_files(directory / "runs" / fmt::format("{}_{}", enum_name(condition), i), c.runs[i], model,
                      parameters.learning.climbing.grid);
    }
  }
  make_output_directory(directory / "figures");
  write_file_atomically(directory / "figures" / "fig3_regimes.csv", fig3_csv(result, parameters.learning.iterations));
  write_file_atomically(directory / "figures" / "fig4_episode_lengths.csv", fig4_csv(result));
  write_file_atomically(directory / "figures" / "fig2b_qgrid_maps.csv",
                        fig2b_csv(result, parameters.learning.climbing.grid));
  write_file_atomically(directory / "summary.json", summary.dump(2) + "\n");
  draw_figures(directory);
  finish_output_folder(directory);
}

void write_checkpoint(const fs::path& directory, const std::string& bytes) {
  make_output_directory(directory);
  // The checkpoint first: a folder holds the marker only once it can resume.
  write_file_atomically(directory / kCheckpointFile, bytes);
  std::error_code error;
  if (!fs::exists(directory / kIncompleteMarker, error)) {
    write_file_atomically(directory / kIncompleteMarker,
                          "crux is running the run of this folder; the same command started again resumes it from "
                          "checkpoint.bin.\n");
  }
}

void write_run_folder(const fs::path& directory, const ExperimentResult& result, const BodyModel& model,
                      const GridParameters& grid, const std::string& config_toml,
                      const nlohmann::ordered_json& summary) {
  begin_output_folder(directory);
  for (const ConditionResult& c : result.conditions) {
    if (!c.runs.empty()) write_run_files(directory, c.runs.front(), model, grid);
  }
  write_file_atomically(directory / "config.toml", config_toml);
  save_wall((directory / "wall.json").string(), result.walls.front().wall);
  write_file_atomically(directory / "summary.json", summary.dump(2) + "\n");
  finish_output_folder(directory);
}

void write_perform_folder(const fs::path& directory, const std::string& config_toml, const Wall& wall,
                          const nlohmann::ordered_json& record, const std::string& trajectory_csv,
                          const std::string& mjcf) {
  begin_output_folder(directory);
  write_file_atomically(directory / "config.toml", config_toml);
  save_wall((directory / "wall.json").string(), wall);
  write_file_atomically(directory / "perform.json", record.dump(2) + "\n");
  write_file_atomically(directory / "trajectory.csv", trajectory_csv);
  if (!mjcf.empty()) write_file_atomically(directory / "climber.xml", mjcf);
  finish_output_folder(directory);
}

}  // namespace crux
