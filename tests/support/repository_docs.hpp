#pragma once
// The repository's docs as tests read them, to check that what they quote is what crux
// does: the text of a file, whether it quotes a line, and the keys a section's table names.

#include <string>
#include <vector>

namespace crux::testing {

// The text of a file of the repository, by its path from the repository's root.
std::string repository_file(const std::string& relative_path);

// Whether `markdown` holds `text`, any run of whitespace in either matching any other
// (a quote may be wrapped across lines).
bool quotes(const std::string& markdown, const std::string& text);

// The names in backquotes in the first cell of each table row of the section that
// starts at the line `heading` (through the next heading of the same or a higher
// level), in order: "| `a`, `b` | ... |" names a and b.
std::vector<std::string> documented_keys(const std::string& markdown, const std::string& heading);

}  // namespace crux::testing
