#pragma once
// Runs the crux binary for end-to-end tests and captures its exit code and output.

#include <filesystem>
#include <string>

namespace crux::testing {

struct Outcome {
  int exit_code = -1;
  std::string out;
  std::string err;
};

Outcome run_crux(const std::string& arguments);
// The same, run from `folder`, so that relative paths are what a user would type there.
Outcome run_crux_in(const std::filesystem::path& folder, const std::string& arguments);
int count_lines(const std::string& text);

}  // namespace crux::testing
