#pragma once
// SHA-256 digests (OpenSSL), recorded in output folders so that a replay can tell
// whether its input files are the ones the run used.

#include <string>
#include <string_view>

namespace crux {

// Lower-case hex digest of `bytes`.
std::string sha256_hex(std::string_view bytes);

// Digest of a file's contents; InputError naming `path` when it cannot be read.
std::string sha256_of_file(const std::string& path, std::string_view kind);

}  // namespace crux
