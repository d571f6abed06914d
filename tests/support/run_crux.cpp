#include "support/run_crux.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
#include <filesystem>

#include "support/test_models.hpp"

namespace crux::testing {

namespace {

std::string read_all(FILE* file) {
  std::string text;
  std::array<char, 4096> buffer;
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), file)) text.append(buffer.data(), n);
  return text;
}

}  // namespace

Outcome run_crux_in(const std::filesystem::path& folder, const std::string& arguments) {
  static std::atomic<int> calls{0};
  // Unique per call, in the process's own folder.
  const auto err_path = test_folder() / ("stderr." + std::to_string(calls++));
  const std::string change_folder = folder.empty() ? std::string() : "cd '" + folder.string() + "' && ";
  const std::string command = change_folder + CRUX_BINARY + " " + arguments + " 2>" + err_path.string();
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  outcome.out = read_all(pipe);
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (FILE* err = std::fopen(err_path.c_str(), "r")) {
    outcome.err = read_all(err);
    std::fclose(err);
  }
  std::filesystem::remove(err_path);
  return outcome;
}

Outcome run_crux(const std::string& arguments) { return run_crux_in({}, arguments); }

int count_lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace crux::testing
