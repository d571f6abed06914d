#pragma once
// A long run's checkpoint file (docs/OUTPUTS.md): checkpoint.bin in the run's output
// folder, rewritten atomically every experiment.checkpoint_every iterations by crux
// train and crux transfer, and gone once the folder is complete. It holds the run's
// identity (its config.toml text with the provenance, without checkpoint_every) and
// run_learning's state (learning_run.hpp), so the same command started again resumes
// only the run that wrote it.

#include <filesystem>
#include <optional>
#include <string>

namespace crux {

inline constexpr const char* kCheckpointFile = "checkpoint.bin";

std::string checkpoint_file_bytes(const std::string& identity, const std::string& state);

// The state in `file` for the run of `identity`; nullopt when the file does not exist.
// InputError naming the file when it is not a crux checkpoint or another run's.
std::optional<std::string> read_checkpoint(const std::filesystem::path& file, const std::string& identity);

}  // namespace crux
