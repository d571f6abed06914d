#pragma once
// Reading a user's input file whole, with the same clear one-line errors for every
// kind of file crux reads (model, wall, config, Q-table).

#include <string>
#include <string_view>

namespace crux {

// The file's bytes. Throws InputError(path, ...) when the path is a directory ("is a
// directory, not a <kind>"), does not exist ("no such file") or cannot be read.
std::string read_input_file(const std::string& path, std::string_view kind);

}  // namespace crux
