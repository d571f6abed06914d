#pragma once
// Result files are written to a temporary sibling and renamed into place, so an
// interrupted run never leaves a half-written file under the final name. A path naming
// a character device or a FIFO (/dev/null, /dev/stdout, a pipe) is written straight
// instead: a rename would replace the node itself with a regular file.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace crux {

// A temporary is named "<target>.tmp." followed by this many lowercase hex digits.
inline constexpr std::size_t kTemporarySuffixDigits = 16;

// How `path` is written. kReplace: a new path or a regular file (a temporary renamed into
// place). kStream: a character device or a FIFO, opened and written, the node kept.
// kRefuse: anything else (a folder, a socket, a block device), never written.
enum class OutputTarget { kReplace, kStream, kRefuse };
struct OutputNode {
  OutputTarget target = OutputTarget::kReplace;
  std::string refusal;  // why, for kRefuse: "is a folder", ...
};
OutputNode output_node(const std::filesystem::path& path);

// Writes `contents` to `path` as output_node says: atomically (a same-directory temporary
// with an unpredictable name created exclusively, fsync, rename), or straight to a
// character device or FIFO. Throws InputError naming `path` when the directory is missing
// or not writable, or output_node refuses it.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// From then on SIGINT, SIGTERM and SIGHUP remove the temporaries being written before
// the process ends as the signal asks.
void remove_temporaries_on_signals();

// Creates `directory` and its parents; InputError naming it when that fails.
void make_output_directory(const std::filesystem::path& directory);

}  // namespace crux
