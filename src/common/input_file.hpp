#pragma once
// Reading a user's input file whole, with the same clear one-line errors for every
// kind of file crux reads (model, wall, config, Q-table).

#include <cstddef>
#include <string>
#include <string_view>

namespace crux {

// Larger inputs are refused: crux's largest real inputs (Q-tables of long runs) are a few
// megabytes.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{1} << 30;

// The file's bytes. Throws InputError(path, ...) when the path is a directory ("is a
// directory, not a <kind>"), is not a regular file (a FIFO, a device: refused without
// waiting on it), is larger than kMaxInputFileBytes, does not exist ("no such file") or
// cannot be read; InputError(kind, ...) when the name is empty.
std::string read_input_file(const std::string& path, std::string_view kind);

}  // namespace crux
