#pragma once
// Result files are written to a temporary sibling and renamed into place, so an
// interrupted run never leaves a half-written file under the final name.

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace crux {

// A temporary is named "<target>.tmp." followed by this many lowercase hex digits.
inline constexpr std::size_t kTemporarySuffixDigits = 16;

// Writes `contents` to `path` atomically: a same-directory temporary with an
// unpredictable name created exclusively, fsync, rename.
// Throws InputError naming `path` when the directory is missing or not writable.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// From then on SIGINT, SIGTERM and SIGHUP remove the temporaries being written before
// the process ends as the signal asks.
void remove_temporaries_on_signals();

// Creates `directory` and its parents; InputError naming it when that fails.
void make_output_directory(const std::filesystem::path& directory);

}  // namespace crux
